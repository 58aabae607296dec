// Grading on several threads (parallel.h): slices of consecutive cases handed out by an atomic
// counter, each thread writing only its slices' results and summing its own counters.
#include "shadowproof/verify/parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

#include <mpfr.h>

#include "batch_ranges.h"
#include "shadowproof/core/error.h"

namespace shadowproof {

namespace {

// Calls work(first, end, counters) for consecutive slices of [0, count) on `jobs` threads and
// adds every thread's counters to `total`. When slices throw, the exception of the lowest
// slice is rethrown once every thread has stopped: slices are taken in increasing order and
// every slice taken before the failure runs to its end, so that is the exception a loop over
// the cases in order would have thrown, whatever the number of threads.
template <class Work>
void for_slices(std::size_t count, unsigned jobs, std::size_t slice, oracle_counters* total, Work work) {
  if (jobs == 0) jobs = default_jobs();
  const std::size_t slices = (count + slice - 1) / slice;
  jobs = static_cast<unsigned>(std::min<std::size_t>(jobs, std::max<std::size_t>(slices, 1)));
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::size_t failed_slice = slices;
  std::mutex lock;
  auto run = [&] {
    oracle_counters mine;
    std::size_t s = 0;
    try {
      while ((s = next.fetch_add(1)) < slices) work(s * slice, std::min(count, (s + 1) * slice), mine);
    } catch (...) {
      std::lock_guard<std::mutex> guard(lock);
      if (s < failed_slice) {
        failure = std::current_exception();
        failed_slice = s;
      }
      next = slices;  // the others stop after their current slice
    }
    std::lock_guard<std::mutex> guard(lock);
    if (total) {
      total->decided_by_intervals += mine.decided_by_intervals;
      total->fell_back_to_rationals += mine.fell_back_to_rationals;
    }
  };
  std::vector<std::thread> threads;
  for (unsigned t = 1; t < jobs; ++t)
    threads.emplace_back([&run] {
      run();
      release_thread_caches();
    });
  run();
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace

void release_thread_caches() { mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE); }

unsigned default_jobs() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : n;
}

void for_each_slice(std::size_t count, unsigned jobs, std::size_t slice,
                    const std::function<void(std::size_t, std::size_t)>& work) {
  if (slice == 0) throw internal_error("for_each_slice: a slice holds at least one index");
  for_slices(count, jobs, slice, nullptr,
             [&](std::size_t first, std::size_t end, oracle_counters&) { work(first, end); });
}

std::vector<case_grade> grade_in_parallel(const std::vector<test_case>& cases, const conventions& conv,
                                          const std::vector<std::vector<double>>& outputs, unsigned jobs,
                                          oracle_mode mode, oracle_counters* counters) {
  if (outputs.size() != cases.size()) throw internal_error("grade_in_parallel: one output vector per case expected");
  std::vector<case_grade> grades(cases.size());
  for_slices(cases.size(), jobs, 256, counters, [&](std::size_t first, std::size_t end, oracle_counters& mine) {
    for (std::size_t i = first; i < end; ++i) grades[i] = grade_case(cases[i], conv, outputs[i].data(), mode, &mine);
  });
  return grades;
}

std::vector<case_grade> run_and_grade_in_parallel(const implementation& impl, const std::vector<test_case>& cases,
                                                  unsigned jobs, oracle_mode mode, oracle_counters* counters) {
  std::vector<case_grade> grades(cases.size());
  const std::size_t n = signature(impl.op).output_count;
  for_slices(cases.size(), jobs, 256, counters, [&](std::size_t first, std::size_t end, oracle_counters& mine) {
    std::vector<double> out(n);
    for (std::size_t i = first; i < end; ++i) {
      std::fill(out.begin(), out.end(), 0.0);
      impl.run(cases[i].inputs.data(), out.data());
      grades[i] = grade_case(cases[i], impl.conv, out.data(), mode, &mine);
    }
  });
  return grades;
}

void grade_batch_in_parallel(case_batch& batch, const conventions& conv, batch_references& refs, batch_grades& grades,
                             unsigned jobs, const implementation* impl, oracle_counters* counters, batch_path path) {
  detail::prepare_references(batch, refs);
  detail::prepare_grades(batch, grades);
  for_slices(batch.count, jobs, 4096, counters, [&](std::size_t first, std::size_t end, oracle_counters& mine) {
    if (impl) detail::run_implementation_range(*impl, batch, first, end);
    detail::compute_references_range(batch, conv, refs, first, end, &mine, path);
    detail::grade_range(batch, conv, refs, grades, first, end, path);
  });
}

}  // namespace shadowproof
