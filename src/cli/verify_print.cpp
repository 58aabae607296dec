// Reports shared by `shadowproof check` and `shadowproof grade`.
#include "verify_print.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "shadowproof/core/error.h"
#include "shadowproof/core/ulp.h"

namespace shadowproof::cli {

std::optional<verdict> parse_fail_on(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const auto v = verdict_from_string(text);
  if (!v) {
    std::string names;
    for (verdict x : all_verdicts()) names += (names.empty() ? "" : ", ") + std::string(to_string(x));
    throw error(errc::verify_unknown_verdict, "unknown --fail-on '" + text + "'; expected one of " + names);
  }
  return v;
}

namespace {

constexpr std::size_t count_width = 6;
constexpr std::size_t verdict_width = 10;

std::string fixed1(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", x);
  return b;
}

std::string pad_right(std::string s, std::size_t w) {
  if (s.size() < w) s.append(w - s.size(), ' ');
  return s;
}

// Display width of UTF-8 text: one column per character.
std::size_t columns(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char ch : s) n += (ch & 0xC0) != 0x80;
  return n;
}

// Writes `text` (starting at column `indent`) on lines of at most `width` columns, breaking after
// ", " or "; " and continuing two columns further in.
void emit(std::ostream& out, const std::string& text, std::size_t indent, std::size_t width) {
  std::string line(indent, ' ');
  std::size_t start = 0;
  bool first = true;
  while (start < text.size()) {
    std::size_t end = text.size();
    const std::size_t room = width > line.size() ? width - line.size() : 0;
    if (columns(text.substr(start)) > room) {
      // The last separator that keeps the piece within the line.
      std::size_t best = std::string::npos;
      for (std::size_t k = start; k + 1 < text.size(); ++k)
        if ((text[k] == ',' || text[k] == ';') && text[k + 1] == ' ' && columns(text.substr(start, k + 1 - start)) <= room)
          best = k + 1;
      if (best != std::string::npos) end = best;
    }
    out << line << text.substr(start, end - start) << '\n';
    start = end;
    while (start < text.size() && text[start] == ' ') ++start;
    if (first) line.append(2, ' ');
    first = false;
  }
}

std::vector<double> outputs_of(const case_grade& g) {
  std::vector<double> got;
  for (const auto& o : g.outputs) got.push_back(o.got);
  return got;
}

// Why the deciding output has its verdict, in words.
std::string verdict_reason(verdict v, const case_grade& g, std::size_t j, const output_conditioning& q,
                           const case_conditioning& cc, scalar_type type) {
  const std::string c = std::to_string(cc.stable_constant) + " u";
  // Operations without exact derivatives (irrational values) have no printed figures: their
  // verdicts come from differences of the exact oracle (docs/verdicts.md).
  const std::string eta = q.defined ? "backward error " + scientific(q.backward_error * cc.unit_roundoff) + " (" +
                                          scientific(q.backward_error) + " u)"
                                    : std::string("backward error (from differences of the exact oracle)");
  switch (v) {
    case verdict::exact: return g.rejected ? "a correct rejection of a problem without an answer" : "correctly rounded";
    case verdict::faithful: return "one ulp from correctly rounded";
    case verdict::stable:
      if (!std::isfinite(g.outputs[j].got) || g.rejected)
        return "no value, but a divisor is within " + c + " of vanishing: ill-conditioned";
      return eta + " <= " + c + ": the problem's conditioning";
    case verdict::unstable: return eta + " > " + c + ": accuracy lost by the formula";
    case verdict::range:
      return std::string("an intermediate over- or underflows ") + std::string(to_string(type)) + ": the format's range";
    case verdict::wrong:
      if (g.rejected) return "the sentinel, yet the case has a well-conditioned answer";
      return eta + " > sqrt(u): no nearby input explains it";
    case verdict::nonfinite: return "NaN/Inf where the exact value exists and no divisor is near zero";
    case verdict::garbage: return "a finite number where no exact value exists";
  }
  return "";
}

std::string output_text(const case_grade& g, const test_case& c, const conventions& conv, std::size_t j,
                        const output_conditioning& q) {
  const output_grade& o = g.outputs[j];
  std::string t = output_name(c.op, j, conv) + ": got " + hex_string(o.got);
  if (!o.exact_defined) return t + ", no exact value";
  t += ", exact " + hex_string(o.reference);
  if (std::isfinite(o.got) && (o.counted() || std::isinf(o.reference)))
    t += ", " + ulps_text(o.ulps) + " ulps" + (q.defined ? ", relative error " + scientific(q.relative_error) : "");
  return t;
}

// The output that shows why the case has its verdict: the first with that verdict, a NaN/Inf
// one first when asked (the worst non-finite case).
std::size_t shown_output(const case_grade& g, bool prefer_nonfinite) {
  if (prefer_nonfinite)
    for (std::size_t j = 0; j < g.outputs.size(); ++j)
      if (g.outputs[j].v == g.v && !std::isfinite(g.outputs[j].got)) return j;
  return g.verdict_output;
}

void print_case(std::ostream& out, const std::string& title, const case_grade& g, const test_case& c,
                const conventions& conv, const report_style& style, bool prefer_nonfinite = false) {
  const std::size_t indent = 4;
  std::string head = title + " case " + std::to_string(g.id) + " [" + std::string(to_string(g.cls)) + "]: " +
                     std::string(to_string(g.v));
  if (g.misclassified) head += ", misclassified";
  emit(out, head, 2, style.width);
  const std::vector<double> got = outputs_of(g);
  const case_conditioning cc = conditioning(c, conv, got.data());
  const std::size_t j = shown_output(g, prefer_nonfinite);
  const output_conditioning q = j < cc.outputs.size() ? cc.outputs[j] : output_conditioning{};
  if (g.rejected && g.v == verdict::exact) {
    emit(out, "every output NaN/Inf or the sentinel: a correct rejection", indent, style.width);
  } else {
    emit(out, output_text(g, c, conv, j, q), indent, style.width);
    emit(out, verdict_reason(g.outputs[j].v, g, j, q, cc, c.type), indent, style.width);
    if (q.defined && std::isfinite(q.condition)) {
      // ‖got − exact‖ / ‖exact‖ has no value when an output is NaN or Inf.
      const std::string error = std::isfinite(cc.normwise_error)
                                    ? "normwise error " + scientific(cc.normwise_error)
                                    : std::string("no normwise error (an output is NaN or Inf)");
      emit(out, "condition " + scientific(q.condition) + ", normwise condition " + scientific(cc.normwise_condition) +
                    ", " + error,
           indent, style.width);
    }
  }
  if (g.scale && g.scale_pivot)
    emit(out, "graded up to scale: lambda " + scientific(*g.scale) + " from the pivot " +
                  output_name(c.op, *g.scale_pivot, conv),
         indent, style.width);
  if (g.exact_class && g.got_class) {
    std::string t = "class: exact " + std::string(to_string(*g.exact_class)) + ", image " + std::string(to_string(*g.got_class));
    if (g.reference_class) t += ", correctly rounded image " + std::string(to_string(*g.reference_class));
    emit(out, t, indent, style.width);
  }
  if (style.wide) {
    emit(out, "inputs (" + std::string(to_string(c.type)) + "), closeness to degeneracy 2^" + fixed1(c.closeness) + ":",
         indent, style.width);
    std::size_t k = 0;
    for (const auto& grp : signature(c.op).inputs) {
      std::string t = grp.name + " =";
      for (std::size_t i = 0; i < grp.size; ++i) t += (i ? ", " : " ") + hex_string(c.inputs[k + i]);
      emit(out, t, indent + 2, style.width);
      k += grp.size;
    }
    for (std::size_t i = 0; i < g.outputs.size(); ++i) {
      const output_conditioning& qi = i < cc.outputs.size() ? cc.outputs[i] : output_conditioning{};
      std::string line = pad_right(std::string(to_string(g.outputs[i].v)), verdict_width) + output_text(g, c, conv, i, qi);
      if (qi.defined)
        line += "; condition " + scientific(qi.condition) + ", backward error " + scientific(qi.backward_error) + " u";
      emit(out, line, indent + 2, style.width);
    }
  }
  out << std::string(indent, ' ') << "exact answer:\n" << wrap_command(reproducer_command(c, conv), 6, style.width) << '\n';
}

// A label cut to `room` columns keeps its start and its end, where names differ by type or class
// ("correctly-rounded-perspect..nfinite-f32" and "..nfinite-f64"): cut at the end only, two rows
// could read the same.
std::string shortened_label(const std::string& text, std::size_t room) {
  if (columns(text) <= room) return text;
  if (room < 8) return text.substr(0, room);
  const std::size_t kept = room - 2;
  const std::size_t tail = std::min<std::size_t>(12, kept / 3);
  return text.substr(0, kept - tail) + ".." + text.substr(text.size() - tail);
}

}  // namespace

std::string ulps_text(std::uint64_t ulps) {
  if (ulps < (std::uint64_t(1) << 16)) return std::to_string(ulps);
  return "2^" + fixed1(std::log2(static_cast<double>(ulps)));
}

std::string scientific(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char b[32];
  std::snprintf(b, sizeof b, "%.2e", x);
  return b;
}

std::string wrap_command(const std::string& command, std::size_t indent, std::size_t width) {
  std::istringstream words(command);
  std::vector<std::string> w;
  for (std::string word; words >> word;) {
    // An option and its value stay together ("--plane 1,2,3,4").
    if (!w.empty() && w.back().rfind("--", 0) == 0 && w.back().find(' ') == std::string::npos &&
        word.rfind("--", 0) != 0)
      w.back() += " " + word;
    else
      w.push_back(word);
  }
  std::string text(indent, ' ');
  std::size_t used = indent;
  bool fresh = true;  // nothing on the line yet
  const std::size_t limit = width - 2;  // room for " \"
  for (std::string word : w) {
    if (!fresh) {
      if (used + 1 + columns(word) > limit) {
        text += " \\\n" + std::string(indent + 2, ' ');
        used = indent + 2;
      } else {
        text += ' ';
        ++used;
      }
    }
    // A word too long for any line is cut after commas; the continuation starts at column 0 so
    // that the shell joins the pieces into one word.
    while (used + columns(word) > limit) {
      const std::size_t room = limit > used ? limit - used : 0;
      const std::size_t space = word.find(' ');
      if (space != std::string::npos && space + 2 <= room) {  // the option, then its value on the next line
        text += word.substr(0, space) + " \\\n" + std::string(indent + 2, ' ');
        word = word.substr(space + 1);
        used = indent + 2;
        continue;
      }
      const std::size_t cut = room > 1 ? word.rfind(',', room - 2) : std::string::npos;
      if (cut == std::string::npos) break;
      text += word.substr(0, cut + 1) + "\\\n";
      word = word.substr(cut + 1);
      used = 0;
    }
    text += word;
    used += columns(word);
    fresh = false;
  }
  return text;
}

void print_verdict_table(std::ostream& out, const std::vector<verdict_row>& rows, const report_style& style) {
  std::size_t label = 14;
  for (const auto& r : rows) label = std::max(label, columns(r.label));
  const std::size_t fixed = 1 + verdict_width + count_width * all_verdicts().size();
  label = std::min(label, style.width > fixed ? style.width - fixed : label);
  // The verdict names staggered over two header lines, right-aligned to their columns.
  std::string head[2] = {std::string(label + 1 + verdict_width, ' '), pad_right("implementation", label + 1) + "verdict   "};
  for (std::size_t v = 0; v < all_verdicts().size(); ++v) {
    const std::string name(to_string(all_verdicts()[v]));
    std::string& line = head[v % 2];
    const std::size_t end = label + 1 + verdict_width + count_width * (v + 1);
    if (line.size() + name.size() < end) line.append(end - name.size() - line.size(), ' ');
    else line += ' ';
    line += name;
  }
  out << head[0] << '\n' << head[1] << '\n';
  for (const auto& r : rows) {
    const std::string l = shortened_label(r.label, label);
    out << pad_right(l, label) << ' ' << pad_right(std::string(to_string(r.summary.worst_verdict)), verdict_width);
    for (std::size_t v = 0; v < all_verdicts().size(); ++v) {
      const std::size_t n = r.summary.verdicts[v];
      const std::string text = n ? std::to_string(n) : "-";
      out << std::string(count_width > text.size() ? count_width - text.size() : 1, ' ') << text;
    }
    out << '\n';
  }
}

void print_examples(std::ostream& out, const std::string& name, const grade_summary& s, const case_lookup& lookup,
                    const conventions_lookup& conv_of, const report_style& style) {
  std::string head = name + ": " + std::string(to_string(s.worst_verdict)) + " (worst of " + std::to_string(s.cases) +
                     (s.cases == 1 ? " case" : " cases") + "); max " + ulps_text(s.max_ulps) + " ulps";
  if (s.nonfinite) head += ", " + std::to_string(s.nonfinite) + " NaN/Inf outputs";
  if (s.garbage) head += ", " + std::to_string(s.garbage) + " garbage outputs";
  if (s.misclassified) head += ", " + std::to_string(s.misclassified) + " misclassified";
  emit(out, head, 0, style.width);
  // Per verdict worse than stable (and stable too with --wide): its worst finite case and its
  // worst case with a NaN/Inf output; a misclassified case when nothing else shows.
  const verdict shown_from = style.wide ? verdict::stable : verdict::unstable;
  bool any = false;
  for (const auto& g : s.examples) {
    if (g.v < shown_from) continue;
    bool nonfinite = false;
    for (const auto& o : g.outputs) nonfinite = nonfinite || !std::isfinite(o.got);
    print_case(out, nonfinite ? "non-finite" : "finite", g, lookup(g.id), conv_of(g.id), style, nonfinite);
    any = true;
  }
  if (!any && s.worst_finite)
    print_case(out, "worst", *s.worst_finite, lookup(s.worst_finite->id), conv_of(s.worst_finite->id), style);
  if (!any && s.worst_nonfinite)
    print_case(out, "worst non-finite", *s.worst_nonfinite, lookup(s.worst_nonfinite->id),
               conv_of(s.worst_nonfinite->id), style, true);
}

nlohmann::json verdict_counts_json(const grade_summary& s) {
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t v = 0; v < all_verdicts().size(); ++v) j[std::string(to_string(all_verdicts()[v]))] = s.verdicts[v];
  return j;
}

nlohmann::json conventions_json(const conventions& c) {
  return {{"storage", c.storage == storage_order::row_major ? "row-major" : "column-major"},
          {"vectors", c.vectors == vector_side::column ? "column" : "row"},
          {"light", c.light == light_sign::towards_light ? "towards-light" : "along-rays"},
          {"depth", std::string(to_string(c.depth))},
          {"sentinel", std::string(to_string(c.sentinel))},
          {"normalises_plane", c.normalises_plane},
          {"homogeneous", c.homogeneous},
          {"directional_only", c.directional_only},
          {"point_light_only", c.point_light_only},
          {"unit_normal", c.unit_normal},
          {"symmetric_view", c.symmetric_view},
          {"handedness", std::string(to_string(c.hand))},
          {"angle", std::string(to_string(c.angle))},
          {"clamps_behind_receiver", c.clamps_behind_receiver}};
}

nlohmann::json case_json(const case_grade& g, const test_case& c, const conventions& conv, bool every_output) {
  const std::vector<double> got = outputs_of(g);
  const case_conditioning cc = conditioning(c, conv, got.data());
  auto number = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(scientific(x)); };
  auto output = [&](std::size_t j) {
    const output_grade& o = g.outputs[j];
    nlohmann::json r{{"index", j},
                     {"name", output_name(c.op, j, conv)},
                     {"verdict", std::string(to_string(o.v))},
                     {"got", hex_string(o.got)},
                     {"expected", o.exact_defined ? nlohmann::json(hex_string(o.reference)) : nlohmann::json(nullptr)},
                     {"ulps", o.counted() ? nlohmann::json(o.ulps) : nlohmann::json(nullptr)},
                     {"bits", o.counted() ? nlohmann::json(o.bits) : nlohmann::json(nullptr)},
                     {"nonfinite", o.nonfinite},
                     {"garbage", o.garbage}};
    if (j < cc.outputs.size() && cc.outputs[j].defined) {
      const output_conditioning& q = cc.outputs[j];
      r["exact"] = number(q.value);
      r["condition"] = number(q.condition);
      r["relative_error"] = number(q.relative_error);
      r["backward_error_u"] = number(q.backward_error);
    }
    return r;
  };
  nlohmann::json j{{"id", g.id},
                   {"class", std::string(to_string(g.cls))},
                   {"verdict", std::string(to_string(g.v))},
                   {"rejected", g.rejected},
                   {"max_ulps", g.max_ulps},
                   {"nonfinite", g.nonfinite},
                   {"garbage", g.garbage},
                   {"misclassified", g.misclassified},
                   {"output", output(g.verdict_output)},
                   {"normwise", {{"condition", number(cc.normwise_condition)},
                                 {"error", number(cc.normwise_error)},
                                 {"backward_error_u", number(cc.normwise_backward_error)},
                                 {"ulps", number(cc.normwise_ulps)}}},
                   {"stable_constant", cc.stable_constant},
                   {"near_singular", cc.near_singular},
                   {"out_of_range", cc.out_of_range},
                   {"reproduce", reproducer_command(c, conv)}};
  j["closeness"] = std::isfinite(c.closeness) ? nlohmann::json(c.closeness) : nlohmann::json(scientific(c.closeness));
  if (g.scale) j["scale"] = *g.scale;
  if (g.scale_pivot) j["pivot"] = output_name(c.op, *g.scale_pivot, conv);
  if (g.exact_class) j["exact_class"] = std::string(to_string(*g.exact_class));
  if (g.got_class) j["image_class"] = std::string(to_string(*g.got_class));
  if (g.reference_class) j["reference_class"] = std::string(to_string(*g.reference_class));
  if (g.plane_value) j["plane_value"] = hex_string(*g.plane_value);
  nlohmann::json inputs = nlohmann::json::object();
  std::size_t k = 0;
  for (const auto& grp : signature(c.op).inputs) {
    nlohmann::json a = nlohmann::json::array();
    for (std::size_t i = 0; i < grp.size; ++i) a.push_back(hex_string(c.inputs[k++]));
    inputs[grp.name] = a;
  }
  j["inputs"] = inputs;
  if (every_output) {
    nlohmann::json all = nlohmann::json::array();
    for (std::size_t i = 0; i < g.outputs.size(); ++i) all.push_back(output(i));
    j["outputs"] = all;
  }
  return j;
}

nlohmann::json summary_json(const grade_summary& s, const case_lookup& lookup, const conventions_lookup& conv_of) {
  auto one = [&](const case_grade& g) { return case_json(g, lookup(g.id), conv_of(g.id)); };
  auto cases = [&](const std::vector<case_grade>& list) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& g : list) a.push_back(one(g));
    return a;
  };
  nlohmann::json j{{"cases", s.cases},
                   {"outputs", s.outputs},
                   {"verdict", std::string(to_string(s.worst_verdict))},
                   {"verdicts", verdict_counts_json(s)},
                   {"max_ulps", s.max_ulps},
                   {"median_ulps", s.median_ulps},
                   {"max_bits", s.max_bits},
                   {"bits_histogram", s.bits_histogram},
                   {"nonfinite", s.nonfinite},
                   {"garbage", s.garbage},
                   {"misclassified", s.misclassified},
                   {"worst", cases(s.worst)},
                   {"examples", cases(s.examples)}};
  j["worst_finite"] = s.worst_finite ? one(*s.worst_finite) : nlohmann::json(nullptr);
  j["worst_nonfinite"] = s.worst_nonfinite ? one(*s.worst_nonfinite) : nlohmann::json(nullptr);
  return j;
}

}  // namespace shadowproof::cli
