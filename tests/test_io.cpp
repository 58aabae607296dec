// Size-capped reads and atomic writes.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <functional>

#include "shadowproof/core/error.h"
#include "shadowproof/core/io.h"

using namespace shadowproof;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("shadowproof-test-io-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string id_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const error& e) {
    return e.id();
  }
  return "no error";
}

}  // namespace

TEST_CASE("an atomic write replaces the file and leaves no temporary behind", "[io]") {
  const auto dir = fresh_dir("replace");
  const auto file = dir / "report.txt";
  write_file_atomically(file, "first");
  write_file_atomically(file, "second version");
  CHECK(read_file(file) == "second version");
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
}

TEST_CASE("a write that cannot happen keeps the previous file and names the path", "[io][errors]") {
  const auto dir = fresh_dir("fail");
  CHECK(id_of([&] { write_file_atomically(dir / "missing-dir" / "x.svg", "data"); }) == "io.cannot_write");
  // Renaming a file over a directory fails after the temporary is written: it must be removed.
  fs::create_directories(dir / "taken");
  fs::create_directories(dir / "taken" / "inner");
  try {
    write_file_atomically(dir / "taken", "data");
    FAIL("no error");
  } catch (const error& e) {
    CHECK(std::string(e.what()).find("cannot write " + (dir / "taken").string()) != std::string::npos);
  }
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
}

TEST_CASE("reads report missing files, directories and files over the size cap", "[io][errors]") {
  const auto dir = fresh_dir("read");
  CHECK(id_of([&] { read_file(dir / "nope.json"); }) == "io.cannot_read");
  CHECK(id_of([&] { read_file(dir); }) == "io.cannot_read");
  write_file_atomically(dir / "big.txt", std::string(100, 'x'));
  CHECK(id_of([&] { read_file(dir / "big.txt", 99); }) == "io.too_large");
  CHECK(read_file(dir / "big.txt", 100).size() == 100);
}
