// CGAL interop (include/shadowproof/cgal/): conversions, shadows and mirror images over three
// exact kernels, and the constructions instantiated with Epeck::FT. Expected values are derived
// by hand; CGAL's own predicates (has_on, collinear) check the images independently.
#include <catch2/catch.hpp>

#include <CGAL/Cartesian.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include "shadowproof/cgal/convert.h"
#include "shadowproof/cgal/images.h"
#include "shadowproof/cgal/number.h"
#include "shadowproof/core/error.h"

using namespace shadowproof;
using CGAL::Epeck;
using gmpq_kernel = CGAL::Simple_cartesian<CGAL::Gmpq>;
using gmpxx_kernel = CGAL::Cartesian<mpq_class>;

TEMPLATE_TEST_CASE("planes, points and vectors convert exactly both ways", "[cgal]", Epeck, gmpq_kernel,
                   gmpxx_kernel) {
  using K = TestType;
  using FT = typename K::FT;
  const FT third = cgal::from_rational<FT>(rational(1, 3));
  const typename K::Plane_3 P(FT(0), third, FT(-2), FT(7) / FT(2));
  const plane<rational> p = cgal::to_plane<K>(P);
  CHECK(p.p == make_vec4<rational>(0, rational(1, 3), -2, rational(7, 2)));
  CHECK(cgal::to_plane_3<K>(p) == P);

  const typename K::Point_3 X(third, FT(-5), FT(0));
  CHECK(cgal::to_vec4<K>(X) == make_vec4<rational>(rational(1, 3), -5, 0, 1));
  CHECK(cgal::to_point_3<K>(cgal::to_vec4<K>(X)) == X);
  // (2, −10, 0, 6) is the same point as (1/3, −5/3, 0, 1); w = −6 names it too.
  CHECK(*cgal::to_point_3<K>(make_vec4<rational>(2, -10, 0, 6)) == typename K::Point_3(third, FT(-5) / FT(3), FT(0)));
  CHECK(*cgal::to_point_3<K>(make_vec4<rational>(-2, 10, 0, -6)) ==
        typename K::Point_3(third, FT(-5) / FT(3), FT(0)));
  CHECK_FALSE(cgal::to_point_3<K>(make_vec4<rational>(1, 0, 0, 0)));

  const typename K::Vector_3 v(FT(0), FT(1), third);
  CHECK(cgal::to_vec4<K>(v) == make_vec4<rational>(0, 1, rational(1, 3), 0));
  CHECK(*cgal::to_direction_3<K>(cgal::to_vec4<K>(v)) == v);
  CHECK_FALSE(cgal::to_direction_3<K>(make_vec4<rational>(0, 0, 0, 0)));
  CHECK(cgal::to_light<K>(v).is_directional());
  CHECK(cgal::to_light<K>(X).l == make_vec4<rational>(rational(1, 3), -5, 0, 1));
  CHECK_THROWS_AS(cgal::to_light<K>(typename K::Vector_3(FT(0), FT(0), FT(0))), error);
}

TEMPLATE_TEST_CASE("the shadow of a CGAL point is exact, on the receiver, on the line to the light", "[cgal]", Epeck,
                   gmpq_kernel, gmpxx_kernel) {
  using K = TestType;
  using FT = typename K::FT;
  using Point = typename K::Point_3;
  // Ground y = 0, light at (2, 5, 1), V = (1, 2, 3): M V = (1, 0, 13, 3) (README), so the shadow
  // is (1/3, 0, 13/3).
  const typename K::Plane_3 ground(FT(0), FT(1), FT(0), FT(0));
  const Point light_at(FT(2), FT(5), FT(1)), V(FT(1), FT(2), FT(3));
  const cgal::shadow_3<K> s = cgal::shadow_of<K>(ground, light_at, V);
  CHECK(s.cls == point_class::shadow);
  REQUIRE(s.point);
  CHECK(*s.point == Point(FT(1) / FT(3), FT(0), FT(13) / FT(3)));
  CHECK(ground.has_on(*s.point));
  CHECK(CGAL::collinear(light_at, V, *s.point));
  CHECK_FALSE(s.at_infinity);

  // A point at the light's height (y = 5) casts its shadow at infinity: M V = (. , 0, ., 0).
  const cgal::shadow_3<K> far = cgal::shadow_of<K>(ground, light_at, Point(FT(0), FT(5), FT(0)));
  CHECK(far.cls == point_class::at_infinity);
  CHECK_FALSE(far.point);
  // M V = 5 (0, 5, 0, 1) − 5 (2, 5, 1, 1) = (−10, 0, −5, 0).
  CHECK(*far.at_infinity == typename K::Vector_3(FT(-10), FT(0), FT(-5)));

  // The light itself has no image; a point of the receiver under a light in the receiver is
  // its own shadow.
  const cgal::shadow_3<K> at_light = cgal::shadow_of<K>(ground, light_at, light_at);
  CHECK(at_light.cls == point_class::at_light);
  CHECK_FALSE(at_light.point);
  CHECK_FALSE(at_light.at_infinity);
  const Point lamp_on_ground(FT(1), FT(0), FT(1)), spot(FT(4), FT(0), FT(-1));
  const cgal::shadow_3<K> in_plane = cgal::shadow_of<K>(ground, lamp_on_ground, spot);
  CHECK(in_plane.cls == point_class::line_in_plane);
  CHECK(*in_plane.point == spot);

  // The sun along x, parallel to the ground: s = 0, t = P·V = 1, M V = −L = (−1, 0, 0, 0).
  const cgal::shadow_3<K> parallel =
      cgal::shadow_of<K>(ground, typename K::Vector_3(FT(1), FT(0), FT(0)), Point(FT(0), FT(1), FT(0)));
  CHECK(parallel.cls == point_class::light_parallel);
  CHECK(*parallel.at_infinity == typename K::Vector_3(FT(-1), FT(0), FT(0)));
}

TEMPLATE_TEST_CASE("the mirror image of a CGAL point is exact and reflecting twice gives it back", "[cgal]", Epeck,
                   gmpq_kernel, gmpxx_kernel) {
  using K = TestType;
  using FT = typename K::FT;
  using Point = typename K::Point_3;
  // x + y + z − 3 = 0: the origin is at t = −3, so its image is 0 − 2 t n / (n·n) = (2, 2, 2).
  const typename K::Plane_3 mirror(FT(1), FT(1), FT(1), FT(-3));
  const Point origin(FT(0), FT(0), FT(0));
  CHECK(cgal::reflection_of<K>(mirror, origin) == Point(FT(2), FT(2), FT(2)));
  // A point with thirds: its image's midpoint lies on the mirror and the segment is along n.
  const Point X(FT(1) / FT(3), FT(-4), FT(5));
  const Point Y = cgal::reflection_of<K>(mirror, X);
  CHECK(mirror.has_on(CGAL::midpoint(X, Y)));
  CHECK(CGAL::cross_product(Y - X, mirror.orthogonal_vector()) == typename K::Vector_3(FT(0), FT(0), FT(0)));
  CHECK(cgal::reflection_of<K>(mirror, Y) == X);
  CHECK(cgal::reflection_transformation_3<K>(mirror).transform(X) == Y);
  // Directions: n flips, a direction in the mirror stays.
  CHECK(cgal::reflection_of<K>(mirror, typename K::Vector_3(FT(1), FT(1), FT(1))) ==
        typename K::Vector_3(FT(-1), FT(-1), FT(-1)));
  CHECK(cgal::reflection_of<K>(mirror, typename K::Vector_3(FT(1), FT(-1), FT(0))) ==
        typename K::Vector_3(FT(1), FT(-1), FT(0)));
}

TEST_CASE("the constructions compile with Epeck::FT and agree exactly with rationals", "[cgal]") {
  using FT = Epeck::FT;
  auto lazy = [](const rational& q) { return cgal::from_rational<FT>(q); };
  const rational a(1, 3), b(-7, 2), c(5), d(2, 9);
  const rational x(3, 4), y(-1, 6), z(11), w(1, 5);
  const plane<FT> P = make_plane<FT>(lazy(a), lazy(b), lazy(c), lazy(d));
  const light<FT> L = make_light<FT>(lazy(x), lazy(y), lazy(z), lazy(w));
  const plane<rational> Pq = make_plane<rational>(a, b, c, d);
  const light<rational> Lq = make_light<rational>(x, y, z, w);

  const mat4<FT> M = shadow_matrix(P, L);
  const mat4<FT> R = reflection_matrix(P);
  const mat4<rational> Mq = shadow_matrix(Pq, Lq), Rq = reflection_matrix(Pq);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) {
      CHECK(cgal::to_rational(M(i, j)) == Mq(i, j));
      CHECK(cgal::to_rational(R(i, j)) == Rq(i, j));
    }
  // Entry (0,0) by hand: P·L − x a = (1/4 + 7/12 + 55 + 2/45) − 1/4 = 55 + 7/12 + 2/45 = 10013/180.
  CHECK(cgal::to_rational(M(0, 0)) == rational(10013, 180));
  const vec4<FT> V = make_point<FT>(lazy(1), lazy(rational(-2, 3)), lazy(4));
  CHECK(classify_point(P, L, V) == classify_point(Pq, Lq, make_point<rational>(1, rational(-2, 3), 4)));
  const mat4<FT> RR = R * R;
  CHECK(RR == identity4<FT>());
}
