// Differential fuzzing against the exact oracle, shrinking, and metamorphic relations.
#include "shadowproof/fuzz/differential.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <tuple>

#include "shadowproof/core/error.h"
#include "shadowproof/core/number.h"
#include "shadowproof/fuzz/shrink.h"
#include "shadowproof/verify/parallel.h"
#include "shadowproof/core/ulp.h"

namespace shadowproof {
namespace {

bool is_supported(operation op) {
  const double zeros[4] = {0, 0, 0, 0};
  return inputs_from_shadow_configuration(op, zeros, zeros, zeros).has_value();
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

std::string base_family(const std::string& family) { return family.substr(0, family.find_first_of("+*")); }

input_class class_of_family(const std::string& family, const std::string& base) {
  if (family.find("+ulp") != std::string::npos || family.find("+2^-") != std::string::npos)
    return input_class::near_degenerate;
  return (base == "regular" || base == "directional_regular" || base == "axis_aligned") ? input_class::regular
                                                                                      : input_class::degenerate;
}

std::vector<double> run(const implementation& impl, const test_case& c) {
  std::vector<double> out(signature(c.op).output_count);
  impl.run(c.inputs.data(), out.data());
  return out;
}

// The failure kinds a grade shows, most severe first. A NaN or ±Inf counts when its verdict says
// so (docs/verdicts.md): not when the whole case is correctly rejected, not next to a divisor
// within c·u of vanishing (stable), not when an intermediate leaves the type's range (range).
// Likewise an output `threshold` ulps or more off counts only when its verdict blames the
// formula (unstable, wrong): an ill-conditioned input answered stably loses those ulps to the
// problem itself, and a range excursion to the format.
std::vector<failure_kind> kinds_of(const case_grade& g, std::uint64_t threshold) {
  std::vector<failure_kind> k;
  bool nonfinite = false;
  bool ulps = false;
  for (const auto& o : g.outputs) {
    nonfinite = nonfinite || o.v == verdict::nonfinite;
    ulps = ulps || (o.counted() && o.ulps >= threshold && (o.v == verdict::unstable || o.v == verdict::wrong));
  }
  if (nonfinite) k.push_back(failure_kind::nonfinite);
  if (g.garbage > 0) k.push_back(failure_kind::garbage);
  if (g.misclassified) k.push_back(failure_kind::misclassified);
  if (ulps) k.push_back(failure_kind::ulps);
  return k;
}

// A verdict that puts the error on the formula, not on the problem's conditioning (stable) nor on
// the format's range (range): some output unstable, wrong, non-finite or garbage.
bool blames_formula(const case_grade& g) {
  return std::any_of(g.outputs.begin(), g.outputs.end(), [](const output_grade& o) {
    return o.v == verdict::unstable || o.v == verdict::wrong || o.v == verdict::nonfinite || o.v == verdict::garbage;
  });
}

// "Fails the same way": the same kind and, for a misclassification, the same pair of classes.
bool same_failure(const case_grade& a, const case_grade& b, failure_kind kind, std::uint64_t threshold) {
  const auto kinds = kinds_of(b, threshold);
  if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) return false;
  if (kind == failure_kind::misclassified) return a.exact_class == b.exact_class && a.got_class == b.got_class;
  return true;
}

// A plane needs a non-zero normal and a light a non-zero entry; the implementation's declared
// requirements (unit normal, w fixed) are kept by pinning those inputs while shrinking.
bool valid_inputs(const test_case& c) {
  if (!invalid_inputs_reason(c).empty()) return false;
  return std::all_of(c.inputs.begin(), c.inputs.end(), [&](double v) { return representable(v, c.type); });
}

std::vector<bool> pinned_inputs(const implementation& impl) {
  std::vector<bool> keep(signature(impl.op).input_count, false);
  const auto plane = group_offset(impl.op, "plane");
  const auto light = group_offset(impl.op, "light");
  if (plane && impl.conv.unit_normal) keep[*plane] = keep[*plane + 1] = keep[*plane + 2] = true;
  if (light && (impl.conv.directional_only || impl.conv.point_light_only)) keep[*light + 3] = true;
  return keep;
}

// ---- metamorphic relations ---------------------------------------------------------------

struct transformed {
  test_case input;
  // Maps the original outputs to the expected outputs of the transformed input, exactly;
  // nothing when the expectation is not representable.
  std::function<std::optional<std::vector<double>>(const std::vector<double>&)> expect;
};

std::optional<double> exact_sum(double a, double b, scalar_type type) {
  const rational s = exact_value(a) + exact_value(b);
  const double d = type == scalar_type::f32 ? static_cast<double>(to_nearest_float(s)) : to_nearest_double(s);
  if (!std::isfinite(d) || exact_value(d) != s) return std::nullopt;
  return d;
}

std::optional<double> round_to_type(const rational& q, scalar_type type) {
  const double d = type == scalar_type::f32 ? static_cast<double>(to_nearest_float(q)) : to_nearest_double(q);
  if (!std::isfinite(d)) return std::nullopt;
  return d;
}

std::optional<transformed> transform(const implementation& impl, const test_case& c, const std::string& relation) {
  const bool matrix = signature(c.op).matrix_size == 4;
  const bool up_to_scale = impl.conv.homogeneous || impl.conv.normalises_plane;
  const operation_symmetries& sym = symmetries(c.op);
  const auto plane = group_offset(c.op, "plane");
  const auto light = group_offset(c.op, "light");
  const auto point = group_offset(c.op, "point");
  transformed t{c, {}};
  auto& in = t.input.inputs;
  auto scaled_outputs = [matrix](int degree) {
    const double factor = std::ldexp(1.0, degree);
    return [matrix, factor](const std::vector<double>& out) -> std::optional<std::vector<double>> {
      if (!matrix) return out;
      std::vector<double> e(out);
      for (double& x : e) x *= factor;  // exact unless it overflows, which the caller sees as inf
      return e;
    };
  };
  if (relation == "scale_plane") {
    if (!plane || sym.plane_degree < 0) return std::nullopt;
    if (matrix && up_to_scale) return std::nullopt;
    if (impl.conv.unit_normal) return std::nullopt;
    for (std::size_t i = 0; i < 4; ++i) in[*plane + i] *= 2;
    t.expect = scaled_outputs(sym.plane_degree);
  } else if (relation == "scale_light") {
    if (!light || sym.light_degree < 0 || impl.conv.point_light_only) return std::nullopt;
    if (matrix && up_to_scale) return std::nullopt;
    for (std::size_t i = 0; i < 4; ++i) in[*light + i] *= 2;
    t.expect = scaled_outputs(sym.light_degree);
  } else if (relation == "swap_xy") {
    if (!sym.swap_xy) return std::nullopt;
    for (const auto& at : {plane, light, point})
      if (at) std::swap(in[*at], in[*at + 1]);
    t.expect = [matrix](const std::vector<double>& out) -> std::optional<std::vector<double>> {
      std::vector<double> e(out);
      if (!matrix) {
        std::swap(e[0], e[1]);
        return e;
      }
      // Conjugating by the x/y swap exchanges rows 0,1 and columns 0,1: the same index map in
      // row-major and column-major storage, and for row or column vectors.
      auto perm = [](std::size_t i) { return i == 0 ? 1 : (i == 1 ? 0 : i); };
      for (std::size_t r = 0; r < 4; ++r)
        for (std::size_t k = 0; k < 4; ++k) e[r * 4 + k] = out[perm(r) * 4 + perm(k)];
      return e;
    };
  } else if (relation == "translate") {
    if (!sym.translation || !plane || !light || !point) return std::nullopt;
    const double shift[3] = {1, -2, 3};
    // Plane: d' = d − n·t; light: position + w t; point: + t. All must stay exact.
    rational d = exact_value(in[*plane + 3]);
    for (std::size_t i = 0; i < 3; ++i) d -= exact_value(in[*plane + i]) * rational(shift[i]);
    const auto new_d = round_to_type(d, c.type);
    if (!new_d || exact_value(*new_d) != d) return std::nullopt;
    in[*plane + 3] = *new_d;
    for (std::size_t i = 0; i < 3; ++i) {
      const auto l = exact_sum(in[*light + i], in[*light + 3] * shift[i], c.type);
      const auto p = exact_sum(in[*point + i], shift[i], c.type);
      if (!l || !p) return std::nullopt;
      in[*light + i] = *l;
      in[*point + i] = *p;
    }
    const scalar_type type = c.type;
    t.expect = [shift, type](const std::vector<double>& out) -> std::optional<std::vector<double>> {
      std::vector<double> e(out);
      for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(out[i])) return std::nullopt;
        const auto r = round_to_type(exact_value(out[i]) + rational(shift[i]), type);
        if (!r) return std::nullopt;
        e[i] = *r;
      }
      return e;
    };
  } else {
    return std::nullopt;
  }
  if (!valid_inputs(t.input)) return std::nullopt;
  return t;
}

template <class T>
std::uint64_t disagreement(const std::vector<double>& expected, const std::vector<double>& got) {
  std::uint64_t worst = 0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    const bool fe = std::isfinite(expected[i]), fg = std::isfinite(got[i]);
    if (fe != fg) return std::numeric_limits<std::uint64_t>::max();
    if (!fe) {
      if (std::isnan(expected[i]) != std::isnan(got[i]) || (!std::isnan(got[i]) && expected[i] != got[i]))
        return std::numeric_limits<std::uint64_t>::max();
      continue;
    }
    worst = std::max(worst, ulp_distance(static_cast<T>(expected[i]), static_cast<T>(got[i])));
  }
  return worst;
}

// Misclassifications are told apart by the pair of classes (a shadow taken for an anti-shadow
// is a different bug from a shadow taken for a point on the receiver).
std::string key_of(failure_kind kind, const std::string& family, const std::string& relation, const case_grade& g) {
  if (kind == failure_kind::metamorphic) return "metamorphic/" + family + "/" + relation;
  if (kind == failure_kind::misclassified && g.exact_class && g.got_class)
    return "misclassified/" + std::string(to_string(*g.exact_class)) + "->" + std::string(to_string(*g.got_class));
  return std::string(to_string(kind)) + "/" + family;
}

}  // namespace

std::string failure_key(const fuzz_failure& f) {
  return key_of(f.kind, base_family(f.family), f.relation, f.original_grade);
}

fuzz_report merge_fuzz_reports(const std::vector<fuzz_report>& shards, operation op) {
  fuzz_report merged;
  std::map<std::string, const fuzz_failure*> first;  // by key, the failure of the lowest case id
  for (const auto& r : shards) {
    merged.impl = r.impl;
    merged.cases += r.cases;
    for (const auto& [kind, n] : r.failing_cases) merged.failing_cases[kind] += n;
    for (const auto& [relation, ulps] : r.metamorphic_max_ulps)
      merged.metamorphic_max_ulps[relation] = std::max(merged.metamorphic_max_ulps[relation], ulps);
    for (const auto& f : r.failures) {
      const auto [it, fresh] = first.emplace(failure_key(f), &f);
      if (!fresh && f.original.id < it->second->original.id) it->second = &f;
    }
  }
  // The unsharded run records a case's failures by kind (enum order), then its metamorphic ones
  // in the order of the relations.
  const auto relations = metamorphic_relations(op);
  const auto rank = [&](const fuzz_failure& f) {
    const auto r = std::find(relations.begin(), relations.end(), f.relation);
    return std::make_tuple(f.original.id, static_cast<int>(f.kind), r - relations.begin());
  };
  for (const auto& [key, f] : first) merged.failures.push_back(*f);
  std::sort(merged.failures.begin(), merged.failures.end(),
            [&](const fuzz_failure& a, const fuzz_failure& b) { return rank(a) < rank(b); });
  return merged;
}

std::string_view to_string(failure_kind k) {
  switch (k) {
    case failure_kind::nonfinite: return "nonfinite";
    case failure_kind::garbage: return "garbage";
    case failure_kind::misclassified: return "misclassified";
    case failure_kind::ulps: return "ulps";
    case failure_kind::metamorphic: return "metamorphic";
  }
  return "unknown";
}

std::vector<std::string> metamorphic_relations(operation op) {
  const operation_symmetries& sym = symmetries(op);
  std::vector<std::string> names;
  if (sym.plane_degree >= 0) names.push_back("scale_plane");
  if (sym.light_degree >= 0) names.push_back("scale_light");
  if (sym.swap_xy) names.push_back("swap_xy");
  if (sym.translation) names.push_back("translate");
  return names;
}

std::optional<std::uint64_t> metamorphic_violation(const implementation& impl, const test_case& c,
                                                   const std::string& relation, std::uint64_t threshold,
                                                   const case_grade* original_grade) {
  const auto t = transform(impl, c, relation);
  if (!t) return std::nullopt;
  const auto original = run(impl, c);
  const auto expected = t->expect(original);
  if (!expected) return std::nullopt;
  const auto got = run(impl, t->input);
  const std::uint64_t d = c.type == scalar_type::f32 ? disagreement<float>(*expected, got)
                                                     : disagreement<double>(*expected, got);
  if (d < threshold) return std::nullopt;
  // Two answers each acceptable for its own input (exact, faithful, stable, range) may disagree
  // by as much as the problem's conditioning allows: the translated input is another float
  // problem, and even a correctly rounded image, shifted and rounded again, loses what the shift
  // cancels. The relation fails only when the oracle blames the formula on one of the two.
  const bool original_blamed =
      blames_formula(original_grade ? *original_grade : grade_case(c, impl.conv, original.data()));
  if (!original_blamed && !blames_formula(grade_case(t->input, impl.conv, got.data())))
    return std::nullopt;
  return d;
}

test_case make_fuzz_case(const generated_case<double>& g, const implementation& impl, std::uint64_t id) {
  auto inputs = inputs_from_shadow_configuration(impl.op, g.plane.data(), g.light.data(), g.point.data());
  if (!inputs) {
    std::string fuzzed;
    for (operation op : all_operations())
      if (is_supported(op)) fuzzed += (fuzzed.empty() ? "" : ", ") + std::string(to_string(op));
    throw error(errc::fuzz_unsupported_operation, "fuzzing supports " + fuzzed + ", not " +
                                                  std::string(to_string(impl.op)) + " (" + impl.name + ")");
  }
  test_case c;
  c.id = id;
  c.op = impl.op;
  c.type = impl.type;
  c.cls = class_of_family(g.family, base_family(g.family));
  c.inputs = std::move(*inputs);
  return c;
}

fuzz_report run_fuzz(const implementation& impl, const fuzz_settings& settings,
                     const std::function<void(std::size_t, std::size_t)>& progress) {
  fuzz_report report;
  report.impl = impl.name;
  prng_source src(settings.seed);
  const generator_requirements req{impl.conv.unit_normal, impl.conv.directional_only, impl.conv.point_light_only};
  const auto relations = settings.metamorphic ? metamorphic_relations(impl.op) : std::vector<std::string>{};
  const std::size_t case_limit = settings.cases.value_or(settings.seconds ? std::numeric_limits<std::size_t>::max() : 10000);
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  double last_progress = 0;
  std::set<std::string> seen;  // (kind, family, relation) already recorded
  const auto keep = pinned_inputs(impl);
  const bool single = impl.type == scalar_type::f32;

  auto generate = [&]() {
    if (single) {
      const auto f = generate_shadow_case<float>(src, req);
      generated_case<double> d;
      std::copy(f.plane.begin(), f.plane.end(), d.plane.begin());
      std::copy(f.light.begin(), f.light.end(), d.light.begin());
      std::copy(f.point.begin(), f.point.end(), d.point.begin());
      d.family = f.family;
      return d;
    }
    return generate_shadow_case<double>(src, req);
  };

  // Counts one case's failures and records (shrunk) the first of each kind and family.
  auto record_case = [&](const generated_case<double>& g, const test_case& c, const case_grade& grade,
                         const std::vector<std::optional<std::uint64_t>>& violation) {
    ++report.cases;
    if (settings.on_case) settings.on_case(c, grade);
    const std::string family = base_family(g.family);

    // Shrinks the case while `fails_on` holds for the simpler inputs and records the failure.
    auto record = [&](failure_kind kind, const std::string& relation, double bits,
                      const std::function<bool(const test_case&)>& fails_on) {
      auto still_fails = [&](const std::vector<double>& inputs) {
        test_case t = c;
        t.inputs = inputs;
        if (!valid_inputs(t)) return false;
        try {
          return fails_on(t);
        } catch (const error&) {
          return false;
        }
      };
      const auto s = shrink_inputs(c.inputs, single, still_fails, keep, settings.shrink_budget);
      fuzz_failure f;
      f.kind = kind;
      f.family = g.family;
      f.relation = relation;
      f.original = c;
      f.shrunk = c;
      f.shrunk.inputs = s.inputs;
      f.original_grade = grade;
      const auto shrunk_out = run(impl, f.shrunk);
      f.shrunk_grade = grade_case(f.shrunk, impl.conv, shrunk_out.data());
      f.bits = bits;
      f.bits_before = s.bits_before;
      f.bits_after = s.bits_after;
      f.threshold = settings.ulps_threshold;
      report.failures.push_back(std::move(f));
    };

    for (failure_kind kind : kinds_of(grade, settings.ulps_threshold)) {
      ++report.failing_cases[std::string(to_string(kind))];
      if (!seen.insert(key_of(kind, family, "", grade)).second) continue;
      record(kind, "", grade.max_bits, [&](const test_case& t) {
        const auto o = run(impl, t);
        return same_failure(grade, grade_case(t, impl.conv, o.data()), kind, settings.ulps_threshold);
      });
    }

    for (std::size_t r = 0; r < relations.size(); ++r) {
      const std::string& relation = relations[r];
      const auto& v = violation[r];
      if (!v) continue;
      report.metamorphic_max_ulps[relation] = std::max(report.metamorphic_max_ulps[relation], *v);
      ++report.failing_cases["metamorphic"];
      if (!seen.insert(key_of(failure_kind::metamorphic, family, relation, grade)).second) continue;
      record(failure_kind::metamorphic, relation,
             bits_of_error(*v == std::numeric_limits<std::uint64_t>::max() ? *v - 1 : *v), [&](const test_case& t) {
               return metamorphic_violation(impl, t, relation, settings.ulps_threshold).has_value();
             });
    }
  };

  // Cases go in chunks: generated in order from the one random stream, run and graded (with
  // every metamorphic relation) on settings.jobs threads, then read in order, so the counts,
  // the failures kept and their shrinking are those of a loop over the cases one by one.
  const std::size_t chunk = 1024;
  std::vector<generated_case<double>> generated;
  std::vector<test_case> cases;
  std::vector<case_grade> grades;
  std::vector<std::vector<std::optional<std::uint64_t>>> violations;  // per case, per relation
  for (std::size_t first = 0; first < case_limit;) {
    if (settings.seconds && elapsed() >= *settings.seconds) break;
    if (progress && elapsed() - last_progress >= 1.0) {
      last_progress = elapsed();
      progress(first, report.failures.size());
    }
    const std::size_t count = std::min(chunk, case_limit - first);
    generated.clear();
    cases.clear();
    for (std::size_t k = 0; k < count; ++k) {
      const auto g = generate();  // drawn in every shard, so case n is the same whatever the shard count
      if (!settings.part.contains(first + k)) continue;
      generated.push_back(g);
      cases.push_back(make_fuzz_case(g, impl, first + k));
    }
    const std::size_t mine = cases.size();
    grades.assign(mine, case_grade{});
    violations.assign(mine, {});
    for_each_slice(mine, settings.jobs, 64, [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k) {
        const auto out = run(impl, cases[k]);
        grades[k] = grade_case(cases[k], impl.conv, out.data());
        for (const auto& relation : relations)
          violations[k].push_back(metamorphic_violation(impl, cases[k], relation, settings.ulps_threshold, &grades[k]));
      }
    });
    for (std::size_t k = 0; k < mine; ++k) record_case(generated[k], cases[k], grades[k], violations[k]);
    first += count;
  }
  if (progress) progress(report.cases, report.failures.size());
  return report;
}

std::string catch2_regression_test(const implementation& impl, const fuzz_failure& f) {
  std::ostringstream s;
  const auto& c = f.shrunk;
  s << "// " << impl.name << ": " << to_string(f.kind) << (f.relation.empty() ? "" : " (" + f.relation + ")")
    << " on a " << base_family(f.family) << " case, shrunk from " << f.bits_before << " to " << f.bits_after
    << " bits.\n";
  s << "TEST_CASE(\"fuzz regression: " << impl.name << " " << to_string(f.kind)
    << (f.relation.empty() ? "" : " " + f.relation) << " on " << base_family(f.family) << "\", \"[fuzz][regression]\") {\n";
  s << "  const auto& impl = shadowproof::find_builtin_implementation(\"" << impl.name << "\");\n"
    << "  const shadowproof::test_case c{0, impl.op, impl.type, shadowproof::input_class::regular, {";
  for (std::size_t i = 0; i < c.inputs.size(); ++i) s << (i ? ", " : "") << hex_string(c.inputs[i]);
  s << "}};\n";
  if (f.kind == failure_kind::metamorphic) {
    s << "  CHECK(shadowproof::metamorphic_violation(impl, c, \"" << f.relation << "\", " << f.threshold << "u).has_value());\n";
  } else {
    s << "  const auto g = shadowproof::run_and_grade(impl, {c}).front();\n";
    switch (f.kind) {
      case failure_kind::nonfinite: s << "  CHECK(g.nonfinite > 0);\n"; break;
      case failure_kind::garbage: s << "  CHECK(g.garbage > 0);\n"; break;
      case failure_kind::misclassified:
        s << "  CHECK(g.misclassified);\n";
        if (f.shrunk_grade.exact_class && f.shrunk_grade.got_class)
          s << "  CHECK(shadowproof::to_string(*g.exact_class) == \"" << to_string(*f.shrunk_grade.exact_class) << "\");\n"
            << "  CHECK(shadowproof::to_string(*g.got_class) == \"" << to_string(*f.shrunk_grade.got_class) << "\");\n";
        break;
      default:
        // Off by the threshold, and by the formula's fault: not the problem's conditioning
        // (stable), not the format's range.
        s << "  CHECK(g.max_ulps >= " << f.threshold << "u);\n"
          << "  CHECK(g.v >= shadowproof::verdict::unstable);\n"
          << "  CHECK(g.v != shadowproof::verdict::range);\n";
        break;
    }
  }
  s << "}\n";
  return s.str();
}

}  // namespace shadowproof
