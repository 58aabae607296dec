// Fuzz target: the scene JSON reader (and the OFF/OBJ readers it calls for inline text).
// Invariant: any input either parses into a scene within the limits or is rejected with
// shadowproof::error; nothing else escapes, nothing crashes or hangs.
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "shadowproof/core/error.h"
#include "shadowproof/clip/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace shadowproof;
  scene_limits limits;
  limits.max_vertices = 512;
  limits.max_faces = 512;
  limits.max_face_vertices = 64;
  limits.numbers.max_bits = 256;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const scene s = parse_scene(text, "/nonexistent-shadowproof-fuzz-dir", limits);
    std::size_t vertices = 0;
    for (const auto& c : s.casters) vertices += c.vertices.size();
    if (vertices > limits.max_vertices) std::abort();
  } catch (const error&) {
  }
  // The same bytes as a mesh file body.
  for (int obj = 0; obj < 2; ++obj) {
    std::istringstream in(text);
    try {
      const caster c = obj ? read_obj(in, "fuzz.obj", limits) : read_off(in, "fuzz.off", limits);
      for (const auto& face : c.faces)
        for (std::size_t i : face)
          if (i >= c.vertices.size()) std::abort();  // the reader must reject bad indices
    } catch (const error&) {
    }
  }
  return 0;
}
