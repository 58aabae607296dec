// The error catalogue's tables, built from errors.def.
#include "shadowproof/core/error.h"

namespace shadowproof {
namespace {

struct entry {
  std::string_view id;
  std::string_view meaning;
};

constexpr entry catalogue[] = {
#define SHADOWPROOF_ERROR(code, id, meaning) {id, meaning},
#include "shadowproof/core/errors.def"
#undef SHADOWPROOF_ERROR
};

}  // namespace

std::string_view id_of(errc code) { return catalogue[static_cast<std::size_t>(code)].id; }

std::string_view meaning_of(errc code) { return catalogue[static_cast<std::size_t>(code)].meaning; }

const std::vector<errc>& all_error_codes() {
  static const std::vector<errc> codes = [] {
    std::vector<errc> v;
    for (std::size_t i = 0; i < std::size(catalogue); ++i) v.push_back(static_cast<errc>(i));
    return v;
  }();
  return codes;
}

error::error(errc code, const std::string& message)
    : std::runtime_error("[shadowproof." + std::string(id_of(code)) + "] " + message), code_(code) {}

internal_error::internal_error(const std::string& what_broke)
    : std::logic_error("[shadowproof.internal] " + what_broke + "; please report it with the input") {}

error zero_light_error() {
  return error(errc::geometry_zero_light, "the light (x,y,z,w) must not be (0,0,0,0): it is neither a point nor a direction");
}

error zero_normal_error() {
  return error(errc::geometry_zero_normal, "the plane (a,b,c,d) needs a non-zero normal (a,b,c); a = b = c = 0 is not a plane");
}

}  // namespace shadowproof
