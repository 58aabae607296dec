#pragma once
/// Grading on several threads. Every case's grade depends on that case alone, so the work is
/// split into slices that threads take in any order, each writing its own cases' results:
/// the grades, and the counters (sums), are identical for any number of threads.
#include <cstddef>
#include <functional>
#include <vector>

#include "shadowproof/verify/batch.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/implementation.h"

namespace shadowproof {

/// The number of threads to use by default: the processors this program may run on (at
/// least 1).
unsigned default_jobs();

/// Frees what MPFR cached for the calling thread (its constants, such as π, are kept per
/// thread): a thread that graded cases calls it before it ends, or that memory is lost.
void release_thread_caches();

/// Calls work(first, end) once for each slice [first, end) = [k·slice, min(count, (k+1)·slice))
/// of [0, count), on `jobs` threads (0 means default_jobs()), slices taken in increasing k.
/// work must write only what belongs to its own indices. When calls throw, the exception of
/// the lowest slice is rethrown after every thread has stopped: the one a loop in index order
/// would have thrown first, for any jobs. Precondition: slice ≥ 1 (internal_error otherwise).
void for_each_slice(std::size_t count, unsigned jobs, std::size_t slice,
                    const std::function<void(std::size_t, std::size_t)>& work);

/// grades[i] = grade_case(cases[i], conv, outputs[i].data(), mode) for every i, on `jobs`
/// threads (0 means default_jobs()); counters, when given, receive the sums of every case's.
/// Precondition: outputs.size() == cases.size(), each with the case's output count.
std::vector<case_grade> grade_in_parallel(const std::vector<test_case>& cases, const conventions& conv,
                                          const std::vector<std::vector<double>>& outputs, unsigned jobs,
                                          oracle_mode mode = oracle_mode::filtered,
                                          oracle_counters* counters = nullptr);

/// run_and_grade (report.h) on `jobs` threads: the same grades, in case order, for any jobs.
/// impl.run is called from several threads at once, so it must not share mutable state (the
/// built-in implementations do not; a routine behind a pipe or a lock should run with jobs = 1).
std::vector<case_grade> run_and_grade_in_parallel(const implementation& impl, const std::vector<test_case>& cases,
                                                  unsigned jobs, oracle_mode mode = oracle_mode::filtered,
                                                  oracle_counters* counters = nullptr);

/// run_implementation (when impl is given), compute_references and grade_batch (batch.h) on
/// `jobs` threads: the same columns for any jobs.
void grade_batch_in_parallel(case_batch& batch, const conventions& conv, batch_references& refs, batch_grades& grades,
                             unsigned jobs, const implementation* impl = nullptr, oracle_counters* counters = nullptr,
                             batch_path path = batch_path::automatic);

}  // namespace shadowproof
