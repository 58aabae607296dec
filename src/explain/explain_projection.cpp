// Explanations of the projection matrices: seed 002's N(α, β), the frustum in any depth convention,
// the orthographic and oblique projections (both signs of cot), and GAMES101's construction, each
// with a figure of the view volume and the canonical volume.
#include <algorithm>
#include <cmath>

#include "explain_detail.h"
#include "shadowproof/core/error.h"

namespace shadowproof {

using namespace detail;

namespace {

const char* convention_depths(depth_convention c) {
  switch (c) {
    case depth_convention::gl: return "near → −1, far → 1 (OpenGL)";
    case depth_convention::d3d: return "near → 0, far → 1 (Direct3D, Vulkan, Metal)";
    case depth_convention::reverse_z: return "near → 1, far → 0 (reverse-Z)";
  }
  return "";
}

// The eye-space panel of a central projection: the frustum with the window [l, r] × [b, t] at
// z = −n and the far window at z = −far_draw, the eye, and each point with its line of sight.
figure_panel frustum_panel(const rational& l, const rational& r, const rational& b, const rational& t, const rational& n,
                           const rational& far_draw, const std::vector<vec4<rational>>& points, const std::string& title) {
  figure_panel panel;
  panel.title = title;
  panel.view = figure_view::side;
  std::array<point3, 8> c;
  for (int i = 0; i < 8; ++i) {
    const rational s = (i & 4) ? far_draw / n : rational(1);
    c[i] = {s * ((i & 1) ? r : l), s * ((i & 2) ? t : b), (i & 4) ? rational(-far_draw) : rational(-n)};
  }
  panel.hexahedron(c, figure_style::volume);
  const point3 eye{0, 0, 0};
  for (int i = 0; i < 4; ++i) panel.segment(eye, c[i], figure_style::axis);
  panel.dot(eye, figure_style::eye, "eye");
  for (const auto& X : points) {
    panel.segment(eye, xyz3(X), figure_style::ray);
    panel.dot(xyz3(X), figure_style::point, point_text(xyz3(X)));
  }
  return panel;
}

std::vector<std::string> point_lines(const mat4<rational>& M, const std::vector<vec4<rational>>& points, depth_convention c) {
  std::vector<std::string> lines;
  for (const auto& X : points) {
    const vec4<rational> image = M * X;
    lines.push_back(projected_line("M", M, X) +
                    (in_clip_volume(image, c) ? ", inside the canonical volume" : ", outside the canonical volume"));
  }
  return lines;
}

std::string ndc_line(const std::string& what, const mat4<rational>& M, const vec4<rational>& X, const point3& expected) {
  const vec4<rational> image = M * X;
  const bool ok = image[3] != 0 && affine_point(image) == expected;
  return what + " " + point_text(xyz3(X)) + " → " + vec_text(image) +
         (image[3] != 0 ? ", NDC " + point_text(affine_point(image)) : std::string(", w = 0")) + " (" + holds(ok) + ")";
}

}  // namespace

// =============================================================================================
// Perspective normalisation N(α, β)

explanation explain_perspective_normalization(const rational& n, const rational& f, const std::vector<vec4<rational>>& points) {
  detail::require_positive(n, errc::project_near_not_positive, "near",
                           "the near plane of a perspective projection lies in front of the eye");
  detail::require_positive(f, errc::project_far_not_positive, "far",
                           "the far plane of a perspective projection lies in front of the eye");
  detail::require_distinct(n, f, "near", "far", "depth");
  explanation e;
  e.title = "Perspective normalisation N(α, β) for near = " + str(n) + ", far = " + str(f);
  e.steps.push_back(text_step(
      "N = [1 0 0 0; 0 1 0 0; 0 0 α β; 0 0 −1 0] maps (x, y, z, 1) to (x, y, αz + β, −z); after "
      "division by w the depth is (αz + β)/(−z). The 45° frustum |x|, |y| ≤ −z lies between z = −n and z = −f."));
  e.steps.push_back(text_step("The near plane z = −n must go to depth −1: (−nα + β)/n = −1, i.e. −nα + β = −n:",
                              {factor(-n) + "·α + β = " + str(-n)}));
  e.steps.push_back(text_step("The far plane z = −f must go to depth +1: −fα + β = f:", {factor(-f) + "·α + β = " + str(f)}));
  const rational det = -n - (-f);
  e.steps.push_back(text_step(
      "The system [−n 1; −f 1] (α, β) = (−n, f) has determinant f − n, non-zero since the planes differ:",
      {"det = " + factor(-n) + "·1 − 1·" + factor(-f) + " = " + str(det)}));
  const rational alpha = (-n - f) / det;
  const rational beta = ((-n) * f - (-n) * (-f)) / det;
  e.steps.push_back(text_step(
      "Cramer's rule: α = ((−n)·1 − 1·f)/(f − n), β = ((−n)·f − (−n)·(−f))/(f − n); these are the seed's "
      "α = (n+f)/(n−f) and β = 2nf/(n−f):",
      {"α = (" + factor(-n) + " − " + factor(f) + ")/" + factor(det) + " = " + str(alpha),
       "β = (" + factor(-n) + "·" + factor(f) + " − " + factor(-n) + "·" + factor(-f) + ")/" + factor(det) + " = " + str(beta)}));
  mat4<rational> N = identity4<rational>();
  N(2, 2) = alpha;
  N(2, 3) = beta;
  N(3, 2) = -1;
  N(3, 3) = 0;
  e.steps.push_back(matrix_step("N:", N));
  const vec4<rational> near_image = N * make_point<rational>(0, 0, -n);
  const vec4<rational> far_image = N * make_point<rational>(0, 0, -f);
  const auto check_line = [](const std::string& name, const rational& depth, const vec4<rational>& image, const rational& expected) {
    return name + ": N (0, 0, " + str(depth) + ", 1) = " + vec_text(image) + ", depth " + str(image[2] / image[3]) + " (" +
           holds(image[2] / image[3] == expected) + ")";
  };
  e.steps.push_back(text_step("Check both conditions:", {check_line("near", -n, near_image, -1), check_line("far", -f, far_image, 1)}));
  if (!points.empty()) e.steps.push_back(text_step("The points:", point_lines(N, points, depth_convention::gl)));
  e.result_name = "N(α, β), as perspective_normalization(n, f) in shadowproof/constructions/project.h builds it";
  e.result = N;
  e.picture.title = "The 45° frustum and the cube [−1, 1]³";
  e.picture.panels = {frustum_panel(-n, n, -n, n, n, f, points, "eye space, looking down −z: the 45° frustum"),
                      canonical_panel(depth_convention::gl, N, points, "after N and division by w")};
  e.picture.caption = "the 45° frustum between $z = " + str(-n) + "$ and $z = " + str(-f) +
                      "$ (the eye at the origin looks down $-z$) and the cube $[-1, 1]^3$ it is mapped onto, near plane at depth $-1$.";
  return e;
}

// =============================================================================================
// Frustum

explanation explain_frustum(const rational& l, const rational& r, const rational& b, const rational& t, const rational& n,
                            const rational& f, depth_convention c, bool infinite_far, const std::vector<vec4<rational>>& points) {
  (void)frustum(l, r, b, t, n, f, c, infinite_far);  // the same preconditions and error messages
  const depth_range<rational> z = ndc_depth_range<rational>(c);
  explanation e;
  e.title = "Perspective frustum [" + str(l) + ", " + str(r) + "] x [" + str(b) + ", " + str(t) + "], near " + str(n) +
            ", far " + (infinite_far ? std::string("infinite") : str(f)) + ", convention " + std::string(to_string(c));
  e.steps.push_back(text_step(
      "The eye looks down −z; the window [l, r] x [b, t] lies on the near plane z = −n. In this convention the "
      "near plane goes to depth z_near and the far plane to z_far:",
      {"z_near = " + str(z.near_ndc) + ", z_far = " + str(z.far_ndc)}));
  e.steps.push_back(text_step(
      "A point (x, y, z) in front of the eye (z < 0) is seen where its ray meets the near plane, at "
      "x_n = n x/(−z), y_n = n y/(−z). The division by −z is the division by w: the last row is (0, 0, −1, 0)."));
  const rational sx = 2 * n / (r - l), ox = (r + l) / (r - l);
  const rational sy = 2 * n / (t - b), oy = (t + b) / (t - b);
  e.steps.push_back(text_step(
      "The window maps onto [−1, 1]: x_ndc = 2 (x_n − l)/(r − l) − 1 = (2n/(r−l) x + (r+l)/(r−l) z)/(−z), and the "
      "same for y:",
      {"2n/(r−l) = " + str(sx) + ", (r+l)/(r−l) = " + str(ox), "2n/(t−b) = " + str(sy) + ", (t+b)/(t−b) = " + str(oy)}));
  rational A, B;
  if (!infinite_far) {
    A = (n * z.near_ndc - f * z.far_ndc) / (f - n);
    B = n * z.near_ndc + n * A;
    e.steps.push_back(text_step(
        "Depth is (A z + B)/(−z). Near z = −n → z_near: −nA + B = n z_near; far z = −f → z_far: −fA + B = f z_far. "
        "Subtracting, A = (n z_near − f z_far)/(f − n), then B = n z_near + nA:",
        {"−" + factor(n) + "·A + B = " + str(n * z.near_ndc) + ", −" + factor(f) + "·A + B = " + str(f * z.far_ndc),
         "A = (" + factor(n) + "·" + factor(z.near_ndc) + " − " + factor(f) + "·" + factor(z.far_ndc) + ")/(" + str(f - n) +
             ") = " + str(A),
         "B = " + factor(n) + "·" + factor(z.near_ndc) + " + " + factor(n) + "·" + factor(A) + " = " + str(B)}));
  } else {
    A = -z.far_ndc;
    B = n * (z.near_ndc - z.far_ndc);
    e.steps.push_back(text_step(
        "Depth is (A z + B)/(−z). Near z = −n → z_near gives −nA + B = n z_near; letting the far plane go to "
        "infinity, (A z + B)/(−z) → −A must be z_far. So A = −z_far and B = n (z_near − z_far):",
        {"A = " + str(A), "B = " + factor(n) + "·(" + str(z.near_ndc) + " − " + factor(z.far_ndc) + ") = " + str(B)}));
  }
  mat4<rational> M;
  M(0, 0) = sx;
  M(0, 2) = ox;
  M(1, 1) = sy;
  M(1, 2) = oy;
  M(2, 2) = A;
  M(2, 3) = B;
  M(3, 2) = -1;
  e.steps.push_back(matrix_step("M:", M));
  std::vector<std::string> checks;
  checks.push_back(ndc_line("near corner (l, b, −n) =", M, make_point<rational>(l, b, rational(-n)), {-1, -1, z.near_ndc}));
  if (!infinite_far) {
    checks.push_back(ndc_line("far corner (rf/n, tf/n, −f) =", M, make_point<rational>(r * f / n, t * f / n, rational(-f)),
                              {1, 1, z.far_ndc}));
  } else {
    const vec4<rational> direction = make_vec4<rational>(r / n, t / n, -1, 0);
    const vec4<rational> image = M * direction;
    checks.push_back("direction (r/n, t/n, −1, 0) → " + vec_text(image) + ", NDC " + point_text(affine_point(image)) + " (" +
                     holds(affine_point(image) == point3{1, 1, z.far_ndc}) + ")");
  }
  e.steps.push_back(text_step("Check opposite corners of the view volume:", checks));
  if (!points.empty()) e.steps.push_back(text_step("The points:", point_lines(M, points, c)));
  e.result_name = "frustum matrix M, as `shadowproof project frustum` prints it";
  e.result = M;
  const rational far_draw = infinite_far ? rational(3) * n : f;
  e.picture.title = "Frustum and canonical volume, " + std::string(to_string(c));
  e.picture.panels = {frustum_panel(l, r, b, t, n, far_draw, points,
                                    infinite_far ? "eye space, looking down −z (far plane at infinity, drawn at 3n)" : "eye space, looking down −z"),
                      canonical_panel(c, M, points, std::string("NDC: ") + convention_depths(c))};
  e.picture.caption = "the frustum with the window $[" + str(l) + ", " + str(r) + "] \\times [" + str(b) + ", " + str(t) +
                      "]$ at $z = " + str(-n) + "$ and the far plane " +
                      (infinite_far ? std::string("at infinity") : "at $z = " + str(-f) + "$") +
                      ", and the canonical volume of the `" + std::string(to_string(c)) + "` convention (" +
                      convention_depths(c) + ").";
  return e;
}

// =============================================================================================
// Orthographic

explanation explain_orthographic(const rational& l, const rational& r, const rational& b, const rational& t, const rational& n,
                                 const rational& f, depth_convention c, const std::vector<vec4<rational>>& points) {
  const mat4<rational> M = orthographic(l, r, b, t, n, f, c);  // throws for a flat box
  const depth_range<rational> z = ndc_depth_range<rational>(c);
  explanation e;
  e.title = "Orthographic box [" + str(l) + ", " + str(r) + "] x [" + str(b) + ", " + str(t) + "] x [" + str(-f) + ", " +
            str(-n) + "], convention " + std::string(to_string(c));
  e.steps.push_back(text_step(
      "The camera looks down −z; the box [l, r] x [b, t] x [−f, −n] must go onto x, y ∈ [−1, 1] with the near plane "
      "z = −n at depth z_near and the far plane z = −f at z_far. Nothing divides by w (it stays 1), so any n ≠ f works:",
      {"z_near = " + str(z.near_ndc) + ", z_far = " + str(z.far_ndc)}));
  e.steps.push_back(text_step(
      "x: the affine map with l → −1 and r → 1 is x' = 2/(r − l) x − (r + l)/(r − l); the same for y:",
      {"2/(r−l) = " + str(rational(2) / (r - l)) + ", −(r+l)/(r−l) = " + str(rational(-(r + l)) / (r - l)),
       "2/(t−b) = " + str(rational(2) / (t - b)) + ", −(t+b)/(t−b) = " + str(rational(-(t + b)) / (t - b))}));
  const rational A = (z.near_ndc - z.far_ndc) / (f - n);
  e.steps.push_back(text_step(
      "Depth is affine, A z + B. The conditions −A n + B = z_near and −A f + B = z_far give, subtracting, "
      "A = (z_near − z_far)/(f − n), and then B = z_near + A n:",
      {"A = (" + factor(z.near_ndc) + " − " + factor(z.far_ndc) + ")/(" + str(f - n) + ") = " + str(A),
       "B = " + factor(z.near_ndc) + " + " + factor(A) + "·" + factor(n) + " = " + str(z.near_ndc + A * n)}));
  e.steps.push_back(matrix_step("M:", M));
  e.steps.push_back(text_step("Check opposite corners of the box:",
                              {ndc_line("near corner (l, b, −n) =", M, make_point<rational>(l, b, rational(-n)), {-1, -1, z.near_ndc}),
                               ndc_line("far corner (r, t, −f) =", M, make_point<rational>(r, t, rational(-f)), {1, 1, z.far_ndc})}));
  if (!points.empty()) e.steps.push_back(text_step("The points:", point_lines(M, points, c)));
  e.result_name = "orthographic matrix M, as orthographic(l, r, b, t, n, f, c) builds it";
  e.result = M;
  figure_panel box;
  box.title = "eye space, looking down −z: the box";
  box.view = figure_view::side;
  box.hexahedron(box_corners(l, r, b, t, -f, -n), figure_style::volume);
  box.dot({0, 0, 0}, figure_style::eye, "eye");
  for (const auto& X : points) box.dot(xyz3(X), figure_style::point, point_text(xyz3(X)));
  e.picture.title = "Orthographic projection, " + std::string(to_string(c));
  e.picture.panels = {box, canonical_panel(c, M, points, std::string("NDC: ") + convention_depths(c))};
  e.picture.caption = "the box $[" + str(l) + ", " + str(r) + "] \\times [" + str(b) + ", " + str(t) + "] \\times [" +
                      str(-f) + ", " + str(-n) + "]$ and the canonical volume of the `" + std::string(to_string(c)) +
                      "` convention (" + convention_depths(c) + ").";
  return e;
}

// =============================================================================================
// Oblique

explanation explain_oblique(const rational& cot_theta, const rational& cot_phi, cot_sign sign,
                            const std::optional<view_box>& box, const std::vector<vec4<rational>>& points) {
  // The library's oblique_shear(c, d) has −c, −d in its third column: plus is the shear of (−cot θ, −cot φ).
  const rational k = sign == cot_sign::minus ? rational(1) : rational(-1);
  const mat4<rational> H = oblique_shear<rational>(k * cot_theta, k * cot_phi);
  explanation e;
  e.title = "Oblique projection with cot θ = " + str(cot_theta) + ", cot φ = " + str(cot_phi) + ", " +
            (sign == cot_sign::minus ? "−cot in H" : "+cot in H");
  const vec4<rational> projector = make_vec4<rational>(cot_theta, cot_phi, sign == cot_sign::minus ? 1 : -1, 0);
  if (sign == cot_sign::plus) {
    e.steps.push_back(text_step(
        "Seed 002's angles: a point (x, y, z) is carried along its projector to (x_p, y_p, 0) on the plane z = 0, and θ "
        "is the angle between that plane and the projector seen in the xz-plane, tan θ = z/(x_p − x); φ is the same "
        "in the yz-plane. So x_p = x + z cot θ, y_p = y + z cot φ, and the projector runs along (cot θ, cot φ, −1):",
        {"projector = " + vec_text(projector)}));
  } else {
    e.steps.push_back(text_step(
        "Angel's angles (seed 002's later slide, the library): θ and φ are measured from the other side, θ' = 180° − θ, "
        "so x_p = x − z cot θ, y_p = y − z cot φ, and the projector runs along (cot θ, cot φ, 1). (With the first "
        "slide's tan θ = z/(x_p − x) this −cot shear would send its projector (cot θ, cot φ, −1) to (2 cot θ, 2 cot φ, "
        "−1): the two slides use different angles.)",
        {"projector = " + vec_text(projector)}));
  }
  const vec4<rational> sent = H * projector;
  e.steps.push_back(matrix_step(
      std::string("The shear H(θ, φ) = [1 0 ") + (sign == cot_sign::minus ? "−" : "") + "cot θ 0; 0 1 " +
          (sign == cot_sign::minus ? "−" : "") + "cot φ 0; 0 0 1 0; 0 0 0 1] keeps z and turns the projector into the z axis:",
      H,
      {"H projector = " + vec_text(sent) + " (" + holds(sent[0] == 0 && sent[1] == 0) + ")",
       "this is the library's oblique_shear(" + str(k * cot_theta) + ", " + str(k * cot_phi) + ")"}));
  mat4<rational> M;
  figure_panel scene;
  std::vector<vec4<rational>> drawn = points;
  if (!box) {
    M = oblique_parallel_projection<rational>(k * cot_theta, k * cot_phi);
    e.steps.push_back(matrix_step("After the shear, M_orth = diag(1, 1, 0, 1) drops z: the projection onto z = 0 is M_orth H:", M));
    e.result_name = "M_orth H, as oblique_parallel_projection(" + str(k * cot_theta) + ", " + str(k * cot_phi) + ") builds it";
    scene.title = "projectors onto the plane z = 0";
    if (drawn.empty())
      for (int y : {0, 1}) drawn.push_back(make_point<rational>(0, y, 2));
    std::vector<point3> keep;
    for (const auto& X : drawn) {
      keep.push_back(xyz3(X));
      keep.push_back(xyz3(M * X));
    }
    scene.polygon(plane_patch({0, 0, 1}, 0, {0, 0, 0}, keep), figure_style::plane, "z = 0");
    for (const auto& X : drawn) {
      const point3 x = xyz3(X), image = xyz3(M * X);
      scene.segment(x, image, figure_style::ray);
      scene.dot(x, figure_style::point, point_text(x));
      scene.dot(image, figure_style::image, point_text(image));
    }
    // The angle θ itself: the right triangle of the first point off the plane, seen in the xz-plane,
    // with legs z and x_p − x (or x − x_p with the −cot angles) and the projector as hypotenuse.
    figure_panel angle;
    angle.view = figure_view::xz;
    angle.title = sign == cot_sign::plus ? "the xz-plane: tan θ = z/(x_p − x)" : "the xz-plane: tan θ = z/(x − x_p)";
    for (const auto& X : drawn) {
      const point3 x = xyz3(X), image = xyz3(M * X);
      if (x[2] == 0 || x[0] == image[0]) continue;
      const point3 foot{x[0], 0, 0}, on_plane{image[0], 0, 0}, top{x[0], 0, x[2]};
      const point3 up_half{x[0], 0, x[2] / 2}, along_half{(x[0] + image[0]) / 2, 0, 0};
      const rational lo = std::min(x[0], image[0]) - 1, hi = std::max(x[0], image[0]) + 1;
      angle.segment({lo, 0, 0}, {hi, 0, 0}, figure_style::axis, "z = 0");
      // The legs, each in two halves so that its label sits at its middle.
      angle.segment(top, up_half, figure_style::link, "z = " + str(x[2]));
      angle.segment(up_half, foot, figure_style::link);
      angle.segment(foot, along_half, figure_style::link,
                    (sign == cot_sign::plus ? "x_p − x = " : "x − x_p = ") +
                        str(sign == cot_sign::plus ? image[0] - x[0] : x[0] - image[0]));
      angle.segment(along_half, on_plane, figure_style::link);
      angle.segment(top, on_plane, figure_style::ray);
      // A mark for θ at the image, from the plane towards the point: the rational points
      // image + r ((1 − t²)/(1 + t²) s, 2t/(1 + t²) σ) of the circle of radius r, for t up to
      // tan(θ/2) (rounded to 1/1000: the mark only has to be seen).
      const rational run = x[0] - image[0], rise = x[2];
      const double a = std::abs(to_nearest_double(run)), h = std::abs(to_nearest_double(rise));
      const rational half_tan(static_cast<long>(std::lround(1000 * h / (std::sqrt(a * a + h * h) + a))), 1000);
      const rational run_length = run > 0 ? run : rational(-run), rise_length = rise > 0 ? rise : rational(-rise);
      const rational radius = std::min(run_length, rise_length) / 3;
      const rational s = run > 0 ? 1 : -1, sigma = rise > 0 ? 1 : -1;
      point3 previous{};
      for (int step = 0; step <= 8; ++step) {
        const rational t = half_tan * rational(step, 8), q = 1 + t * t;
        const point3 p{image[0] + radius * s * (1 - t * t) / q, 0, radius * sigma * 2 * t / q};
        if (step > 0) angle.segment(previous, p, figure_style::axis, step == 4 ? "θ" : "");
        previous = p;
      }
      angle.dot(top, figure_style::point, "(x, z) = (" + str(x[0]) + ", " + str(x[2]) + ")");
      angle.dot(on_plane, figure_style::image, "(x_p, 0) = (" + str(image[0]) + ", 0)");
      break;
    }
    e.picture.panels = {scene};
    if (!angle.items.empty()) e.picture.panels.push_back(angle);
    e.picture.caption = "projectors along $" + vec_text(projector) + "$ ($\\cot\\theta = " + str(cot_theta) +
                        "$, $\\cot\\phi = " + str(cot_phi) + "$, " + (sign == cot_sign::minus ? "$-\\cot$" : "$+\\cot$") +
                        " in $H$) carry " + (points.empty() ? "the points $(0, 0, 2)$ and $(0, 1, 2)$" : "the points") +
                        " onto the plane $z = 0$" +
                        (angle.items.empty() ? std::string(".")
                                             : std::string("; the right panel shows $\\theta$ as the angle, at the image, between "
                                                           "the plane and the projector in the xz-plane."));
  } else {
    const mat4<rational> O = orthographic(box->l, box->r, box->b, box->t, box->n, box->f, box->c);
    M = O * H;
    e.steps.push_back(matrix_step("Keeping depth, the box is normalised after the shear: orthographic(l, r, b, t, n, f) is", O));
    e.steps.push_back(matrix_step("and M = orthographic · H:", M));
    // The sheared box: the points X with H X in the box.
    const depth_range<rational> z = ndc_depth_range<rational>(box->c);
    const auto unshear = [&](const rational& x, const rational& y, const rational& zz) {
      return make_point<rational>(x + k * cot_theta * zz, y + k * cot_phi * zz, zz);
    };
    e.steps.push_back(text_step(
        "Check the sheared box, the points X with H X in [l, r] x [b, t] x [−f, −n]:",
        {ndc_line("near corner over (l, b, −n):", M, unshear(box->l, box->b, -box->n), {-1, -1, z.near_ndc}),
         ndc_line("far corner over (r, t, −f):", M, unshear(box->r, box->t, -box->f), {1, 1, z.far_ndc})}));
    e.result_name = "orthographic · H, as oblique(l, r, b, t, n, f, " + str(k * cot_theta) + ", " + str(k * cot_phi) + ", c) builds it";
    scene.title = "eye space: the sheared box";
    std::array<point3, 8> corners;
    for (int i = 0; i < 8; ++i)
      corners[i] = xyz3(unshear((i & 1) ? box->r : box->l, (i & 2) ? box->t : box->b, (i & 4) ? rational(-box->f) : rational(-box->n)));
    scene.hexahedron(corners, figure_style::volume);
    scene.arrow(corners[0], add(corners[0], xyz3(projector)), figure_style::ray, "projector " + vec_text(projector));
    for (const auto& X : points) scene.dot(xyz3(X), figure_style::point, point_text(xyz3(X)));
    e.picture.panels = {scene, canonical_panel(box->c, M, points, std::string("NDC: ") + convention_depths(box->c))};
    e.picture.caption = "the sheared box of the projector $" + vec_text(projector) + "$ over $[" + str(box->l) + ", " +
                        str(box->r) + "] \\times [" + str(box->b) + ", " + str(box->t) + "] \\times [" + str(-box->f) + ", " +
                        str(-box->n) + "]$ and the canonical volume it is mapped onto.";
  }
  if (!points.empty())
    e.steps.push_back(text_step("The points:", box ? point_lines(M, points, box->c) : [&] {
      std::vector<std::string> lines;
      for (const auto& X : points) lines.push_back("M " + vec_text(X) + " = " + vec_text(M * X));
      return lines;
    }()));
  e.result = M;
  e.picture.title = std::string("Oblique projection, ") + (sign == cot_sign::minus ? "−cot θ" : "+cot θ") + " in H";
  return e;
}

// =============================================================================================
// GAMES101

explanation explain_games101(const rational& n, const rational& f, const rational& c, const rational& aspect,
                             const std::vector<vec4<rational>>& points) {
  const mat4<rational> projection = games101_projection(n, f, c, aspect);  // throws for bad parameters
  explanation e;
  e.title = "GAMES101 projection, near z = " + str(n) + ", far z = " + str(f) + ", cot(fovy/2) = " + str(c) +
            ", aspect = " + str(aspect);
  e.steps.push_back(text_step(
      "GAMES101 takes the z coordinates of the planes, n and f with f < n < 0 (the camera looks down −z). First "
      "every point (x, y, z) is squeezed towards the axis onto the box over the near window: by similar triangles "
      "x → n x/z and y → n y/z, for every point, not only those of the near plane. With w = z that gives rows 1, 2 and "
      "4: (n, 0, 0, 0), (0, n, 0, 0) and (0, 0, 1, 0)."));
  const rational A = n + f, B = -n * f;
  e.steps.push_back(text_step(
      "Row 3 is (0, 0, A, B). The near plane stays put, (x, y, n, 1) → (nx, ny, n², n): A n + B = n²; the far "
      "centre stays put, (0, 0, f, 1) → (0, 0, f², f): A f + B = f². Subtracting, A (n − f) = n² − f², so A = n + f "
      "and B = n² − A n = −nf:",
      {"A = " + str(A) + ", B = " + str(B),
       "(seed 004 prints nf in place of n + f: " + str(n * f) + (n * f == A ? ", which happens to agree here)" : ", wrong here)")}));
  const mat4<rational> persp = games101_persp_to_ortho(n, f);
  e.steps.push_back(matrix_step(
      "persp→ortho (a projective map: its last row is (0, 0, 1, 0), so the eye goes to infinity; not affine):", persp,
      {"M (1, 1, n, 1) = " + vec_text(persp * make_point<rational>(1, 1, n)) + " = n·(1, 1, n, 1) (" +
           holds(persp * make_point<rational>(1, 1, n) == n * make_point<rational>(1, 1, n)) + ")",
       "M (0, 0, f, 1) = " + vec_text(persp * make_point<rational>(0, 0, f)) + " = f·(0, 0, f, 1) (" +
           holds(persp * make_point<rational>(0, 0, f) == f * make_point<rational>(0, 0, f)) + ")"}));
  const rational top = -n / c, right = top * aspect;
  e.steps.push_back(text_step(
      "The near window: top = −n·tan(fovy/2) = −n/c (positive; the seed's tan(fovy/2)·zNear = n/c is negative for "
      "n < 0 and turns the image upside down), bottom = −top, right = top·aspect, left = −right:",
      {"top = " + str(top) + ", right = " + str(right)}));
  const mat4<rational> to_origin = translation<rational>(0, 0, -(n + f) / 2);
  const mat4<rational> ortho = scaling<rational>(1 / right, 1 / top, 2 / (n - f));
  e.steps.push_back(matrix_step("Centre the box, T(0, 0, −(n+f)/2):", to_origin));
  e.steps.push_back(matrix_step(
      "Scale it to [−1, 1]³ (not [−2, 2]³: 2/(r − l) halves the width 2·right), S(1/right, 1/top, 2/(n − f)):", ortho));
  e.steps.push_back(matrix_step(
      "projection = ortho · translate · persp→ortho (near → +1, far → −1, and w = z < 0 in front of the eye):", projection,
      {ndc_line("near corner (−right, −top, n) =", projection, make_point<rational>(-right, -top, n), {-1, -1, 1}),
       ndc_line("far corner (right f/n, top f/n, f) =", projection, make_point<rational>(right * f / n, top * f / n, f), {1, 1, -1})}));
  if (!points.empty()) {
    std::vector<std::string> lines;
    for (const auto& X : points) lines.push_back(projected_line("M", projection, X));
    e.steps.push_back(text_step("The points:", lines));
  }
  e.result_name = "GAMES101 projection, as games101_projection(n, f, c, aspect) builds it";
  e.result = projection;
  // Figure: frustum (z from n to f), the squeezed box, the cube.
  figure_panel frustum_view, squeezed, cube;
  frustum_view.title = "eye space: z from n to f";
  frustum_view.view = figure_view::side;
  std::array<point3, 8> fc, bc;
  for (int i = 0; i < 8; ++i) {
    const rational s = (i & 4) ? f / n : rational(1);
    fc[i] = {s * ((i & 1) ? right : -right), s * ((i & 2) ? top : -top), (i & 4) ? f : n};
    bc[i] = {(i & 1) ? right : -right, (i & 2) ? top : -top, (i & 4) ? f : n};
  }
  frustum_view.hexahedron(fc, figure_style::volume);
  frustum_view.dot({0, 0, 0}, figure_style::eye, "eye");
  for (int i = 0; i < 4; ++i) frustum_view.segment({0, 0, 0}, fc[i], figure_style::axis);
  squeezed.title = "after persp→ortho: the box";
  squeezed.view = figure_view::side;
  squeezed.hexahedron(bc, figure_style::volume);
  for (const auto& X : points) {
    frustum_view.dot(xyz3(X), figure_style::point, point_text(xyz3(X)));
    const vec4<rational> Y = persp * X;
    if (Y[3] != 0) squeezed.dot(affine_point(Y), figure_style::image, point_text(affine_point(Y)));
  }
  cube.title = "NDC: near → +1, far → −1";
  cube.hexahedron(box_corners(-1, 1, -1, 1, -1, 1), figure_style::canonical);
  cube.dot({0, 0, 1}, figure_style::axis, "near z = 1");
  cube.dot({0, 0, -1}, figure_style::axis, "far z = -1");
  for (const auto& X : points) {
    const vec4<rational> Y = projection * X;
    if (Y[3] != 0) cube.dot(affine_point(Y), figure_style::image, point_text(affine_point(Y)));
  }
  e.picture.title = "GAMES101: squeeze the frustum, centre and scale the box";
  e.picture.panels = {frustum_view, squeezed, cube};
  e.picture.caption = "the frustum between $z = " + str(n) + "$ and $z = " + str(f) + "$ with top $= -n/c = " + str(top) +
                      "$ and right $= " + str(right) + "$, the box persp$\\to$ortho squeezes it into, and the cube $[-1, 1]^3$ "
                      "with the near plane at depth $+1$.";
  return e;
}

}  // namespace shadowproof
