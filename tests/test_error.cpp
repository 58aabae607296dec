// The error catalogue: one id per failure, the documentation lists exactly the catalogue, every
// id is raised somewhere, and the two error types read as documented.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "shadowproof/core/error.h"

using namespace shadowproof;

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The enumerator names, in catalogue order, straight from errors.def.
const std::vector<std::string> code_names = {
#define SHADOWPROOF_ERROR(code, id, meaning) #code,
#include "shadowproof/core/errors.def"
#undef SHADOWPROOF_ERROR
};

}  // namespace

TEST_CASE("every error id is unique and shaped subsystem.failure", "[error]") {
  std::set<std::string> seen;
  for (errc c : all_error_codes()) {
    const std::string id(id_of(c));
    INFO(id);
    CHECK(std::regex_match(id, std::regex("[a-z0-9_]+\\.[a-z0-9_]+")));
    CHECK(seen.insert(id).second);
    CHECK(!meaning_of(c).empty());
  }
  CHECK(seen.size() == code_names.size());
}

TEST_CASE("docs/errors.md lists exactly the catalogue, with the same sentences", "[error]") {
  const std::string doc = slurp(std::filesystem::path(SHADOWPROOF_SOURCE_DIR) / "docs" / "errors.md");
  REQUIRE(!doc.empty());
  for (errc c : all_error_codes()) {
    const std::string row = "| `" + std::string(id_of(c)) + "` | " + std::string(meaning_of(c)) + " |";
    INFO(row);
    CHECK(doc.find(row) != std::string::npos);
  }
  // No catalogue row (a line starting with the id) for an id the catalogue does not have.
  const std::regex id_row("\n\\| `([a-z0-9_]+\\.[a-z0-9_]+)` \\|");
  std::size_t rows = 0;
  for (auto it = std::sregex_iterator(doc.begin(), doc.end(), id_row); it != std::sregex_iterator(); ++it) ++rows;
  CHECK(rows == all_error_codes().size());
}

TEST_CASE("every error id is raised somewhere in the library or the command line", "[error]") {
  std::string code;
  const std::filesystem::path root(SHADOWPROOF_SOURCE_DIR);
  for (const char* dir : {"src", "include"})
    for (const auto& e : std::filesystem::recursive_directory_iterator(root / dir))
      if (e.path().extension() == ".cpp" || e.path().extension() == ".h") code += slurp(e.path());
  for (const auto& name : code_names) {
    INFO(name);
    CHECK(code.find("errc::" + name) != std::string::npos);
  }
}

TEST_CASE("an error reads [shadowproof.<id>] message; an internal error asks to be reported", "[error]") {
  const error e(errc::number_malformed, "cannot read \"x\"");
  CHECK(std::string(e.what()) == "[shadowproof.number.malformed] cannot read \"x\"");
  CHECK(e.id() == "number.malformed");
  CHECK(e.code() == errc::number_malformed);
  const internal_error i("ear clipping found no ear");
  CHECK(std::string(i.what()) ==
        "[shadowproof.internal] ear clipping found no ear; please report it with the input");
  CHECK(std::string(zero_light_error().what()).rfind("[shadowproof.geometry.zero_light] ", 0) == 0);
}
