#pragma once
// Small helpers shared by the test programs.
#include <functional>
#include <string>

#include "shadowproof/core/error.h"
#include "shadowproof/core/number.h"

namespace shadowproof::testing {

/// The canonical rational p/d.
inline rational q(long p, long d = 1) {
  rational r(p, d);
  r.canonicalize();
  return r;
}

/// what() of the shadowproof::error that f throws, or "no error".
inline std::string error_text(const std::function<void()>& f) {
  try {
    f();
  } catch (const error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace shadowproof::testing
