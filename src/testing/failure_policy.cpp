// Failure policies: an ulps threshold, and the verdict names today's grades decide.
#include "shadowproof/testing/failure_policy.h"

#include <algorithm>
#include <charconv>

#include "shadowproof/core/error.h"

namespace shadowproof {
namespace {

// The verdicts today's grades decide (judgement.cpp maps them); the rest of the scale waits for
// the grader to give it.
bool graded_today(std::string_view name) { return name == "nonfinite" || name == "garbage"; }

std::string scale_text() {
  std::string s;
  for (auto v : verdict_scale()) s += (s.empty() ? "" : ", ") + std::string(v);
  return s;
}

}  // namespace

const std::vector<std::string_view>& verdict_scale() {
  static const std::vector<std::string_view> scale = {"exact",  "faithful", "stable",    "unstable",
                                                      "wrong",  "range",    "nonfinite", "garbage"};
  return scale;
}

failure_policy::failure_policy() : ulps_(0) {}

failure_policy failure_policy::ulps_above(std::uint64_t n) {
  failure_policy p;
  p.ulps_ = n;
  return p;
}

failure_policy failure_policy::verdicts(const std::vector<std::string>& names) {
  failure_policy p;
  p.ulps_.reset();
  for (const auto& v : verdict_scale()) {
    if (std::find(names.begin(), names.end(), v) == names.end()) continue;
    if (!graded_today(v))
      throw error(errc::testing_fail_on, "the verdict '" + std::string(v) +
                                             "' is not graded yet; fail on ulps>N, nonfinite or garbage");
    p.verdicts_.emplace_back(v);
  }
  for (const auto& n : names)
    if (std::find(verdict_scale().begin(), verdict_scale().end(), n) == verdict_scale().end())
      throw error(errc::testing_fail_on, "unknown verdict '" + n + "' (one of: " + scale_text() + ")");
  if (p.verdicts_.empty()) throw error(errc::testing_fail_on, "a failure policy needs at least one verdict");
  return p;
}

failure_policy failure_policy::parse(std::string_view text) {
  std::optional<std::uint64_t> ulps;
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view term = text.substr(start, comma - start);
    if (term.rfind("ulps>", 0) == 0) {
      const std::string_view digits = term.substr(5);
      std::uint64_t n = 0;
      const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
      if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size())
        throw error(errc::testing_fail_on, "cannot read '" + std::string(term) +
                                               "': expected ulps>N with N a whole number below 2^64");
      if (ulps) throw error(errc::testing_fail_on, "'" + std::string(text) + "' gives ulps>N twice");
      ulps = n;
    } else if (!term.empty()) {
      names.emplace_back(term);
    } else {
      throw error(errc::testing_fail_on, "empty term in '" + std::string(text) +
                                             "' (expected ulps>N or verdict names, separated by commas)");
    }
    start = comma + 1;
  }
  failure_policy p = names.empty() ? failure_policy() : verdicts(names);
  p.ulps_ = ulps;
  if (!ulps && names.empty()) throw error(errc::testing_fail_on, "a failure policy needs at least one term");
  return p;
}

std::string failure_policy::to_string() const {
  std::string s = ulps_ ? "ulps>" + std::to_string(*ulps_) : "";
  for (const auto& v : verdicts_) s += (s.empty() ? "" : ",") + v;
  return s;
}

}  // namespace shadowproof
