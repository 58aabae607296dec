// Runs a libFuzzer harness as a plain program: every file given on the command line, or every
// file in every directory given, is fed to LLVMFuzzerTestOneInput once. Used by ctest to replay
// the committed corpus without clang.
//   replay_<target> [--every K] FILE_OR_DIR...
// --every K replays a fixed sample of each directory: its files in name order at positions
// 0, K, 2K, ... (for a harness too slow to replay its whole corpus in the default suite).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

int replay_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "replay: cannot read %s\n", path.c_str());
    return 1;
  }
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t count = 0, every = 1;
  int failures = 0;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--every" && i + 1 < argc) {
      every = std::max<std::size_t>(1, std::stoul(argv[++i]));
      continue;
    }
    const std::filesystem::path arg = argv[i];
    if (std::filesystem::is_directory(arg)) {
      std::vector<std::filesystem::path> files;
      for (const auto& entry : std::filesystem::directory_iterator(arg))
        if (entry.is_regular_file()) files.push_back(entry.path());
      std::sort(files.begin(), files.end());
      for (std::size_t k = 0; k < files.size(); k += every) failures += replay_file(files[k]), ++count;
    } else {
      failures += replay_file(arg), ++count;
    }
  }
  std::printf("replayed %zu inputs\n", count);
  if (count == 0) {
    std::fprintf(stderr, "replay: no input files\n");
    return 1;
  }
  return failures == 0 ? 0 : 1;
}
