// Verdicts (docs/verdicts.md): the correctly rounded answer is never flagged, in any operation,
// type, input class and declared convention; planted defects get the verdict they deserve; the
// engines' verdicts hold; the case generator keeps the promises the verdicts rely on.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>

#include "shadowproof/core/number.h"
#include "shadowproof/impls/builtin.h"
#include "shadowproof/impls/reference.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/exact.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/protocol.h"
#include "shadowproof/verify/report.h"

using namespace shadowproof;

namespace {

// One declared convention and how the reference honours it.
struct variant {
  std::string name;
  conventions conv;
  rational scale = 1;         // the multiple a homogeneous result is returned as
  bool use_sentinel = false;  // the sentinel (instead of NaN) where there is no answer
};

std::vector<variant> convention_variants() {
  std::vector<variant> v;
  v.push_back({"canonical", {}});
  conventions c;
  c.storage = storage_order::column_major;
  v.push_back({"column-major", c});
  c = {};
  c.vectors = vector_side::row;
  v.push_back({"row vectors", c});
  c.storage = storage_order::column_major;
  v.push_back({"row vectors, column-major", c});
  c = {};
  c.light = light_sign::along_rays;
  v.push_back({"light along its rays", c});
  c = {};
  c.depth = depth_convention::d3d;
  v.push_back({"depth d3d", c});
  c.depth = depth_convention::reverse_z;
  v.push_back({"depth reverse-z", c});
  c = {};
  c.homogeneous = true;
  v.push_back({"homogeneous, 2M", c, rational(2)});
  v.push_back({"homogeneous, -M", c, rational(-1)});
  v.push_back({"homogeneous, 3M rounded", c, rational(3)});
  v.push_back({"homogeneous, -5/7 M rounded", c, rational(-5, 7)});
  c = {};
  c.normalises_plane = true;
  v.push_back({"normalises the plane, 5/7 M rounded", c, rational(5, 7)});
  c = {};
  c.directional_only = true;
  v.push_back({"directional lights only", c});
  c = {};
  c.point_light_only = true;
  v.push_back({"point lights only", c});
  c = {};
  c.unit_normal = true;
  v.push_back({"unit normals only", c});
  c = {};
  c.symmetric_view = true;
  v.push_back({"symmetric volumes only", c});
  c = {};
  c.clamps_behind_receiver = true;
  c.directional_only = true;
  v.push_back({"clamps behind the receiver", c});
  c = {};
  c.sentinel = sentinel_kind::zero;
  v.push_back({"sentinel zero", c, rational(1), true});
  c.sentinel = sentinel_kind::identity;
  v.push_back({"sentinel identity", c, rational(1), true});
  c = {};
  c.hand = handedness::left;
  v.push_back({"left-handed", c});
  c = {};
  c.angle = angle_unit::degrees;
  v.push_back({"angles in degrees", c});
  return v;
}

// Operations whose exact values are irrational (square roots, cotangents): graded as they are,
// never up to scale.
bool has_irrational_values(operation op) {
  return op == operation::perspective_fov || op == operation::perspective_fov_infinite || op == operation::look_at ||
         op == operation::target_to;
}

// The scale a result of op under conv may carry (1 unless it is graded up to scale).
rational scale_for(operation op, const variant& v) {
  const bool up_to_scale = signature(op).matrix_size &&
                           (v.conv.homogeneous || (v.conv.normalises_plane && symmetries(op).plane_degree > 0));
  return up_to_scale ? v.scale : rational(1);
}

// Grades the reference of (op, type, variant) on `per_class` cases of every class (the first
// `naive` of them in both oracle modes); every case must be exact, 0 ulps, nothing flagged.
std::size_t grade_reference(operation op, scalar_type type, const variant& v, std::size_t per_class,
                            std::size_t naive, std::uint64_t seed) {
  if (v.conv.sentinel != sentinel_kind::none && !sentinel_applies(op, v.conv.sentinel)) return 0;
  if (v.conv.homogeneous && has_irrational_values(op)) return 0;  // refused: see test_verify
  const implementation ref = correctly_rounded_implementation(op, type, v.conv, scale_for(op, v), v.use_sentinel);
  std::size_t graded = 0;
  for (input_class cls : all_input_classes()) {
    const auto cases = generate_cases(op, type, per_class, seed, cls, v.conv);
    std::vector<double> out(signature(op).output_count);
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const test_case& c = cases[i];
      ref.run(c.inputs.data(), out.data());
      for (oracle_mode mode : {oracle_mode::filtered, oracle_mode::naive}) {
        if (mode == oracle_mode::naive && i >= naive) continue;
        const case_grade g = grade_case(c, v.conv, out.data(), mode);
        const bool flagged = g.v != verdict::exact || g.max_ulps != 0 || g.nonfinite != 0 || g.garbage != 0 ||
                             g.misclassified;
        if (flagged) {
          INFO(ref.name << ", " << v.name << ", " << (mode == oracle_mode::naive ? "naive" : "filtered")
                        << ": verdict " << to_string(g.v) << " at output " << g.verdict_output << ", max ulps "
                        << g.max_ulps << ", misclassified " << g.misclassified << "\n  " << case_json_line(c));
          CHECK_FALSE(flagged);
        }
      }
      ++graded;
    }
  }
  return graded;
}

// The implementation's outputs for every case, changed by `plant`.
template <class Plant>
std::vector<case_grade> grade_planted(operation op, scalar_type type, input_class cls, std::size_t count,
                                      const conventions& conv, Plant plant) {
  const implementation ref = correctly_rounded_implementation(op, type, conv);
  std::vector<case_grade> grades;
  for (const auto& c : generate_cases(op, type, count, 31, cls, conv)) {
    std::vector<double> out(signature(op).output_count);
    ref.run(c.inputs.data(), out.data());
    plant(c, out);
    grades.push_back(grade_case(c, conv, out.data()));
  }
  return grades;
}

std::size_t count_verdict(const std::vector<case_grade>& grades, verdict v) {
  std::size_t n = 0;
  for (const auto& g : grades) n += g.v == v;
  return n;
}

double next_up(double x, scalar_type type) {
  return type == scalar_type::f32 ? static_cast<double>(std::nextafter(static_cast<float>(x), 1e30f))
                                  : std::nextafter(x, 1e300);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The invariant: the correctly rounded answer is never flagged.

TEST_CASE("the correctly rounded answer is exact in every operation, type, class and convention", "[verdicts]") {
  std::size_t graded = 0;
  for (operation op : all_operations())
    for (scalar_type type : {scalar_type::f32, scalar_type::f64})
      for (const variant& v : convention_variants()) graded += grade_reference(op, type, v, 6, 2, 7);
  CHECK(graded > 4000);
}

// 10^5 cases per operation: ctest -L long (configure with -DSHADOWPROOF_LONG_TESTS=ON), or
// test_verdicts "[long]". The count per operation is SHADOWPROOF_LONG_CASES (default 100000).
TEST_CASE("the correctly rounded answer is exact at scale", "[.long][verdicts]") {
  const char* text = std::getenv("SHADOWPROOF_LONG_CASES");
  const std::size_t per_op = text ? std::stoul(text) : 100000;
  const std::size_t combinations = 2 * all_input_classes().size() * convention_variants().size();
  for (operation op : all_operations()) {
    std::size_t graded = 0;
    for (scalar_type type : {scalar_type::f32, scalar_type::f64})
      for (const variant& v : convention_variants())
        graded += grade_reference(op, type, v, (per_op + combinations - 1) / combinations, 0, 1000 + graded);
    INFO(to_string(op));
    CHECK(graded >= per_op * 8 / 10);  // sentinel variants that mean nothing for op are skipped
  }
}

TEST_CASE("the built-in references are registered and exact under check", "[verdicts]") {
  for (operation op : all_operations())
    for (scalar_type type : {scalar_type::f32, scalar_type::f64}) {
      const implementation& impl = find_builtin_implementation("correctly-rounded-" + std::string(to_string(op)) + "-" +
                                                               std::string(to_string(type)));
      const auto grades = run_and_grade(impl, generate_cases(op, type, 40, 3, std::nullopt, impl.conv));
      CHECK(summarize(grades).worst_verdict == verdict::exact);
    }
}

// ---------------------------------------------------------------------------------------------
// Planted defects.

TEST_CASE("a planted one-ulp error is faithful, and only --fail-on faithful catches it", "[verdicts]") {
  for (operation op : all_operations())
    for (scalar_type type : {scalar_type::f32, scalar_type::f64}) {
      const auto grades = grade_planted(op, type, input_class::regular, 30, {}, [&](const test_case&, std::vector<double>& out) {
        for (double& x : out)
          if (std::isfinite(x)) {
            x = next_up(x, type);
            break;
          }
      });
      INFO(to_string(op) << " " << to_string(type));
      CHECK(count_verdict(grades, verdict::faithful) == grades.size());
      const grade_summary s = summarize(grades);
      CHECK(s.worst_verdict == verdict::faithful);
      CHECK(s.max_ulps == 1);
      CHECK(reaches(s, verdict::faithful));
      CHECK_FALSE(reaches(s, verdict::stable));
    }
}

TEST_CASE("a transposed matrix is wrong where the matrix is not symmetric", "[verdicts]") {
  for (operation op : all_operations()) {
    const std::size_t k = signature(op).matrix_size;
    if (!k) continue;
    const auto grades = grade_planted(op, scalar_type::f32, input_class::regular, 40, {}, [&](const test_case&, std::vector<double>& out) {
      const std::vector<double> m = out;
      for (std::size_t r = 0; r < k; ++r)
        for (std::size_t c = 0; c < k; ++c) out[c * k + r] = m[r * k + c];
    });
    INFO(to_string(op));
    CHECK(summarize(grades).worst_verdict == verdict::wrong);
    CHECK(count_verdict(grades, verdict::wrong) >= grades.size() * 9 / 10);
  }
}

TEST_CASE("a dropped term is wrong", "[verdicts]") {
  // The reference evaluated with one input zeroed, as if the formula had left out every term with
  // it: the plane's offset d (shadows, mirrors), the box's left side, A's first entry, the eye's
  // x; for the perspectives the aspect (c/aspect computed as c), for the size builders the
  // height (2/h computed as 2).
  for (operation op : all_operations())
    for (scalar_type type : {scalar_type::f32, scalar_type::f64}) {
      const auto grades = grade_planted(op, type, input_class::regular, 40, {}, [&](const test_case& c, std::vector<double>& out) {
        test_case changed = c;
        const std::string name(to_string(op));
        if (op == operation::perspective || op == operation::perspective_fov ||
            op == operation::perspective_fov_infinite || op == operation::ortho_size ||
            op == operation::perspective_size)
          changed.inputs[1] = 1;
        else if (name.find("shadow") == 0 || op == operation::reflection_matrix) changed.inputs[3] = 0;
        else changed.inputs[0] = 0;
        if (!invalid_inputs_reason(changed).empty()) return;
        out = correctly_rounded_outputs(changed, {});
      });
      INFO(to_string(op) << " " << to_string(type));
      CHECK(summarize(grades).worst_verdict == verdict::wrong);
      CHECK(count_verdict(grades, verdict::wrong) >= grades.size() * 8 / 10);
    }
}

TEST_CASE("a NaN where a well-conditioned answer exists is nonfinite", "[verdicts]") {
  for (operation op : all_operations())
    for (scalar_type type : {scalar_type::f32, scalar_type::f64}) {
      const auto grades = grade_planted(op, type, input_class::regular, 30, {}, [&](const test_case&, std::vector<double>& out) {
        out[out.size() - 1] = std::numeric_limits<double>::quiet_NaN();
      });
      INFO(to_string(op) << " " << to_string(type));
      CHECK(count_verdict(grades, verdict::nonfinite) == grades.size());
    }
}

TEST_CASE("where no answer exists, NaN or the sentinel is exact and a finite number is garbage", "[verdicts]") {
  // A singular normal matrix (row 2 = 2 × row 0): no (A⁻¹)ᵀ.
  test_case c;
  c.op = operation::normal_matrix;
  c.type = scalar_type::f32;
  c.inputs = {1, 2, 3, 0, 1, 4, 2, 4, 6};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> rejected(9, nan), identity{1, 0, 0, 0, 1, 0, 0, 0, 1}, zero(9, 0.0);
  CHECK(grade_case(c, {}, rejected.data()).v == verdict::exact);
  CHECK(grade_case(c, {}, identity.data()).v == verdict::garbage);
  CHECK(grade_case(c, {}, identity.data()).garbage == 9);
  conventions qt;
  qt.sentinel = sentinel_kind::identity;
  const case_grade g = grade_case(c, qt, identity.data());
  CHECK(g.v == verdict::exact);
  CHECK(g.rejected);
  CHECK(grade_case(c, qt, zero.data()).v == verdict::garbage);
  // The sentinel where an answer exists: A = 2 I has (A⁻¹)ᵀ = I/2, well-conditioned: wrong.
  c.inputs = {2, 0, 0, 0, 2, 0, 0, 0, 2};
  CHECK(grade_case(c, qt, identity.data()).v == verdict::wrong);
  // A flat view volume (b = t = 1) rejected as a whole with NaN: exact, where before every
  // defined entry counted as non-finite.
  test_case flat;
  flat.op = operation::ortho;
  flat.type = scalar_type::f32;
  flat.inputs = {-1, 1, 1, 1, 1, 3};
  const std::vector<double> all_nan(16, nan);
  const case_grade f = grade_case(flat, {}, all_nan.data());
  CHECK(f.v == verdict::exact);
  CHECK(f.nonfinite == 0);
  CHECK(f.rejected);
}

TEST_CASE("any honest rescaling of a homogeneous result grades exact, with the scale and its pivot", "[verdicts]") {
  conventions homogeneous;
  homogeneous.homogeneous = true;
  for (operation op : {operation::shadow_matrix, operation::reflection_matrix, operation::normal_matrix})
    for (scalar_type type : {scalar_type::f32, scalar_type::f64})
      for (const rational& scale : {rational(2), rational(-1), rational(3), rational(-5, 7), rational(1, 3)}) {
        const implementation ref = correctly_rounded_implementation(op, type, homogeneous, scale);
        for (const auto& c : generate_cases(op, type, 60, 5, std::nullopt, homogeneous)) {
          std::vector<double> out(signature(op).output_count);
          ref.run(c.inputs.data(), out.data());
          const case_grade g = grade_case(c, homogeneous, out.data());
          INFO(to_string(op) << " " << to_string(type) << " scale " << to_string(scale) << "\n  " << case_json_line(c));
          CHECK(g.v == verdict::exact);
          CHECK(g.max_ulps == 0);
          if (g.scale) {
            REQUIRE(g.scale_pivot);
            // λ lies within the rounding of the pivot: λ·exact rounds to the pivot's output.
            CHECK(std::fabs(*g.scale - to_nearest_double(scale)) <= 1e-5 * std::fabs(to_nearest_double(scale)));
          }
        }
      }
}

// ---------------------------------------------------------------------------------------------
// The generator keeps the promises the verdicts rely on.

TEST_CASE("near-degenerate cases lie within the type's resolution, degenerate ones exactly on the degeneracy",
          "[verdicts][generator]") {
  for (operation op : all_operations())
    for (scalar_type type : {scalar_type::f32, scalar_type::f64}) {
      const double resolution = type == scalar_type::f32 ? -23 : -52;
      for (const auto& c : generate_cases(op, type, 200, 9, input_class::near_degenerate)) {
        INFO(to_string(op) << " " << case_json_line(c));
        CHECK(std::isfinite(c.closeness));
        CHECK(c.closeness >= resolution);
        CHECK(c.closeness == closeness_to_degeneracy(c));
      }
      if (op == operation::reflection_matrix) continue;  // no valid mirror is degenerate
      for (const auto& c : generate_cases(op, type, 200, 9, input_class::degenerate)) {
        INFO(to_string(op) << " " << case_json_line(c));
        CHECK(std::isinf(c.closeness));
      }
    }
}

TEST_CASE("a singular normal matrix is only ever degenerate", "[verdicts][generator]") {
  for (scalar_type type : {scalar_type::f32, scalar_type::f64})
    for (const auto& c : generate_cases(operation::normal_matrix, type, 400, 13)) {
      const exact_result a = exact_result_of(c, {});
      INFO(case_json_line(c));
      CHECK(a.defined[0] == (c.cls != input_class::degenerate));
    }
}

TEST_CASE("range cases over- or underflow a straightforward evaluation; the other classes do not", "[verdicts][generator]") {
  for (operation op : all_operations())
    for (scalar_type type : {scalar_type::f32, scalar_type::f64})
      for (input_class cls : all_input_classes())
        for (const auto& c : generate_cases(op, type, 40, 17, cls)) {
          const std::vector<double> out = correctly_rounded_outputs(c, {});
          INFO(to_string(op) << " " << case_json_line(c));
          if (cls == input_class::range || cls == input_class::regular)
            CHECK(conditioning(c, {}, out.data()).out_of_range == (cls == input_class::range));
        }
}

TEST_CASE("cases honour point-only, directional-only, unit-normal and symmetric restrictions", "[verdicts][generator]") {
  conventions point, directional, unit, symmetric;
  point.point_light_only = true;
  directional.directional_only = true;
  unit.unit_normal = true;
  symmetric.symmetric_view = true;
  for (scalar_type type : {scalar_type::f32, scalar_type::f64})
    for (operation op : {operation::shadow_matrix, operation::shadow_point}) {
      for (const auto& c : generate_cases(op, type, 200, 19, std::nullopt, point)) CHECK(c.inputs[7] != 0);
      for (const auto& c : generate_cases(op, type, 200, 19, std::nullopt, directional)) CHECK(c.inputs[7] == 0);
      for (const auto& c : generate_cases(op, type, 200, 19, std::nullopt, unit)) {
        if (c.cls == input_class::range) continue;  // scaled lights only, the plane keeps its unit normal
        CHECK(std::fabs(c.inputs[0]) + std::fabs(c.inputs[1]) + std::fabs(c.inputs[2]) == 1);
      }
    }
  for (scalar_type type : {scalar_type::f32, scalar_type::f64})
    for (operation op : {operation::ortho, operation::frustum})
      for (const auto& c : generate_cases(op, type, 200, 23, std::nullopt, symmetric)) {
        CHECK(c.inputs[0] == -c.inputs[1]);
        CHECK(c.inputs[2] == -c.inputs[3]);
      }
}

// ---------------------------------------------------------------------------------------------
// The engines' verdicts (docs/findings.md).

namespace {

grade_summary summary_of(const std::string& name, std::optional<input_class> cls, std::size_t count = 400) {
  const implementation& impl = find_builtin_implementation(name);
  std::vector<case_grade> part;
  for (const auto& g : run_and_grade(impl, generate_cases(impl.op, impl.type, count, 1, cls, impl.conv))) part.push_back(g);
  return summarize(part);
}

// Cases whose light rays are nearly parallel to the receiver: a directional light tilted by
// 2^-k (k = 10 … 20) out of the receiver's direction (b, −a, 0); or, for a point light, a point V
// whose line to the light is tilted by as much (V nearly level with the light, its shadow far
// away). Integer planes and lights, every number exact in float.
std::vector<test_case> near_parallel_light_cases(bool point_light, std::size_t count) {
  std::mt19937_64 rng(5);
  auto integer = [&](int lo, int hi) { return static_cast<double>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
  std::vector<test_case> cases;
  while (cases.size() < count) {
    test_case c;
    c.op = operation::shadow_point;
    c.type = scalar_type::f32;
    c.id = cases.size();
    c.cls = input_class::near_degenerate;
    const double a = integer(-6, 6), b = integer(1, 6), cc = integer(-6, 6);
    const double eps = std::ldexp(1.0, -static_cast<int>(integer(10, 17)));
    c.inputs = {a, b, cc, integer(-5, 5)};
    double l[4], v[3];
    if (point_light) {
      l[0] = integer(-5, 5);
      l[1] = integer(-5, 5);
      l[2] = integer(-5, 5);
      l[3] = 1;
      const double k = integer(1, 4) * (integer(0, 1) ? 1 : -1);
      v[0] = l[0] + k * b + eps * a;
      v[1] = l[1] - k * a + eps * b;
      v[2] = l[2] + eps * cc;
    } else {
      l[0] = b + eps * a;
      l[1] = -a + eps * b;
      l[2] = eps * cc;
      l[3] = 0;
      for (double& x : v) x = integer(-40, 40) / 8;
    }
    bool exact = true;
    for (double x : l) exact = exact && static_cast<double>(static_cast<float>(x)) == x;
    for (double x : v) exact = exact && static_cast<double>(static_cast<float>(x)) == x;
    if (!exact) continue;
    c.inputs.insert(c.inputs.end(), l, l + 4);
    c.inputs.insert(c.inputs.end(), v, v + 3);
    if (!invalid_inputs_reason(c).empty()) continue;
    cases.push_back(c);
  }
  return cases;
}

}  // namespace

#ifdef SHADOWPROOF_HAVE_IRRLICHT
TEST_CASE("Irrlicht's buildShadowMatrix is wrong, also on unit normals with point lights", "[verdicts][engines]") {
  const grade_summary any = summary_of("irrlicht-shadow-f32", input_class::regular);
  CHECK(any.worst_verdict == verdict::wrong);
  CHECK(any.verdicts[static_cast<std::size_t>(verdict::wrong)] == any.cases);
  CHECK(summary_of("irrlicht-shadow-f32", std::nullopt).worst_verdict == verdict::wrong);
  // Unit normals: right for the sun (directional lights), wrong for point lights (D·w left out).
  const implementation& unit = find_builtin_implementation("irrlicht-shadow-unit-normal-f32");
  const auto cases = generate_cases(unit.op, unit.type, 200, 1, input_class::regular, unit.conv);
  const auto grades = run_and_grade(unit, cases);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    INFO(case_json_line(cases[i]));
    CHECK(grades[i].v == (cases[i].inputs[7] == 0 ? verdict::exact : verdict::wrong));
  }
}

TEST_CASE("Irrlicht's projection builders are no worse than stable within the range", "[verdicts][engines]") {
  for (const char* name : {"irrlicht-ortho-rh-f32", "irrlicht-perspective-rh-f32"})
    for (input_class cls : {input_class::regular, input_class::near_degenerate, input_class::degenerate}) {
      INFO(name << " " << to_string(cls));
      CHECK(summary_of(name, cls).worst_verdict <= verdict::stable);
    }
}
#endif

#ifdef SHADOWPROOF_HAVE_GLM
TEST_CASE("GLM's projection builders are no worse than stable within the range", "[verdicts][engines]") {
  for (const char* name : {"glm-ortho-f32", "glm-frustum-f32", "glm-frustum-f64", "glm-frustum-zo-f32"})
    for (input_class cls : {input_class::regular, input_class::near_degenerate, input_class::degenerate}) {
      INFO(name << " " << to_string(cls));
      CHECK(summary_of(name, cls).worst_verdict <= verdict::stable);
    }
}
#endif

TEST_CASE("mirrors whose |n|² over- or underflows are range, and stable otherwise", "[verdicts][engines]") {
  std::vector<std::string> names{"reflect-divide-f32", "reflect-divide-f64", "reflect-divide-fma-f32",
                                 "reflect-normalize-f32", "reflect-normalize-f64"};
#ifdef SHADOWPROOF_HAVE_GLM
  names.push_back("glm-reflect3d-f32");
  names.push_back("glm-reflect3d-f64");
#endif
#ifdef SHADOWPROOF_HAVE_OGRE
  names.push_back("ogre-reflection-f32");
#endif
  for (const auto& name : names) {
    INFO(name);
    const grade_summary range = summary_of(name, input_class::range);
    CHECK(range.worst_verdict == verdict::range);
    CHECK(range.verdicts[static_cast<std::size_t>(verdict::range)] >= range.cases / 2);
    for (input_class cls : {input_class::regular, input_class::near_degenerate, input_class::degenerate}) {
      INFO(to_string(cls));
      CHECK(summary_of(name, cls).worst_verdict <= verdict::stable);
    }
  }
}

TEST_CASE("Eigen's intersection and seed 003's ray formula are stable but ill-conditioned near parallel lights",
          "[verdicts][engines]") {
  std::vector<std::pair<std::string, bool>> routines{{"seed003-ray-f32", true}, {"seed003-ray-f64", true}};
#ifdef SHADOWPROOF_HAVE_EIGEN
  routines.push_back({"eigen-intersection-f32", false});
  routines.push_back({"eigen-intersection-f32", true});
  routines.push_back({"eigen-intersection-f64", false});
#endif
  for (const auto& [name, point_light] : routines) {
    const implementation& impl = find_builtin_implementation(name);
    double worst_condition = 0;
    for (test_case c : near_parallel_light_cases(point_light, 300)) {
      c.type = impl.type;
      std::vector<double> out(3);
      impl.run(c.inputs.data(), out.data());
      const case_grade g = grade_case(c, impl.conv, out.data());
      INFO(name << " " << case_json_line(c));
      CHECK(g.v <= verdict::stable);
      worst_condition = std::max(worst_condition, conditioning(c, impl.conv, out.data()).normwise_condition);
    }
    INFO(name);
    CHECK(worst_condition >= 1 << 14);  // ill-conditioned: the errors come from the problem
  }
}
