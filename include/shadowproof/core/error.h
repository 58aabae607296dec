#pragma once
/// Errors for malformed input. Degenerate but legal geometry is a result, never an error.
#include <stdexcept>
#include <string>

namespace shadowproof {

/// Thrown for malformed input; `id()` is stable (e.g. "number.malformed"), `what()` reads
/// "[shadowproof.<id>] <message naming the culprit>". The CLI prints what() and exits with 2.
class error : public std::runtime_error {
 public:
  error(std::string id, const std::string& message)
      : std::runtime_error("[shadowproof." + id + "] " + message), id_(std::move(id)) {}
  const std::string& id() const noexcept { return id_; }

 private:
  std::string id_;
};

}  // namespace shadowproof
