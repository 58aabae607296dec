#pragma once
// The exact CGAL kernel of the clip subsystem and conversions between its numbers and
// `rational`. Only src/clip/*.cpp include this header; CGAL types never reach a public header.
//
// Epeck (lazy exact numbers behind interval filters) was measured against
// Cartesian<mpq_class> on the 10k-triangle sphere and is faster (docs/clipping.md);
// SHADOWPROOF_CLIP_CARTESIAN_GMPQ switches to the other one.
#include <CGAL/Cartesian.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <type_traits>

#include "shadowproof/clip/shadow_region.h"

namespace shadowproof::detail {

#ifdef SHADOWPROOF_CLIP_CARTESIAN_GMPQ
using kernel = CGAL::Cartesian<mpq_class>;
#else
using kernel = CGAL::Exact_predicates_exact_constructions_kernel;
#endif
using ft = kernel::FT;
using cpoint = kernel::Point_2;
using csegment = kernel::Segment_2;

// Templates, so that only the branch of the kernel's exact type is instantiated.
template <class F>
F to_field(const rational& q) {
  if constexpr (std::is_same_v<F, rational>) {
    return q;
  } else {
    using et = typename F::ET;
    if constexpr (std::is_same_v<et, rational>) return F(q);
    else return F(et(q.get_mpq_t()));
  }
}

template <class F>
rational from_field(const F& x) {
  if constexpr (std::is_same_v<F, rational>) {
    return x;
  } else {
    using et = std::decay_t<decltype(CGAL::exact(x))>;
    if constexpr (std::is_same_v<et, rational>) return CGAL::exact(x);
    else return rational(CGAL::exact(x).mpq());
  }
}

/// The kernel's field number equal to q (exact).
inline ft to_ft(const rational& q) { return to_field<ft>(q); }
/// The rational equal to x (forces the exact value of a lazy number).
inline rational to_q(const ft& x) { return from_field<ft>(x); }

/// The kernel's point equal to p. With the lazy kernel the point is made a leaf holding its
/// exact value (and the interval around it): built from two lazy numbers it would be a node
/// whose exact value is recomputed, under a lock, the first time a predicate needs it, which
/// the arrangement's sweep does for every endpoint shared by two segments.
/// (A template, so that only the branch of the kernel in use is instantiated.)
template <class P = cpoint>
P to_cpoint(const point2& p) {
  if constexpr (std::is_same_v<kernel, CGAL::Exact_predicates_exact_constructions_kernel>) {
    using exact_kernel = typename kernel::Exact_kernel;
    using eft = typename exact_kernel::FT;
    if constexpr (std::is_same_v<eft, rational>) return P(typename P::Rep(typename exact_kernel::Point_2(p[0], p[1])));
    else return P(typename P::Rep(typename exact_kernel::Point_2(eft(p[0].get_mpq_t()), eft(p[1].get_mpq_t()))));
  } else {
    return P(to_ft(p[0]), to_ft(p[1]));
  }
}
/// The rational point equal to p. With the lazy kernel the point's exact value is forced
/// once and read directly: p.x() and p.y() would each build and force a new lazy number.
/// (A template, so that only the branch of the kernel in use is instantiated.)
template <class P = cpoint>
point2 to_point2(const P& p) {
  if constexpr (std::is_same_v<kernel, CGAL::Exact_predicates_exact_constructions_kernel>) {
    const auto& e = CGAL::exact(p);
    using et = std::decay_t<decltype(e.x())>;
    if constexpr (std::is_same_v<et, rational>) return {e.x(), e.y()};
    else return {rational(e.x().mpq()), rational(e.y().mpq())};
  } else {
    return {to_q(p.x()), to_q(p.y())};
  }
}

}  // namespace shadowproof::detail
