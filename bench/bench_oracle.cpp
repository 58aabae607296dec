// Cases graded per second, for every operation and type, all in the same run on the same cases:
// the float code itself, the filtered oracle one case at a time (grade_case), the filtered
// oracle over a batch (compute_references + grade_batch, generic and AVX2 filters), and the
// all-rational oracle; their ratios, and how many cases the filtered oracle left to rationals.
//
//   bench/bench_oracle [--table=ROUNDS] [--op=NAME,...]   the table (the default, 3 rounds),
//                                         of every operation or of those named
//   bench/bench_oracle --threads=ROUNDS   the batch grader and run_and_grade_in_parallel on 1
//                                         and 2 threads, wall-clock
//   bench/bench_oracle --verdicts=ROUNDS  grade_case with verdicts vs values only: what the
//                                         verdicts cost, per operation, type and class
//   bench/bench_oracle --agree=N [--impl=NAME]
//       grades N regular and N near-degenerate cases per implementation with both oracles and
//       reports any difference (exit 1), the check the unit tests run on a sample.
//   bench/bench_oracle --split=ROUNDS [--op=NAME,...]
//       the batch oracle (AVX2 where available) alone, regular cases, compute_references and
//       grade_batch timed apart: a loop to run under a profiler, and where a batch's time goes
//   bench/bench_oracle --gbench [Google Benchmark flags]   the same measurements per benchmark
//
// Method. Cases and the float code's outputs are generated before any clock starts. Each round
// times every variant in turn on the same cases (so a change of load on a shared machine hits
// them alike) and each variant keeps its best round, in thread CPU time; every result feeds a
// checksum that is printed, so nothing can be optimised away. The load average is printed
// before and after: on a machine shared with other work, compare ratios, not rates.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "shadowproof/constructions/handedness.h"
#include "shadowproof/constructions/look_at.h"
#include "shadowproof/constructions/project.h"
#include "shadowproof/impls/builtin.h"
#include "shadowproof/verify/batch.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/implementation.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/parallel.h"
#include "shadowproof/verify/protocol.h"
#include "shadowproof/verify/report.h"

namespace {

using namespace shadowproof;

// ---------------------------------------------------------------------------------------------
// The implementation timed for each operation and type: a built-in one graded at the canonical
// scale, or the library's own formula in that type where no built-in one exists.

template <class T>
void library_ortho(const double* in, double* out) {
  const auto M = orthographic<T>(static_cast<T>(in[0]), static_cast<T>(in[1]), static_cast<T>(in[2]),
                                 static_cast<T>(in[3]), static_cast<T>(in[4]), static_cast<T>(in[5]),
                                 depth_convention::gl);
  for (std::size_t i = 0; i < 16; ++i) out[i] = M(i / 4, i % 4);
}

// The camera builders registered in f32 only, written here in double as the textbook f32 ones
// are (src/impls/reference_camera.cpp): c = 1/tan(fovy/2); the placement is the look-at
// rotation transposed with the eye; the width/height builders are the box ones at ±w/2, ±h/2
// (halving is exact).
void library_perspective_fov_infinite_f64(const double* in, double* out) {
  const double c = 1 / std::tan(in[0] / 2), n = in[2];
  for (std::size_t i = 0; i < 16; ++i) out[i] = 0;
  out[0] = c / in[1];
  out[5] = c;
  out[10] = -1;
  out[11] = -2 * n;
  out[14] = -1;
}

void library_target_to_f64(const double* in, double* out) {
  const vec3<double> eye{in[0], in[1], in[2]}, target{in[3], in[4], in[5]}, up{in[6], in[7], in[8]};
  const mat4<double> v = look_at_float(eye, target, up, handedness::right);
  for (std::size_t r = 0; r < 4; ++r)
    for (std::size_t c = 0; c < 4; ++c) out[4 * r + c] = r < 3 && c < 3 ? v(c, r) : 0.0;
  for (std::size_t r = 0; r < 3; ++r) out[4 * r + 3] = eye[r];
  out[15] = 1;
}

template <bool perspective>
void library_view_size_f64(const double* in, double* out) {
  const double w = in[0] / 2, h = in[1] / 2;
  const mat4<double> M = perspective ? frustum<double>(-w, w, -h, h, in[2], in[3], depth_convention::gl)
                                     : orthographic<double>(-w, w, -h, h, in[2], in[3], depth_convention::gl);
  for (std::size_t i = 0; i < 16; ++i) out[i] = M(i / 4, i % 4);
}

implementation representative(operation op, scalar_type type) {
  static const std::pair<operation, const char*> preferred[] = {
      {operation::shadow_matrix, "seed000-general"},      {operation::shadow_point, "eigen-intersection"},
      {operation::reflection_matrix, "reflect-divide"},   {operation::ortho, "ortho-closed-form"},
      {operation::frustum, "frustum-closed-form"},        {operation::normal_matrix, "normal-inverse-transpose"},
      {operation::perspective, "perspective-closed-form"}};
  std::string stem = "textbook-" + std::string(to_string(op));  // the camera operations
  for (const auto& [o, name] : preferred)
    if (o == op) stem = name;
  const std::string name = stem + "-" + std::string(to_string(type));
  for (const implementation& impl : builtin_implementations())
    if (impl.name == name) return impl;
  if (type == scalar_type::f64) {
    const conventions c;
    switch (op) {
      case operation::ortho:
        return {"library-ortho-f64", op, type, c, "orthographic<double> (project.h)", library_ortho<double>};
      case operation::perspective_fov_infinite:
        return {"library-perspective-fov-infinite-f64", op, type, c, "c = 1/tan(fovy/2), double",
                library_perspective_fov_infinite_f64};
      case operation::target_to:
        return {"library-target-to-f64", op, type, c, "look_at_float<double> transposed", library_target_to_f64};
      case operation::ortho_size:
        return {"library-ortho-size-f64", op, type, c, "orthographic<double> at ±w/2, ±h/2",
                library_view_size_f64<false>};
      case operation::perspective_size:
        return {"library-perspective-size-f64", op, type, c, "frustum<double> at ±w/2, ±h/2",
                library_view_size_f64<true>};
      default: break;
    }
  }
  throw std::runtime_error("no implementation for " + name);
}

// ---------------------------------------------------------------------------------------------
// Clocks and sinks.

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string load_average() {
  double load[3] = {0, 0, 0};
  if (getloadavg(load, 3) != 3) return "unknown";
  char text[64];
  std::snprintf(text, sizeof text, "%.2f %.2f %.2f", load[0], load[1], load[2]);
  return text;
}

std::string rate(double cases_per_second) {
  char text[32];
  if (cases_per_second >= 1e6) std::snprintf(text, sizeof text, "%.3g M/s", cases_per_second / 1e6);
  else std::snprintf(text, sizeof text, "%.3g k/s", cases_per_second / 1e3);
  return text;
}

std::uint64_t checksum = 0;  // every timed result feeds it; printed at the end

// ---------------------------------------------------------------------------------------------
// One operation, type and class: the same cases for every variant.

struct workload {
  implementation impl;
  std::vector<test_case> cases;
  std::vector<std::vector<double>> outputs;  // the float code's, per case
  case_batch batch;                          // the same cases and outputs, as columns
};

workload make_workload(operation op, scalar_type type, std::optional<input_class> cls, std::size_t count) {
  workload w{representative(op, type), {}, {}, {}};
  w.cases = generate_cases(op, type, count, 99, cls, w.impl.conv);
  const std::size_t n = signature(op).output_count;
  for (const auto& c : w.cases) {
    std::vector<double> out(n, 0.0);
    w.impl.run(c.inputs.data(), out.data());
    w.outputs.push_back(std::move(out));
  }
  w.batch = make_batch(w.cases);
  run_implementation(w.impl, w.batch);
  return w;
}

struct timings {
  double float_code = 1e300, scalar = 1e300, batch_generic = 1e300, batch_avx2 = 1e300, rational = 1e300;
  double rational_fraction = 0;  // of the filtered scalar oracle's cases
};

// Seconds per case of `f(repeats)` over `cases` cases, the best of this and previous rounds.
void keep_best(double& best, std::size_t cases, std::size_t repeats, const std::function<void()>& f) {
  const double t0 = thread_seconds();
  for (std::size_t r = 0; r < repeats; ++r) f();
  best = std::min(best, (thread_seconds() - t0) / static_cast<double>(cases * repeats));
}

timings measure(workload& w, std::size_t rounds) {
  timings t;
  const std::size_t n = w.cases.size(), out_count = signature(w.impl.op).output_count;
  const std::size_t rational_cases = std::min<std::size_t>(n, 256);
  std::vector<double> out(out_count);
  batch_references refs;
  batch_grades grades;
  oracle_counters counters;
  for (std::size_t r = 0; r < rounds; ++r) {
    keep_best(t.float_code, n, 20, [&] {
      for (const auto& c : w.cases) {
        w.impl.run(c.inputs.data(), out.data());
        benchmark::DoNotOptimize(out.data());
        checksum += static_cast<std::uint64_t>(out[0] != 0);
      }
    });
    counters = {};
    keep_best(t.scalar, n, 2, [&] {
      for (std::size_t i = 0; i < n; ++i)
        checksum += grade_case(w.cases[i], w.impl.conv, w.outputs[i].data(), oracle_mode::filtered, &counters).max_ulps;
    });
    keep_best(t.batch_generic, n, 2, [&] {
      compute_references(w.batch, w.impl.conv, refs, nullptr, batch_path::generic);
      grade_batch(w.batch, w.impl.conv, refs, grades, batch_path::generic);
      checksum += grades.max_ulps[n / 2] + grades.ulps[n / 3];
    });
    if (avx2_batch_available())
      keep_best(t.batch_avx2, n, 2, [&] {
        compute_references(w.batch, w.impl.conv, refs, nullptr, batch_path::avx2);
        grade_batch(w.batch, w.impl.conv, refs, grades, batch_path::avx2);
        checksum += grades.max_ulps[n / 2] + grades.ulps[n / 3];
      });
    keep_best(t.rational, rational_cases, 1, [&] {
      for (std::size_t i = 0; i < rational_cases; ++i)
        checksum += grade_case(w.cases[i], w.impl.conv, w.outputs[i].data(), oracle_mode::naive).max_ulps;
    });
  }
  const double total = static_cast<double>(counters.decided_by_intervals + counters.fell_back_to_rationals);
  t.rational_fraction = total > 0 ? static_cast<double>(counters.fell_back_to_rationals) / total : 0;
  return t;
}

// Whether `op` is one of the comma-separated names in `only` (every operation when empty).
bool selected(operation op, const std::string& only) {
  if (only.empty()) return true;
  const std::string name(to_string(op));
  std::size_t start = 0;
  while (start <= only.size()) {
    const std::size_t end = std::min(only.find(',', start), only.size());
    if (only.compare(start, end - start, name) == 0 && end - start == name.size()) return true;
    start = end + 1;
  }
  return false;
}

int table(std::size_t rounds, const std::string& ops) {
  std::printf("load average before: %s; AVX2 filter: %s; %zu rounds, best kept\n\n", load_average().c_str(),
              avx2_batch_available() ? "yes" : "no (not measured)", rounds);
  std::printf("| operation / type / class | implementation | float code | filtered, one case | filtered, batch "
              "(generic) | filtered, batch (AVX2) | all-rational | batch ÷ rational | float ÷ batch | decided by "
              "rationals |\n|---|---|---|---|---|---|---|---|---|---|\n");
  for (operation op : all_operations())
    for (scalar_type type : {scalar_type::f32, scalar_type::f64})
      for (input_class cls : {input_class::regular, input_class::near_degenerate}) {
        if (!selected(op, ops)) continue;
        workload w = make_workload(op, type, cls, 4096);
        const timings t = measure(w, rounds);
        const double batch = std::min(t.batch_generic, t.batch_avx2);
        std::printf("| %s / %s / %s | %s | %s | %s | %s | %s | %s | %.0f× | %.1f× | %.3f%% |\n",
                    std::string(to_string(op)).c_str(), std::string(to_string(type)).c_str(),
                    std::string(to_string(cls)).c_str(), w.impl.name.c_str(), rate(1 / t.float_code).c_str(),
                    rate(1 / t.scalar).c_str(), rate(1 / t.batch_generic).c_str(),
                    t.batch_avx2 < 1e300 ? rate(1 / t.batch_avx2).c_str() : "–", rate(1 / t.rational).c_str(),
                    t.rational / batch, batch / t.float_code, 100 * t.rational_fraction);
        std::fflush(stdout);
      }
  std::printf("\nload average after: %s; checksum %llu\n", load_average().c_str(),
              static_cast<unsigned long long>(checksum));
  return 0;
}

// The batch oracle alone on regular cases, `rounds` passes over 4096 cases per operation and
// type: references and grades timed apart (thread CPU, whole passes), for a profiler to sample.
int split(std::size_t rounds, const std::string& ops) {
  const batch_path path = avx2_batch_available() ? batch_path::avx2 : batch_path::generic;
  std::printf("load average before: %s; %s filter; %zu passes of 4096 cases\n\n", load_average().c_str(),
              path == batch_path::avx2 ? "AVX2" : "generic", rounds);
  std::printf("| operation / type | references | grades | both |\n|---|---|---|---|\n");
  for (operation op : all_operations())
    for (scalar_type type : {scalar_type::f32, scalar_type::f64}) {
      if (!selected(op, ops)) continue;
      workload w = make_workload(op, type, input_class::regular, 4096);
      batch_references refs;
      batch_grades grades;
      double references = 0, grading = 0;
      for (std::size_t r = 0; r < rounds; ++r) {
        const double t0 = thread_seconds();
        compute_references(w.batch, w.impl.conv, refs, nullptr, path);
        const double t1 = thread_seconds();
        grade_batch(w.batch, w.impl.conv, refs, grades, path);
        grading += thread_seconds() - t1;
        references += t1 - t0;
        checksum += grades.max_ulps[r % w.batch.count];
      }
      const double cases = static_cast<double>(rounds * w.batch.count);
      std::printf("| %s / %s | %.1f ns | %.1f ns | %s |\n", std::string(to_string(op)).c_str(),
                  std::string(to_string(type)).c_str(), 1e9 * references / cases, 1e9 * grading / cases,
                  rate(cases / (references + grading)).c_str());
      std::fflush(stdout);
    }
  std::printf("\nload average after: %s; checksum %llu\n", load_average().c_str(),
              static_cast<unsigned long long>(checksum));
  return 0;
}

// What the verdicts cost: grade_case with verdicts against grade_case with values only
// (grade_depth::values_only: ulps, classes and rejections, every verdict left exact), on the
// same cases of every operation, type and class in alternating rounds, best round kept.
int verdicts_cost(std::size_t rounds) {
  std::printf("load average before: %s; %zu rounds, best kept, 2000 cases per row\n\n", load_average().c_str(), rounds);
  std::printf("| operation / type / class | implementation | values only | with verdicts | verdicts cost | "
              "cases beyond faithful |\n|---|---|---|---|---|---|\n");
  double worst = 0;
  for (operation op : all_operations())
    for (scalar_type type : {scalar_type::f32, scalar_type::f64}) {
      const implementation* impl = nullptr;
      for (const implementation& i : builtin_implementations())
        if (i.op == op && i.type == type && i.name.rfind("correctly-rounded", 0) != 0 && (!impl || i.name < impl->name))
          impl = &i;
      if (!impl) continue;
      for (input_class cls : {input_class::regular, input_class::near_degenerate}) {
        const auto cases = generate_cases(op, type, 2000, 99, cls, impl->conv);
        std::vector<std::vector<double>> outputs;
        for (const auto& c : cases) {
          outputs.emplace_back(signature(op).output_count, 0.0);
          impl->run(c.inputs.data(), outputs.back().data());
        }
        const std::size_t n = cases.size();
        std::size_t beyond = 0;
        for (std::size_t i = 0; i < n; ++i) beyond += grade_case(cases[i], impl->conv, outputs[i].data()).v > verdict::faithful;
        double values = 1e300, verdicts = 1e300;
        for (std::size_t r = 0; r < rounds; ++r)
          for (grade_depth depth : {grade_depth::values_only, grade_depth::verdicts})
            keep_best(depth == grade_depth::values_only ? values : verdicts, n, 2, [&] {
              for (std::size_t i = 0; i < n; ++i)
                checksum += grade_case(cases[i], impl->conv, outputs[i].data(), oracle_mode::filtered, nullptr, depth)
                                .max_ulps;
            });
        worst = std::max(worst, verdicts / values);
        std::printf("| %s / %s / %s | %s | %s | %s | %.2f× | %.1f%% |\n", std::string(to_string(op)).c_str(),
                    std::string(to_string(type)).c_str(), std::string(to_string(cls)).c_str(), impl->name.c_str(),
                    rate(1 / values).c_str(), rate(1 / verdicts).c_str(), verdicts / values,
                    100.0 * static_cast<double>(beyond) / static_cast<double>(n));
        std::fflush(stdout);
      }
    }
  std::printf("\nworst verdicts cost: %.2f×; load average after: %s; checksum %llu\n", worst, load_average().c_str(),
              static_cast<unsigned long long>(checksum));
  return 0;
}

// 1 and 2 threads on the same large batch of every implementation's cases, wall-clock, the
// best of `rounds` alternating rounds: the batch grader (grade_batch_in_parallel, running the
// implementation too) and run_and_grade_in_parallel (grade_case per case).
int threads(std::size_t rounds) {
  std::printf("load average before: %s; %u processors\n\n", load_average().c_str(), default_jobs());
  std::vector<std::pair<const implementation*, std::vector<test_case>>> work;
  std::size_t total = 0;
  for (const implementation& impl : builtin_implementations()) {
    work.emplace_back(&impl, generate_cases(impl.op, impl.type, 5000, 1, std::nullopt, impl.conv));
    total += 5000;
  }
  double best_batch[3] = {1e300, 1e300, 1e300}, best_scalar[3] = {1e300, 1e300, 1e300};
  for (std::size_t r = 0; r < rounds; ++r)
    for (unsigned jobs : {1u, 2u}) {
      double t0 = wall_seconds();
      for (auto& [impl, cases] : work) {
        case_batch batch = make_batch(cases);
        batch_references refs;
        batch_grades grades;
        grade_batch_in_parallel(batch, impl->conv, refs, grades, jobs, impl);
        checksum += grades.max_ulps.back();
      }
      best_batch[jobs] = std::min(best_batch[jobs], wall_seconds() - t0);
      t0 = wall_seconds();
      for (auto& [impl, cases] : work) checksum += run_and_grade_in_parallel(*impl, cases, jobs).back().max_ulps;
      best_scalar[jobs] = std::min(best_scalar[jobs], wall_seconds() - t0);
    }
  std::printf("| %zu cases (%zu implementations × 5000), run and graded | 1 thread | 2 threads | 2 ÷ 1 |\n"
              "|---|---|---|---|\n",
              total, work.size());
  std::printf("| batch grader | %s | %s | %.2f× |\n", rate(total / best_batch[1]).c_str(),
              rate(total / best_batch[2]).c_str(), best_batch[1] / best_batch[2]);
  std::printf("| run_and_grade (grade_case per case) | %s | %s | %.2f× |\n", rate(total / best_scalar[1]).c_str(),
              rate(total / best_scalar[2]).c_str(), best_scalar[1] / best_scalar[2]);
  std::printf("\nload average after: %s; checksum %llu\n", load_average().c_str(),
              static_cast<unsigned long long>(checksum));
  return 0;
}

// ---------------------------------------------------------------------------------------------
// Agreement of the two oracles on many cases.

bool same_grade(const case_grade& a, const case_grade& b) {
  if (a.outputs.size() != b.outputs.size()) return false;
  for (std::size_t i = 0; i < a.outputs.size(); ++i) {
    const auto &x = a.outputs[i], &y = b.outputs[i];
    if (x.exact_defined != y.exact_defined || std::memcmp(&x.reference, &y.reference, sizeof(double)) != 0 ||
        x.ulps != y.ulps || x.nonfinite != y.nonfinite || x.garbage != y.garbage)
      return false;
  }
  return a.max_ulps == b.max_ulps && a.exact_class == b.exact_class && a.got_class == b.got_class &&
         a.misclassified == b.misclassified && a.plane_value == b.plane_value && a.scale_pivot == b.scale_pivot;
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
      std::printf("%-32s %-16s %zu cases: %zu differ, %.3f%% decided by rationals\n", impl.name.c_str(),
                  std::string(to_string(cls)).c_str(), count, differ,
                  100.0 * static_cast<double>(counters.fell_back_to_rationals) / static_cast<double>(count));
      std::fflush(stdout);
      failures += differ ? 1 : 0;
    }
  }
  return failures ? 1 : 0;
}

// ---------------------------------------------------------------------------------------------
// The same measurements as Google Benchmark benchmarks (one per variant and operation).

void register_benchmarks() {
  for (operation op : all_operations())
    for (scalar_type type : {scalar_type::f32, scalar_type::f64}) {
      const std::string suffix = std::string(to_string(op)) + "/" + std::string(to_string(type));
      auto w = std::make_shared<workload>(make_workload(op, type, input_class::regular, 4096));
      benchmark::RegisterBenchmark(("float_code/" + suffix).c_str(), [w](benchmark::State& state) {
        std::vector<double> out(signature(w->impl.op).output_count);
        for (auto _ : state)
          for (const auto& c : w->cases) {
            w->impl.run(c.inputs.data(), out.data());
            benchmark::DoNotOptimize(out.data());
          }
        state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * w->cases.size()));
      });
      benchmark::RegisterBenchmark(("filtered_one_case/" + suffix).c_str(), [w](benchmark::State& state) {
        for (auto _ : state)
          for (std::size_t i = 0; i < w->cases.size(); ++i)
            benchmark::DoNotOptimize(grade_case(w->cases[i], w->impl.conv, w->outputs[i].data()).max_ulps);
        state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * w->cases.size()));
      });
      benchmark::RegisterBenchmark(("filtered_batch/" + suffix).c_str(), [w](benchmark::State& state) {
        batch_references refs;
        batch_grades grades;
        for (auto _ : state) {
          compute_references(w->batch, w->impl.conv, refs);
          grade_batch(w->batch, w->impl.conv, refs, grades);
          benchmark::DoNotOptimize(grades.max_ulps.data());
        }
        state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * w->cases.size()));
      });
    }
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t agree_count = 0, table_rounds = 3, thread_rounds = 0, verdict_rounds = 0, split_rounds = 0;
  bool gbench = false;
  std::string only, ops;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--agree=", 8) == 0) agree_count = std::stoul(argv[i] + 8);
    else if (std::strncmp(argv[i], "--table=", 8) == 0) table_rounds = std::stoul(argv[i] + 8);
    else if (std::strncmp(argv[i], "--threads=", 10) == 0) thread_rounds = std::stoul(argv[i] + 10);
    else if (std::strncmp(argv[i], "--verdicts=", 11) == 0) verdict_rounds = std::stoul(argv[i] + 11);
    else if (std::strncmp(argv[i], "--split=", 8) == 0) split_rounds = std::stoul(argv[i] + 8);
    else if (std::strncmp(argv[i], "--impl=", 7) == 0) only = argv[i] + 7;
    else if (std::strncmp(argv[i], "--op=", 5) == 0) ops = argv[i] + 5;
    else if (std::strcmp(argv[i], "--gbench") == 0) gbench = true;
  }
  if (agree_count) return agree(agree_count, only);
  if (thread_rounds) return threads(thread_rounds);
  if (verdict_rounds) return verdicts_cost(verdict_rounds);
  if (split_rounds) return split(split_rounds, ops);
  if (!gbench) return table(table_rounds, ops);
  register_benchmarks();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
