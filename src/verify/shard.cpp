// Parsing shard specifications "i/N".
#include "shadowproof/verify/shard.h"

#include <charconv>

#include "shadowproof/core/error.h"

namespace shadowproof {
namespace {

// A decimal without sign, spaces or leading '+'; nothing when the text is not one.
bool parse_decimal(std::string_view text, std::uint64_t& value) {
  if (text.empty() || text.size() > 19) return false;
  for (char ch : text)
    if (ch < '0' || ch > '9') return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

shard parse_shard(std::string_view text) {
  const auto bad = [&](const std::string& why) {
    return error(errc::shard_spec, "bad --shard '" + std::string(text) + "': " + why);
  };
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) throw bad("expected i/N, e.g. 0/4 for the first of 4 shards");
  shard s;
  if (!parse_decimal(text.substr(0, slash), s.index) || !parse_decimal(text.substr(slash + 1), s.count))
    throw bad("expected i/N with decimal i and N, e.g. 0/4 for the first of 4 shards");
  if (s.count == 0) throw bad("the shard count N must be at least 1");
  if (s.count > max_shard_count) throw bad("at most " + std::to_string(max_shard_count) + " shards");
  if (s.index >= s.count) throw bad("the shard index i runs from 0 to N-1 = " + std::to_string(s.count - 1));
  return s;
}

std::string to_string(const shard& s) { return std::to_string(s.index) + "/" + std::to_string(s.count); }

}  // namespace shadowproof
