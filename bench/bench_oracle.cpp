// Cases graded per second: the interval-filtered oracle, the all-rational oracle, and the
// float implementation's own evaluation, on the same cases in the same run.
//   bench/bench_oracle --benchmark_counters_tabular=true
// items_per_second is cases per second; compare rows with the same <impl>/<class>.
//   bench/bench_oracle --agree=1000000 [--impl=NAME]
// instead grades that many regular and that many near-degenerate cases per implementation with
// both oracles and reports any difference (exit 1), the check the unit test runs on a sample.
//   bench/bench_oracle --ratio=ROUNDS [--impl=NAME]
// prints the README's table: cases per second of the float code, the filtered oracle without and
// with verdicts (what the verdicts cost) and the naive oracle, alternating them ROUNDS times on
// the same cases and keeping each one's best round.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/implementation.h"
#include "shadowproof/impls/builtin.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/protocol.h"

namespace {

using namespace shadowproof;

struct fixture {
  const implementation* impl = nullptr;
  std::vector<test_case> cases;
  std::vector<std::vector<double>> outputs;
};

const fixture& make_fixture(const std::string& name, std::optional<input_class> cls) {
  static std::vector<std::unique_ptr<fixture>> cache;
  static std::vector<std::string> keys;
  const std::string key = name + "/" + (cls ? std::string(to_string(*cls)) : "mixed");
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (keys[i] == key) return *cache[i];
  auto f = std::make_unique<fixture>();
  for (const auto& impl : builtin_implementations())
    if (impl.name == name) f->impl = &impl;
  if (!f->impl) throw std::runtime_error("no implementation " + name);
  f->cases = generate_cases(f->impl->op, f->impl->type, 2000, 99, cls, f->impl->conv);
  for (const auto& c : f->cases) {
    std::vector<double> out(signature(c.op).output_count);
    f->impl->run(c.inputs.data(), out.data());
    f->outputs.push_back(std::move(out));
  }
  keys.push_back(key);
  cache.push_back(std::move(f));
  return *cache.back();
}

void float_evaluation(benchmark::State& state, const std::string& name, std::optional<input_class> cls) {
  const fixture& f = make_fixture(name, cls);
  std::vector<double> out(signature(f.impl->op).output_count);
  for (auto _ : state) {
    for (const auto& c : f.cases) {
      f.impl->run(c.inputs.data(), out.data());
      benchmark::DoNotOptimize(out.data());
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * f.cases.size()));
}

void oracle(benchmark::State& state, const std::string& name, std::optional<input_class> cls, oracle_mode mode) {
  const fixture& f = make_fixture(name, cls);
  oracle_counters counters;
  for (auto _ : state) {
    for (std::size_t i = 0; i < f.cases.size(); ++i) {
      case_grade g = grade_case(f.cases[i], f.impl->conv, f.outputs[i].data(), mode, &counters);
      benchmark::DoNotOptimize(g.max_ulps);
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * f.cases.size()));
  if (mode == oracle_mode::filtered) {
    const double total = static_cast<double>(counters.decided_by_intervals + counters.fell_back_to_rationals);
    state.counters["decided_by_intervals"] = static_cast<double>(counters.decided_by_intervals) / total;
  }
}

void register_all() {
  const std::vector<std::string> names{"seed000-general-f32", "seed000-general-f64", "eigen-intersection-f32",
                                       "eigen-intersection-f64", "reflect-divide-f32", "glm-frustum-f32",
                                       "glm-inverse-transpose-f64"};
  const std::vector<std::optional<input_class>> classes{input_class::regular, input_class::near_degenerate,
                                                        std::nullopt};
  for (const auto& name : names) {
    bool present = false;
    for (const auto& impl : builtin_implementations()) present = present || impl.name == name;
    if (!present) continue;  // engine not installed
    for (const auto& cls : classes) {
      const std::string suffix = name + "/" + (cls ? std::string(to_string(*cls)) : "mixed");
      benchmark::RegisterBenchmark(("float_impl/" + suffix).c_str(), float_evaluation, name, cls)
          ->Unit(benchmark::kMicrosecond);
      benchmark::RegisterBenchmark(("filtered_oracle/" + suffix).c_str(), oracle, name, cls, oracle_mode::filtered)
          ->Unit(benchmark::kMicrosecond);
      benchmark::RegisterBenchmark(("naive_oracle/" + suffix).c_str(), oracle, name, cls, oracle_mode::naive)
          ->Unit(benchmark::kMicrosecond);
    }
  }
}

}  // namespace

bool same_grade(const case_grade& a, const case_grade& b) {
  if (a.outputs.size() != b.outputs.size()) return false;
  for (std::size_t i = 0; i < a.outputs.size(); ++i) {
    const auto &x = a.outputs[i], &y = b.outputs[i];
    if (x.exact_defined != y.exact_defined || std::memcmp(&x.reference, &y.reference, sizeof(double)) != 0 ||
        x.ulps != y.ulps || x.nonfinite != y.nonfinite || x.garbage != y.garbage)
      return false;
  }
  for (std::size_t i = 0; i < a.outputs.size(); ++i)
    if (a.outputs[i].v != b.outputs[i].v) return false;
  return a.max_ulps == b.max_ulps && a.exact_class == b.exact_class && a.got_class == b.got_class &&
         a.misclassified == b.misclassified && a.plane_value == b.plane_value && a.scale_pivot == b.scale_pivot &&
         a.v == b.v && a.scale == b.scale;
}

int agree(std::size_t count, const std::string& only) {
  int failures = 0;
  for (const auto& impl : builtin_implementations()) {
    if (!only.empty() && impl.name != only) continue;
    for (input_class cls : {input_class::regular, input_class::near_degenerate}) {
      oracle_counters counters;
      std::size_t differ = 0;
      std::vector<double> out(signature(impl.op).output_count);
      const std::size_t batch = 10000;
      for (std::size_t first = 0; first < count; first += batch) {
        const auto cases = generate_cases(impl.op, impl.type, std::min(batch, count - first), 1000 + first, cls,
                                          impl.conv, first);
        for (const auto& c : cases) {
          impl.run(c.inputs.data(), out.data());
          if (!same_grade(grade_case(c, impl.conv, out.data(), oracle_mode::filtered, &counters),
                          grade_case(c, impl.conv, out.data(), oracle_mode::naive))) {
            if (differ++ < 3) std::printf("  DIFFER: %s\n", case_json_line(c).c_str());
          }
        }
      }
      std::printf("%-32s %-16s %zu cases: %zu differ, %.1f%% decided by intervals\n", impl.name.c_str(),
                  std::string(to_string(cls)).c_str(), count, differ,
                  100.0 * static_cast<double>(counters.decided_by_intervals) / static_cast<double>(count));
      std::fflush(stdout);
      failures += differ ? 1 : 0;
    }
  }
  return failures ? 1 : 0;
}

// Seconds of this thread's processor time.
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Rounds alternate the float code, the filtered oracle with and without verdicts and the naive
// oracle on the same 2000 cases, so that a change of load on a shared machine hits all of them
// alike; each one's best round (least thread time per case) is kept.
int ratio(std::size_t rounds, const std::string& only) {
  const std::vector<std::string> names{"seed000-general-f32", "eigen-intersection-f32", "reflect-divide-f32",
                                       "seed000-general-f64", "eigen-intersection-f64", "reflect-divide-f64",
                                       "glm-frustum-f32",     "glm-inverse-transpose-f64"};
  std::printf("| implementation / class | float code itself | filtered oracle, values only | filtered oracle "
              "with verdicts | verdicts cost | all-rational oracle | filtered ÷ rational | cases > 1 ulp |\n"
              "| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (const auto& name : names) {
    if (!only.empty() && name != only) continue;
    bool present = false;
    for (const auto& impl : builtin_implementations()) present = present || impl.name == name;
    if (!present) continue;
    for (input_class cls : {input_class::regular, input_class::near_degenerate}) {
      const fixture& f = make_fixture(name, cls);
      std::vector<double> out(signature(f.impl->op).output_count);
      const double n = static_cast<double>(f.cases.size());
      double best_float = 1e300, best_values = 1e300, best_verdicts = 1e300, best_naive = 1e300;
      std::uint64_t sink = 0;
      std::size_t beyond_ulp = 0;
      for (std::size_t i = 0; i < f.cases.size(); ++i)
        beyond_ulp += grade_case(f.cases[i], f.impl->conv, f.outputs[i].data()).v > verdict::faithful;
      for (std::size_t r = 0; r < rounds; ++r) {
        double t0 = thread_seconds();
        for (int k = 0; k < 100; ++k)
          for (const auto& c : f.cases) {
            f.impl->run(c.inputs.data(), out.data());
            benchmark::DoNotOptimize(out.data());
          }
        best_float = std::min(best_float, (thread_seconds() - t0) / (100 * n));
        for (grade_depth depth : {grade_depth::values_only, grade_depth::verdicts}) {
          t0 = thread_seconds();
          for (int k = 0; k < 5; ++k)
            for (std::size_t i = 0; i < f.cases.size(); ++i)
              sink += grade_case(f.cases[i], f.impl->conv, f.outputs[i].data(), oracle_mode::filtered, nullptr, depth)
                          .max_ulps;
          double& best = depth == grade_depth::values_only ? best_values : best_verdicts;
          best = std::min(best, (thread_seconds() - t0) / (5 * n));
        }
        t0 = thread_seconds();
        for (std::size_t i = 0; i < f.cases.size(); ++i)
          sink += grade_case(f.cases[i], f.impl->conv, f.outputs[i].data(), oracle_mode::naive).max_ulps;
        best_naive = std::min(best_naive, (thread_seconds() - t0) / n);
      }
      benchmark::DoNotOptimize(sink);
      auto rate = [](double seconds) {
        char text[32];
        const double per_second = 1 / seconds;
        if (per_second >= 1e6) std::snprintf(text, sizeof text, "%.3g M/s", per_second / 1e6);
        else std::snprintf(text, sizeof text, "%.3g k/s", per_second / 1e3);
        return std::string(text);
      };
      std::printf("| %s / %s | %s | %s | %s | %.2f× | %s | %.1f× | %.0f%% |\n", name.c_str(),
                  std::string(to_string(cls)).c_str(), rate(best_float).c_str(), rate(best_values).c_str(),
                  rate(best_verdicts).c_str(), best_verdicts / best_values, rate(best_naive).c_str(),
                  best_naive / best_verdicts, 100.0 * static_cast<double>(beyond_ulp) / n);
      std::fflush(stdout);
    }
  }
  return 0;
}

int main(int argc, char** argv) {
  std::size_t agree_count = 0, ratio_rounds = 0;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--agree=", 8) == 0) agree_count = std::stoul(argv[i] + 8);
    if (std::strncmp(argv[i], "--ratio=", 8) == 0) ratio_rounds = std::stoul(argv[i] + 8);
    if (std::strncmp(argv[i], "--impl=", 7) == 0) only = argv[i] + 7;
  }
  if (agree_count) return agree(agree_count, only);
  if (ratio_rounds) return ratio(ratio_rounds, only);
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
