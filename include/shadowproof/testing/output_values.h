#pragma once
/// A routine's outputs as a matcher reads them: the numbers in memory order and their format.
#include <cstddef>
#include <iterator>
#include <ostream>
#include <type_traits>
#include <utility>
#include <vector>

#include "shadowproof/verify/operation.h"

namespace shadowproof {

namespace detail {
// The element type of anything std::data() accepts (C arrays, std::array, std::vector, spans).
template <class C>
using element_of = std::remove_cv_t<std::remove_pointer_t<decltype(std::data(std::declval<const C&>()))>>;
template <class C, class = void>
struct is_float_range : std::false_type {};
template <class C>
struct is_float_range<C, std::void_t<element_of<C>, decltype(std::size(std::declval<const C&>()))>>
    : std::bool_constant<std::is_same_v<element_of<C>, float> || std::is_same_v<element_of<C>, double>> {};
}  // namespace detail

/// The outputs of a float routine under test: `size()` numbers in the order the routine wrote
/// them (its storage order), widened to double, which is exact, and the format they were
/// computed in (f32 for float, f64 for double). Nothing is rounded or reordered.
class output_values {
 public:
  /// The n floats at p.
  output_values(const float* p, std::size_t n);
  /// The n doubles at p.
  output_values(const double* p, std::size_t n);
  /// A C array or a contiguous container of float or double (std::array, std::vector, a span):
  /// what CHECK_THAT / EXPECT_THAT are given.
  template <class C, std::enable_if_t<detail::is_float_range<C>::value, int> = 0>
  output_values(const C& c)  // NOLINT: implicit on purpose, so a matcher accepts the array itself
      : output_values(std::data(c), std::size(c)) {}

  scalar_type type() const { return type_; }
  std::size_t size() const { return values_.size(); }
  const double* data() const { return values_.data(); }
  const std::vector<double>& values() const { return values_; }

 private:
  std::vector<double> values_;
  scalar_type type_;
};

/// Writes "{0x1p+0, -0x1.8p+1, ...} (f32)": every number bit-exactly, as C hex floats.
std::ostream& operator<<(std::ostream& out, const output_values& v);

}  // namespace shadowproof
