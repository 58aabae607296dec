#pragma once
/// Exact conversion between shadowproof's rational and the field types of CGAL's exact kernels:
/// mpq_class (Cartesian<mpq_class>, and Epeck's exact type where CGAL uses gmpxx), CGAL::Gmpq
/// (Simple_cartesian<Gmpq>), CGAL::Lazy_exact_nt<either> (Epeck::FT), and double one way
/// (every double is a rational; the way back would round, so it does not compile).
///
/// The constructions need no conversion at all: they are templates over the number type and
/// compile with Epeck::FT (and the other exact FTs) as they are, e.g.
///   shadowproof::shadow_matrix(shadowproof::plane<CGAL::Epeck::FT>{...}, shadowproof::light<CGAL::Epeck::FT>{...})
/// gives the same exact matrix as with rational (tests/test_cgal.cpp checks it).
/// Header-only; link shadowproof::cgal (find_package(shadowproof 0.2 REQUIRED COMPONENTS cgal)).
#include <CGAL/Gmpq.h>
#include <CGAL/Lazy_exact_nt.h>
#include <gmpxx.h>

#include <type_traits>

#include "shadowproof/core/number.h"

namespace shadowproof::cgal {

namespace detail {
template <class T>
struct is_lazy : std::false_type {};
template <class ET>
struct is_lazy<CGAL::Lazy_exact_nt<ET>> : std::true_type {
  using exact_type = ET;
};
template <class>
inline constexpr bool unsupported_number_type = false;
}  // namespace detail

/// The exact value of x (no rounding ever: a lazy number is evaluated exactly first).
template <class FT>
rational to_rational(const FT& x) {
  if constexpr (std::is_same_v<FT, mpq_class>) {
    return x;
  } else if constexpr (std::is_same_v<FT, CGAL::Gmpq>) {
    return rational(x.mpq());
  } else if constexpr (detail::is_lazy<FT>::value) {
    return to_rational(CGAL::exact(x));
  } else if constexpr (std::is_same_v<FT, double> || std::is_same_v<FT, float>) {
    return exact_value(static_cast<double>(x));
  } else {
    static_assert(detail::unsupported_number_type<FT>,
                  "shadowproof::cgal converts mpq_class, CGAL::Gmpq, CGAL::Lazy_exact_nt of those, and double");
  }
}

/// The field number equal to q, exactly. Only for exact field types (mpq_class, CGAL::Gmpq,
/// CGAL::Lazy_exact_nt of those): a double could not hold q.
template <class FT>
FT from_rational(const rational& q) {
  if constexpr (std::is_same_v<FT, mpq_class>) {
    return q;
  } else if constexpr (std::is_same_v<FT, CGAL::Gmpq>) {
    return CGAL::Gmpq(q.get_mpq_t());
  } else if constexpr (detail::is_lazy<FT>::value) {
    return FT(from_rational<typename detail::is_lazy<FT>::exact_type>(q));
  } else {
    static_assert(detail::unsupported_number_type<FT>,
                  "shadowproof::cgal builds exact field numbers only: mpq_class, CGAL::Gmpq, "
                  "CGAL::Lazy_exact_nt of those (a double would round)");
  }
}

}  // namespace shadowproof::cgal
