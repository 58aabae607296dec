// Fuzz target: the number parser. Invariants on every input it accepts: the bit limit holds,
// the printed exact form reads back to the same value, and rounding to float and double picks a
// nearest neighbour (checked exactly against the adjacent representable values).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string_view>

#include "shadowproof/core/error.h"
#include "shadowproof/core/number.h"

namespace {

template <class F>
void check_nearest(const shadowproof::rational& q, F rounded) {
  using shadowproof::rational;
  if (!std::isfinite(rounded)) return;
  const rational here = shadowproof::exact_value(static_cast<double>(rounded));
  const rational error = abs(q - here);
  for (F neighbour : {std::nextafter(rounded, std::numeric_limits<F>::infinity()),
                      std::nextafter(rounded, -std::numeric_limits<F>::infinity())}) {
    if (!std::isfinite(neighbour)) continue;
    if (abs(q - shadowproof::exact_value(static_cast<double>(neighbour))) < error) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace shadowproof;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const number_limits limits{512};
  try {
    const rational q = parse_number(text, limits);
    if (bit_size(q) > limits.max_bits) std::abort();
    if (parse_number(to_string(q), limits) != q) std::abort();
    check_nearest(q, to_nearest_double(q));
    check_nearest(q, to_nearest_float(q));
  } catch (const error&) {
    // Rejected input with a message: the expected outcome for most fuzz inputs.
  }
  return 0;
}
