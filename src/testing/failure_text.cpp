// Failure messages of the matchers and the property runner.
#include "failure_text.h"

#include <cmath>
#include <cstdio>

#include "shadowproof/core/number.h"
#include "shadowproof/core/ulp.h"
#include "shadowproof/verify/exact_answer.h"

namespace shadowproof::detail {
namespace {

// Memory index j of a k x k matrix -> its canonical row-major index: column-major storage and
// row vectors each transpose (conventions.h), both together cancel.
std::size_t canonical_index(std::size_t j, std::size_t k, const conventions& conv) {
  const bool transposed = (conv.storage == storage_order::column_major) != (conv.vectors == vector_side::row);
  return (k == 0 || !transposed) ? j : (j % k) * k + j / k;
}

// The shortest decimal that reads back as x in the case's format, then x bit-exactly in hex.
std::string number_text(double x, scalar_type type) {
  if (!std::isfinite(x)) return hex_string(x);
  char b[40];
  std::snprintf(b, sizeof b, type == scalar_type::f32 ? "%.9g" : "%.17g", x);
  return std::string(b) + " (" + hex_string(x) + ")";
}

bool graded_up_to_scale(const test_case& c, const conventions& conv) {
  return signature(c.op).matrix_size &&
         (conv.homogeneous || (conv.normalises_plane && symmetries(c.op).plane_degree > 0));
}

}  // namespace

std::string inputs_text(const test_case& c) {
  std::string s;
  std::size_t k = 0;
  for (const auto& g : signature(c.op).inputs) {
    s += (s.empty() ? "" : ", ") + g.name + " (";
    for (std::size_t i = 0; i < g.size; ++i) s += (i ? ", " : "") + to_string(exact_value(c.inputs[k + i]));
    s += ")";
    k += g.size;
  }
  return s;
}

std::string conventions_text(const conventions& conv, operation op) {
  std::string s;
  auto add = [&s](const char* w) { s += (s.empty() ? "" : ", ") + std::string(w); };
  if (signature(op).matrix_size) {
    if (conv.storage == storage_order::column_major) add("column-major");
    if (conv.vectors == vector_side::row) add("row vectors");
  }
  if (conv.light == light_sign::along_rays) add("light along its rays");
  if (conv.depth != depth_convention::gl) s += (s.empty() ? "" : ", ") + std::string(to_string(conv.depth)) + " depth";
  if (conv.homogeneous) add("up to scale");
  if (conv.normalises_plane) add("normalised plane");
  if (conv.clamps_behind_receiver) add("points behind the receiver stay put");
  return s;
}

std::string failure_text(const test_case& c, const conventions& conv, const double* got, const case_judgement& j) {
  const auto& sig = signature(c.op);
  const auto exact = exact_answer(c, conv);
  // The exact values in the routine's memory order.
  std::vector<std::optional<rational>> in_memory(sig.output_count);
  for (std::size_t i = 0; i < sig.output_count; ++i) in_memory[i] = exact[canonical_index(i, sig.matrix_size, conv)];
  // Up to scale: λ = got[k] / exact[k] (grade.h), when both are usable.
  std::string s;
  if (graded_up_to_scale(c, conv) && j.scale_pivot) {
    const std::size_t k = *j.scale_pivot;
    const auto& e = in_memory[k];
    if (e && *e != 0 && std::isfinite(got[k]) && got[k] != 0) {
      const rational lambda = exact_value(got[k]) / *e;
      for (auto& v : in_memory)
        if (v) *v *= lambda;
      s += "  up to scale: exact values are λ times the exact matrix, λ = " + to_string(lambda) + " from entry " +
           output_name(c.op, canonical_index(k, sig.matrix_size, conv)) + "\n";
    }
  }
  for (const auto& e : j.entries) {
    const std::size_t canonical = canonical_index(e.output, sig.matrix_size, conv);
    s += "  " + output_name(c.op, canonical);
    if (canonical != e.output) s += " [stored at " + std::to_string(e.output) + "]";
    s += ": got " + number_text(e.got, c.type);
    const auto& x = in_memory[e.output];
    if (!x) {
      s += ", but no exact value exists";
      s += e.failure == entry_failure::garbage ? " (a finite number where none exists)\n" : "\n";
      continue;
    }
    s += ", exact " + to_string(*x) + ", correctly rounded " + number_text(e.rounded, c.type);
    if (e.failure == entry_failure::nonfinite) s += ": non-finite where the exact value is finite\n";
    else s += ": " + std::to_string(e.ulps) + (e.ulps == 1 ? " ulp\n" : " ulps\n");
  }
  if (j.exact_class)
    s += "  wrong side: the point is of class " + *j.exact_class + ", its float image of class " + *j.image_class +
         "\n";
  s += "  inputs (" + std::string(to_string(c.type)) + "): " + inputs_text(c) + "\n";
  s += "  exact answer: " + reproducer_command(c, conv) + "\n";
  return s;
}

}  // namespace shadowproof::detail
