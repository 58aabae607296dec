#pragma once
/// Shards: a deterministic partition of a run's case stream between N independent workers.
#include <cstdint>
#include <string>
#include <string_view>

namespace shadowproof {

/// Shard `index` of `count`: the cases whose id ≡ index (mod count). Every case id belongs to
/// exactly one shard of a given count, and which one depends on nothing else (not on the
/// workers, threads or order of execution), so the union of the N shards of a run is the run.
/// Ids are dealt round robin, so every shard holds about the same share of each input class.
/// count = 1 is the whole run.
struct shard {
  std::uint64_t index = 0;
  std::uint64_t count = 1;
  /// True when case `id` belongs to this shard.
  bool contains(std::uint64_t id) const { return id % count == index; }
  /// True for the whole run (1 shard).
  bool whole() const { return count == 1; }
};

/// Largest shard count accepted (a campaign of 2^20 workers is past any cluster we know of,
/// and a cap keeps a typo from meaning a billion empty shards).
inline constexpr std::uint64_t max_shard_count = std::uint64_t{1} << 20;

/// Parses "i/N" (decimal, 0 ≤ i < N ≤ max_shard_count). Throws error shard_spec naming the
/// text otherwise.
shard parse_shard(std::string_view text);

/// "i/N".
std::string to_string(const shard& s);

}  // namespace shadowproof
