#pragma once
// The batch grader's steps over a range of cases [first, end), for batch.cpp and the parallel
// grader (parallel.cpp): each case's results depend on that case alone, so ranges can run on
// any threads in any order and give the same columns.
#include <cstddef>

#include "shadowproof/verify/batch.h"

namespace shadowproof::detail {

/// Sizes the columns of `out` for the batch (every case undecided, every grade empty).
void prepare_references(const case_batch& batch, batch_references& out);
void prepare_grades(const case_batch& batch, batch_grades& out);

/// run_implementation, compute_references and grade_batch on cases [first, end) only, into
/// columns already sized by the functions above.
void run_implementation_range(const implementation& impl, case_batch& batch, std::size_t first, std::size_t end);
void compute_references_range(const case_batch& batch, const conventions& conv, batch_references& out,
                              std::size_t first, std::size_t end, oracle_counters* counters, batch_path path);
void grade_range(const case_batch& batch, const conventions& conv, const batch_references& refs, batch_grades& out,
                 std::size_t first, std::size_t end, batch_path path);

}  // namespace shadowproof::detail
