// Names of the declared conventions that the command line and case files spell out.
#include "shadowproof/verify/conventions.h"

namespace shadowproof {

std::string_view to_string(sentinel_kind s) {
  switch (s) {
    case sentinel_kind::none: return "none";
    case sentinel_kind::zero: return "zero";
    case sentinel_kind::identity: return "identity";
  }
  return "unknown";
}

std::optional<sentinel_kind> sentinel_from_string(std::string_view name) {
  for (sentinel_kind s : {sentinel_kind::none, sentinel_kind::zero, sentinel_kind::identity})
    if (to_string(s) == name) return s;
  return std::nullopt;
}

}  // namespace shadowproof
