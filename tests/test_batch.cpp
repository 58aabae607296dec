// Grading many cases at once (shadowproof/verify/batch.h): the batch's references and grades
// are grade_case's, field for field, for every built-in implementation and its conventions;
// the AVX2 filter and the generic one decide the same cases with the same bits.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "../src/verify/kernels/batch.h"
#include "../src/verify/oracle_fast.h"
#include "shadowproof/impls/builtin.h"
#include "shadowproof/verify/batch.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/protocol.h"
#include "shadowproof/verify/report.h"

using namespace shadowproof;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Case i's outputs out of the batch's columns.
std::vector<double> outputs_of(const case_batch& b, std::size_t i) {
  std::vector<double> got(signature(b.op).output_count);
  for (std::size_t j = 0; j < got.size(); ++j) got[j] = b.output_column(j)[i];
  return got;
}

// The operations with batch filters and kernels (right-handed: a left-handed convention goes to
// the kernel for one case or the generic oracle).
bool has_batch_filter(const implementation& impl) {
  const operation op = impl.op;
  return impl.conv.hand == handedness::right &&
         (op == operation::shadow_matrix || op == operation::shadow_point || op == operation::reflection_matrix ||
          op == operation::ortho || op == operation::frustum || op == operation::normal_matrix ||
          op == operation::perspective || op == operation::ortho_size || op == operation::perspective_size ||
          op == operation::look_at || op == operation::target_to || op == operation::perspective_fov ||
          op == operation::perspective_fov_infinite);
}

// look-at or target-to: slow to grade where the filter does not decide (degenerate frames go
// to rationals), so their tests take fewer cases.
bool frame_builder(const implementation& impl) {
  return impl.op == operation::look_at || impl.op == operation::target_to;
}

// perspective-fov or perspective-fov-infinite: fifteen implementations, many of them with the
// same conventions, and verdicts slow to grade: fewer cases.
bool field_of_view_builder(const implementation& impl) {
  return impl.op == operation::perspective_fov || impl.op == operation::perspective_fov_infinite;
}

// Whether impl is the first right-handed look-at (target-to) implementation of its type met:
// the others have the same filter on the same generated cases.
bool first_frame_builder_of_its_type(const implementation& impl) {
  for (const implementation& other : builtin_implementations())
    if (other.op == impl.op && other.type == impl.type && has_batch_filter(other)) return &other == &impl;
  return false;
}

// Field for field: the batch's columns for case i against grade_case's grade of it.
void require_same_grade(const batch_grades& batch, std::size_t i, const case_grade& g) {
  const std::size_t count = batch.count;
  REQUIRE(batch.outputs_per_case == g.outputs.size());
  for (std::size_t j = 0; j < g.outputs.size(); ++j) {
    INFO("output " << j);
    const output_grade& o = g.outputs[j];
    const std::uint8_t flags = batch.flags[j * count + i];
    REQUIRE(((flags & batch_grades::counted) != 0) == o.counted());
    REQUIRE(((flags & batch_grades::nonfinite_output) != 0) == o.nonfinite);
    REQUIRE(((flags & batch_grades::garbage_output) != 0) == o.garbage);
    REQUIRE(((flags & batch_grades::exact_undefined) != 0) == !o.exact_defined);
    if (o.counted()) REQUIRE(batch.ulps[j * count + i] == o.ulps);
  }
  REQUIRE(batch.max_ulps[i] == g.max_ulps);
  REQUIRE(batch.worst_output[i] == g.worst_output);
  REQUIRE(batch.nonfinite[i] == g.nonfinite);
  REQUIRE(batch.garbage[i] == g.garbage);
  REQUIRE((batch.misclassified[i] != 0) == g.misclassified);
  REQUIRE(batch.got_class[i] == (g.got_class ? static_cast<int>(*g.got_class) : -1));
  if (g.plane_value) REQUIRE(same_bits(batch.plane_value[i], *g.plane_value));
  else REQUIRE(std::isnan(batch.plane_value[i]));
}

// Some outputs replaced by values every grader must handle: infinities, NaN, a huge finite
// value, the next float or double.
void perturb(case_batch& b, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  for (double& x : b.outputs) {
    switch (rng() % 40) {
      case 0: x = std::numeric_limits<double>::infinity(); break;
      case 1: x = -std::numeric_limits<double>::infinity(); break;
      case 2: x = std::numeric_limits<double>::quiet_NaN(); break;
      case 3: x = b.type == scalar_type::f32 ? 3e38 : 1e308; break;
      case 4:
        if (std::isfinite(x))
          x = b.type == scalar_type::f32 ? std::nextafter(static_cast<float>(x), 1e30f) : std::nextafter(x, 1e300);
        break;
      default: break;
    }
  }
}

}  // namespace

TEST_CASE("batch grades are grade_case's, field for field, for every built-in implementation", "[batch]") {
  // With the AVX2 filter and column grader where the processor has them, and with the generic ones.
  // 48 cases (every input class, full AVX2 blocks and a tail) where a batch filter decides, 10
  // for the look-at builders (two blocks and a tail: their verdicts are slow), 14 for the
  // field-of-view builders (three blocks and a tail), 12 for a left-handed convention (the
  // one-case oracle).
  std::size_t graded = 0, expected = 0;
  for (const implementation& impl : builtin_implementations()) {
    const std::size_t count =
        has_batch_filter(impl) ? (frame_builder(impl) ? 10 : field_of_view_builder(impl) ? 14 : 48) : 12;
    expected += count;
    const auto cases = generate_cases(impl.op, impl.type, count, 31, std::nullopt, impl.conv);
    case_batch batch = make_batch(cases);
    run_implementation(impl, batch);
    perturb(batch, graded);
    batch_references refs;
    oracle_counters batch_counters;
    compute_references(batch, impl.conv, refs, &batch_counters);
    batch_grades grades, generic;
    grade_batch(batch, impl.conv, refs, grades);
    grade_batch(batch, impl.conv, refs, generic, batch_path::generic);
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const case_grade g = grade_case(cases[i], impl.conv, outputs_of(batch, i).data());
      INFO("implementation " << impl.name << ", case " << case_json_line(cases[i]));
      require_same_grade(grades, i, g);
      require_same_grade(generic, i, g);
      ++graded;
    }
    CHECK(batch_counters.decided_by_intervals + batch_counters.fell_back_to_rationals == cases.size());
  }
  CHECK(graded == expected);
}

TEST_CASE("batch references are the correctly rounded exact outputs, whichever path decides them", "[batch]") {
  // Against grade_case's references (the reference field of each output grade) with outputs
  // that are the references themselves: every output is then exact, 0 ulps.
  for (const implementation& impl : builtin_implementations()) {
    if (impl.conv.homogeneous || impl.conv.normalises_plane) continue;  // graded up to scale
    const std::size_t count = has_batch_filter(impl) && !frame_builder(impl) ? 120 : 24;
    const auto cases = generate_cases(impl.op, impl.type, count, 5, std::nullopt, impl.conv);
    case_batch batch = make_batch(cases);
    batch_references refs;
    compute_references(batch, impl.conv, refs);
    batch.outputs = refs.values;
    batch_grades grades;
    grade_batch(batch, impl.conv, refs, grades);
    for (std::size_t i = 0; i < cases.size(); ++i) {
      INFO("implementation " << impl.name << ", case " << case_json_line(cases[i]));
      const case_grade g = grade_case(cases[i], impl.conv, outputs_of(batch, i).data());
      for (std::size_t j = 0; j < g.outputs.size(); ++j)
        if (g.outputs[j].exact_defined) REQUIRE(same_bits(refs.values[j * batch.count + i], g.outputs[j].reference));
      REQUIRE(grades.max_ulps[i] == 0);
      REQUIRE(g.max_ulps == 0);
    }
  }
}

TEST_CASE("a shadow-point image moved to the light's side of V is misclassified in the batch as one by one", "[batch]") {
  // Regular shadow-point cases whose float image is replaced by 2V − C (C the correctly rounded
  // image, rounded to float): on the line through the light and V, reflected through V, so on
  // the other side of V from C. The image filter decides these classes (no sign is near zero):
  // the batch's image class, plane value and misclassification must be grade_case's.
  const implementation& impl = find_builtin_implementation("eigen-intersection-f32");
  const auto cases = generate_cases(impl.op, impl.type, 64, 17, input_class::regular, impl.conv);
  case_batch batch = make_batch(cases);
  batch_references refs;
  compute_references(batch, impl.conv, refs);
  for (std::size_t j = 0; j < 3; ++j)
    for (std::size_t i = 0; i < batch.count; ++i)
      batch.output_column(j)[i] =
          static_cast<float>(2 * batch.input_column(8 + j)[i] - refs.values[j * batch.count + i]);
  batch_grades grades, generic;
  grade_batch(batch, impl.conv, refs, grades);
  grade_batch(batch, impl.conv, refs, generic, batch_path::generic);
  std::size_t misclassified = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const case_grade g = grade_case(cases[i], impl.conv, outputs_of(batch, i).data());
    INFO("case " << case_json_line(cases[i]));
    require_same_grade(grades, i, g);
    require_same_grade(generic, i, g);
    misclassified += g.misclassified ? 1 : 0;
  }
  CHECK(misclassified >= cases.size() / 2);  // the comparison is about misclassified images
}

TEST_CASE("the AVX2 filter and the generic filter give the same references bit for bit", "[batch]") {
  if (!avx2_batch_available()) {
    WARN("this processor has no AVX2 and FMA: only the generic filter runs here");
    return;
  }
  std::size_t filtered_by_both = 0, compared = 0;
  for (const implementation& impl : builtin_implementations()) {
    if (!has_batch_filter(impl)) continue;
    // The look-at builders: one implementation of each type, 43 regular and near-degenerate
    // cases (their degenerate frames go to rationals, one by one on both paths); the
    // field-of-view builders 43 cases of every class; the others 203 (a tail of 3).
    const bool frame = frame_builder(impl);
    if (frame && !first_frame_builder_of_its_type(impl)) continue;
    for (input_class cls : {input_class::regular, input_class::near_degenerate, input_class::degenerate}) {
      if (frame && cls == input_class::degenerate) continue;
      const auto cases =
          generate_cases(impl.op, impl.type, frame || field_of_view_builder(impl) ? 43 : 203, 17, cls, impl.conv);
      const case_batch batch = make_batch(cases);
      batch_references generic, avx2;
      compute_references(batch, impl.conv, generic, nullptr, batch_path::generic);
      compute_references(batch, impl.conv, avx2, nullptr, batch_path::avx2);
      INFO("implementation " << impl.name << ", class " << to_string(cls));
      for (std::size_t i = 0; i < batch.count; ++i) {
        INFO("case " << case_json_line(cases[i]));
        for (std::size_t j = 0; j < signature(impl.op).output_count; ++j)
          REQUIRE(same_bits(generic.values[j * batch.count + i], avx2.values[j * batch.count + i]));
        REQUIRE(generic.undefined[i] == avx2.undefined[i]);
        REQUIRE(generic.point_class[i] == avx2.point_class[i]);
        // The AVX2 filter leaves the tail of fewer than four cases to the kernel for one case;
        // elsewhere both filters decide exactly the same cases.
        if (i < batch.count / 4 * 4) REQUIRE((generic.decided_by[i] == 0) == (avx2.decided_by[i] == 0));
        filtered_by_both += generic.decided_by[i] == 0 && avx2.decided_by[i] == 0;
        ++compared;
      }
    }
  }
  // The comparison means something only if the filters decide most cases themselves.
  CHECK(filtered_by_both * 2 > compared);
}

TEST_CASE("the batch filter decides nearly every regular case", "[batch]") {
  for (const implementation& impl : builtin_implementations()) {
    if (impl.conv.homogeneous || impl.conv.normalises_plane) continue;
    if (!has_batch_filter(impl)) continue;
    if (frame_builder(impl) && !first_frame_builder_of_its_type(impl)) continue;
    const auto cases = generate_cases(impl.op, impl.type, 400, 3, input_class::regular, impl.conv);
    const case_batch batch = make_batch(cases);
    batch_references refs;
    compute_references(batch, impl.conv, refs, nullptr, batch_path::generic);
    std::size_t by_filter = 0, by_rationals = 0;
    for (std::uint8_t d : refs.decided_by) {
      by_filter += d == 0;
      by_rationals += d == 3;
    }
    INFO("implementation " << impl.name << ": " << by_filter << " of 400 decided by the filter");
    CHECK(by_filter >= 396);
    CHECK(by_rationals == 0);
  }
}

TEST_CASE("a batch round-trips its cases", "[batch]") {
  const auto cases = generate_cases(operation::shadow_point, scalar_type::f64, 10, 8);
  const case_batch batch = make_batch(cases);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const test_case c = case_at(batch, i);
    CHECK(c.id == cases[i].id);
    CHECK(c.cls == cases[i].cls);
    CHECK(c.inputs == cases[i].inputs);
  }
  std::vector<test_case> mixed = cases;
  mixed.push_back(generate_cases(operation::ortho, scalar_type::f64, 1, 8).front());
  CHECK_THROWS_AS(make_batch(mixed), internal_error);
}

TEST_CASE("left-handed projections: batch references are the all-rational oracle's", "[batch]") {
  // A left-handed matrix is the right-handed one with column 2 negated; the batch filters skip
  // such cases and the kernels negate. The all-rational oracle builds the matrix itself.
  conventions left;
  left.hand = handedness::left;
  for (operation op : {operation::ortho, operation::frustum, operation::perspective, operation::ortho_size,
                       operation::perspective_size})
    for (scalar_type type : {scalar_type::f32, scalar_type::f64}) {
      const auto cases = generate_cases(op, type, 120, 9, std::nullopt, left);
      case_batch batch = make_batch(cases);
      batch_references refs;
      compute_references(batch, left, refs);
      batch.outputs = refs.values;
      for (std::size_t i = 0; i < cases.size(); ++i) {
        INFO("case " << case_json_line(cases[i]));
        const case_grade g = grade_case(cases[i], left, outputs_of(batch, i).data(), oracle_mode::naive);
        for (std::size_t j = 0; j < g.outputs.size(); ++j)
          if (g.outputs[j].exact_defined) REQUIRE(same_bits(refs.values[j * batch.count + i], g.outputs[j].reference));
        REQUIRE(g.max_ulps == 0);
      }
    }
}

TEST_CASE("quotients of two exact values: batch references at the ends of the range are the all-rational oracle's",
          "[batch]") {
  // 2/w, 2/h, 2n/w, 2n/h (the size builders) and c/aspect (perspective) are one division in the
  // output type where they are normal numbers; subnormal and overflowing quotients, flat and
  // negative extents go one case at a time. Hand-picked inputs on both sides of those limits,
  // through the AVX2 and the generic filter (two lanes of four and a tail), every depth
  // convention, against the all-rational oracle.
  const double f32_ends[] = {1.5, 0.75, 3e38, 0x1p-127, 1e-38, 5e-39, 0x1p-149, 0x1p126, 0x1p127, 0.0, -1.0, 7.0};
  const double f64_ends[] = {1.5, 0.75, 1e300, 0x1p-1074, 1e-300, 0x1p-1022, 0x1p1022, 0x1p1023, 0.0, -1.0, 7.0, 1e-200};
  std::size_t filtered = 0, compared = 0;  // cases the filter decided, of all
  for (operation op : {operation::ortho_size, operation::perspective_size, operation::perspective})
    for (scalar_type type : {scalar_type::f32, scalar_type::f64})
      for (depth_convention depth : {depth_convention::gl, depth_convention::d3d, depth_convention::reverse_z}) {
        conventions conv;
        conv.depth = depth;
        const double* ends = type == scalar_type::f32 ? f32_ends : f64_ends;
        std::vector<test_case> cases;
        for (std::size_t a = 0; a < 12; ++a) {
          test_case c;
          c.id = cases.size();
          c.op = op;
          c.type = type;
          // The quotient's numerator or first extent from the list, the other extent and the
          // depths regular (perspective: c from the list over aspect 1.25, and 2 over it).
          const double x = type == scalar_type::f32 ? static_cast<float>(ends[a]) : ends[a];
          if (op == operation::perspective) {
            cases.push_back(c);
            cases.back().inputs = {x, 1.25, 0.5, 100.0};
            c.id = cases.size();
            cases.push_back(c);
            cases.back().inputs = {2.0, x, 0.5, 100.0};
          } else {
            cases.push_back(c);
            cases.back().inputs = {x, 0.75, 0.5, 100.0};
            c.id = cases.size();
            cases.push_back(c);
            const double half = type == scalar_type::f32 ? static_cast<float>(x / 2) : x / 2;
            cases.back().inputs = {2.0, 3.0, half, x};  // perspective-size: 2n over w
          }
        }
        case_batch batch = make_batch(cases);
        for (batch_path path : {batch_path::automatic, batch_path::generic}) {
          batch_references refs;
          compute_references(batch, conv, refs, nullptr, path);
          batch.outputs = refs.values;
          for (std::size_t i = 0; i < cases.size(); ++i) {
            filtered += refs.decided_by[i] == 0;
            ++compared;
            INFO(to_string(op) << " " << to_string(type) << ", depth " << static_cast<int>(depth) << ", case "
                               << case_json_line(cases[i]));
            const case_grade g = grade_case(cases[i], conv, outputs_of(batch, i).data(), oracle_mode::naive);
            for (std::size_t j = 0; j < g.outputs.size(); ++j) {
              REQUIRE(((refs.undefined[i] >> j) & 1) == (g.outputs[j].exact_defined ? 0u : 1u));
              if (g.outputs[j].exact_defined)
                REQUIRE(same_bits(refs.values[j * batch.count + i], g.outputs[j].reference));
            }
          }
        }
      }
  // Both sides of the limits: the filter decides the regular ones and leaves the others.
  CHECK(filtered * 4 > compared);
  CHECK(filtered * 4 < compared * 3);
}

TEST_CASE("the field-of-view filters decide the angles at the edges of their ranges as the kernels for one case", "[batch]") {
  // Angles at every threshold of the cotangent's evaluation (the smallest angle it takes, the
  // switch to π/2 − x, π and 180° and their neighbours, values outside the half turn) and
  // aspects at the edges of their range, every combination, in both units and both types:
  // the generic filter, the AVX2 filter and the kernel for one case must decide the same
  // lanes (the filters decide no lane the kernel declines) with the same bits.
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const double pi_below = 0x1.921fb54442d18p+1;  // the double nearest π, below it
  const std::vector<double> radians = {0x1p-400, std::nextafter(0x1p-400, 0.0), 1e-300, 1e-5, 0.5, 1.6,
                                       std::nextafter(1.6, 2.0), std::nextafter(1.6, 0.0), 1.5707963267948966,
                                       3.0, pi_below, std::nextafter(pi_below, 4.0), 0.0, -1.0, nan, inf};
  const std::vector<double> degrees = {0x1p-390, std::nextafter(0x1p-390, 0.0), 1e-100, 1.0, 45.0, 90.0,
                                       std::nextafter(90.0, 100.0), std::nextafter(90.0, 0.0), 120.0,
                                       std::nextafter(180.0, 0.0), 180.0, 200.0, 0.0, -45.0, nan, inf};
  const std::vector<double> aspects = {1.0, 0.75, 0x1p-300, std::nextafter(0x1p-300, 0.0), 0x1p300,
                                       std::nextafter(0x1p300, inf), 0.0, -1.0};
  std::size_t decided_by_filter = 0, lanes = 0;
  for (const operation op : {operation::perspective_fov, operation::perspective_fov_infinite})
    for (const scalar_type type : {scalar_type::f32, scalar_type::f64})
      for (const angle_unit unit : {angle_unit::radians, angle_unit::degrees}) {
        conventions conv;
        conv.angle = unit;
        std::vector<double> columns[4];
        for (const double fovy : unit == angle_unit::radians ? radians : degrees)
          for (const double aspect : aspects) {
            columns[0].push_back(fovy);
            columns[1].push_back(aspect);
            columns[2].push_back(0.5);
            columns[3].push_back(100.0);
          }
        const std::size_t count = columns[0].size();  // a multiple of 4: no tail
        const double* in[4] = {columns[0].data(), columns[1].data(), columns[2].data(), columns[3].data()};
        auto run = [&](detail::batch_filter filter, std::vector<double>& values, std::vector<std::uint8_t>& decided) {
          values.assign(16 * count, 0.0);
          decided.assign(count, 0);
          double* out[16];
          for (std::size_t j = 0; j < 16; ++j) out[j] = values.data() + j * count;
          filter(in, count, conv, {out, decided.data(), nullptr});
        };
        std::vector<double> generic, avx2;
        std::vector<std::uint8_t> generic_decided, avx2_decided;
        run(detail::generic_batch_filter(op, type), generic, generic_decided);
        const bool with_avx2 = avx2_batch_available();
        if (with_avx2) run(detail::avx2_batch_filter(op, type), avx2, avx2_decided);
        const bool infinite = op == operation::perspective_fov_infinite;
        const detail::fast_kernel kernel =
            type == scalar_type::f32 ? (infinite ? detail::fast_perspective_fov_infinite_f32 : detail::fast_perspective_fov_f32)
                                     : (infinite ? detail::fast_perspective_fov_infinite_f64 : detail::fast_perspective_fov_f64);
        for (std::size_t i = 0; i < count; ++i) {
          INFO(to_string(op) << " " << to_string(type) << " fovy " << columns[0][i] << " aspect " << columns[1][i]);
          const double x[4] = {columns[0][i], columns[1][i], columns[2][i], columns[3][i]};
          detail::fast_reference r;
          const bool by_kernel = kernel(x, conv, r);
          if (with_avx2) REQUIRE(generic_decided[i] == avx2_decided[i]);
          if (!generic_decided[i]) continue;
          REQUIRE(by_kernel);
          REQUIRE(r.defined);
          for (std::size_t j = 0; j < 16; ++j) {
            REQUIRE(same_bits(generic[j * count + i], r.value[j]));
            if (with_avx2) REQUIRE(same_bits(avx2[j * count + i], r.value[j]));
          }
          ++decided_by_filter;
        }
        lanes += count;
      }
  // In range: 10 of 16 angles times 4 of 8 aspects, 320 of the 1024 lanes; the filters leave
  // a few of them (a focal scale beyond double's range) to the kernel.
  CHECK(lanes == 1024);
  CHECK(decided_by_filter >= 256);
}
