// Enclosures of cot(fovy/2) and √q by MPFR with directed rounding (irrational.h).
#include "shadowproof/constructions/irrational.h"

#include <mpfr.h>

#include <cmath>

namespace shadowproof {
namespace {

// An MPFR number with its precision, freed on scope exit.
class mp {
 public:
  explicit mp(long precision) { mpfr_init2(x_, static_cast<mpfr_prec_t>(precision)); }
  ~mp() { mpfr_clear(x_); }
  mp(const mp&) = delete;
  mp& operator=(const mp&) = delete;
  mpfr_ptr get() { return x_; }
  // The exact value (an MPFR number is a dyadic rational).
  rational exact() {
    rational q;
    mpfr_get_q(q.get_mpq_t(), x_);
    return q;
  }

 private:
  mpfr_t x_;
};

}  // namespace

bool field_of_view_in_range(double fovy, angle_unit unit) {
  if (!(fovy > 0)) return false;
  if (unit == angle_unit::degrees) return exact_value(fovy) < 180;
  // π is irrational and no double equals it: a 128-bit enclosure separates it from every double.
  mp lo(128), hi(128);
  mpfr_const_pi(lo.get(), MPFR_RNDD);
  mpfr_const_pi(hi.get(), MPFR_RNDU);
  const rational x = exact_value(fovy);
  if (x < lo.exact()) return true;
  if (x > hi.exact()) return false;
  throw internal_error("a double inside a 128-bit enclosure of pi");
}

enclosure cot_half_angle(double fovy, angle_unit unit, long precision) {
  mp h_lo(precision), h_hi(precision), c_lo(precision), c_hi(precision);
  if (unit == angle_unit::radians) {
    mpfr_set_d(h_lo.get(), fovy, MPFR_RNDN);  // exact: precision ≥ 53
    mpfr_div_2ui(h_lo.get(), h_lo.get(), 1, MPFR_RNDN);  // exact: a power of two
    mpfr_cot(c_lo.get(), h_lo.get(), MPFR_RNDD);
    mpfr_cot(c_hi.get(), h_lo.get(), MPFR_RNDU);
  } else {
    // h = fovy·π/360 in [h_lo, h_hi] (fovy > 0); cot decreases on (0, π).
    mpfr_const_pi(h_lo.get(), MPFR_RNDD);
    mpfr_const_pi(h_hi.get(), MPFR_RNDU);
    mpfr_mul_d(h_lo.get(), h_lo.get(), fovy, MPFR_RNDD);
    mpfr_mul_d(h_hi.get(), h_hi.get(), fovy, MPFR_RNDU);
    mpfr_div_ui(h_lo.get(), h_lo.get(), 360, MPFR_RNDD);
    mpfr_div_ui(h_hi.get(), h_hi.get(), 360, MPFR_RNDU);
    mpfr_cot(c_lo.get(), h_hi.get(), MPFR_RNDD);
    mpfr_cot(c_hi.get(), h_lo.get(), MPFR_RNDU);
  }
  return {c_lo.exact(), c_hi.exact()};
}

std::optional<rational> exact_sqrt(const rational& q) {
  if (sgn(q) < 0) throw internal_error("exact_sqrt of a negative number");
  mpz_class n = q.get_num(), d = q.get_den();
  if (!mpz_perfect_square_p(n.get_mpz_t()) || !mpz_perfect_square_p(d.get_mpz_t())) return std::nullopt;
  mpz_class rn, rd;
  mpz_sqrt(rn.get_mpz_t(), n.get_mpz_t());
  mpz_sqrt(rd.get_mpz_t(), d.get_mpz_t());
  return rational(rn, rd);
}

enclosure sqrt_enclosure(const rational& q, long precision) {
  mp lo(precision), hi(precision);
  mpfr_set_q(lo.get(), q.get_mpq_t(), MPFR_RNDD);
  mpfr_set_q(hi.get(), q.get_mpq_t(), MPFR_RNDU);
  mpfr_sqrt(lo.get(), lo.get(), MPFR_RNDD);
  mpfr_sqrt(hi.get(), hi.get(), MPFR_RNDU);
  return {lo.exact(), hi.exact()};
}

rational signed_sqrt_representative(int s, const rational& q) {
  if (s == 0 || sgn(q) == 0) return rational(0);
  if (const auto r = exact_sqrt(q)) return s < 0 ? rational(-*r) : *r;
  const rational m = correctly_rounding_representative([&](long p) { return sqrt_enclosure(q, p); }, "a square root");
  // The rounding is symmetric about 0, so −m rounds as −√q does.
  return s < 0 ? rational(-m) : m;
}

}  // namespace shadowproof
