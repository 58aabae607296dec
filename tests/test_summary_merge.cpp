// Merging summaries of shards (shadowproof/verify/summary_merge.h): for any partition of a
// run's grades, the merged summary is the summary of the whole run, field by field, whatever
// the order of the parts; ties between equally bad cases go to the lowest id.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "shadowproof/impls/builtin.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/report.h"
#include "shadowproof/verify/shard.h"
#include "shadowproof/verify/summary_merge.h"

using namespace shadowproof;

namespace {

std::vector<std::uint64_t> ids_of(const std::vector<case_grade>& grades) {
  std::vector<std::uint64_t> ids;
  for (const auto& g : grades) ids.push_back(g.id);
  return ids;
}

void require_same_summary(const mergeable_summary& a, const mergeable_summary& b) {
  const grade_summary &x = a.summary, &y = b.summary;
  REQUIRE(x.cases == y.cases);
  REQUIRE(x.outputs == y.outputs);
  REQUIRE(x.max_ulps == y.max_ulps);
  REQUIRE(x.median_ulps == y.median_ulps);
  REQUIRE(x.max_bits == y.max_bits);
  REQUIRE(x.bits_histogram == y.bits_histogram);
  REQUIRE(x.nonfinite == y.nonfinite);
  REQUIRE(x.garbage == y.garbage);
  REQUIRE(x.misclassified == y.misclassified);
  REQUIRE(x.verdicts == y.verdicts);
  REQUIRE(x.worst_verdict == y.worst_verdict);
  REQUIRE(ids_of(x.worst) == ids_of(y.worst));
  REQUIRE(ids_of(x.examples) == ids_of(y.examples));
  REQUIRE(x.worst_finite.has_value() == y.worst_finite.has_value());
  if (x.worst_finite) REQUIRE(x.worst_finite->id == y.worst_finite->id);
  REQUIRE(x.worst_nonfinite.has_value() == y.worst_nonfinite.has_value());
  if (x.worst_nonfinite) REQUIRE(x.worst_nonfinite->id == y.worst_nonfinite->id);
  REQUIRE(a.ulps_counts == b.ulps_counts);
}

// The summary merged from the shards of `grades` for `count` shards, parts given in `order`.
mergeable_summary merged_from_shards(const std::vector<case_grade>& grades, std::uint64_t count,
                                     const std::vector<std::size_t>& order, std::size_t keep) {
  std::vector<mergeable_summary> parts;
  std::vector<case_grade> candidates;
  for (std::size_t i : order) {
    const shard part{i, count};
    std::vector<case_grade> mine;
    for (const auto& g : grades)
      if (part.contains(g.id)) mine.push_back(g);
    parts.push_back(summarize_mergeable(mine, keep));
    for (const auto& g : singled_out_cases(parts.back().summary)) candidates.push_back(g);
  }
  std::reverse(candidates.begin(), candidates.end());  // any order
  return merge_summaries(parts, candidates, keep);
}

}  // namespace

TEST_CASE("shards of a run merge to the summary of the whole run, in any order", "[summary_merge]") {
  // Implementations with every kind of result: NaN under a parallel light, misclassified
  // points, large errors near degeneracy, and correctly rounded ones.
  for (const char* name : {"seed001-shader-f32", "seed003-ray-f32", "homogeneous-image-f32"}) {
    const implementation& impl = find_builtin_implementation(name);
    const auto cases = generate_cases(impl.op, impl.type, 400, 11, std::nullopt, impl.conv);
    const auto grades = run_and_grade(impl, cases);
    const mergeable_summary whole = summarize_mergeable(grades, 3);
    REQUIRE(whole.summary.cases == 400);
    std::mt19937_64 rng(5);
    for (std::uint64_t count : std::vector<std::uint64_t>{1, 2, 3, 7, 64, 1000}) {  // 1000 > cases: most shards are empty
      std::vector<std::size_t> order(count);
      std::iota(order.begin(), order.end(), 0);
      std::shuffle(order.begin(), order.end(), rng);
      INFO(name << " in " << count << " shards");
      require_same_summary(merged_from_shards(grades, count, order, 3), whole);
    }
  }
}

TEST_CASE("equally bad cases in different shards: the lowest id is the worst", "[summary_merge]") {
  // Two cases alike in everything but the id, one off by 1000 ulps in each shard of two.
  output_grade bad;
  bad.ulps = 1000;
  bad.bits = 9.967;
  bad.v = verdict::wrong;
  case_grade a;
  a.outputs = {bad};
  a.max_ulps = 1000;
  a.v = verdict::wrong;
  case_grade b = a;
  a.id = 6;  // shard 0 of 2
  b.id = 3;  // shard 1 of 2
  const std::vector<case_grade> grades{a, b};
  const mergeable_summary whole = summarize_mergeable(grades, 1);
  REQUIRE(whole.summary.worst.size() == 1);
  REQUIRE(whole.summary.worst[0].id == 3);
  for (const auto& order : {std::vector<std::size_t>{0, 1}, std::vector<std::size_t>{1, 0}}) {
    const mergeable_summary m = merged_from_shards(grades, 2, order, 1);
    REQUIRE(m.summary.worst.size() == 1);
    CHECK(m.summary.worst[0].id == 3);
    CHECK(m.summary.worst_finite->id == 3);
    CHECK(m.summary.median_ulps == 1000);
  }
}

TEST_CASE("the merged median is the lower median of every counted output", "[summary_merge]") {
  // Outputs off by 0, 1, 5 and 9 ulps in two shards: sorted 0 1 5 9, lower median 1.
  auto one = [](std::uint64_t id, std::vector<std::uint64_t> ulps) {
    case_grade g;
    g.id = id;
    for (auto u : ulps) {
      output_grade o;
      o.ulps = u;
      g.outputs.push_back(o);
      g.max_ulps = std::max(g.max_ulps, u);
    }
    return g;
  };
  const std::vector<case_grade> grades{one(0, {9, 0}), one(1, {5, 1})};
  const auto m = merged_from_shards(grades, 2, {1, 0}, 3);
  CHECK(m.summary.median_ulps == 1);
  CHECK(summarize(grades).median_ulps == 1);
}

TEST_CASE("a shard specification reads i/N with 0 <= i < N", "[summary_merge]") {
  CHECK(parse_shard("0/1").whole());
  const shard s = parse_shard("2/7");
  CHECK(s.index == 2);
  CHECK(s.count == 7);
  CHECK(s.contains(9));
  CHECK_FALSE(s.contains(10));
  CHECK(to_string(s) == "2/7");
  for (const char* bad : {"7/7", "1/0", "", "/", "1/", "/2", "-1/4", "+1/4", "1 /4", "1/2/3", "0x1/4", "0/1048577",
                          "99999999999999999999/1"})
    CHECK_THROWS_WITH(parse_shard(bad), Catch::Contains("[shadowproof.shard.spec] bad --shard '" + std::string(bad) + "'"));
  // Every id belongs to exactly one shard of a count.
  for (std::uint64_t id = 0; id < 50; ++id) {
    int owners = 0;
    for (std::uint64_t i = 0; i < 7; ++i) owners += shard{i, 7}.contains(id) ? 1 : 0;
    CHECK(owners == 1);
  }
}
