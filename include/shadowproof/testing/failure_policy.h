#pragma once
/// When a graded result fails a test: an ulps threshold today, verdict names as they are graded.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowproof {

/// The verdict scale a failure policy is written in, best first: exact (correctly rounded),
/// faithful (one of the two neighbours of the exact value), stable (no worse than the problem's
/// conditioning allows), unstable (worse than that), wrong (a wrong meaning, e.g. an image on
/// the wrong side), range (over- or underflow the exact value does not have), nonfinite (NaN or
/// infinity where the exact value is finite), garbage (a finite number where no exact value
/// exists).
const std::vector<std::string_view>& verdict_scale();

/// What makes one graded result a failure. Two forms, combinable:
///   ulps_above(n): any output more than n ulps from the correctly rounded exact value fails,
///     and so does every result no ulps count measures: a non-finite output where the exact
///     value is finite, a finite output where none exists, a shadow-point image on the wrong
///     side of the receiver or the light. A correctly rounded result never fails (0 ulps).
///   verdicts({...}): a result whose verdict (verdict_scale()) is one of these fails. Today's
///     grades decide `nonfinite` and `garbage`; the other names are accepted once the grader
///     gives them and throw error "testing.fail_on" until then.
/// Written as text, terms are separated by commas: "ulps>2", "nonfinite,garbage",
/// "ulps>4,nonfinite". A policy with no term fails nothing and is rejected.
class failure_policy {
 public:
  /// The default: ulps_above(0), i.e. anything but the correctly rounded result fails.
  failure_policy();
  /// Fails outputs more than n ulps off, and every non-finite, garbage or misclassified result.
  static failure_policy ulps_above(std::uint64_t n);
  /// Fails results with one of these verdicts. Throws error "testing.fail_on" for a name not in
  /// verdict_scale(), or not yet graded.
  static failure_policy verdicts(const std::vector<std::string>& names);
  /// Parses the text form ("ulps>2", "nonfinite,garbage", ...). Throws error "testing.fail_on"
  /// naming the term it cannot read.
  static failure_policy parse(std::string_view text);

  /// The n of ulps_above(n), if the policy has one.
  const std::optional<std::uint64_t>& ulps_threshold() const { return ulps_; }
  /// The verdict names, in verdict_scale() order.
  const std::vector<std::string>& verdict_names() const { return verdicts_; }
  /// The text form, e.g. "ulps>2" or "ulps>2,nonfinite"; parse(to_string()) gives it back.
  std::string to_string() const;

 private:
  std::optional<std::uint64_t> ulps_;
  std::vector<std::string> verdicts_;
};

}  // namespace shadowproof
