#pragma once
/// Errors. Malformed input throws `error` with an id from the catalogue (errors.def); the CLI
/// prints it and exits with 2. A broken internal invariant throws `internal_error`, a bug in
/// shadowproof rather than in the input; the CLI exits with 3 and the fuzz harnesses report it
/// as a finding. Degenerate but legal geometry is a result, never an error.
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace shadowproof {

/// One enumerator per catalogue entry of errors.def, in its order.
enum class errc {
#define SHADOWPROOF_ERROR(code, id, meaning) code,
#include "shadowproof/core/errors.def"
#undef SHADOWPROOF_ERROR
};

/// The stable id printed as [shadowproof.<id>], e.g. "number.malformed".
std::string_view id_of(errc code);
/// The catalogue's one-sentence description of the failure.
std::string_view meaning_of(errc code);
/// Every code, in catalogue order.
const std::vector<errc>& all_error_codes();

/// Thrown for malformed input; `what()` reads "[shadowproof.<id>] <message naming the culprit>".
class error : public std::runtime_error {
 public:
  error(errc code, const std::string& message);
  errc code() const noexcept { return code_; }
  /// id_of(code()), as a string.
  std::string id() const { return std::string(id_of(code_)); }

 private:
  errc code_;
};

/// Thrown when shadowproof breaks one of its own invariants: never the input's fault.
/// `what()` reads "[shadowproof.internal] <what broke>; please report it with the input".
class internal_error : public std::logic_error {
 public:
  explicit internal_error(const std::string& what_broke);
};

/// The one message of geometry.zero_light, wherever a light is checked.
error zero_light_error();
/// The one message of geometry.zero_normal, wherever a plane is checked.
error zero_normal_error();

}  // namespace shadowproof
