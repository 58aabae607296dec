#pragma once
/// A shadow scene as C++ objects: a finite receiver polygon (with holes), a light and casters,
/// and the readers that build one from JSON, OFF and OBJ text.
#include <array>
#include <cstddef>
#include <istream>
#include <string>
#include <vector>

#include "shadowproof/core/io.h"
#include "shadowproof/core/light.h"
#include "shadowproof/core/number.h"

namespace shadowproof {

/// A finite point (x, y, z) with exact coordinates.
using point3 = std::array<rational, 3>;

/// A planar polygon in 3D given by its vertices in order (either orientation); the closing
/// edge from the last vertex to the first is implicit.
struct polygon3 {
  std::vector<point3> vertices;
};

/// The receiver: a simple planar polygon with optional simple holes strictly inside it. Its
/// plane is derived from the vertices (Newell's normal) and checked to be exactly planar.
struct receiver_polygon {
  polygon3 outer;
  std::vector<polygon3> holes;
};

/// A caster: planar faces sharing a vertex list. A caster polygon is one face listing every
/// vertex; a triangle mesh has one face per triangle. Faces may have more than three vertices
/// (OFF/OBJ n-gons); each face must be planar and simple. `name` is the JSON path used in
/// error messages and pictures ("/casters/2").
struct caster {
  std::string name;
  bool is_polygon = false;  ///< one face given as a polygon (errors then name the caster itself)
  std::vector<point3> vertices;
  std::vector<std::vector<std::size_t>> faces;
};

/// The whole scene. The light uses the foundation's convention: w ≠ 0 point light at
/// (x/w, y/w, z/w), w = 0 directional light with (x, y, z) pointing towards the light.
struct scene {
  receiver_polygon receiver;
  light<rational> light_source;
  std::vector<caster> casters;
};

/// Size caps applied by the readers and by compute_shadow_region (error "scene.too_large").
struct scene_limits {
  std::size_t max_vertices = 2'000'000;   ///< vertices over all casters together
  std::size_t max_faces = 1'000'000;      ///< faces over all casters together
  /// Vertices of one face, receiver or hole polygon. Caster faces are triangulated by ear
  /// clipping, quadratic (cubic in the worst case) in the face's size, hence the cap.
  std::size_t max_face_vertices = 4096;
  number_limits numbers{};               ///< size of every number read
  std::size_t max_json_depth = 64;        ///< nesting of JSON arrays and objects
  std::size_t max_json_values = 20'000'000;  ///< values in one JSON document
  std::size_t max_file_bytes = default_max_file_bytes;  ///< size of a scene or mesh file (core/io.h)
};

/// Reads a scene from JSON text. Schema:
///   {"receiver": {"polygon": [[x,y,z], ...], "holes": [[[x,y,z], ...], ...]},
///    "light": [x,y,z,w],
///    "casters": [{"polygon": [[x,y,z], ...]},
///                {"mesh": {"vertices": [[x,y,z], ...], "faces": [[i,j,k], ...]}},
///                {"mesh": {"file": "path.off"}}]}
/// Numbers are JSON numbers read from their literal text (0.1 is 1/10 exactly, never the
/// double nearest to it) or strings in parse_number's syntax ("1/3", "f32:0.1"). Mesh files
/// (OFF or OBJ, by extension) are read relative to `base_directory`. Throws error
/// "scene.<what>" naming the JSON path of the offending element ("/casters/1/mesh/faces/3/2").
scene parse_scene(const std::string& json_text, const std::string& base_directory,
                  const scene_limits& limits = {});

/// Reads the scene file at `path` (core/io.h's read_file, capped at limits.max_file_bytes);
/// relative mesh paths are relative to its directory. Throws error "scene.unreadable" when the
/// file cannot be opened, "io.too_large" when it is larger than the cap.
scene read_scene_file(const std::string& path, const scene_limits& limits = {});

/// Reads an OFF mesh ("OFF", counts "nv nf ne", nv vertex lines, nf face lines "n i0 .. in-1";
/// '#' starts a comment). `what` names the mesh in messages. Numbers are read exactly.
caster read_off(std::istream& in, const std::string& what, const scene_limits& limits = {});

/// Reads an OBJ mesh: "v x y z [w]" and "f a b c ..." (1-based, negative = relative to the
/// end, "a/t/n" forms accepted); other statements are ignored. Numbers are read exactly.
caster read_obj(std::istream& in, const std::string& what, const scene_limits& limits = {});

/// Reads an OFF or OBJ file chosen by its extension (.off / .obj, case-insensitive), whole
/// (core/io.h's read_file, capped at limits.max_file_bytes). Every coordinate becomes an exact
/// rational once (plain decimals such as -52.9283 without the general parser), shared by all
/// the faces that use it. Throws error "scene.mesh_unreadable" naming `what` and the path
/// when it cannot be opened, "io.too_large" when it is larger than the cap.
caster read_mesh_file(const std::string& path, const std::string& what,
                      const scene_limits& limits = {});

}  // namespace shadowproof
