#pragma once
/// The irrational numbers the camera constructions need, known exactly by enclosures that
/// tighten with precision, and their correct rounding by Ziv's strategy.
///
/// A field of view is a float angle θ, so the focal scale cot(θ/2) is transcendental for every
/// θ ≠ 0 in radians (Lindemann–Weierstrass), and rational in degrees only at θ = 90° (Niven);
/// a look-at camera normalises vectors, so its entries are q/√s with q, s rational. Neither is
/// a rational number in general, so the oracle cannot hold them exactly; it holds an enclosure
/// [lo, hi] with rational (dyadic) ends, computed by MPFR with directed rounding at p bits, and
/// doubles p until both ends round to the same float and the same double. Rounding to nearest
/// is monotone, so the exact value, which lies between, rounds to that value too: the result is
/// the correct rounding, never a guess. The loop ends for every value that is not exactly a
/// rounding boundary (a midpoint between two floats); such a value is rational, and every
/// rational case is caught first and rounded exactly (exact_sqrt, cot(45°) = 1).
#include <optional>

#include "shadowproof/core/error.h"
#include "shadowproof/core/number.h"

namespace shadowproof {

/// Rational bounds lo ≤ x ≤ hi of a real number x.
struct enclosure {
  rational lo, hi;
};

/// Unit of a field-of-view angle: radians, or degrees (θ° = θ·π/180 radians).
enum class angle_unit { radians, degrees };

/// "radians" or "degrees" (the command-line spelling).
inline std::string_view to_string(angle_unit u) { return u == angle_unit::degrees ? "degrees" : "radians"; }

/// True when 0 < fovy < π (180°): exactly when cot(fovy/2) > 0, the focal scale of a camera.
/// Decided exactly (in radians, against an MPFR enclosure of π, which no double equals).
bool field_of_view_in_range(double fovy, angle_unit unit);

/// lo ≤ cot(fovy/2) ≤ hi from MPFR at `precision` bits (≥ 64) with directed rounding: the
/// width is a few units in the last place of `precision` bits. Precondition:
/// field_of_view_in_range(fovy, unit). In degrees the half angle fovy·π/360 is itself enclosed
/// first (cot is decreasing on (0, π)).
enclosure cot_half_angle(double fovy, angle_unit unit, long precision);

/// √q exactly when q ≥ 0 is the square of a rational (numerator and denominator perfect
/// squares); nothing otherwise (then √q is irrational). Throws internal_error for q < 0.
std::optional<rational> exact_sqrt(const rational& q);

/// lo ≤ √q ≤ hi from MPFR at `precision` bits with directed rounding (q ≥ 0).
enclosure sqrt_enclosure(const rational& q, long precision);

/// Ziv's strategy: `enclose(p)` for p = 64, 128, … up to 2^16 bits until both ends of the
/// enclosure round to the same float and to the same double; returns the lower end, which then
/// rounds (to_nearest_float, to_nearest_double) exactly as the enclosed number does. Throws
/// internal_error when 2^16 bits do not decide (only a number on a rounding boundary can need
/// more, and callers exclude those: see the header comment).
template <class Enclose>
rational correctly_rounding_representative(Enclose enclose, const char* what) {
  for (long precision = 64; precision <= 65536; precision *= 2) {
    const enclosure e = enclose(precision);
    if (e.lo == e.hi) return e.lo;
    if (to_nearest_float(e.lo) == to_nearest_float(e.hi) && to_nearest_double(e.lo) == to_nearest_double(e.hi))
      return e.lo;
  }
  throw internal_error(std::string("the rounding of ") + what + " is undecided at 65536 bits");
}

/// The correctly rounding representative (as above) of s·√q for a sign s ∈ {−1, 0, 1} and
/// q ≥ 0: exact when √q is rational.
rational signed_sqrt_representative(int s, const rational& q);

}  // namespace shadowproof
