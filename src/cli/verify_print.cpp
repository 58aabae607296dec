// Tables, JSON and reproducers shared by `shadowproof check` and `shadowproof grade`.
#include "verify_print.h"

#include <cstdio>
#include <iomanip>
#include <sstream>

#include "shadowproof/core/ulp.h"

namespace shadowproof::cli {
namespace {

std::string fixed1(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", x);
  return b;
}

std::string histogram_text(const std::vector<std::size_t>& h) {
  std::ostringstream s;
  for (std::size_t i = 0; i < h.size(); ++i) s << (i ? " " : "") << h[i];
  return s.str();
}

std::string hex_list(const test_case& c, std::size_t first, std::size_t n) {
  std::string s;
  for (std::size_t i = 0; i < n; ++i) s += (i ? "," : "") + hex_string(c.inputs[first + i]);
  return s;
}

}  // namespace

void print_table(std::ostream& out, const std::vector<report_row>& rows) {
  std::size_t w = 4;
  for (const auto& r : rows) w = std::max(w, r.impl.size());
  out << std::left << std::setw(static_cast<int>(w)) << "impl" << "  " << std::setw(19) << "op" << std::setw(16)
      << "class" << std::right << std::setw(7) << "cases" << std::setw(21) << "max ulps" << std::setw(21)
      << "median" << std::setw(6) << "bits" << "  " << std::left << std::setw(34)
      << "bits histogram 0|1|4|8|16|24|53|>53" << std::right << std::setw(7) << "miscls" << std::setw(8)
      << "nonfin" << std::setw(8) << "garbage" << '\n';
  for (const auto& r : rows) {
    const auto& s = r.summary;
    out << std::left << std::setw(static_cast<int>(w)) << r.impl << "  " << std::setw(19) << to_string(r.op)
        << std::setw(16) << r.cls << std::right << std::setw(7) << s.cases << std::setw(21) << s.max_ulps
        << std::setw(21) << s.median_ulps << std::setw(6) << fixed1(s.max_bits) << "  " << std::left
        << std::setw(34) << histogram_text(s.bits_histogram) << std::right << std::setw(7) << s.misclassified
        << std::setw(8) << s.nonfinite << std::setw(8) << s.garbage << '\n';
  }
}

void print_worst(std::ostream& out, const std::string& title, const case_grade& g, const test_case& c,
                 const conventions& conv) {
  const output_grade& o = g.outputs[g.worst_output];
  out << "  " << title << " [" << to_string(g.cls) << "] case " << g.id << ", output " << g.worst_output << ": got "
      << hex_string(o.got);
  if (!o.exact_defined) {
    out << ", exact undefined" << (o.garbage ? " (finite garbage)" : "");
  } else {
    out << ", exact rounds to " << hex_string(o.reference);
    if (o.nonfinite) out << " (non-finite where the exact value is finite)";
    else out << " (" << o.ulps << " ulps, " << fixed1(o.bits) << " bits)";
  }
  if (g.exact_class)
    out << "; class exact " << to_string(*g.exact_class) << ", image " << to_string(*g.got_class)
        << (g.misclassified ? " (MISCLASSIFIED)" : "");
  out << "\n    inputs (" << to_string(c.type) << "):";
  std::size_t k = 0;
  for (const auto& grp : signature(c.op).inputs) {
    out << ' ' << grp.name << '=' << hex_list(c, k, grp.size);
    k += grp.size;
  }
  out << "\n    exact:  " << shadowproof::reproducer_command(c, conv) << '\n';
}

nlohmann::json worst_json(const case_grade& g, const test_case& c, const conventions& conv) {
  const output_grade& o = g.outputs[g.worst_output];
  nlohmann::json j{{"id", g.id},
                   {"class", std::string(to_string(g.cls))},
                   {"output", g.worst_output},
                   {"got", hex_string(o.got)},
                   {"exact_defined", o.exact_defined},
                   {"ulps", o.counted() ? nlohmann::json(o.ulps) : nlohmann::json(nullptr)},
                   {"bits", o.counted() ? nlohmann::json(o.bits) : nlohmann::json(nullptr)},
                   {"nonfinite", g.nonfinite},
                   {"garbage", g.garbage},
                   {"misclassified", g.misclassified},
                   {"reproduce", shadowproof::reproducer_command(c, conv)}};
  j["expected"] = o.exact_defined ? nlohmann::json(hex_string(o.reference)) : nlohmann::json(nullptr);
  nlohmann::json inputs = nlohmann::json::object();
  std::size_t k = 0;
  for (const auto& grp : signature(c.op).inputs) {
    nlohmann::json a = nlohmann::json::array();
    for (std::size_t i = 0; i < grp.size; ++i) a.push_back(hex_string(c.inputs[k++]));
    inputs[grp.name] = a;
  }
  j["inputs"] = inputs;
  if (g.exact_class) {
    j["exact_class"] = std::string(to_string(*g.exact_class));
    j["image_class"] = std::string(to_string(*g.got_class));
  }
  if (g.plane_value) j["plane_value"] = hex_string(*g.plane_value);
  return j;
}

nlohmann::json conventions_json(const conventions& c) {
  return {{"storage", c.storage == storage_order::row_major ? "row-major" : "column-major"},
          {"vectors", c.vectors == vector_side::column ? "column" : "row"},
          {"light", c.light == light_sign::towards_light ? "towards-light" : "along-rays"},
          {"depth", std::string(to_string(c.depth))},
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

nlohmann::json summary_json(const grade_summary& s, const case_lookup& lookup, const conventions_lookup& conv_of) {
  nlohmann::json worst = nlohmann::json::array();
  for (const auto& g : s.worst) worst.push_back(worst_json(g, lookup(g.id), conv_of(g.id)));
  return {{"cases", s.cases},
          {"outputs", s.outputs},
          {"max_ulps", s.max_ulps},
          {"median_ulps", s.median_ulps},
          {"max_bits", s.max_bits},
          {"bits_histogram", s.bits_histogram},
          {"nonfinite", s.nonfinite},
          {"garbage", s.garbage},
          {"misclassified", s.misclassified},
          {"worst", worst}};
}

}  // namespace shadowproof::cli
