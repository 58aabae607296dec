#pragma once
// The HTML report's section for one graded implementation (check) or outputs file (grade).
#include <string>
#include <vector>

#include "html_report.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/report.h"
#include "verify_print.h"

namespace shadowproof::cli {

/// What one implementation's section shows.
struct graded_run {
  std::string name;
  std::string origin;  ///< where the formula comes from (empty for grade)
  operation op = operation::shadow_matrix;
  scalar_type type = scalar_type::f32;
  const conventions* conv = nullptr;
  const grade_summary* summary = nullptr;
  const point_cloud* plot = nullptr;  ///< every case, for the plot
  case_lookup lookup;
  bool failed = false;
};

/// Adds case c, graded g, to a plot: its closeness to degeneracy against its bits of error.
void add_to_plot(point_cloud& plot, const test_case& c, const case_grade& g);

/// The section: verdict, counts per verdict, the plot of every case, the singled-out cases
/// with their deciding output and reproducer, and the conventions.
html_section graded_section(const graded_run& run);

}  // namespace shadowproof::cli
