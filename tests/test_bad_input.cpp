// The bad-input catalogue (tests/data/bad_input/) through the C++ API: every `api:` case must
// throw shadowproof::error with exactly the catalogued id and message.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>

#include "shadowproof/core/error.h"
#include "shadowproof/core/io.h"
#include "shadowproof/core/light.h"
#include "shadowproof/core/number.h"
#include "shadowproof/core/plane.h"
#include "shadowproof/clip/shadow_region.h"
#include "shadowproof/clip/scene.h"

using namespace shadowproof;
namespace fs = std::filesystem;

namespace {

const fs::path data_dir = fs::path(SHADOWPROOF_SOURCE_DIR) / "tests" / "data" / "bad_input";

std::map<std::string, std::string> read_case(const fs::path& file) {
  std::map<std::string, std::string> fields;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto colon = line.find(": ");
    if (colon != std::string::npos) fields[line.substr(0, colon)] = line.substr(colon + 2);
  }
  return fields;
}

std::string substitute(std::string s, const std::string& key, const std::string& value) {
  for (auto at = s.find(key); at != std::string::npos; at = s.find(key, at + value.size())) s.replace(at, key.size(), value);
  return s;
}

// The API call behind each kind.
std::map<std::string, std::function<void(const std::string&)>> api_kinds() {
  return {
      {"number", [](const std::string& s) { parse_number(s); }},
      {"list4", [](const std::string& s) { parse_number_list(s, 4, "--plane"); }},
      {"plane", [](const std::string& s) { auto v = parse_number_list(s, 4, "--plane"); make_plane(v[0], v[1], v[2], v[3]); }},
      {"light", [](const std::string& s) { auto v = parse_number_list(s, 4, "--light"); make_light(v[0], v[1], v[2], v[3]); }},
      {"read", [](const std::string& s) { read_file(s); }},
      {"write", [](const std::string& s) { write_file_atomically(s, "data"); }},
      {"scene", [](const std::string& s) { compute_shadow_region(read_scene_file(s)); }},
  };
}

}  // namespace

TEST_CASE("every catalogued bad input fails through the API with its exact id and message", "[bad_input]") {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(data_dir))
    if (e.path().extension() == ".txt") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 30);
  const fs::path tmp = fs::temp_directory_path() / "shadowproof-bad-input-api";
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  const auto kinds = api_kinds();
  int ran = 0;
  for (const auto& file : files) {
    auto fields = read_case(file);
    if (!fields.count("api")) continue;
    const std::string api = fields["api"];
    const std::string kind = api.substr(0, api.find(' '));
    const std::string input = substitute(substitute(api.substr(kind.size() + 1), "{DATA}", data_dir.string()), "{TMP}", tmp.string());
    const std::string expected = "[shadowproof." + fields["id"] + "] " +
                                 substitute(substitute(fields["message"], "{DATA}", data_dir.string()), "{TMP}", tmp.string());
    INFO(file.filename().string());
    REQUIRE(kinds.count(kind) == 1);
    try {
      kinds.at(kind)(input);
      FAIL("no error for " << file.filename());
    } catch (const error& e) {
      CHECK(e.id() == fields["id"]);
      CHECK(std::string(e.what()) == expected);
    }
    ++ran;
  }
  CHECK(ran >= 45);
}
