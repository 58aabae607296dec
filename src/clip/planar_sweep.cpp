// An exact sweep over weighted chart segments (planar_sweep.h).
//
// Two passes over the segments in lexicographic order of their left ends.
// 1. Intersections: each segment is tested against the segments still open whose bounding
//    boxes meet its own (boxes from intervals around the rationals, so none is missed); a
//    pair is decided by four orientations (interval filter first, exact rationals when the
//    filter straddles 0). A proper crossing is computed once, by Cramer's rule on the integer
//    coefficients of the two lines; an end of one segment inside another (touching, or
//    collinear overlap) splits the other there. Every vertex is then numbered in
//    lexicographic order, so that the split points of a segment are sorted by their numbers.
// 2. Windings: the pieces between consecutive split points meet only at their ends; identical
//    pieces (overlaps) are merged with their weights added. The sweep line runs through the
//    vertices in lexicographic order — equivalently, a vertical line after the shear
//    x' = x + εy, under which no edge is vertical and orientations do not change — and holds
//    the edges it crosses in a balanced tree, ordered by orientation tests alone: two edges on
//    the line never cross, so which is below the other is decided at the later of their left
//    ends. An edge inserted above another takes that one's upper winding as its lower one.
#include "planar_sweep.h"

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

#include "polygon2.h"
#include "shadowproof/core/error.h"

namespace shadowproof::detail {

namespace planar_sweep_internals {

// Interval arithmetic without per-operation rounding-mode switches: only inside a
// CGAL::Protect_FPU_rounding<true> scope (rounding towards +∞). Exact fallbacks switch back
// to rounding to nearest for GMP (nearest_rounding).
using interval = CGAL::Interval_nt<false>;

class nearest_rounding {
 public:
  nearest_rounding() : saved_(CGAL::FPU_get_cw()) { CGAL::FPU_set_cw(CGAL_FE_TONEAREST); }
  ~nearest_rounding() { CGAL::FPU_set_cw(saved_); }
  nearest_rounding(const nearest_rounding&) = delete;
  nearest_rounding& operator=(const nearest_rounding&) = delete;

 private:
  CGAL::FPU_CW_t saved_;
};

// A vertex with bounds around its coordinates (valid when `filtered`). Computed under
// rounding to nearest: mpq_get_d truncates, so the double is exact for a dyadic rational of at
// most 53 significant bits and within one ulp otherwise.
struct fpoint {
  const point2* p = nullptr;
  double xl = 0, xh = 0, yl = 0, yh = 0;
  bool filtered = false;
};

bool bounds(const rational& q, double d, double& lo, double& hi) {
  if (d == 0 && sgn(q) == 0) {
    lo = hi = 0;
    return true;
  }
  const double m = std::fabs(d);
  if (!(m > 0x1p-400 && m < 0x1p400)) return false;
  if (mpz_sizeinbase(q.get_num_mpz_t(), 2) <= 53 && mpz_popcount(q.get_den_mpz_t()) == 1) {
    lo = hi = d;
    return true;
  }
  lo = std::nextafter(d, -HUGE_VAL);
  hi = std::nextafter(d, HUGE_VAL);
  return true;
}

// `approx`: the truncated doubles of p's coordinates.
fpoint make_fpoint(const point2& p, const std::array<double, 2>& approx) {
  fpoint f;
  f.p = &p;
  f.filtered = bounds(p[0], approx[0], f.xl, f.xh) && bounds(p[1], approx[1], f.yl, f.yh);
  return f;
}

std::array<double, 2> truncated(const point2& p) { return {p[0].get_d(), p[1].get_d()}; }

// Sign of (b − a) × (c − a); inside a rounding-upwards scope.
int orientation(const fpoint& a, const fpoint& b, const fpoint& c) {
  if (a.filtered && b.filtered && c.filtered) {
    const interval ax(a.xl, a.xh), ay(a.yl, a.yh);
    const interval d = (interval(b.xl, b.xh) - ax) * (interval(c.yl, c.yh) - ay) -
                       (interval(b.yl, b.yh) - ay) * (interval(c.xl, c.xh) - ax);
    if (d.inf() > 0) return 1;
    if (d.sup() < 0) return -1;
  }
  nearest_rounding exact;
  return sgn(orient2(*a.p, *b.p, *c.p));
}

// Lexicographic order of points: truncated doubles first (GMP's conversion is monotone, so
// different doubles order the rationals), exact comparison on equal ones.
struct lex_order {
  const std::vector<const point2*>& pts;
  const std::vector<std::array<double, 2>>& approx;
  bool operator()(std::size_t i, std::size_t j) const {
    for (std::size_t k = 0; k < 2; ++k) {
      const double a = approx[i][k], b = approx[j][k];
      if (std::isfinite(a) && std::isfinite(b) && a != b) return a < b;
      const int c = cmp((*pts[i])[k], (*pts[j])[k]);
      if (c != 0) return c < 0;
    }
    return false;
  }
};

// Numbers the distinct points of `pts` (truncated doubles `approx`) in lexicographic order:
// id[i] for pts[i], and the representative of each number with its doubles.
void number_points(const std::vector<const point2*>& pts, const std::vector<std::array<double, 2>>& approx,
                   std::vector<std::uint32_t>& id, std::vector<const point2*>& distinct,
                   std::vector<std::array<double, 2>>& distinct_approx) {
  std::vector<std::size_t> order(pts.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  const lex_order less{pts, approx};
  std::sort(order.begin(), order.end(), less);
  id.assign(pts.size(), 0);
  distinct.clear();
  distinct_approx.clear();
  std::size_t last = 0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t i = order[k];
    if (distinct.empty() || less(last, i)) {
      distinct.push_back(pts[i]);
      distinct_approx.push_back(approx[i]);
      last = i;
    }
    id[i] = static_cast<std::uint32_t>(distinct.size() - 1);
  }
}

struct segment {
  std::uint32_t lo = 0, hi = 0;  // lo < hi, or lo == hi for an isolated point
  windings weight{};
  bool degenerate = false;
};

// 128-bit integers (a GCC and Clang extension).
__extension__ typedef __int128 i128;
__extension__ typedef unsigned __int128 u128;

// The line through a segment as A x + B y = C with integer coefficients, also held in 128-bit
// integers when each is below 2^62 in magnitude (then Cramer's products fit).
struct int_line {
  mpz_class a, b, c;
  bool small = false;
  i128 a128 = 0, b128 = 0, c128 = 0;
};

i128 to_int128(const mpz_class& z) { return mpz_get_si(z.get_mpz_t()); }  // |z| < 2^62

// When the four coordinates share one denominator d < 2^31 and their numerators (the integer
// points P = d p, Q = d q) are below 2^30: A d x + B d y = C with A = Q_y − P_y,
// B = P_x − Q_x, C = A P_x + B P_y, in 64-bit arithmetic (|A d|, |B d|, |C| < 2^62).
// Otherwise the rational line times the lcm of its denominators, in GMP.
int_line line_through(const point2& p, const point2& q) {
  const auto den = [](const rational& x) { return x.get_den_mpz_t(); };
  const auto fits = [](const rational& x) { return mpz_sizeinbase(x.get_num_mpz_t(), 2) <= 30; };
  int_line l;
  if (mpz_sizeinbase(den(p[0]), 2) <= 31 && mpz_cmp(den(p[0]), den(p[1])) == 0 && mpz_cmp(den(p[0]), den(q[0])) == 0 &&
      mpz_cmp(den(p[0]), den(q[1])) == 0 && fits(p[0]) && fits(p[1]) && fits(q[0]) && fits(q[1])) {
    const long d = mpz_get_si(den(p[0]));
    const long px = mpz_get_si(p[0].get_num_mpz_t()), py = mpz_get_si(p[1].get_num_mpz_t());
    const long qx = mpz_get_si(q[0].get_num_mpz_t()), qy = mpz_get_si(q[1].get_num_mpz_t());
    const i128 a = qy - py, b = px - qx;
    l.small = true;
    l.a128 = a * d;
    l.b128 = b * d;
    l.c128 = a * px + b * py;
    return l;
  }
  const rational a = q[1] - p[1], b = p[0] - q[0], c = a * p[0] + b * p[1];
  mpz_class scale;
  mpz_lcm(scale.get_mpz_t(), a.get_den_mpz_t(), b.get_den_mpz_t());
  mpz_lcm(scale.get_mpz_t(), scale.get_mpz_t(), c.get_den_mpz_t());
  l.a = a.get_num() * (scale / a.get_den());
  l.b = b.get_num() * (scale / b.get_den());
  l.c = c.get_num() * (scale / c.get_den());
  l.small = mpz_sizeinbase(l.a.get_mpz_t(), 2) <= 62 && mpz_sizeinbase(l.b.get_mpz_t(), 2) <= 62 &&
            mpz_sizeinbase(l.c.get_mpz_t(), 2) <= 62;
  if (l.small) {
    l.a128 = to_int128(l.a);
    l.b128 = to_int128(l.b);
    l.c128 = to_int128(l.c);
  }
  return l;
}

void set_mpz(mpz_ptr z, u128 m, bool negative) {
  const unsigned long long limbs[2] = {static_cast<unsigned long long>(m), static_cast<unsigned long long>(m >> 64)};
  mpz_import(z, 2, -1, sizeof limbs[0], 0, 0, limbs);
  if (negative) mpz_neg(z, z);
}

// num/den in lowest terms (den > 0).
rational quotient(i128 num, i128 den) {
  const bool negative = (num < 0) != (den < 0) && num != 0;
  u128 n = num < 0 ? -static_cast<u128>(num) : static_cast<u128>(num);
  u128 d = den < 0 ? -static_cast<u128>(den) : static_cast<u128>(den);
  rational q;
  if ((n >> 64) == 0 && (d >> 64) == 0) {  // one limb each: the gcd in 64-bit arithmetic, else GMP's
    const u128 g = std::gcd(static_cast<unsigned long long>(n), static_cast<unsigned long long>(d));
    set_mpz(mpq_numref(q.get_mpq_t()), n / g, negative);
    set_mpz(mpq_denref(q.get_mpq_t()), d / g, false);
    return q;
  }
  set_mpz(mpq_numref(q.get_mpq_t()), n, negative);
  set_mpz(mpq_denref(q.get_mpq_t()), d, false);
  q.canonicalize();
  return q;
}

// x = (C₁B₂ − C₂B₁)/D, y = (A₁C₂ − A₂C₁)/D, D = A₁B₂ − A₂B₁ ≠ 0.
point2 meet(const int_line& l, const int_line& m) {
  if (l.small && m.small) {
    // |products| < 2^124, their differences < 2^125.
    const i128 d = l.a128 * m.b128 - m.a128 * l.b128;
    if (d == 0) throw internal_error("crossing segments on parallel lines");
    return {quotient(l.c128 * m.b128 - m.c128 * l.b128, d), quotient(l.a128 * m.c128 - m.a128 * l.c128, d)};
  }
  const auto big = [](const int_line& k) {
    if (!k.small) return std::array<mpz_class, 3>{k.a, k.b, k.c};
    std::array<mpz_class, 3> z;
    const i128 v[3] = {k.a128, k.b128, k.c128};
    for (int i = 0; i < 3; ++i) set_mpz(z[i].get_mpz_t(), v[i] < 0 ? -static_cast<u128>(v[i]) : static_cast<u128>(v[i]), v[i] < 0);
    return z;
  };
  const auto [la, lb, lc] = big(l);
  const auto [ma, mb, mc] = big(m);
  const mpz_class d = la * mb - ma * lb;
  if (sgn(d) == 0) throw internal_error("crossing segments on parallel lines");
  rational x(lc * mb - mc * lb, d), y(la * mc - ma * lc, d);
  x.canonicalize();
  y.canonicalize();
  return {std::move(x), std::move(y)};
}

}  // namespace planar_sweep_internals

std::optional<planar_map> planar_sweep(const std::vector<const point2*>& pts, const std::vector<sweep_segment>& input,
                                       const std::vector<std::size_t>& point_pieces) {
  using namespace planar_sweep_internals;
  planar_map out;

  // The input points numbered; segments from their lower to their upper end.
  std::vector<std::array<double, 2>> approx(pts.size()), first_approx;
  for (std::size_t i = 0; i < pts.size(); ++i) approx[i] = truncated(*pts[i]);
  std::vector<std::uint32_t> vid;
  std::vector<const point2*> first;
  number_points(pts, approx, vid, first, first_approx);
  approx = {};
  std::vector<segment> segs;
  segs.reserve(input.size() + point_pieces.size());
  for (const auto& s : input) {
    std::uint32_t a = vid[s.a], b = vid[s.b];
    if (a == b) continue;
    long sign = 1;
    if (b < a) {
      std::swap(a, b);
      sign = -1;
    }
    segs.push_back({a, b, {sign * s.shadow, sign * s.receiver}, s.degenerate});
  }
  // Identical segments merged (their weights add up); cancelled ones dropped.
  std::sort(segs.begin(), segs.end(), [](const segment& x, const segment& y) { return x.lo != y.lo ? x.lo < y.lo : x.hi < y.hi; });
  {
    std::vector<segment> merged;
    for (const auto& s : segs) {
      if (!merged.empty() && merged.back().lo == s.lo && merged.back().hi == s.hi) {
        auto& m = merged.back();
        m.weight = {m.weight[0] + s.weight[0], m.weight[1] + s.weight[1]};
        m.degenerate = m.degenerate || s.degenerate;
      } else {
        merged.push_back(s);
      }
    }
    segs.clear();
    for (const auto& s : merged)
      if (s.degenerate || s.weight[0] != 0 || s.weight[1] != 0) segs.push_back(s);
  }
  const std::size_t nsegs = segs.size();
  for (auto i : point_pieces) segs.push_back({vid[i], vid[i], {0, 0}, true});

  std::vector<fpoint> fp(first.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    fp[i] = make_fpoint(*first[i], first_approx[i]);
    if (!fp[i].filtered) return std::nullopt;
  }

  // Pass 1: candidate pairs by an x-sweep over boxes, the open segments kept in horizontal
  // bands about as high as a segment (a segment in every band its box meets; a pair is tested
  // in the lowest band both meet). Splits as (segment, point reference): a reference below
  // first.size() is an input point, above it a crossing.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> splits;
  std::vector<std::array<std::uint32_t, 2>> crossing_pairs;
  {
    const std::size_t budget = 64 * segs.size() + 10000000;
    std::size_t scanned = 0;
    std::vector<double> ylo(segs.size()), yhi(segs.size());
    double y0 = HUGE_VAL, y1 = -HUGE_VAL, extent = 0;
    for (std::size_t k = 0; k < segs.size(); ++k) {
      const fpoint &p = fp[segs[k].lo], &q = fp[segs[k].hi];
      ylo[k] = std::min(p.yl, q.yl);
      yhi[k] = std::max(p.yh, q.yh);
      y0 = std::min(y0, ylo[k]);
      y1 = std::max(y1, yhi[k]);
      extent += yhi[k] - ylo[k];
    }
    // Bands of height h from y0; band() is monotone under any rounding, so boxes that meet
    // have band ranges that meet.
    const double span = y1 - y0;
    double h = segs.empty() ? 1 : extent / static_cast<double>(segs.size());
    if (!(h > span / 4096)) h = span / 4096;
    const std::size_t nbands = span > 0 && h > 0 ? std::min<std::size_t>(4096, static_cast<std::size_t>(span / h) + 1) : 1;
    const auto band = [&](double y) -> std::size_t {
      if (nbands == 1) return 0;
      const double b = (y - y0) / h;
      return b <= 0 ? 0 : std::min(nbands - 1, static_cast<std::size_t>(b));
    };
    std::vector<std::uint32_t> band_lo(segs.size()), band_hi(segs.size());
    for (std::size_t k = 0; k < segs.size(); ++k) {
      band_lo[k] = static_cast<std::uint32_t>(band(ylo[k]));
      band_hi[k] = static_cast<std::uint32_t>(band(yhi[k]));
    }
    std::vector<std::uint32_t> order(segs.size());
    std::iota(order.begin(), order.end(), std::uint32_t(0));
    std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) { return fp[segs[x].lo].xl < fp[segs[y].lo].xl; });
    std::vector<std::vector<std::uint32_t>> active(nbands);
    const auto split = [&](std::uint32_t s, std::uint32_t v) {
      if (segs[s].lo < v && v < segs[s].hi) splits.emplace_back(s, v);
    };
    CGAL::Protect_FPU_rounding<true> up;
    for (const std::uint32_t s : order) {
      const segment& S = segs[s];
      const fpoint &p = fp[S.lo], &q = fp[S.hi];
      const std::size_t b0 = band_lo[s], b1 = band_hi[s];
      for (std::size_t b = b0; b <= b1; ++b) {
        auto& list = active[b];
        std::size_t kept = 0;
        for (std::size_t k = 0; k < list.size(); ++k) {
          const std::uint32_t t = list[k];
          const segment& T = segs[t];
          const fpoint &r = fp[T.lo], &u = fp[T.hi];
          if (u.xh < p.xl) continue;  // closed before s opens (for good)
          list[kept++] = t;
          if (std::max(b0, std::size_t(band_lo[t])) != b) continue;  // tested in a lower band
          if (yhi[t] < ylo[s] || ylo[t] > yhi[s]) continue;
          const bool s_point = S.lo == S.hi, t_point = T.lo == T.hi;
          if (s_point && t_point) continue;
          if (s_point || t_point) {
            const std::uint32_t seg = s_point ? t : s;
            const std::uint32_t v = s_point ? S.lo : T.lo;
            const segment& G = segs[seg];
            if (G.lo < v && v < G.hi && orientation(fp[G.lo], fp[G.hi], fp[v]) == 0) splits.emplace_back(seg, v);
            continue;
          }
          // Orientations of t's ends about s, then of s's ends about t (shared ends are 0).
          const int o_r = (T.lo == S.lo || T.lo == S.hi) ? 0 : orientation(p, q, r);
          const int o_u = (T.hi == S.lo || T.hi == S.hi) ? 0 : orientation(p, q, u);
          if (o_r == 0 && o_u == 0) {  // collinear: each end inside the other splits it
            split(s, T.lo);
            split(s, T.hi);
            split(t, S.lo);
            split(t, S.hi);
            continue;
          }
          if (o_r * o_u > 0) continue;
          const int o_p = (S.lo == T.lo || S.lo == T.hi) ? 0 : orientation(r, u, p);
          const int o_q = (S.hi == T.lo || S.hi == T.hi) ? 0 : orientation(r, u, q);
          if (o_p * o_q > 0) continue;
          if (o_r != 0 && o_u != 0 && o_p != 0 && o_q != 0) {
            crossing_pairs.push_back({s, t});
            continue;
          }
          // They meet at one point, an end of one of them (on the other's line, so on it).
          if (o_r == 0) split(s, T.lo);
          if (o_u == 0) split(s, T.hi);
          if (o_p == 0) split(t, S.lo);
          if (o_q == 0) split(t, S.hi);
        }
        scanned += list.size();
        list.resize(kept);
        list.push_back(s);
      }
      if (scanned > budget) return std::nullopt;
    }
  }

  // Crossings, exactly, then every vertex numbered in lexicographic order.
  out.crossings = crossing_pairs.size();
  out.owned.reserve(crossing_pairs.size());
  {
    std::vector<std::optional<int_line>> lines(nsegs);
    const auto line = [&](std::uint32_t s) -> const int_line& {
      if (!lines[s]) lines[s] = line_through(*first[segs[s].lo], *first[segs[s].hi]);
      return *lines[s];
    };
    const std::uint32_t base = static_cast<std::uint32_t>(first.size());
    for (std::size_t k = 0; k < crossing_pairs.size(); ++k) {
      const auto [s, t] = crossing_pairs[k];
      out.owned.push_back(meet(line(s), line(t)));
      splits.emplace_back(s, base + static_cast<std::uint32_t>(k));
      splits.emplace_back(t, base + static_cast<std::uint32_t>(k));
    }
  }
  std::vector<const point2*> all(first);
  for (const auto& p : out.owned) {
    all.push_back(&p);
    first_approx.push_back(truncated(p));
  }
  std::vector<std::uint32_t> final_id;
  std::vector<std::array<double, 2>> vertex_approx;
  number_points(all, first_approx, final_id, out.vertices, vertex_approx);
  first_approx = {};
  for (auto& s : segs) {
    s.lo = final_id[s.lo];
    s.hi = final_id[s.hi];
  }
  for (auto& sp : splits) sp.second = final_id[sp.second];
  std::sort(splits.begin(), splits.end());

  // Pass 2a: the edges, pieces of segments between consecutive split points, merged.
  const std::size_t nv = out.vertices.size();
  out.point_piece.assign(nv, 0);
  for (std::size_t k = nsegs; k < segs.size(); ++k) out.point_piece[segs[k].lo] = 1;
  std::vector<planar_map::edge> pieces;
  pieces.reserve(nsegs + splits.size());
  for (std::size_t s = 0, at = 0; s < nsegs; ++s) {
    std::uint32_t from = segs[s].lo;
    for (; at < splits.size() && splits[at].first == s; ++at) {
      const std::uint32_t v = splits[at].second;
      if (v == from) continue;  // one point found twice
      pieces.push_back({from, v, segs[s].weight, {}, segs[s].degenerate});
      from = v;
    }
    pieces.push_back({from, segs[s].hi, segs[s].weight, {}, segs[s].degenerate});
  }
  std::sort(pieces.begin(), pieces.end(),
            [](const planar_map::edge& x, const planar_map::edge& y) { return x.lo != y.lo ? x.lo < y.lo : x.hi < y.hi; });
  for (const auto& e : pieces) {
    if (!out.edges.empty() && out.edges.back().lo == e.lo && out.edges.back().hi == e.hi) {
      auto& m = out.edges.back();
      m.weight = {m.weight[0] + e.weight[0], m.weight[1] + e.weight[1]};
      m.degenerate = m.degenerate || e.degenerate;
    } else {
      out.edges.push_back(e);
    }
  }
  pieces = {};
  {
    std::vector<planar_map::edge> kept;
    kept.reserve(out.edges.size());
    for (const auto& e : out.edges)
      if (e.degenerate || e.weight[0] != 0 || e.weight[1] != 0) kept.push_back(e);
    out.edges = std::move(kept);
  }

  // Pass 2b: the sweep. Edges starting and ending at each vertex (edges are sorted by lo).
  const std::size_t ne = out.edges.size();
  std::vector<fpoint> vf(nv);
  for (std::size_t i = 0; i < nv; ++i) vf[i] = make_fpoint(*out.vertices[i], vertex_approx[i]);
  std::vector<std::uint32_t> start_at(nv + 1, 0), end_at(nv + 1, 0), ending(ne);
  for (const auto& e : out.edges) {
    ++start_at[e.lo + 1];
    ++end_at[e.hi + 1];
  }
  for (std::size_t i = 0; i < nv; ++i) {
    start_at[i + 1] += start_at[i];
    end_at[i + 1] += end_at[i];
  }
  {
    std::vector<std::uint32_t> fill(end_at.begin(), end_at.end() - 1);
    for (std::uint32_t e = 0; e < ne; ++e) ending[fill[out.edges[e].hi]++] = e;
  }
  auto& E = out.edges;
  // Edge e below edge f, both on the sweep line (decided at the later left end; they never
  // cross, and an end of one never lies inside the other).
  const auto below = [&](std::uint32_t e, std::uint32_t f) {
    if (e == f) return false;
    const auto &a = E[e], &b = E[f];
    int o;
    if (a.lo == b.lo) {
      o = orientation(vf[a.lo], vf[a.hi], vf[b.hi]);
      if (o == 0) throw internal_error("two edges of the sweep overlap");
      return o > 0;
    }
    if (a.lo > b.lo) {
      o = orientation(vf[b.lo], vf[b.hi], vf[a.lo]);
      if (o == 0) throw internal_error("an edge of the sweep starts inside another");
      return o < 0;
    }
    o = orientation(vf[a.lo], vf[a.hi], vf[b.lo]);
    if (o == 0) throw internal_error("an edge of the sweep starts inside another");
    return o > 0;
  };
  // The side of vertex v of edge e on the sweep line (v never lies inside e).
  const auto side = [&](std::uint32_t e, std::uint32_t v) {
    const int o = orientation(vf[E[e].lo], vf[E[e].hi], vf[v]);
    if (o == 0) throw internal_error("a vertex of the sweep lies inside an edge");
    return o;
  };
  struct probe {
    std::uint32_t v;
  };
  struct order {
    using is_transparent = void;
    const decltype(below)* edges_below;
    const decltype(side)* side_of;
    bool operator()(std::uint32_t e, std::uint32_t f) const { return (*edges_below)(e, f); }
    bool operator()(std::uint32_t e, probe p) const { return (*side_of)(e, p.v) > 0; }
    bool operator()(probe p, std::uint32_t e) const { return (*side_of)(e, p.v) < 0; }
  };
  using status_tree = std::set<std::uint32_t, order>;
  status_tree status(order{&below, &side});
  std::vector<status_tree::iterator> where(ne, status.end());
  out.isolated.assign(nv, windings{0, 0});
  out.adjacent.reserve(2 * ne);
  const auto check = [](const windings& x, const windings& y) {
    if (x != y) throw internal_error("winding numbers of the sweep do not match (an open chain)");
  };
  std::vector<std::uint32_t> starting;
  CGAL::Protect_FPU_rounding<true> up;
  for (std::uint32_t v = 0; v < nv; ++v) {
    const std::uint32_t s0 = start_at[v], s1 = start_at[v + 1], e0 = end_at[v], e1 = end_at[v + 1];
    if (s0 == s1 && e0 == e1 && !out.point_piece[v]) continue;
    for (std::uint32_t k = e0; k < e1; ++k) status.erase(where[ending[k]]);
    const auto next = status.lower_bound(probe{v});
    const bool has_pred = next != status.begin();
    const std::uint32_t pred = has_pred ? *std::prev(next) : 0;
    windings run = has_pred ? E[pred].above() : windings{0, 0};
    if (s0 == s1) {
      if (next != status.end()) {
        check(E[*next].below, run);
        if (has_pred) out.adjacent.push_back({pred, *next});
      } else {
        check(run, windings{0, 0});
      }
      if (e0 == e1) out.isolated[v] = run;
      continue;
    }
    starting.assign(s0 == s1 ? 0 : s1 - s0, 0);
    std::iota(starting.begin(), starting.end(), s0);
    // Bottom to top: f above e when f's far end is to the left of e, seen from v.
    std::sort(starting.begin(), starting.end(), [&](std::uint32_t e, std::uint32_t f) {
      if (e == f) return false;
      const int o = orientation(vf[v], vf[E[e].hi], vf[E[f].hi]);
      if (o == 0) throw internal_error("two edges of the sweep overlap");
      return o > 0;
    });
    bool has_lower = has_pred;
    std::uint32_t lower = pred;
    for (const std::uint32_t e : starting) {
      E[e].below = run;
      run = E[e].above();
      where[e] = status.emplace_hint(next, e);
      if (has_lower) out.adjacent.push_back({lower, e});
      has_lower = true;
      lower = e;
    }
    if (next != status.end()) {
      check(E[*next].below, run);
      out.adjacent.push_back({lower, *next});
    } else {
      check(run, windings{0, 0});
    }
  }
  if (!status.empty()) throw internal_error("edges left on the sweep line");
  return out;
}

}  // namespace shadowproof::detail
