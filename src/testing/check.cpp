// The property runner: generated cases, grading, the worst failure, shrinking, the report.
#include "shadowproof/testing/check.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "failure_text.h"
#include "judgement.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/number.h"
#include "shadowproof/fuzz/shrink.h"
#include "shadowproof/verify/grade.h"

namespace shadowproof {
namespace {

// The routine seen through doubles (the float one's inputs narrow exactly, outputs widen
// exactly).
using widened_routine = std::function<void(const double* inputs, double* outputs)>;

// Cases are generated and graded this many at a time, so memory does not grow with the count.
constexpr std::size_t chunk_size = 1024;

std::uint64_t mix(std::uint64_t x) {  // SplitMix64's finaliser: decorrelates consecutive seeds
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

struct outcome {
  detail::case_judgement judgement;
  std::vector<double> outputs;
  std::string threw;  // what the routine threw, if it did
};

outcome run_case(const widened_routine& routine, const test_case& c, const check_settings& s) {
  outcome o;
  // Outputs the routine does not write stay NaN, and are graded as the non-finite values they are.
  o.outputs.assign(signature(c.op).output_count, std::numeric_limits<double>::quiet_NaN());
  try {
    routine(c.inputs.data(), o.outputs.data());
  } catch (const std::exception& e) {
    o.threw = e.what();
  } catch (...) {
    o.threw = "an exception not derived from std::exception";
  }
  if (!o.threw.empty()) {
    o.judgement.fails = true;
    o.judgement.verdict = "threw";
    o.judgement.severity = 4;
    return o;
  }
  o.judgement = detail::judge(grade_case(c, s.conv, o.outputs.data()), s.fail_on);
  return o;
}

// Where an input group starts, or nothing when the operation has none of that name.
std::optional<std::size_t> group_offset(operation op, std::string_view name) {
  std::size_t k = 0;
  for (const auto& g : signature(op).inputs) {
    if (g.name == name) return k;
    k += g.size;
  }
  return std::nullopt;
}

// Inputs a shrunk case must keep as generated: a unit normal, a light's w fixed by the routine's
// restrictions.
std::vector<bool> pinned_inputs(operation op, const conventions& conv) {
  std::vector<bool> keep(signature(op).input_count, false);
  const auto plane = group_offset(op, "plane");
  const auto light = group_offset(op, "light");
  if (plane && conv.unit_normal) keep[*plane] = keep[*plane + 1] = keep[*plane + 2] = true;
  if (light && (conv.directional_only || conv.point_light_only)) keep[*light + 3] = true;
  return keep;
}

// A shrunk case stays a case the routine accepts: an instance of the operation, every input a
// value of the type, within the routine's input restrictions.
bool acceptable(const test_case& c, const conventions& conv) {
  if (!invalid_inputs_reason(c).empty()) return false;
  for (double x : c.inputs)
    if (!representable(x, c.type)) return false;
  const auto box = group_offset(c.op, "box");
  if (box && conv.symmetric_view && (c.inputs[*box] != -c.inputs[*box + 1] || c.inputs[*box + 2] != -c.inputs[*box + 3]))
    return false;
  const auto plane = group_offset(c.op, "plane");
  const auto light = group_offset(c.op, "light");
  if (plane && light && conv.clamps_behind_receiver) {
    rational s = 0;
    for (std::size_t k = 0; k < 4; ++k) s += exact_value(c.inputs[*plane + k]) * exact_value(c.inputs[*light + k]);
    if (sgn(s) <= 0) return false;
  }
  return true;
}

// One chunk of cases: the classes in turn, each class from its own deterministic stream.
std::vector<test_case> chunk_cases(operation op, scalar_type type, const check_settings& s, std::size_t first,
                                   std::size_t count) {
  const std::size_t m = s.classes.size();
  std::vector<std::vector<test_case>> by_class(m);
  for (std::size_t k = 0; k < m; ++k) {
    std::size_t n = 0;
    for (std::size_t i = first; i < first + count; ++i) n += i % m == k;
    by_class[k] = generate_cases(op, type, n, mix(s.seed ^ mix(first / chunk_size * m + k)), s.classes[k], s.conv);
  }
  std::vector<test_case> cases;
  std::vector<std::size_t> next(m, 0);
  for (std::size_t i = first; i < first + count; ++i) {
    test_case c = std::move(by_class[i % m][next[i % m]++]);
    c.id = i;
    cases.push_back(std::move(c));
  }
  return cases;
}

std::string case_lines(const test_case& c, const check_settings& s, const outcome& o) {
  if (!o.threw.empty())
    return "  the routine threw: " + o.threw + "\n  inputs (" + std::string(to_string(c.type)) +
           "): " + detail::inputs_text(c) + "\n  exact answer: " + reproducer_command(c, s.conv) + "\n";
  return detail::failure_text(c, s.conv, o.outputs.data(), o.judgement);
}

check_result run_check(operation op, scalar_type type, const widened_routine& routine, const check_settings& s) {
  if (s.classes.empty()) throw error(errc::testing_input, "check needs at least one input class");
  check_result r;
  r.routine = std::string(to_string(op)) + " (" + std::string(to_string(type)) + ")";
  std::optional<outcome> worst;
  for (std::size_t first = 0; first < s.cases; first += chunk_size) {
    for (const test_case& c : chunk_cases(op, type, s, first, std::min(chunk_size, s.cases - first))) {
      ++r.cases;
      outcome o = run_case(routine, c, s);
      if (!o.judgement.fails) continue;
      ++r.failed;
      ++r.failed_by_verdict[o.judgement.verdict];
      if (!worst || detail::worse(o.judgement, worst->judgement)) {
        worst = std::move(o);
        r.worst = c;
      }
    }
  }
  if (!worst) return r;

  // Shrink the worst case while the routine still fails it the same way, and for an ulps
  // failure by at least as many ulps (a simpler case with a milder error would hide how bad
  // the worst one is).
  const detail::case_judgement target = worst->judgement;
  auto still_fails = [&](const std::vector<double>& inputs) {
    test_case t = *r.worst;
    t.inputs = inputs;
    if (!acceptable(t, s.conv)) return false;
    const detail::case_judgement j = run_case(routine, t, s).judgement;
    return j.verdict == target.verdict && (j.verdict != "ulps" || j.max_ulps >= target.max_ulps);
  };
  const shrink_result shrunk = shrink_inputs(r.worst->inputs, type == scalar_type::f32, still_fails,
                                             pinned_inputs(op, s.conv), s.shrink_budget);
  r.shrunk = *r.worst;
  r.shrunk->inputs = shrunk.inputs;
  const outcome shrunk_outcome = run_case(routine, *r.shrunk, s);

  std::ostringstream report;
  report << r.routine << ": " << r.failed << " of " << r.cases << " cases fail (" << s.fail_on.to_string();
  const std::string conv = detail::conventions_text(s.conv, op);
  if (!conv.empty()) report << "; " << conv;
  report << "; seed " << s.seed << "):";
  for (const auto& [v, n] : r.failed_by_verdict) report << ' ' << n << ' ' << v;
  report << "\nworst case, shrunk from " << shrunk.bits_before << " to " << shrunk.bits_after << " bits:\n"
         << case_lines(*r.shrunk, s, shrunk_outcome) << "the same case as generated (case " << r.worst->id << ", "
         << to_string(r.worst->cls) << "):\n"
         << case_lines(*r.worst, s, *worst);
  r.report = report.str();
  return r;
}

}  // namespace

std::ostream& operator<<(std::ostream& out, const check_result& r) {
  if (!r) return out << r.report;
  return out << r.routine << ": " << r.cases << " cases pass";
}

check_result check(operation op, const float_routine& routine, const check_settings& settings) {
  const std::size_t in = signature(op).input_count, n = signature(op).output_count;
  return run_check(op, scalar_type::f32, [&](const double* inputs, double* outputs) {
    std::vector<float> x(inputs, inputs + in);  // exact: every input is a float
    std::vector<float> y(n, std::numeric_limits<float>::quiet_NaN());
    routine(x.data(), y.data());
    for (std::size_t i = 0; i < n; ++i) outputs[i] = y[i];
  }, settings);
}

check_result check(operation op, const double_routine& routine, const check_settings& settings) {
  return run_check(op, scalar_type::f64, routine, settings);
}

}  // namespace shadowproof
