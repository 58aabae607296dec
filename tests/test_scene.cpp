// Tests of scene.h: the JSON scene reader and the OFF/OBJ mesh readers.
#include <catch2/catch.hpp>

#include <sstream>

#include "shadowproof/core/error.h"
#include "shadowproof/clip/scene.h"

using namespace shadowproof;

namespace {

const std::string data_dir = std::string(SHADOWPROOF_SOURCE_DIR) + "/tests/data/scenes";

std::string message_of(const std::string& json) {
  try {
    parse_scene(json, ".");
  } catch (const error& e) {
    return e.what();
  }
  return "no error";
}

const char* square_receiver = R"("receiver": {"polygon": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]})";

}  // namespace

TEST_CASE("JSON number literals are read exactly from their text") {
  const scene s = parse_scene(std::string("{") + square_receiver + R"(,
    "light": [0.1, -2.5e-3, 123456789012345678901234567890, 0],
    "casters": [{"polygon": [[0.1, "1/3", "f32:0.1"], [1E+2, 0, 0], [0, 1, 0]]}]})", ".");
  CHECK(s.light_source.l[0] == rational(1, 10));
  CHECK(s.light_source.l[1] == rational(-1, 400));
  CHECK(s.light_source.l[2] == rational("123456789012345678901234567890"));
  CHECK(s.light_source.l[3] == 0);
  REQUIRE(s.casters.size() == 1);
  const auto& v = s.casters[0].vertices;
  CHECK(v[0][0] == rational(1, 10));
  CHECK(v[0][1] == rational(1, 3));
  // f32:0.1 is the float nearest to 0.1: 13421773 / 2^27.
  CHECK(v[0][2] == rational(13421773, 134217728));
  CHECK(v[1][0] == 100);
  CHECK(s.casters[0].is_polygon);
  CHECK(s.casters[0].faces == std::vector<std::vector<std::size_t>>{{0, 1, 2}});
}

TEST_CASE("inline meshes and holes are read with their structure") {
  const scene s = parse_scene(R"({"receiver": {"polygon": [[0,0,0],[4,0,0],[4,4,0],[0,4,0]],
    "holes": [[[1,1,0],[2,1,0],[2,2,0]]]}, "light": [0,0,1,1],
    "casters": [{"mesh": {"vertices": [[0,0,1],[1,0,1],[0,1,1],[1,1,1]], "faces": [[0,1,2],[1,3,2]]}}]})", ".");
  CHECK(s.receiver.holes.size() == 1);
  CHECK(s.receiver.holes[0].vertices.size() == 3);
  CHECK(s.casters[0].name == "/casters/0/mesh");
  CHECK_FALSE(s.casters[0].is_polygon);
  CHECK(s.casters[0].faces.size() == 2);
  CHECK(s.casters[0].faces[1] == std::vector<std::size_t>{1, 3, 2});
}

TEST_CASE("scene errors name the JSON path of the offending element") {
  const std::string r = std::string("{") + square_receiver + ", ";
  CHECK(message_of(r + R"("casters": []})") == "[shadowproof.scene.missing] /: missing key \"light\"");
  CHECK(message_of(r + R"("light": [0,0,1], "casters": []})") ==
        "[shadowproof.scene.type] /light: the light needs 4 numbers [x, y, z, w], found 3");
  CHECK(message_of(r + R"("light": [0,0,0,0], "casters": []})") ==
        "[shadowproof.scene.zero_light] /light: (0, 0, 0, 0) is neither a point nor a direction");
  CHECK(message_of(r + R"("light": [0,0,1,0], "casters": [], "lights": 1})") ==
        "[shadowproof.scene.unknown_key] /lights: unknown key (allowed here: receiver, light, casters)");
  CHECK(message_of(r + R"("light": [0,0,1,0], "casters": [{"polygon": [[0,0,1],[1,0,1],[0,true,1]]}]})") ==
        "[shadowproof.scene.type] /casters/0/polygon/2/1: expected a number, found a boolean");
  CHECK(message_of(r + R"("light": [0,0,1,0], "casters": [{"polygon": [[0,0,1],[1,0,1]]}]})") ==
        "[shadowproof.scene.empty_polygon] /casters/0/polygon: a polygon needs at least 3 vertices, found 2");
  CHECK(message_of(r + R"("light": [0,0,1,0], "casters": [{"mesh": {"vertices": [[0,0,1],[1,0,1],[0,1,1]], "faces": [[0,1,1.5]]}}]})") ==
        "[shadowproof.scene.bad_index] /casters/0/mesh/faces/0/2: vertex index 3/2 is not an integer in [0, 3)");
  CHECK(message_of(r + R"("light": [0,0,1,0], "casters": [{"mesh": {"file": 7}}]})") ==
        "[shadowproof.scene.type] /casters/0/mesh/file: expected a file name string, found a number");
  CHECK(message_of(r + R"("light": [0,0,1,0], "casters": [{"polygon": [[0,0,1],[1,0,1],[0,1,1]], "mesh": {}}]})") ==
        "[shadowproof.scene.type] /casters/0: a caster has exactly one of \"polygon\" or \"mesh\"");
  CHECK(message_of("[1, 2") .find("[shadowproof.scene.json] the scene is not valid JSON: ") == 0);
  CHECK(message_of(r + R"("light": [0,0,1e400,0], "casters": []})") ==
        "[shadowproof.scene.json] the JSON number 1e400 is beyond the range nlohmann/json accepts; "
        "write it as a string (\"1e400\") to read it exactly");
  // As a string it is read exactly (and then direction (0, 0, 10^400, 0) is a valid light).
  CHECK(parse_scene(r + R"("light": [0,0,"1e400",0], "casters": []})", ".").light_source.l[2] ==
        rational("1" + std::string(400, '0')));
  CHECK(message_of(r + R"("light": ["1/0",0,1,0], "casters": []})").find(
            "[shadowproof.scene.bad_number] /light/0: \"1/0\" is not a valid number: ") == 0);
}

TEST_CASE("size caps give a clear error instead of running out of memory") {
  scene_limits small;
  small.max_vertices = 2;
  try {
    parse_scene(std::string("{") + square_receiver +
                    R"(, "light": [0,0,1,0], "casters": [{"polygon": [[0,0,1],[1,0,1],[0,1,1]]}]})",
                ".", small);
    FAIL("no error");
  } catch (const error& e) {
    CHECK(std::string(e.what()) == "[shadowproof.scene.too_large] /casters/0/polygon: the casters have more than 2 vertices "
                                   "(raise it with --max-vertices)");
  }
}

TEST_CASE("OFF reader: comments, n-gons and exact numbers") {
  std::istringstream in("OFF\n# comment\n4 1 0\n0 0 0.1\n1 0 1/3\n1 1 0\n0 1 0 # end\n4 0 1 2 3 255 0 0\n");
  const caster c = read_off(in, "test.off");
  REQUIRE(c.vertices.size() == 4);
  CHECK(c.vertices[0][2] == rational(1, 10));
  CHECK(c.vertices[1][2] == rational(1, 3));
  CHECK(c.faces == std::vector<std::vector<std::size_t>>{{0, 1, 2, 3}});
  std::istringstream bad("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  try {
    read_off(bad, "bad.off");
    FAIL("no error");
  } catch (const error& e) {
    CHECK(std::string(e.what()) == "[shadowproof.scene.bad_index] bad.off line 6: face 0: vertex index 3 is out of range (3 vertices)");
  }
  std::istringstream truncated("OFF\n3 1 0\n0 0 0\n");
  CHECK_THROWS_WITH(read_off(truncated, "t.off"), "[shadowproof.scene.mesh_malformed] t.off line 3: unexpected end of file, expected a vertex coordinate");
}

TEST_CASE("OBJ reader: 1-based, negative and slashed indices, homogeneous vertices") {
  std::istringstream in("# obj\nv 0 0 0\nv 2 0 0 2\nv 0 1 0\nvn 0 0 1\nf 1/1/1 2//1 -1\n");
  const caster c = read_obj(in, "test.obj");
  REQUIRE(c.vertices.size() == 3);
  CHECK(c.vertices[1][0] == 1);  // (2, 0, 0, 2) is the point (1, 0, 0)
  CHECK(c.faces == std::vector<std::vector<std::size_t>>{{0, 1, 2}});
  std::istringstream bad("v 0 0 0\nf 1 2 3\n");
  CHECK_THROWS_WITH(read_obj(bad, "b.obj"), "[shadowproof.scene.bad_index] b.obj line 2: vertex index 2 is out of range (1 vertices so far)");
}

TEST_CASE("mesh files are found relative to the scene file") {
  const scene off = read_scene_file(data_dir + "/tetra_off.json");
  const scene obj = read_scene_file(data_dir + "/tetra_obj.json");
  REQUIRE(off.casters.size() == 1);
  CHECK(off.casters[0].vertices == obj.casters[0].vertices);
  CHECK(off.casters[0].faces == obj.casters[0].faces);
  CHECK(off.casters[0].name == "/casters/0/mesh");
  CHECK_THROWS_WITH(read_scene_file(data_dir + "/missing_mesh.json"),
                    Catch::Contains("[shadowproof.scene.mesh_unreadable] /casters/0/mesh/file: cannot open the mesh file"));
  CHECK_THROWS_WITH(read_scene_file(data_dir + "/no_such_scene.json"),
                    Catch::StartsWith("[shadowproof.scene.unreadable] cannot open the scene file"));
}

TEST_CASE("mesh numbers read by the OFF fast path equal parse_number's exact values") {
  // Plain decimals take a shortcut to an exact rational; anything else goes through
  // parse_number. Either way the value is parse_number's.
  const std::vector<std::string> words = {"-52.9283", "0.1",   "007.50", "-0",   "-0.000", "123456789012345678",
                                          "1234567890123456789", "0.000000000000000001", "5.", ".5", "1e-3",
                                          "1/3",      "-2.5e2", "0x1.8p-3", "f32:0.1", "99999999.9999999999"};
  for (const auto& w : words) {
    std::istringstream in("OFF 3 1 0\n" + w + " 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    const caster c = read_off(in, "t.off");
    INFO(w);
    CHECK(c.vertices[0][0] == parse_number(w));
  }
  std::istringstream bad("OFF 3 1 0\n1.2.3 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  CHECK_THROWS_WITH(read_off(bad, "t.off"), Catch::StartsWith("[shadowproof.scene.bad_number] t.off line 2: \"1.2.3\" is not a valid number: "));
}

TEST_CASE("mesh and scene files are read through the size-capped reader") {
  scene_limits tiny;
  tiny.max_file_bytes = 10;
  CHECK_THROWS_WITH(read_mesh_file(data_dir + "/meshes/tetra.off", "/casters/0/mesh/file", tiny),
                    Catch::StartsWith("[shadowproof.io.too_large] ") && Catch::Contains("is larger than the limit of 10 bytes"));
  CHECK_THROWS_WITH(read_scene_file(data_dir + "/tetra_off.json", tiny), Catch::StartsWith("[shadowproof.io.too_large] "));
  CHECK(scene_limits{}.max_file_bytes == default_max_file_bytes);
}
