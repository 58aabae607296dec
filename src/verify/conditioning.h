#pragma once
// The verdicts that need the exact partial derivatives (docs/verdicts.md): outputs more than an
// ulp off whose relative error alone does not prove them stable, non-finite outputs where the
// exact value exists, and a sentinel returned for a case that has an answer. The derivatives
// come from the operation's exact<N> template over dual numbers (dual.h): over intervals first
// and, when an interval cannot decide a comparison, over rationals, so that both oracle modes
// reach the same verdicts.
#include <cstddef>
#include <optional>

#include "shadowproof/constructions/classify.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/grade.h"

namespace shadowproof::detail {

/// Why an output's verdict waits for the derivatives.
enum class pending_kind {
  finite,     ///< a finite output more than an ulp off: stable, range, unstable or wrong
  nonfinite,  ///< NaN or ±Inf where the exact value exists: stable, range or nonfinite
  rejection,  ///< the declared sentinel where the case has an answer: stable, range or wrong
};

/// The outputs (indices in the implementation's layout) whose verdicts wait, with the reason.
struct pending_outputs {
  std::size_t index[16];
  pending_kind kind[16];
  std::size_t count = 0;
  void add(std::size_t j, pending_kind k) {
    index[count] = j;
    kind[count++] = k;
  }
};

/// Sets g.outputs[j].v for every pending output j: from the operation's sensitivity kernel when
/// it decides (filtered mode), from the generic derivatives otherwise (`mode` naive: rationals
/// only). `reference` holds the canonical outputs correctly rounded (NaN where undefined) and
/// `cls` the exact class of a shadow-point case, for the kernel.
void decide_pending(case_grade& g, const test_case& c, const conventions& conv, const double* got,
                    const pending_outputs& pending, oracle_mode mode, const double* reference,
                    std::optional<point_class> cls);

/// True when |got − ref| ≤ c·u |f| for every real f that rounds to ref (so η ≤ c·u whatever the
/// derivatives): the cheap proof that an output a few ulps off is stable. ref is finite, non-zero.
bool certainly_stable(double got, double ref, scalar_type type, int c);

/// True when a straightforward evaluation of some output of c (the operation's own formula)
/// over- or underflows the type, or the exact output itself lies outside its normal range: the
/// mark of the `range` class, which the generator checks.
bool leaves_range(const test_case& c, const conventions& conv);

/// u of the type: 2^-24 or 2^-53.
double unit_roundoff(scalar_type type);

/// The threshold of `wrong`: η above it means no input within that relative distance explains
/// the output. √u rounded down to a power of two: 2^-12 for f32, 2^-27 for f64.
double wrong_threshold(scalar_type type);

}  // namespace shadowproof::detail
