// The degeneracy-biased generators: reproducible, exactly representable, and exactly degenerate
// where they say so.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <set>

#include "shadowproof/constructions/classify.h"
#include "shadowproof/fuzz/generate.h"

using namespace shadowproof;

namespace {

template <class F>
point_class exact_class(const generated_case<F>& c) {
  auto q = [](F x) { return exact_value(static_cast<double>(x)); };
  return classify_point(make_plane(q(c.plane[0]), q(c.plane[1]), q(c.plane[2]), q(c.plane[3])),
                        make_light(q(c.light[0]), q(c.light[1]), q(c.light[2]), q(c.light[3])),
                        make_point(q(c.point[0]), q(c.point[1]), q(c.point[2])));
}

// The variations that keep an exact degeneracy exact (no ulp or 2^-k nudge).
bool keeps_exactness(const std::string& family) {
  return family.find("+ulp") == std::string::npos && family.find("+2^-") == std::string::npos;
}

std::string base_family(const std::string& family) {
  return family.substr(0, family.find_first_of("+*"));
}

}  // namespace

TEMPLATE_TEST_CASE("exact degenerate families are exactly degenerate", "[generate]", float, double) {
  prng_source src(99);
  std::map<std::string, int> checked;
  for (int i = 0; i < 6000; ++i) {
    const auto c = generate_shadow_case<TestType>(src);
    if (!keeps_exactness(c.family)) continue;
    for (auto x : c.plane) REQUIRE(std::isfinite(x));
    const std::string base = base_family(c.family);
    const point_class k = exact_class(c);
    INFO(c.family);
    if (base == "light_parallel") CHECK((k == point_class::light_parallel || k == point_class::line_in_plane));
    if (base == "light_on_plane") CHECK((k == point_class::light_on_plane || k == point_class::line_in_plane));
    if (base == "vertex_on_plane") CHECK((k == point_class::on_receiver || k == point_class::line_in_plane));
    if (base == "vertex_at_light") CHECK((k == point_class::at_light || k == point_class::line_in_plane));
    if (base == "vertex_at_light_height")
      CHECK((k == point_class::at_infinity || k == point_class::light_on_plane || k == point_class::line_in_plane));
    if (base == "vertex_beyond_light") CHECK((k == point_class::beyond_light || k == point_class::light_on_plane));
    if (base == "vertex_below_receiver") CHECK((k == point_class::behind_receiver || k == point_class::light_on_plane));
    ++checked[base];
  }
  for (const char* family : exact_families) CHECK(checked[family] > 100);
}

TEMPLATE_TEST_CASE("every family and variation is produced", "[generate]", float, double) {
  prng_source src(5);
  std::set<std::string> variations;
  bool saw_subnormal = false, saw_signed_zero = false;
  for (int i = 0; i < 5000; ++i) {
    const auto c = generate_shadow_case<TestType>(src);
    const auto at = c.family.find_first_of("+*");
    variations.insert(at == std::string::npos ? "exact" : c.family.substr(at, 4));
    for (auto x : c.point) {
      saw_subnormal = saw_subnormal || std::fpclassify(x) == FP_SUBNORMAL;
      saw_signed_zero = saw_signed_zero || (x == 0 && std::signbit(x));
    }
  }
  CHECK(variations.size() >= 7);
  CHECK(saw_subnormal);
  CHECK(saw_signed_zero);
}

TEST_CASE("the same seed gives the same cases", "[generate]") {
  prng_source a(123), b(123), c(124);
  bool differs = false;
  for (int i = 0; i < 200; ++i) {
    const auto x = generate_shadow_case<float>(a), y = generate_shadow_case<float>(b), z = generate_shadow_case<float>(c);
    CHECK(x.family == y.family);
    CHECK(x.plane == y.plane);
    CHECK(x.light == y.light);
    CHECK(x.point == y.point);
    differs = differs || x.point != z.point || x.family != z.family;
  }
  CHECK(differs);
}

TEST_CASE("prng_source draws uniformly below its bound", "[generate]") {
  prng_source src(1);
  std::array<int, 7> counts{};
  for (int i = 0; i < 70000; ++i) ++counts[src.below(7)];
  for (int n : counts) CHECK((n > 9000 && n < 11000));
}

TEST_CASE("requirements of an implementation hold for every generated case", "[generate]") {
  prng_source src(77);
  for (int i = 0; i < 3000; ++i) {
    const generator_requirements req{i % 2 == 0, i % 3 == 0, i % 3 == 1};
    const auto c = generate_shadow_case<float>(src, req);
    INFO(c.family);
    if (req.unit_normal) {
      int ones = 0, zeros = 0;
      for (int k = 0; k < 3; ++k) {
        ones += std::fabs(c.plane[k]) == 1.0f;
        zeros += c.plane[k] == 0.0f;
      }
      CHECK((ones == 1 && zeros == 2));
    }
    if (req.directional_only) CHECK(c.light[3] == 0.0f);
    if (req.point_light_only) CHECK(c.light[3] == 1.0f);
  }
}
