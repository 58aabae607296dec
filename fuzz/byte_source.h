#pragma once
/// Decoding fuzzer input into geometry. libFuzzer's own helpers draw floats uniformly by value
/// and almost never hit an exact degeneracy, so coordinates are decoded here from small-integer
/// grids, raw float bits and perturbations of exact degenerate configurations.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "shadowproof/fuzz/generate.h"

namespace shadowproof {

/// A source of choices read from fuzzer bytes; it gives 0 once the bytes run out, so every
/// input decodes to some case and short inputs to the simplest ones.
class byte_source {
 public:
  byte_source(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  /// A value in [0, n): as many bytes as n needs, little-endian, reduced modulo n.
  std::uint64_t below(std::uint64_t n) {
    if (n <= 1) return 0;
    std::uint64_t x = 0;
    for (std::uint64_t span = n - 1, shift = 0; span > 0; span >>= 8, shift += 8) x |= std::uint64_t(byte()) << shift;
    return x % n;
  }
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  bool exhausted() const { return pos_ >= size_; }

  /// Raw bits reinterpreted as F (any value: NaN, infinities, subnormals, -0 included).
  template <class F>
  F raw() {
    using bits_t = std::conditional_t<sizeof(F) == 4, std::uint32_t, std::uint64_t>;
    bits_t b = 0;
    for (std::size_t i = 0; i < sizeof(F); ++i) b |= bits_t(byte()) << (8 * i);
    F x;
    std::memcpy(&x, &b, sizeof x);
    return x;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

/// Decodes a shadow case: the first byte picks the mode. Mode 0-5: the degeneracy-biased
/// generator driven by the bytes; mode 6: small-integer grid [-8, 8]; mode 7: raw float bits.
template <class F>
generated_case<F> decode_shadow_case(byte_source& src) {
  const std::uint8_t mode = src.byte() % 8;
  if (mode < 6) return generate_shadow_case<F>(src);
  generated_case<F> c;
  auto next = [&]() -> F {
    return mode == 6 ? F(static_cast<long>(src.below(17)) - 8) : src.raw<F>();
  };
  for (auto& x : c.plane) x = next();
  for (auto& x : c.light) x = next();
  for (auto& x : c.point) x = next();
  c.family = mode == 6 ? "grid" : "raw_bits";
  return c;
}

}  // namespace shadowproof
