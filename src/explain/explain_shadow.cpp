// Explanations of the shadow matrix (with the class of each point), the reflection matrix and the
// reflection by a change of frame, each with a figure of the user's case.
#include "explain_detail.h"
#include "shadowproof/constructions/reflect.h"
#include "shadowproof/constructions/shadow.h"
#include "shadowproof/core/error.h"

namespace shadowproof {

using namespace detail;

namespace {

// The parameter that decides the class, as text: λ* = s/(s − w t) for a point light, μ = t/s for a
// directional one (see docs/derivations.md, "Real shadows, false shadows, ...").
std::string class_parameter(const rational& s, const rational& t, const rational& w) {
  if (s == 0) return "";
  if (w == 0) {
    const rational mu = t / s;
    return "μ = t/s = " + str(mu) + (mu > 0 ? " > 0: downstream of V" : (mu < 0 ? " < 0: upstream of V" : ""));
  }
  if (s == w * t) return "s = w t: the line from the light through V is parallel to the receiver";
  const rational lambda = s / (s - w * t);
  std::string where = lambda > 1 ? " > 1" : (lambda > 0 && lambda < 1 ? ", between 0 and 1" : (lambda < 0 ? " < 0" : ""));
  return "λ* = s/(s − w t) = " + str(lambda) + where + " on the line light + λ (V − light)";
}

figure_style image_style(point_class c) {
  switch (c) {
    case point_class::shadow: return figure_style::real_shadow;
    case point_class::behind_receiver: return figure_style::false_shadow;
    case point_class::beyond_light: return figure_style::anti_shadow;
    default: return figure_style::image;
  }
}

std::string short_class(point_class c) {
  switch (c) {
    case point_class::shadow: return "real shadow";
    case point_class::behind_receiver: return "false shadow";
    case point_class::beyond_light: return "anti-shadow";
    case point_class::at_infinity: return "image at infinity";
    case point_class::on_receiver: return "on the receiver";
    default: return std::string(to_string(c));
  }
}

figure shadow_figure(const plane<rational>& P, const light<rational>& L, const std::vector<vec4<rational>>& points,
                     const mat4<rational>& M) {
  const point3 n{P.a(), P.b(), P.c()};
  const rational& d = P.d();
  const bool point_light = L.is_point();
  const point3 ell = point_light ? point3{L.l[0] / L.l[3], L.l[1] / L.l[3], L.l[2] / L.l[3]} : point3{0, 0, 0};
  const point3 towards{L.l[0], L.l[1], L.l[2]};
  std::vector<point3> keep;
  if (point_light) keep.push_back(ell);
  for (const auto& V : points) {
    keep.push_back(xyz3(V));
    const vec4<rational> image = M * V;
    if (image[3] != 0) keep.push_back(affine_point(image));
  }
  const point3 centre = foot_on_plane(n, d, point_light ? ell : (points.empty() ? point3{0, 0, 0} : xyz3(points.front())));
  figure_panel panel;
  panel.title = "receiver, light, points and their images";
  const std::vector<point3> patch = plane_patch(n, d, centre, keep);
  panel.polygon(patch, figure_style::receiver, "P = (" + str(P.a()) + ", " + str(P.b()) + ", " + str(P.c()) + ", " + str(d) + ")");
  const rational reach = max_norm(sub(keep.empty() ? centre : keep.front(), centre)) + 1;
  if (point_light) {
    panel.dot(ell, figure_style::light, "light " + point_text(ell));
  } else {
    // Beside the receiver, so that it does not cover the points.
    panel.arrow(add(patch[1], with_length(towards, reach)), patch[1], figure_style::light_travel, "light travels along −L");
  }
  std::string caption;
  const rational s = dot(P.p, L.l);
  for (const auto& V : points) {
    const point3 v = xyz3(V);
    const point_class c = classify_point(P, L, V);
    const vec4<rational> image4 = M * V;
    panel.dot(v, figure_style::point, "V = " + point_text(v));
    caption += (caption.empty() ? "" : "; ") + std::string("$V = ") + point_text(v) + "$: " + short_class(c);
    if (image4[3] == 0) {
      // No finite image: show where the line goes.
      if (point_light && c == point_class::at_infinity) {
        panel.segment(ell, v, figure_style::ray);
        panel.arrow(v, add(v, sub(v, ell)), figure_style::extension, "image at infinity");
      } else if (!point_light && c == point_class::light_parallel) {
        panel.arrow(v, sub(v, with_length(towards, reach)), figure_style::extension, "image at infinity");
      }
      continue;
    }
    const point3 img = affine_point(image4);
    caption += " at $" + point_text(img) + "$";
    if (c == point_class::on_receiver || c == point_class::line_in_plane) continue;
    if (point_light) {
      switch (c) {
        case point_class::shadow:
          panel.segment(ell, v, figure_style::ray);
          panel.segment(v, img, figure_style::ray);
          break;
        case point_class::behind_receiver:
          panel.segment(ell, img, figure_style::ray);
          panel.segment(img, v, figure_style::extension);
          break;
        case point_class::beyond_light:
          panel.segment(ell, v, figure_style::ray);
          panel.segment(ell, img, figure_style::extension);
          break;
        default: panel.segment(v, img, figure_style::extension); break;
      }
    } else {
      const point3 upstream = c == point_class::shadow ? v : img;
      panel.segment(add(upstream, with_length(towards, reach)), upstream, figure_style::ray);
      panel.segment(v, img, c == point_class::shadow ? figure_style::ray : figure_style::extension);
    }
    panel.dot(img, image_style(c), short_class(c) + " " + point_text(img));
  }
  figure f;
  f.title = "Shadow of points on the plane P = (" + str(P.a()) + ", " + str(P.b()) + ", " + str(P.c()) + ", " + str(d) +
            ")";
  f.panels = {panel};
  f.caption = std::string("the receiver $P = ") + vec_text(P.p) + "$ (grey), " +
              (point_light ? "the point light at $" + point_text(ell) + "$"
                           : "the directional light $L = " + vec_text(L.l) + "$ (the arrow shows its travel, $-L$)") +
              (s == 0 ? " (parallel to the receiver)" : "") + (caption.empty() ? "." : "; " + caption + ".");
  return f;
}

}  // namespace

// =============================================================================================
// Shadow

explanation explain_shadow(const plane<rational>& P, const light<rational>& L, const std::vector<vec4<rational>>& points) {
  explanation e;
  e.title = "Shadow matrix for the plane P = " + vec_text(P.p) + " and the light L = " + vec_text(L.l);
  const std::string light_text =
      L.is_directional() ? "a directional light; (x, y, z) = " + list_text(xyz(L.l)) + " points towards it"
                         : "a point light at " + list_text({L.l[0] / L.l[3], L.l[1] / L.l[3], L.l[2] / L.l[3]});
  e.steps.push_back(text_step("The receiver is the set of points X with P·X = 0; the light is " + light_text + ".",
                              {"P = " + vec_text(P.p), "L = " + vec_text(L.l)}));

  const rational s = dot(P.p, L.l);
  e.steps.push_back(text_step(
      "The line through a point V and the light is V + kL. It meets the plane where "
      "P·(V + kL) = P·V + k (P·L) = 0, so everything depends on P·L:",
      {"P·L = " + dot_text(P.p, L.l, 4)}));
  if (s != 0) {
    e.steps.push_back(text_step(
        "P·L ≠ 0, so k = −(P·V)/(P·L) and the shadow of V is V − (P·V)/(P·L) L. Multiplied by P·L "
        "(a homogeneous vector and its multiples are the same point) it is (P·L) V − (P·V) L = "
        "((P·L) I − L Pᵀ) V: the shadow matrix is M = (P·L) I − L Pᵀ."));
  } else {
    e.steps.push_back(text_step(
        std::string("P·L = 0: ") +
        (L.is_directional() ? "the light is parallel to the plane" : "the light lies on the plane") +
        ". No k solves the equation for a point off the plane; M = (P·L) I − L Pᵀ = −L Pᵀ still "
        "holds but has rank 1: every point off the plane maps to the light itself."));
  }
  const mat4<rational> sI = s * identity4<rational>();
  const mat4<rational> LP = outer(L.l, P.p);
  e.steps.push_back(matrix_step("(P·L) I, with P·L = " + str(s) + ":", sI));
  e.steps.push_back(matrix_step("L Pᵀ: row i is L_i times P = " + vec_text(P.p) + ":", LP));
  const mat4<rational> M = sI - LP;
  e.steps.push_back(matrix_step("M = (P·L) I − L Pᵀ:", M));

  vec4<rational> PM;
  for (std::size_t j = 0; j < 4; ++j)
    for (std::size_t i = 0; i < 4; ++i) PM[j] += P.p[i] * M(i, j);
  e.steps.push_back(text_step(
      "Every image lies on the plane: Pᵀ M = (P·L) Pᵀ − (P·L) Pᵀ = 0, so P·(M V) = 0 for every V.",
      {"Pᵀ M = " + vec_text(PM) + " (" + holds(is_zero(PM)) + ")"}));
  if (!points.empty())
    e.steps.push_back(text_step(
        "Not every image is a shadow. With s = P·L, t = P·V and w = L_w, the line from a point light through V "
        "meets the receiver at λ* = s/(s − w t) on light + λ (V − light): beyond V (λ* > 1) it is a real shadow, "
        "between the light and V (0 < λ* < 1) a false shadow, behind the light (λ* < 0) an anti-shadow, and "
        "s = w t puts it at infinity. For a directional light the image is V − μ L with μ = t/s, a real shadow "
        "when μ > 0."));

  for (const auto& V : points) {
    std::vector<std::string> lines;
    const rational t = dot(P.p, V);
    lines.push_back("P·V = " + dot_text(P.p, V, 4));
    if (s != 0) {
      const rational k = -t / s;
      lines.push_back("k = −(P·V)/(P·L) = −(" + str(t) + ")/(" + str(s) + ") = " + str(k));
      lines.push_back("V + kL = " + vec_text(V + k * L.l));
    }
    const vec4<rational> image = M * V;
    lines.push_back("M V = (P·L) V − (P·V) L = " + str(s) + "·" + vec_text(V) + " − " + factor(t) + "·" + vec_text(L.l) +
                    " = " + vec_text(image));
    if (image[3] != 0)
      lines.push_back("affine image (x/w, y/w, z/w) = " + list_text({image[0] / image[3], image[1] / image[3], image[2] / image[3]}));
    else
      lines.push_back(is_zero(image) ? "M V = 0: no point (V and the light span a line in the plane, or V is the light)"
                                     : "w = 0: the image is a point at infinity");
    const point_class c = classify_point(P, L, V);
    const std::string parameter = class_parameter(s, t, L.l[3]);
    lines.push_back("class " + std::string(to_string(c)) + ": " + std::string(meaning_of(c)) +
                    (parameter.empty() ? "" : " (" + parameter + ")"));
    e.steps.push_back(text_step("The point V = " + list_text(xyz(V)) + ":", lines));
  }
  e.result_name = "shadow matrix M = (P·L) I − L Pᵀ (image = M V), as `shadowproof shadow` prints it";
  e.result = M;
  e.picture = shadow_figure(P, L, points, M);
  return e;
}

// =============================================================================================
// Reflection

namespace {

figure mirror_figure(const plane<rational>& P, const mat4<rational>& M, const std::vector<vec4<rational>>& points,
                     const std::string& title) {
  const point3 n{P.a(), P.b(), P.c()};
  std::vector<point3> keep;
  for (const auto& X : points) {
    keep.push_back(xyz3(X));
    keep.push_back(xyz3(M * X));
  }
  const point3 centre = foot_on_plane(n, P.d(), points.empty() ? point3{0, 0, 0} : xyz3(points.front()));
  figure_panel panel;
  panel.title = "mirror, points and their images";
  const std::vector<point3> patch = plane_patch(n, P.d(), centre, keep);
  panel.polygon(patch, figure_style::mirror, "mirror " + vec_text(P.p));
  panel.arrow(patch[1], add(patch[1], with_length(n, 1)), figure_style::normal, "n = " + point_text(n));
  std::string caption;
  for (const auto& X : points) {
    const point3 x = xyz3(X), image = xyz3(M * X);
    panel.segment(x, image, figure_style::link);
    panel.dot(x, figure_style::point, "X = " + point_text(x));
    panel.dot(image, figure_style::image, "X' = " + point_text(image));
    caption += (caption.empty() ? "" : "; ") + std::string("$X = ") + point_text(x) + "$ goes to $X' = " + point_text(image) + "$";
  }
  figure f;
  f.title = title;
  f.panels = {panel};
  f.caption = "the mirror $" + vec_text(P.p) + "$ with its normal $n = " + point_text(n) + "$" +
              (caption.empty() ? "." : "; " + caption + " (the midpoint of each pair lies on the mirror).");
  return f;
}

}  // namespace

explanation explain_reflection(const plane<rational>& P, const std::vector<vec4<rational>>& points) {
  explanation e;
  e.title = "Reflection matrix for the mirror P = " + vec_text(P.p);
  const rational &a = P.a(), &b = P.b(), &c = P.c(), &d = P.d();
  e.steps.push_back(text_step("The mirror is n·X + d = 0 with n = (a, b, c), not normalised:",
                              {"n = " + list_text({a, b, c}) + ", d = " + str(d)}));
  const rational nn = dot3(P.p, P.p);
  e.steps.push_back(text_step("Its squared length:", {"n·n = " + dot_text(P.p, P.p, 3)}));
  e.steps.push_back(text_step(
      "The image of X walks along n twice the signed distance: X' = X − 2 (n·X + d)/(n·n) n. That "
      "is affine in X, so X' = M X with M = [I − 2nnᵀ/(n·n), −2dn/(n·n); 0 0 0 1]."));
  std::vector<std::vector<rational>> nnT(3, std::vector<rational>(3));
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) nnT[i][j] = P.p[i] * P.p[j];
  e.steps.push_back(text_step("n nᵀ:", matrix_lines(nnT)));
  const rational scale2 = rational(2) / nn;
  std::vector<std::vector<rational>> A(3, std::vector<rational>(3));
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) A[i][j] = (i == j ? rational(1) : rational(0)) - scale2 * nnT[i][j];
  std::vector<std::string> lines{"2/(n·n) = " + str(scale2)};
  for (const auto& l : matrix_lines(A)) lines.push_back(l);
  e.steps.push_back(text_step("The linear part I − 2nnᵀ/(n·n):", lines));
  const std::vector<rational> shift{-scale2 * d * a, -scale2 * d * b, -scale2 * d * c};
  e.steps.push_back(text_step("The translation −2d n/(n·n):", {"−2d n/(n·n) = " + list_text(shift)}));
  mat4<rational> M = identity4<rational>();
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) M(i, j) = A[i][j];
    M(i, 3) = shift[i];
  }
  e.steps.push_back(matrix_step("M:", M));
  e.steps.push_back(text_step("Checks: a reflection undone is the identity, and it reverses orientation.",
                              {"M M = I (" + holds(M * M == identity4<rational>()) + ")", "det M = " + str(determinant(M))}));
  for (const auto& X : points) {
    const rational side = dot(P.p, X);
    const vec4<rational> image = M * X;
    e.steps.push_back(text_step(
        "The point X = " + list_text(xyz(X)) + ":",
        {"n·X + d = " + dot_text(P.p, X, 4), "X' = X − 2 (n·X + d)/(n·n) n = " + list_text(xyz(image)),
         "the midpoint " + point_text(scale(rational(1, 2), add(xyz3(X), xyz3(image)))) + " is on the mirror (" +
             holds(dot(P.p, rational(1, 2) * (X + image)) == 0) + "), and n·X' + d = " + str(dot(P.p, image)) +
             " = −(n·X + d) (" + holds(dot(P.p, image) == -side) + ")"}));
  }
  e.result_name = "reflection matrix M, as `shadowproof reflect` prints it";
  e.result = M;
  e.picture = mirror_figure(P, M, points, "Reflection in the mirror " + vec_text(P.p));
  return e;
}

// =============================================================================================
// Reflection by a change of frame (seed 003)

explanation explain_reflection_by_frames(const std::array<rational, 4>& q, const rational& d,
                                         const std::vector<vec4<rational>>& points) {
  if (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0)
    throw error(errc::geometry_zero_quaternion,
                "the quaternion (0, 0, 0, 0) is no rotation: give any non-zero (w, x, y, z), e.g. 1,0,0,0 for none");
  const frame3<rational> f = frame_from_quaternion(q[0], q[1], q[2], q[3]);
  const point3 U = f.rows[0], N = f.rows[1], V = f.rows[2];
  const plane<rational> mirror = frame_plane(f, d);
  explanation e;
  e.title = "Reflection through a change of frame (seed 003), q = " + list_text({q[0], q[1], q[2], q[3]}) + ", d = " + str(d);
  const rational q2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  e.steps.push_back(text_step(
      "The rotation of the quaternion q = (w, x, y, z), divided by |q|² so that it is exact and rational, has "
      "the orthonormal rows U, N, V (frame_from_quaternion); N is the mirror's unit normal:",
      {"|q|² = " + str(q2), "U = " + point_text(U), "N = " + point_text(N), "V = " + point_text(V)}));
  const mat4<rational> R = frame_matrix(f);
  e.steps.push_back(matrix_step("R, with rows U, N, V:", R,
                                {"R Rᵀ = I (" + holds(R * transpose(R) == identity4<rational>()) + ")",
                                 "R N = " + vec_text(R * make_vec4<rational>(N[0], N[1], N[2], 0)) + " (the y axis)"}));
  e.steps.push_back(text_step("The mirror ⟨N, X⟩ + d = 0:", {"P = " + vec_text(mirror.p)}));
  const mat4<rational> T_in = translation<rational>(d * N[0], d * N[1], d * N[2]);
  const mat4<rational> T_out = translation<rational>(-d * N[0], -d * N[1], -d * N[2]);
  const mat4<rational> S = scaling<rational>(1, -1, 1);
  e.steps.push_back(matrix_step(
      "T(dN) moves the mirror to the origin: its point −dN, the closest to the origin, goes to 0:", T_in,
      {"T(dN) (−dN, 1) = " + vec_text(T_in * make_point<rational>(-d * N[0], -d * N[1], -d * N[2]))}));
  e.steps.push_back(text_step(
      "Then R turns N onto the y axis, S(1, −1, 1) mirrors in the plane y = 0 (it flips y; it is not the "
      "half-turn about the Y axis), Rᵀ turns back and T(−dN) moves back. With column vectors the rightmost factor "
      "acts first: M = T(−dN) Rᵀ S R T(dN)."));
  const mat4<rational> M = T_out * transpose(R) * S * R * T_in;
  e.steps.push_back(matrix_step("M = T(−dN) Rᵀ S R T(dN):", M,
                                {"equals the closed form of the mirror (" + holds(M == reflection_matrix(mirror)) + ")"}));
  const mat4<rational> printed = T_in * transpose(R) * S * R * T_out;
  const plane<rational> flipped = frame_plane(f, rational(-d));
  e.steps.push_back(matrix_step(
      "The seed prints T(dN) Rᵀ S R T(−dN). Read with column vectors (X' = M X) that is the reflection about "
      "⟨N, X⟩ − d = 0, wrong unless d = 0:",
      printed,
      {"equals the mirror ⟨N, X⟩ − d = 0 (" + holds(printed == reflection_matrix(flipped)) + ")",
       "equals M: " + std::string(printed == M ? "yes (d = 0)" : "no")}));
  const mat4<rational> row_form = transpose(T_in) * transpose(R) * S * R * transpose(T_out);
  e.steps.push_back(text_step(
      "Read with row vectors (X' = X M_row, the row-vector translations T_row(t) = T(t)ᵀ), the printed order acts "
      "from left to right as the seed's steps are listed, and M_rowᵀ is M: right as printed.",
      {"M_rowᵀ = M (" + holds(transpose(row_form) == M) + ")"}));
  figure_panel panel;
  panel.title = "mirror, frame U, N, V at −dN, points";
  const point3 base{-d * N[0], -d * N[1], -d * N[2]};
  std::vector<point3> keep{base};
  for (const auto& X : points) {
    keep.push_back(xyz3(X));
    keep.push_back(xyz3(M * X));
    keep.push_back(xyz3(printed * X));
  }
  const point3 n{mirror.a(), mirror.b(), mirror.c()};
  panel.polygon(plane_patch(n, d, base, keep), figure_style::mirror, "⟨N, X⟩ + d = 0");
  panel.arrow(base, add(base, U), figure_style::frame_axis, "U");
  panel.arrow(base, add(base, N), figure_style::normal, "N");
  panel.arrow(base, add(base, V), figure_style::frame_axis, "V");
  std::string caption;
  for (const auto& X : points) {
    const point3 x = xyz3(X), image = xyz3(M * X), wrong = xyz3(printed * X);
    std::vector<std::string> lines{"X = " + vec_text(X)};
    vec4<rational> W = T_in * X;
    lines.push_back("T(dN) X = " + vec_text(W));
    W = R * W;
    lines.push_back("R · that = " + vec_text(W) + " (coordinates along U, N, V)");
    W = S * W;
    lines.push_back("S · that = " + vec_text(W) + " (the N coordinate flipped)");
    W = transpose(R) * W;
    lines.push_back("Rᵀ · that = " + vec_text(W));
    W = T_out * W;
    lines.push_back("T(−dN) · that = " + vec_text(W) + " = X'");
    lines.push_back("the printed order, read with columns, gives " + vec_text(printed * X));
    e.steps.push_back(text_step("The point X = " + point_text(x) + ", one factor at a time:", lines));
    panel.segment(x, image, figure_style::link);
    panel.dot(x, figure_style::point, "X = " + point_text(x));
    panel.dot(image, figure_style::image, "X' = " + point_text(image));
    if (wrong != image) panel.dot(wrong, figure_style::wrong, "printed order, columns: " + point_text(wrong));
    if (wrong != image) panel.segment(x, wrong, figure_style::wrong);
    caption += (caption.empty() ? "" : "; ") + std::string("$X = ") + point_text(x) + "$ goes to $" + point_text(image) +
               "$" + (wrong != image ? " (the printed order read with columns gives $" + point_text(wrong) + "$)" : "");
  }
  e.picture.title = "Reflection by a change of frame";
  e.picture.panels = {panel};
  e.picture.caption = "the mirror $\\langle N, X \\rangle + d = 0$ with $N = " + point_text(N) + "$, $d = " + str(d) +
                      "$ and the frame $U = " + point_text(U) + "$, $V = " + point_text(V) + "$ of $q = " +
                      list_text({q[0], q[1], q[2], q[3]}) + "$ drawn at $-dN$" +
                      (caption.empty() ? "." : "; " + caption + ".");
  e.result_name = "M = T(−dN) Rᵀ S R T(dN), as reflection_by_frame builds it (= the mirror's reflection matrix)";
  e.result = reflection_by_frame(f, d);
  return e;
}

}  // namespace shadowproof
