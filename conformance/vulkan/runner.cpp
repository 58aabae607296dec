// A small Vulkan compute runner that grades real shaders on a real driver through
// shadowproof's JSON-lines protocol (docs/protocol.md):
//
//   shadowproof_vk_runner SHADER.spv --inputs N --outputs M cases.jsonl > outputs.jsonl
//   shadowproof_vk_runner --describe          the device and driver that would run them
//
// Every case line's "numbers" (its f32 inputs, in the order the line lists its groups) goes
// into one storage buffer (binding 0, N floats per case); the shader writes M floats per case
// into a second one (binding 1); the push constant is the case count; one invocation per
// case, local size 64. Outputs are written as JSON numbers: a float widened to double, in the
// shortest form that reads back as that double, so nothing is rounded on the way out. What is
// graded is the driver's compiled code: its contraction into fused multiply-adds, its
// division, inverse() and normalize() — whatever the shader compiler and the driver make of it.
// The device is the first one with a compute queue; with Mesa's lavapipe installed
// (mesa-vulkan-drivers) and VK_ICD_FILENAMES pointing at it, that is the CPU driver.
#include <vulkan/vulkan.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace {

void check(VkResult r, const char* what) {
  if (r != VK_SUCCESS) throw std::runtime_error(std::string(what) + " failed with VkResult " + std::to_string(r));
}

std::vector<std::uint32_t> read_spirv(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot read " + path);
  std::vector<char> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (bytes.size() % 4 != 0 || bytes.empty()) throw std::runtime_error(path + " is not SPIR-V");
  std::vector<std::uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), bytes.size());
  return words;
}

struct buffer {
  VkBuffer handle = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
};

std::uint32_t host_visible_type(VkPhysicalDevice gpu, std::uint32_t allowed) {
  VkPhysicalDeviceMemoryProperties p;
  vkGetPhysicalDeviceMemoryProperties(gpu, &p);
  const VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  for (std::uint32_t i = 0; i < p.memoryTypeCount; ++i)
    if ((allowed & (1u << i)) && (p.memoryTypes[i].propertyFlags & want) == want) return i;
  throw std::runtime_error("no host-visible coherent memory");
}

buffer make_buffer(VkPhysicalDevice gpu, VkDevice device, VkDeviceSize size) {
  buffer b;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  check(vkCreateBuffer(device, &info, nullptr, &b.handle), "vkCreateBuffer");
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device, b.handle, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = host_visible_type(gpu, req.memoryTypeBits);
  check(vkAllocateMemory(device, &alloc, nullptr, &b.memory), "vkAllocateMemory");
  check(vkBindBufferMemory(device, b.handle, b.memory, 0), "vkBindBufferMemory");
  check(vkMapMemory(device, b.memory, 0, size, 0, &b.mapped), "vkMapMemory");
  return b;
}

// A float as a JSON number that reads back exactly (NaN and infinities as the protocol's
// strings).
std::string json_number(float x) {
  if (std::isnan(x)) return "\"nan\"";
  if (std::isinf(x)) return x > 0 ? "\"inf\"" : "\"-inf\"";
  char text[64];
  const auto r = std::to_chars(text, text + sizeof text, static_cast<double>(x));
  return std::string(text, r.ptr);
}

struct case_line {
  std::uint64_t id;
  std::vector<float> inputs;
};

std::vector<case_line> read_cases(const std::string& path, std::size_t inputs) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error("cannot read " + path);
  std::vector<case_line> cases;
  std::string line;
  while (std::getline(f, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto j = nlohmann::ordered_json::parse(line);
    if (j.at("type") != "f32") throw std::runtime_error("shaders take f32 cases only");
    case_line c{j.at("id").get<std::uint64_t>(), {}};
    for (const auto& [name, values] : j.at("numbers").items())
      for (const auto& v : values) {
        const double d = v.get<double>();
        const float x = static_cast<float>(d);
        if (static_cast<double>(x) != d) throw std::runtime_error("input " + name + " is not a float value");
        c.inputs.push_back(x);
      }
    if (c.inputs.size() != inputs)
      throw std::runtime_error("case " + std::to_string(c.id) + " has " + std::to_string(c.inputs.size()) +
                               " inputs, the shader takes " + std::to_string(inputs));
    cases.push_back(std::move(c));
  }
  return cases;
}

int run(const std::string& spirv_path, std::size_t n_in, std::size_t n_out, const std::string& cases_path) {
  const bool describe = cases_path == "--describe";
  const auto cases = describe ? std::vector<case_line>{} : read_cases(cases_path, n_in);
  const auto code = describe ? std::vector<std::uint32_t>{} : read_spirv(spirv_path);
  const std::uint32_t count = static_cast<std::uint32_t>(cases.size());
  if (count == 0 && !describe) return 0;

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "shadowproof_vk_runner";
  app.apiVersion = VK_API_VERSION_1_2;
  VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  ici.pApplicationInfo = &app;
  VkInstance instance;
  check(vkCreateInstance(&ici, nullptr, &instance), "vkCreateInstance");

  std::uint32_t n_gpus = 0;
  check(vkEnumeratePhysicalDevices(instance, &n_gpus, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> gpus(n_gpus);
  check(vkEnumeratePhysicalDevices(instance, &n_gpus, gpus.data()), "vkEnumeratePhysicalDevices");
  VkPhysicalDevice gpu = VK_NULL_HANDLE;
  std::uint32_t family = 0;
  for (VkPhysicalDevice g : gpus) {
    std::uint32_t n = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(g, &n, nullptr);
    std::vector<VkQueueFamilyProperties> props(n);
    vkGetPhysicalDeviceQueueFamilyProperties(g, &n, props.data());
    for (std::uint32_t i = 0; i < n && gpu == VK_NULL_HANDLE; ++i)
      if (props[i].queueFlags & VK_QUEUE_COMPUTE_BIT) gpu = g, family = i;
    if (gpu != VK_NULL_HANDLE) break;
  }
  if (gpu == VK_NULL_HANDLE) throw std::runtime_error("no Vulkan device with a compute queue");
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 gp{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  gp.pNext = &driver;
  vkGetPhysicalDeviceProperties2(gpu, &gp);
  const std::string description = std::string(gp.properties.deviceName) + ", " + driver.driverName + " " + driver.driverInfo;
  if (cases_path == "--describe") {  // what is graded: the device and its driver
    std::cout << description << "\n";
    vkDestroyInstance(instance, nullptr);
    return 0;
  }
  std::cerr << "shadowproof_vk_runner: " << description << "\n";

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  qci.queueFamilyIndex = family;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  VkDevice device;
  check(vkCreateDevice(gpu, &dci, nullptr, &device), "vkCreateDevice");
  VkQueue queue;
  vkGetDeviceQueue(device, family, 0, &queue);

  buffer in = make_buffer(gpu, device, sizeof(float) * n_in * count);
  buffer out = make_buffer(gpu, device, sizeof(float) * n_out * count);
  auto* in_f = static_cast<float*>(in.mapped);
  for (std::size_t i = 0; i < cases.size(); ++i) std::memcpy(in_f + i * n_in, cases[i].inputs.data(), sizeof(float) * n_in);
  std::memset(out.mapped, 0, sizeof(float) * n_out * count);

  VkDescriptorSetLayoutBinding bindings[2]{};
  for (std::uint32_t i = 0; i < 2; ++i) {
    bindings[i].binding = i;
    bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    bindings[i].descriptorCount = 1;
    bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  }
  VkDescriptorSetLayoutCreateInfo dsl{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  dsl.bindingCount = 2;
  dsl.pBindings = bindings;
  VkDescriptorSetLayout set_layout;
  check(vkCreateDescriptorSetLayout(device, &dsl, nullptr, &set_layout), "vkCreateDescriptorSetLayout");
  VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(std::uint32_t)};
  VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pli.setLayoutCount = 1;
  pli.pSetLayouts = &set_layout;
  pli.pushConstantRangeCount = 1;
  pli.pPushConstantRanges = &push;
  VkPipelineLayout pipeline_layout;
  check(vkCreatePipelineLayout(device, &pli, nullptr, &pipeline_layout), "vkCreatePipelineLayout");
  VkShaderModuleCreateInfo smi{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  smi.codeSize = code.size() * 4;
  smi.pCode = code.data();
  VkShaderModule module;
  check(vkCreateShaderModule(device, &smi, nullptr, &module), "vkCreateShaderModule");
  VkComputePipelineCreateInfo cpi{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  cpi.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  cpi.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  cpi.stage.module = module;
  cpi.stage.pName = "main";
  cpi.layout = pipeline_layout;
  VkPipeline pipeline;
  check(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &cpi, nullptr, &pipeline), "vkCreateComputePipelines");

  VkDescriptorPoolSize pool_size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2};
  VkDescriptorPoolCreateInfo dpi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  dpi.maxSets = 1;
  dpi.poolSizeCount = 1;
  dpi.pPoolSizes = &pool_size;
  VkDescriptorPool pool;
  check(vkCreateDescriptorPool(device, &dpi, nullptr, &pool), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo dsa{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  dsa.descriptorPool = pool;
  dsa.descriptorSetCount = 1;
  dsa.pSetLayouts = &set_layout;
  VkDescriptorSet set;
  check(vkAllocateDescriptorSets(device, &dsa, &set), "vkAllocateDescriptorSets");
  VkDescriptorBufferInfo infos[2] = {{in.handle, 0, VK_WHOLE_SIZE}, {out.handle, 0, VK_WHOLE_SIZE}};
  VkWriteDescriptorSet writes[2]{};
  for (std::uint32_t i = 0; i < 2; ++i) {
    writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    writes[i].dstSet = set;
    writes[i].dstBinding = i;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[i].pBufferInfo = &infos[i];
  }
  vkUpdateDescriptorSets(device, 2, writes, 0, nullptr);

  VkCommandPoolCreateInfo cpci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  cpci.queueFamilyIndex = family;
  VkCommandPool command_pool;
  check(vkCreateCommandPool(device, &cpci, nullptr, &command_pool), "vkCreateCommandPool");
  VkCommandBufferAllocateInfo cba{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  cba.commandPool = command_pool;
  cba.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  cba.commandBufferCount = 1;
  VkCommandBuffer cmd;
  check(vkAllocateCommandBuffers(device, &cba, &cmd), "vkAllocateCommandBuffers");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout, 0, 1, &set, 0, nullptr);
  vkCmdPushConstants(cmd, pipeline_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof count, &count);
  vkCmdDispatch(cmd, (count + 63) / 64, 1, 1);
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0,
                       nullptr, 0, nullptr);
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  check(vkQueueSubmit(queue, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
  check(vkQueueWaitIdle(queue), "vkQueueWaitIdle");

  const auto* out_f = static_cast<const float*>(out.mapped);
  std::ostringstream text;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    text << "{\"id\": " << cases[i].id << ", \"output\": [";
    for (std::size_t j = 0; j < n_out; ++j) text << (j ? ", " : "") << json_number(out_f[i * n_out + j]);
    text << "]}\n";
  }
  std::cout << text.str();

  vkDestroyCommandPool(device, command_pool, nullptr);
  vkDestroyDescriptorPool(device, pool, nullptr);
  vkDestroyPipeline(device, pipeline, nullptr);
  vkDestroyShaderModule(device, module, nullptr);
  vkDestroyPipelineLayout(device, pipeline_layout, nullptr);
  vkDestroyDescriptorSetLayout(device, set_layout, nullptr);
  for (buffer* b : {&in, &out}) {
    vkUnmapMemory(device, b->memory);
    vkDestroyBuffer(device, b->handle, nullptr);
    vkFreeMemory(device, b->memory, nullptr);
  }
  vkDestroyDevice(device, nullptr);
  vkDestroyInstance(instance, nullptr);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string spirv, cases;
    std::size_t n_in = 0, n_out = 0;
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--inputs" && i + 1 < argc) n_in = std::stoul(argv[++i]);
      else if (a == "--outputs" && i + 1 < argc) n_out = std::stoul(argv[++i]);
      else if (spirv.empty()) spirv = a;
      else cases = a;
    }
    if (argc == 2 && std::string(argv[1]) == "--describe") return run("", 0, 0, "--describe");
    if (spirv.empty() || cases.empty() || n_in == 0 || n_out == 0) {
      std::cerr << "usage: shadowproof_vk_runner SHADER.spv --inputs N --outputs M cases.jsonl > outputs.jsonl\n";
      return 2;
    }
    return run(spirv, n_in, n_out, cases);
  } catch (const std::exception& e) {
    std::cerr << "shadowproof_vk_runner: " << e.what() << "\n";
    return 2;
  }
}
