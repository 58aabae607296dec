// Shared helpers of the explanations, the text layout, and the explanations of the normal matrix
// and of a change of basis.
#include "shadowproof/explain/explain.h"

#include <algorithm>
#include <sstream>

#include "explain_detail.h"
#include "shadowproof/constructions/basis.h"
#include "shadowproof/constructions/normal_matrix.h"
#include "shadowproof/core/error.h"

namespace shadowproof {

namespace detail {

std::string str(const rational& q) { return to_string(q); }

std::string factor(const rational& q) { return q < 0 || q.get_den() != 1 ? "(" + str(q) + ")" : str(q); }

std::string list_text(const std::vector<rational>& v) {
  std::string s = "(";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + str(v[i]);
  return s + ")";
}

std::string vec_text(const vec4<rational>& v) { return list_text(std::vector<rational>(v.v.begin(), v.v.end())); }

std::string point_text(const point3& p) { return list_text({p[0], p[1], p[2]}); }

std::vector<rational> xyz(const vec4<rational>& v) { return {v[0], v[1], v[2]}; }

point3 xyz3(const vec4<rational>& v) { return {v[0], v[1], v[2]}; }

std::string dot_text(const vec4<rational>& a, const vec4<rational>& b, std::size_t count) {
  std::string s;
  rational sum = 0;
  for (std::size_t i = 0; i < count; ++i) {
    s += (i ? " + " : "") + factor(a[i]) + "·" + factor(b[i]);
    sum += a[i] * b[i];
  }
  return s + " = " + str(sum);
}

std::vector<std::string> matrix_lines(const std::vector<std::vector<rational>>& rows) {
  std::size_t width = 0;
  for (const auto& row : rows)
    for (const auto& x : row) width = std::max(width, str(x).size());
  std::vector<std::string> lines;
  for (const auto& row : rows) {
    std::string line = "[";
    for (std::size_t j = 0; j < row.size(); ++j) {
      const std::string s = str(row[j]);
      line += std::string(width - s.size() + (j == 0 ? 0 : 1), ' ') + s;
    }
    lines.push_back(line + " ]");
  }
  return lines;
}

std::vector<std::string> matrix_lines(const mat4<rational>& m) {
  std::vector<std::vector<rational>> rows;
  for (const auto& row : m.m) rows.emplace_back(row.begin(), row.end());
  return matrix_lines(rows);
}

explanation_step text_step(std::string why, std::vector<std::string> lines) {
  return {std::move(why), std::move(lines), std::nullopt};
}

explanation_step matrix_step(std::string why, const mat4<rational>& m, std::vector<std::string> lines) {
  return {std::move(why), std::move(lines), m};
}

std::string holds(bool ok) { return ok ? "holds" : "FAILS"; }

point3 affine_point(const vec4<rational>& v) { return {v[0] / v[3], v[1] / v[3], v[2] / v[3]}; }

std::string projected_line(const std::string& name, const mat4<rational>& M, const vec4<rational>& X) {
  const vec4<rational> image = M * X;
  std::string line = name + " " + vec_text(X) + " = " + vec_text(image);
  if (image[3] == 0) return line + ": w = 0, a point at infinity";
  return line + ", NDC " + point_text(affine_point(image));
}

point3 add(const point3& a, const point3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
point3 sub(const point3& a, const point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
point3 scale(const rational& s, const point3& a) { return {s * a[0], s * a[1], s * a[2]}; }
rational dot3(const point3& a, const point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
point3 cross(const point3& a, const point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
rational max_norm(const point3& a) { return std::max({abs(a[0]), abs(a[1]), abs(a[2])}); }
point3 with_length(const point3& a, const rational& length) { return scale(length / max_norm(a), a); }

point3 foot_on_plane(const point3& n, const rational& d, const point3& p) {
  return sub(p, scale((dot3(n, p) + d) / dot3(n, n), n));
}

std::vector<point3> plane_patch(const point3& n, const rational& d, const point3& centre, const std::vector<point3>& keep) {
  // The coordinate axis least aligned with n gives a direction not parallel to it.
  std::size_t least = 0;
  for (std::size_t i = 1; i < 3; ++i)
    if (abs(n[i]) < abs(n[least])) least = i;
  point3 e{0, 0, 0};
  e[least] = 1;
  const point3 u = cross(n, e), v = cross(n, u);
  rational a = 0, b = 0;
  for (const auto& k : keep) {
    const point3 rel = sub(foot_on_plane(n, d, k), centre);
    a = std::max(a, rational(abs(dot3(rel, u) / dot3(u, u))));
    b = std::max(b, rational(abs(dot3(rel, v) / dot3(v, v))));
  }
  // A margin of a quarter of the extent, and at least one unit of length along each direction.
  a = a * rational(5, 4) + rational(1) / max_norm(u);
  b = b * rational(5, 4) + rational(1) / max_norm(v);
  const auto corner = [&](int sa, int sb) { return add(centre, add(scale(sa * a, u), scale(sb * b, v))); };
  return {corner(1, 1), corner(-1, 1), corner(-1, -1), corner(1, -1)};
}

std::array<point3, 8> box_corners(const rational& x0, const rational& x1, const rational& y0, const rational& y1,
                                  const rational& z0, const rational& z1) {
  std::array<point3, 8> c;
  for (int i = 0; i < 8; ++i) c[i] = {(i & 1) ? x1 : x0, (i & 2) ? y1 : y0, (i & 4) ? z1 : z0};
  return c;
}

std::array<rational, 2> ndc_depth_span(depth_convention c) {
  return c == depth_convention::gl ? std::array<rational, 2>{-1, 1} : std::array<rational, 2>{0, 1};
}

figure_panel canonical_panel(depth_convention c, const mat4<rational>& M, const std::vector<vec4<rational>>& points,
                             const std::string& title) {
  figure_panel panel;
  panel.title = title;
  const depth_range<rational> near_far = ndc_depth_range<rational>(c);
  // The near plane in front: +z recedes when the far plane has the larger depth.
  panel.view = near_far.far_ndc > near_far.near_ndc ? figure_view::depth : figure_view::front;
  const auto z = ndc_depth_span(c);
  panel.hexahedron(box_corners(-1, 1, -1, 1, z[0], z[1]), figure_style::canonical);
  const depth_range<rational> planes = ndc_depth_range<rational>(c);
  panel.dot({0, 0, planes.near_ndc}, figure_style::axis, "near z = " + str(planes.near_ndc));
  panel.dot({0, 0, planes.far_ndc}, figure_style::axis, "far z = " + str(planes.far_ndc));
  for (const auto& X : points) {
    const vec4<rational> image = M * X;
    if (image[3] == 0) continue;
    const point3 p = affine_point(image);
    panel.dot(p, in_clip_volume(image, c) ? figure_style::image : figure_style::false_shadow, point_text(p));
  }
  return panel;
}

}  // namespace detail

using namespace detail;

std::string_view meaning_of(point_class c) {
  switch (c) {
    case point_class::on_receiver: return "on the receiver: the point is its own shadow";
    case point_class::shadow: return "a real shadow: the point lies between the light and the receiver";
    case point_class::behind_receiver:
      return "a false shadow: the point is behind the receiver, so no light reaches that image through it";
    case point_class::beyond_light:
      return "an anti-shadow: the point is farther from the receiver than the light, and its image lies on the "
             "far side of the light";
    case point_class::at_infinity:
      return "at infinity: the line from the light through the point is parallel to the receiver";
    case point_class::at_light: return "the light itself: its image is the zero vector, no point";
    case point_class::light_on_plane: return "the light lies on the receiver: every such point maps to the light";
    case point_class::light_parallel:
      return "the light is parallel to the receiver: every such point maps to the light's direction, at infinity";
    case point_class::line_in_plane:
      return "the line to the light lies in the receiver: the matrix gives no image (the point, on the receiver, "
             "is its own shadow)";
  }
  return "unknown";
}

cot_sign parse_cot_sign(std::string_view text) {
  if (text == "minus") return cot_sign::minus;
  if (text == "plus") return cot_sign::plus;
  throw error(errc::explain_cot_sign,
              "unknown --cot-sign '" + std::string(text) + "': expected minus (H has -cot, the library's oblique_shear) "
              "or plus (H has +cot, with tan(theta) = z/(x_p - x))");
}

// =============================================================================================
// Normal matrix

explanation explain_normal_matrix(const mat4<rational>& M, const std::vector<vec4<rational>>& normals) {
  explanation e;
  e.title = "Normal matrix G = (M⁻¹)ᵀ";
  e.steps.push_back(matrix_step(
      "A tangent t maps to M t. A normal n must map to some G n with (M t)ᵀ (G n) = tᵀ (Mᵀ G) n = 0 "
      "whenever tᵀ n = 0, which holds for all such pairs when Mᵀ G = I: G = (M⁻¹)ᵀ. (M itself only "
      "works when it is a rotation times a uniform scale.) The matrix M:",
      M));
  mat4<rational> cof;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) {
      const rational minor = minor3(M, i, j);
      cof(i, j) = ((i + j) % 2 == 0) ? minor : rational(-minor);
    }
  std::string expansion;
  rational det = 0;
  for (std::size_t j = 0; j < 4; ++j) {
    expansion += (j ? " + " : "") + factor(M(0, j)) + "·" + factor(cof(0, j));
    det += M(0, j) * cof(0, j);
  }
  e.steps.push_back(text_step("The determinant, expanded along the first row (m0j times cofactor C0j):",
                              {"det M = " + expansion + " = " + str(det)}));
  if (det == 0)
    throw error(errc::matrix_singular,
                "the matrix is singular (determinant 0): it flattens space, so neither its inverse "
                "nor its normal matrix (M⁻¹)ᵀ exists");
  e.steps.push_back(matrix_step(
      "The cofactor matrix cof(M): entry (i, j) is (−1)^(i+j) times the determinant of M without row i "
      "and column j. Mᵀ cof(M) = det(M) I, so cof(M) is the division-free normal matrix:",
      cof));
  const mat4<rational> G = (rational(1) / det) * cof;
  e.steps.push_back(matrix_step("G = cof(M)/det M:", G));
  e.steps.push_back(text_step("Check:", {"Mᵀ G = I (" + holds(transpose(M) * G == identity4<rational>()) + ")"}));
  if (M(3, 0) == 0 && M(3, 1) == 0 && M(3, 2) == 0 && M(3, 3) == 1)
    e.steps.push_back(text_step(
        "M is affine (last row 0 0 0 1), so on a normal (n, 0) only the upper-left 3x3 of G acts: it is "
        "the shaders' 3x3 normal matrix (A⁻¹)ᵀ of the linear part A."));

  // The figure follows a normal and a tangent perpendicular to it.
  std::vector<vec4<rational>> shown = normals;
  if (shown.empty()) shown.push_back(make_vec4<rational>(1, 1, 0, 0));
  for (const auto& n : normals) {
    const vec4<rational> Gn = G * n, Mn = M * n;
    e.steps.push_back(text_step(
        "The normal n = " + list_text(xyz(n)) + ":",
        {"G n = " + list_text(xyz(Gn)), "M n = " + list_text(xyz(Mn)) + (proportional(Gn, Mn) || (is_zero(Gn) && is_zero(Mn))
                                                                              ? " (the same direction: M keeps normals here)"
                                                                              : " (a different direction: M would tilt this normal)")}));
  }
  figure_panel before, after;
  before.title = "before: tangent t ⟂ normal n";
  after.title = "after: M t ⟂ G n, but not M n";
  const point3 origin{0, 0, 0};
  const point3 n3 = xyz3(shown.front());
  // A tangent: perpendicular to n, from n × e for the axis e least aligned with n.
  std::size_t least = 0;
  for (std::size_t i = 1; i < 3; ++i)
    if (abs(n3[i]) < abs(n3[least])) least = i;
  point3 axis{0, 0, 0};
  axis[least] = 1;
  const point3 t3 = cross(n3, axis);
  if (max_norm(n3) != 0 && max_norm(t3) != 0) {
    for (figure_panel* p : {&before, &after})
      for (int k = 0; k < 3; ++k) {
        point3 a{0, 0, 0};
        a[k] = 1;
        p->segment(origin, a, figure_style::axis, k == 0 ? "x" : (k == 1 ? "y" : "z"));
      }
    before.arrow(origin, with_length(n3, 1), figure_style::normal, "n = " + point_text(n3));
    before.arrow(origin, with_length(t3, 1), figure_style::tangent, "t = " + point_text(t3));
    const vec4<rational> t4 = make_vec4<rational>(t3[0], t3[1], t3[2], 0);
    const point3 Mt = xyz3(M * t4), Gn = xyz3(G * shown.front()), Mn = xyz3(M * shown.front());
    if (max_norm(Mt) != 0) after.arrow(origin, with_length(Mt, 1), figure_style::tangent, "M t = " + point_text(Mt));
    if (max_norm(Gn) != 0) after.arrow(origin, with_length(Gn, 1), figure_style::normal, "G n = " + point_text(Gn));
    if (max_norm(Mn) != 0 && !proportional(M * shown.front(), G * shown.front()))
      after.arrow(origin, with_length(Mn, 1), figure_style::wrong, "M n = " + point_text(Mn));
    e.picture.title = "Normals transform by G = (M⁻¹)ᵀ";
    e.picture.panels = {before, after};
    e.picture.caption = "the normal $n = " + point_text(n3) + "$ and the tangent $t = " + point_text(t3) +
                        "$ before and after the map: $G n$ stays perpendicular to $M t$" +
                        (proportional(M * shown.front(), G * shown.front()) ? "." : ", $M n$ (dashed) does not.");
  }
  e.result_name = "normal matrix G = (M⁻¹)ᵀ, as `shadowproof normal-matrix` prints it";
  e.result = G;
  return e;
}

// =============================================================================================
// Change of basis

explanation explain_change_of_basis(const std::array<rational, 3>& x_axis, const std::array<rational, 3>& y_axis,
                                    const std::array<rational, 3>& z_axis, const std::array<rational, 3>& origin,
                                    const std::vector<vec4<rational>>& points) {
  explanation e;
  e.title = "Change of basis: child axes X_c = " + point_text(x_axis) + ", Y_c = " + point_text(y_axis) +
            ", Z_c = " + point_text(z_axis) + ", origin O_c = " + point_text(origin);
  e.steps.push_back(text_step(
      "A child point with coordinates (a, b, c) is O_c + a X_c + b Y_c + c Z_c in the parent: the matrix with "
      "the columns X_c, Y_c, Z_c, O_c maps (a, b, c, 1) to it, and a direction (a, b, c, 0) ignores O_c."));
  const mat4<rational> M = child_to_parent(x_axis, y_axis, z_axis, origin);
  e.steps.push_back(matrix_step("Child → parent, M_c→p:", M));
  const rational det = determinant(M);
  e.steps.push_back(text_step("Its determinant (the volume of the three axes):", {"det M_c→p = " + str(det)}));
  const mat4<rational> inverse_matrix = inverse(M);  // throws matrix.singular for dependent axes
  e.steps.push_back(matrix_step("Parent → child is the inverse, M_p→c = adj(M)/det M:", inverse_matrix,
                                {"M_c→p M_p→c = I (" + holds(M * inverse_matrix == identity4<rational>()) + ")"}));
  const mat4<rational> shortcut = parent_to_child_orthonormal(x_axis, y_axis, z_axis, origin);
  if (is_orthonormal(x_axis, y_axis, z_axis)) {
    e.steps.push_back(matrix_step(
        "The axes are orthonormal (X·X = Y·Y = Z·Z = 1, X·Y = Y·Z = Z·X = 0, exactly), so the 3x3 part of the "
        "inverse is its transpose: seed 004's shortcut, rows X_c, Y_c, Z_c and the column −(X_c·O_c, Y_c·O_c, "
        "Z_c·O_c):",
        shortcut, {"equals the inverse (" + holds(shortcut == inverse_matrix) + ")"}));
  } else {
    e.steps.push_back(text_step(
        "The axes are not orthonormal, so the transpose is not the inverse: seed 004's shortcut (rows X_c, Y_c, "
        "Z_c) would give a different matrix.",
        {"shortcut = inverse: " + std::string(shortcut == inverse_matrix ? "yes" : "no")}));
  }
  figure_panel panel;
  panel.title = "parent axes (grey) and the child frame (green)";
  const point3 o{0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    point3 a{0, 0, 0};
    a[k] = 1;
    panel.arrow(o, a, figure_style::axis, k == 0 ? "x" : (k == 1 ? "y" : "z"));
  }
  panel.arrow(origin, add(origin, x_axis), figure_style::frame_axis, "X_c");
  panel.arrow(origin, add(origin, y_axis), figure_style::frame_axis, "Y_c");
  panel.arrow(origin, add(origin, z_axis), figure_style::frame_axis, "Z_c");
  panel.dot(origin, figure_style::point, "O_c = " + point_text(origin));
  for (const auto& X : points) {
    const vec4<rational> parent = M * X;
    e.steps.push_back(text_step("The child point (a, b, c) = " + list_text(xyz(X)) + ":",
                                {"M_c→p (a, b, c, 1) = " + vec_text(parent),
                                 "back: M_p→c " + vec_text(parent) + " = " + vec_text(inverse_matrix * parent)}));
    const point3 step1 = add(origin, scale(X[0], x_axis)), step2 = add(step1, scale(X[1], y_axis)),
                 step3 = add(step2, scale(X[2], z_axis));
    panel.segment(origin, step1, figure_style::walk);
    panel.segment(step1, step2, figure_style::walk);
    panel.segment(step2, step3, figure_style::walk);
    panel.dot(step3, figure_style::image, "child " + list_text(xyz(X)) + " = parent " + point_text(step3));
  }
  e.picture.title = "Change of basis";
  e.picture.panels = {panel};
  e.picture.caption = "the child frame with origin $O_c = " + point_text(origin) + "$ and axes $X_c = " +
                      point_text(x_axis) + "$, $Y_c = " + point_text(y_axis) + "$, $Z_c = " + point_text(z_axis) +
                      "$ in the parent's axes" + (points.empty() ? "" : "; each child point is reached by walking from $O_c$ along the axes (dashed)") + ".";
  e.result_name = "child → parent matrix M_c→p (columns X_c, Y_c, Z_c, O_c), as child_to_parent builds it";
  e.result = M;
  return e;
}

// =============================================================================================
// Text

namespace {

// Breaks a sentence into lines of at most `width` characters (counting UTF-8 code points) after
// the first line's `prefix`; continuation lines are indented by as many spaces.
std::string wrap(const std::string& text, const std::string& prefix, std::size_t width = 96) {
  const auto length = [](const std::string& s) {
    std::size_t n = 0;
    for (unsigned char ch : s) n += (ch & 0xC0) != 0x80;
    return n;
  };
  const std::string indent(length(prefix), ' ');
  std::istringstream words(text);
  std::string word, line = prefix, out;
  bool empty = true;
  while (words >> word) {
    if (!empty && length(line) + 1 + length(word) > width) {
      out += line + '\n';
      line = indent;
      empty = true;
    }
    line += (empty ? "" : " ") + word;
    empty = false;
  }
  return out + line + '\n';
}

}  // namespace

std::string to_text(const explanation& e) {
  std::ostringstream out;
  out << e.title << "\n\n";
  for (std::size_t i = 0; i < e.steps.size(); ++i) {
    const explanation_step& s = e.steps[i];
    out << wrap(s.why, std::to_string(i + 1) + ". ");
    for (const auto& line : s.lines) out << "     " << line << '\n';
    if (s.matrix)
      for (const auto& line : matrix_lines(*s.matrix)) out << "     " << line << '\n';
  }
  out << "\nResult: " << e.result_name << ":\n";
  for (const auto& line : matrix_lines(e.result)) out << "  " << line << '\n';
  return out.str();
}

}  // namespace shadowproof
