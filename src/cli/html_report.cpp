// The HTML report: inline CSS, one inline SVG scatter per implementation, no external resource.
#include "html_report.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "shadowproof/core/io.h"
#include "shadowproof/core/svg.h"

namespace shadowproof::cli {
namespace {

// Verdicts and failure kinds, from best to worst, coloured as a reader expects: green for
// answers a correct program may give, amber for a formula losing accuracy or the format's range
// running out, red for answers no nearby input explains.
std::string badge_class(const std::string& verdict) {
  if (verdict == "exact" || verdict == "faithful" || verdict == "stable" || verdict == "pass") return "good";
  if (verdict == "unstable" || verdict == "range") return "warn";
  return "bad";
}

const char* const style_sheet = R"(
body{font:14px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,"DejaVu Sans",sans-serif;color:#1d2330;
  margin:0;background:#f4f5f7}
main{max-width:1100px;margin:0 auto;padding:20px 28px 60px}
h1{font-size:22px;margin:8px 0 4px}h2{font-size:17px;margin:0 0 8px;word-break:break-all}
h3{font-size:14px;margin:14px 0 6px}
p.cmd,pre{font:12.5px/1.4 ui-monospace,"DejaVu Sans Mono",Menlo,Consolas,monospace}
p.cmd{color:#555;margin:0 0 10px;word-break:break-all}
table{border-collapse:collapse;background:#fff;margin:8px 0 18px}
th,td{text-align:left;padding:4px 10px;border-bottom:1px solid #e3e5ea;vertical-align:top}
th{background:#eceef2;font-weight:600}
td.n{text-align:right;font-variant-numeric:tabular-nums}
section{background:#fff;border:1px solid #dcdfe5;border-radius:6px;padding:14px 18px;margin:18px 0}
.badge{display:inline-block;border-radius:10px;padding:1px 9px;font-weight:600;font-size:12.5px;color:#fff}
.good{background:#2e7d32}.warn{background:#b26a00}.bad{background:#c62828}
.failed{outline:2px solid #c62828}
.facts span{display:inline-block;margin:0 14px 4px 0}.facts b{font-weight:600}
.conventions span{background:#f1f3f6;border-radius:4px;padding:1px 7px;margin:0 6px 5px 0}
.grid{display:flex;flex-wrap:wrap;gap:18px;align-items:flex-start}
pre{background:#f6f8fa;border:1px solid #e3e5ea;border-radius:4px;padding:8px 10px;margin:4px 0 10px;
  overflow-x:auto;white-space:pre}
pre.repro{user-select:all;background:#fffbe6;border-color:#e8d9a0}
.muted{color:#666}
)";

// Cell indices of the closeness axis for the values that are not numbers of it.
constexpr long long degenerate_cell = std::numeric_limits<long long>::min();
constexpr long long unknown_cell = std::numeric_limits<long long>::max();
constexpr long long above_cell = unknown_cell - 1;

}  // namespace

void point_cloud::add(double closeness, double bits, bool nonfinite) {
  ++cases_;
  long long x = unknown_cell;
  if (std::isinf(closeness)) x = closeness < 0 ? degenerate_cell : above_cell;
  else if (!std::isnan(closeness)) x = std::llround(std::min(std::max(closeness, -1e6), 1e6) * 16);
  // Non-finite cases sit in a band whatever their bits.
  const long long y = nonfinite || std::isnan(bits) ? 0 : std::llround(std::min(std::max(bits, 0.0), 64.0) * 8);
  ++cells_[{nonfinite, x, y}];
}

std::vector<html_point> point_cloud::points() const {
  std::vector<html_point> out;
  out.reserve(cells_.size());
  for (const auto& [cell, n] : cells_) {
    const auto [nonfinite, x, y] = cell;
    html_point p;
    p.closeness = x == degenerate_cell ? -std::numeric_limits<double>::infinity()
                  : x == unknown_cell  ? std::numeric_limits<double>::quiet_NaN()
                  : x == above_cell    ? std::numeric_limits<double>::infinity()
                                       : static_cast<double>(x) / 16;
    p.bits = static_cast<double>(y) / 8;
    p.nonfinite = nonfinite;
    p.count = n;
    out.push_back(p);
  }
  return out;
}

namespace {

struct plot_range {
  double xmin = -10, xmax = 2;
};

// x from the finite closeness values; the exactly degenerate ones get a band of their own.
plot_range range_of(const std::vector<html_point>& points) {
  double lo = 0, hi = 0;
  for (const auto& p : points)
    if (std::isfinite(p.closeness)) {
      lo = std::min(lo, p.closeness);
      hi = std::max(hi, p.closeness);
    }
  plot_range r;
  r.xmin = std::floor(lo / 10) * 10 - 2;
  r.xmax = std::max(hi, 0.0) + 2;
  return r;
}

// Bits of error of each case against its log2 closeness to degeneracy. Cases falling on the
// same pixel are drawn once, darker the more there are, so a plot of a million cases stays a
// few kilobytes. Cases exactly on the degeneracy sit in a band at the left.
std::string scatter(const std::vector<html_point>& points, const std::string& colour) {
  const double W = 560, H = 280, left = 46, band = 34, right = 12, top = 26, bottom = 40;
  const plot_range r = range_of(points);
  const double ymax = 70;  // 0..64 bits, then the band of non-finite results
  const double x0 = left + band + 6;  // where the finite closeness values start
  auto sx = [&](double x) { return x0 + (x - r.xmin) / (r.xmax - r.xmin) * (W - x0 - right); };
  auto sy = [&](double y) { return H - bottom - y / ymax * (H - top - bottom); };
  svg_document f(W, H, 10);
  for (int y = 0; y <= 64; y += 16) {
    f.line(left, sy(y), W - right, sy(y), "#e2e4e8");
    f.text(left - 6, sy(y) + 3.5, std::to_string(y), "end");
  }
  const double span = r.xmax - r.xmin;
  const double step = span > 400 ? 100 : span > 200 ? 50 : span > 80 ? 20 : span > 30 ? 10 : 5;
  for (double x = std::ceil(r.xmin / step) * step; x <= r.xmax; x += step) {
    f.line(sx(x), top, sx(x), H - bottom, "#eef0f3");
    f.text(sx(x), H - bottom + 13, std::to_string(static_cast<long long>(x)), "middle");
  }
  f.rect(left, top, band, H - bottom - top, "#f3eef8");
  f.text(left + band / 2, H - bottom + 13, "on it", "middle");
  f.rect(left, sy(ymax), W - right - left, sy(64) - sy(ymax), "#fbeaea");
  f.text(W - right - 4, sy(66) + 3.5, "NaN / Inf / garbage", "end", "#a33");
  f.text(12, (top + H - bottom) / 2, "bits of error", "middle", "", 0, -90);
  f.text((x0 + W - right) / 2, H - 8, "log2 closeness to degeneracy (left: closer)", "middle");
  std::map<std::pair<long, long>, std::size_t> pixels;
  for (const auto& p : points) {
    if (std::isnan(p.closeness)) continue;
    const double px = std::isfinite(p.closeness) ? sx(p.closeness) : left + band / 2;
    const double y = p.nonfinite ? 67 : std::min(std::max(p.bits, 0.0), 64.0);
    pixels[{std::lround(px * 0.5), std::lround(sy(y) * 0.5)}] += p.count;  // 2-pixel cells
  }
  for (const auto& [cell, n] : pixels) {
    const double opacity = std::min(1.0, 0.35 + 0.13 * std::log2(static_cast<double>(n)));
    f.circle(static_cast<double>(cell.first) * 2.0, static_cast<double>(cell.second) * 2.0, 2.2, colour, opacity);
  }
  std::size_t cases = 0;
  for (const auto& p : points) cases += p.count;
  f.text(left, 15, std::to_string(cases) + " cases", "start", "#555");
  return f.str();
}

void facts_line(std::ostringstream& h, const std::vector<std::pair<std::string, std::string>>& facts) {
  h << "<p class=\"facts\">";
  for (const auto& [label, value] : facts)
    h << "<span><b>" << html_escape(label) << "</b> " << html_escape(value) << "</span>";
  h << "</p>\n";
}

std::string anchor(std::size_t i) { return "impl-" + std::to_string(i); }

void section_html(std::ostringstream& h, const html_section& s, std::size_t index) {
  h << "<section id=\"" << anchor(index) << "\"" << (s.failed ? " class=\"failed\"" : "") << ">\n<h2>"
    << html_escape(s.name) << " <span class=\"badge " << badge_class(s.verdict) << "\">" << html_escape(s.verdict)
    << "</span></h2>\n";
  facts_line(h, s.facts);
  h << "<div class=\"grid\">\n<div>" << scatter(s.points, "#1f5fa8") << "</div>\n<div>\n";
  if (!s.counts.empty()) {
    h << "<table class=\"counts\"><tr><th>" << html_escape(s.counts_label) << "</th><th>cases</th></tr>\n";
    for (const auto& [name, n] : s.counts)
      h << "<tr><td><span class=\"badge " << badge_class(name) << "\">" << html_escape(name)
        << "</span></td><td class=\"n\">" << n << "</td></tr>\n";
    h << "</table>\n";
  }
  h << "</div>\n</div>\n";
  if (!s.conventions.empty()) {
    h << "<h3>Conventions declared</h3>\n<p class=\"facts conventions\">";
    for (const auto& [name, value] : s.conventions)
      h << "<span>" << html_escape(name) << " <b>" << html_escape(value) << "</b></span>";
    h << "</p>\n";
  }
  if (s.worst.empty()) {
    h << "<p class=\"muted\">No case worse than faithful: nothing to reproduce.</p>\n";
  } else {
    h << "<h3>Worst cases</h3>\n";
    for (const auto& c : s.worst) {
      h << "<p><b>" << html_escape(c.title) << "</b></p>\n";
      if (!c.details.empty()) {
        h << "<pre>";
        for (const auto& line : c.details) h << html_escape(line) << '\n';
        h << "</pre>\n";
      }
      if (!c.reproducer.empty()) h << "<pre class=\"repro\">" << html_escape(c.reproducer) << "</pre>\n";
    }
  }
  h << "</section>\n";
}

}  // namespace

std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += ch;
    }
  return out;
}

std::string render_html(const html_page& page) {
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
    << "<title>" << html_escape(page.title) << "</title>\n<style>" << style_sheet << "</style>\n</head>\n<body>\n<main>\n"
    << "<h1>" << html_escape(page.title) << "</h1>\n";
  if (!page.command.empty()) h << "<p class=\"cmd\">$ " << html_escape(page.command) << "</p>\n";
  for (const auto& line : page.summary) h << "<p>" << html_escape(line) << "</p>\n";
  h << "<table class=\"overview\"><tr><th>implementation</th><th>verdict</th>";
  const bool with_counts = std::any_of(page.sections.begin(), page.sections.end(),
                                       [](const html_section& s) { return !s.facts.empty(); });
  if (with_counts) h << "<th>" << html_escape(page.sections.front().facts.front().first) << "</th>";
  h << "<th>worst cases</th></tr>\n";
  for (std::size_t i = 0; i < page.sections.size(); ++i) {
    const auto& s = page.sections[i];
    h << "<tr><td><a href=\"#" << anchor(i) << "\">" << html_escape(s.name) << "</a></td><td><span class=\"badge "
      << badge_class(s.verdict) << "\">" << html_escape(s.verdict) << "</span></td>";
    if (with_counts) h << "<td>" << (s.facts.empty() ? "" : html_escape(s.facts.front().second)) << "</td>";
    h << "<td class=\"n\">" << s.worst.size() << "</td></tr>\n";
  }
  h << "</table>\n";
  for (std::size_t i = 0; i < page.sections.size(); ++i) section_html(h, page.sections[i], i);
  h << "</main>\n</body>\n</html>\n";
  return h.str();
}

void write_html(const std::string& path, const html_page& page) { write_file_atomically(path, render_html(page)); }

std::string shell_command_line(int argc, const char* const* argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    std::string word = argv[i];
    if (i == 0) word = "shadowproof";  // the program as a user calls it, not the build path
    const bool plain = !word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                               "0123456789-_./=:,+@%") == std::string::npos;
    if (!line.empty()) line += ' ';
    if (plain) {
      line += word;
    } else {
      line += '\'';
      for (char ch : word) line += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
      line += '\'';
    }
  }
  return line;
}

}  // namespace shadowproof::cli
