#include "shadowproof/explain/explain.h"

#include <algorithm>
#include <sstream>

#include "shadowproof/core/error.h"

namespace shadowproof {

namespace {

std::string str(const rational& q) { return to_string(q); }

// A factor in a product: negative numbers and fractions get brackets, "(-2)·(1/3)".
std::string factor(const rational& q) {
  return q < 0 || q.get_den() != 1 ? "(" + str(q) + ")" : str(q);
}

std::string list_text(const std::vector<rational>& v) {
  std::string s = "(";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + str(v[i]);
  return s + ")";
}

std::string vec_text(const vec4<rational>& v) { return list_text(std::vector<rational>(v.v.begin(), v.v.end())); }

std::vector<rational> xyz(const vec4<rational>& v) { return {v[0], v[1], v[2]}; }

// "a0·b0 + a1·b1 + ... = value" over the first `count` coordinates.
std::string dot_text(const vec4<rational>& a, const vec4<rational>& b, std::size_t count) {
  std::string s;
  rational sum = 0;
  for (std::size_t i = 0; i < count; ++i) {
    s += (i ? " + " : "") + factor(a[i]) + "·" + factor(b[i]);
    sum += a[i] * b[i];
  }
  return s + " = " + str(sum);
}

// Rows of an aligned matrix, the layout `shadowproof shadow` uses.
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

explanation_step text_step(std::string why, std::vector<std::string> lines = {}) {
  return {std::move(why), std::move(lines), std::nullopt};
}

explanation_step matrix_step(std::string why, const mat4<rational>& m, std::vector<std::string> lines = {}) {
  return {std::move(why), std::move(lines), m};
}

std::string holds(bool ok) { return ok ? "holds" : "FAILS"; }

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

// =============================================================================================
// Shadow

explanation explain_shadow(const plane<rational>& P, const light<rational>& L,
                           const std::vector<vec4<rational>>& points) {
  explanation e;
  e.title = "Shadow matrix for the plane P = " + vec_text(P.p) + " and the light L = " + vec_text(L.l);
  const std::string light_text =
      L.is_directional() ? "a directional light; (x, y, z) = " + list_text(xyz(L.l)) + " points towards it"
                         : "a point light at " + list_text({L.l[0] / L.l[3], L.l[1] / L.l[3], L.l[2] / L.l[3]});
  e.steps.push_back(text_step(
      "The receiver is the set of points X with P·X = 0; the light is " + light_text + ".",
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
    lines.push_back("M V = (P·L) V − (P·V) L = " + str(s) + "·" + vec_text(V) + " − " + factor(t) + "·" +
                    vec_text(L.l) + " = " + vec_text(image));
    if (image[3] != 0)
      lines.push_back("affine image (x/w, y/w, z/w) = " +
                      list_text({image[0] / image[3], image[1] / image[3], image[2] / image[3]}));
    else
      lines.push_back(is_zero(image) ? "M V = 0: no point (V and the light span a line in the plane, or V is the light)"
                                     : "w = 0: the image is a point at infinity");
    e.steps.push_back(text_step("The point V = " + list_text(xyz(V)) + ":", lines));
  }
  e.result_name = "shadow matrix M = (P·L) I − L Pᵀ (image = M V), as `shadowproof shadow` prints it";
  e.result = M;
  return e;
}

// =============================================================================================
// Reflection

explanation explain_reflection(const plane<rational>& P) {
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
  const rational scale = rational(2) / nn;
  std::vector<std::vector<rational>> A(3, std::vector<rational>(3));
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) A[i][j] = (i == j ? rational(1) : rational(0)) - scale * nnT[i][j];
  std::vector<std::string> lines{"2/(n·n) = " + str(scale)};
  for (const auto& l : matrix_lines(A)) lines.push_back(l);
  e.steps.push_back(text_step("The linear part I − 2nnᵀ/(n·n):", lines));
  const std::vector<rational> shift{-scale * d * a, -scale * d * b, -scale * d * c};
  e.steps.push_back(text_step("The translation −2d n/(n·n):", {"−2d n/(n·n) = " + list_text(shift)}));
  mat4<rational> M = identity4<rational>();
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) M(i, j) = A[i][j];
    M(i, 3) = shift[i];
  }
  e.steps.push_back(matrix_step("M:", M));
  e.steps.push_back(text_step("Checks: a reflection undone is the identity, and it reverses orientation.",
                              {"M M = I (" + holds(M * M == identity4<rational>()) + ")",
                               "det M = " + str(determinant(M))}));
  e.result_name = "reflection matrix M, as `shadowproof reflect` prints it";
  e.result = M;
  return e;
}

// =============================================================================================
// Perspective normalisation N(α, β)

explanation explain_perspective_normalization(const rational& n, const rational& f) {
  detail::require_distinct(n, f, "near", "far", "depth");
  explanation e;
  e.title = "Perspective normalisation N(α, β) for near = " + str(n) + ", far = " + str(f);
  e.steps.push_back(text_step(
      "N = [1 0 0 0; 0 1 0 0; 0 0 α β; 0 0 −1 0] maps (x, y, z, 1) to (x, y, αz + β, −z); after "
      "division by w the depth is (αz + β)/(−z). The 45° frustum lies between z = −n and z = −f."));
  e.steps.push_back(text_step(
      "The near plane z = −n must go to depth −1: (−nα + β)/n = −1, i.e. −nα + β = −n:",
      {factor(-n) + "·α + β = " + str(-n)}));
  e.steps.push_back(text_step("The far plane z = −f must go to depth +1: −fα + β = f:",
                              {factor(-f) + "·α + β = " + str(f)}));
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
       "β = (" + factor(-n) + "·" + factor(f) + " − " + factor(-n) + "·" + factor(-f) + ")/" + factor(det) +
           " = " + str(beta)}));
  mat4<rational> N = identity4<rational>();
  N(2, 2) = alpha;
  N(2, 3) = beta;
  N(3, 2) = -1;
  N(3, 3) = 0;
  e.steps.push_back(matrix_step("N:", N));
  const vec4<rational> near_image = N * make_point<rational>(0, 0, -n);
  const vec4<rational> far_image = N * make_point<rational>(0, 0, -f);
  std::vector<std::string> checks;
  const auto check_line = [](const std::string& name, const rational& depth, const vec4<rational>& image,
                             const rational& expected) {
    std::string line = name + ": N (0, 0, " + str(depth) + ", 1) = " + vec_text(image);
    if (image[3] != 0)
      return line + ", depth " + str(image[2] / image[3]) + " (" + holds(image[2] / image[3] == expected) + ")";
    return line + ": w = 0, the plane passes through the eye";
  };
  checks.push_back(check_line("near", -n, near_image, -1));
  checks.push_back(check_line("far", -f, far_image, 1));
  e.steps.push_back(text_step("Check both conditions:", checks));
  e.result_name = "N(α, β), as perspective_normalization(n, f) in shadowproof/constructions/project.h builds it";
  e.result = N;
  return e;
}

// =============================================================================================
// Frustum

explanation explain_frustum(const rational& l, const rational& r, const rational& b, const rational& t,
                           const rational& n, const rational& f, depth_convention c, bool infinite_far) {
  (void)frustum(l, r, b, t, n, f, c, infinite_far);  // the same preconditions and error messages
  const depth_range<rational> z = ndc_depth_range<rational>(c);
  explanation e;
  e.title = "Perspective frustum [" + str(l) + ", " + str(r) + "] x [" + str(b) + ", " + str(t) +
            "], near " + str(n) + ", far " + (infinite_far ? std::string("infinite") : str(f)) +
            ", convention " + std::string(to_string(c));
  e.steps.push_back(text_step(
      "The eye looks down −z; the window [l, r] x [b, t] lies on the near plane z = −n. In this "
      "convention the near plane goes to depth z_near and the far plane to z_far:",
      {"z_near = " + str(z.near_ndc) + ", z_far = " + str(z.far_ndc)}));
  e.steps.push_back(text_step(
      "A point (x, y, z) in front of the eye (z < 0) is seen where its ray meets the near plane, at "
      "x_n = n x/(−z), y_n = n y/(−z). The division by −z is the division by w: the last row is "
      "(0, 0, −1, 0)."));
  const rational sx = 2 * n / (r - l), ox = (r + l) / (r - l);
  const rational sy = 2 * n / (t - b), oy = (t + b) / (t - b);
  e.steps.push_back(text_step(
      "The window maps onto [−1, 1]: x_ndc = 2 (x_n − l)/(r − l) − 1 = (2n/(r−l) x + (r+l)/(r−l) z)/(−z), "
      "and the same for y:",
      {"2n/(r−l) = " + str(sx) + ", (r+l)/(r−l) = " + str(ox),
       "2n/(t−b) = " + str(sy) + ", (t+b)/(t−b) = " + str(oy)}));
  rational A, B;
  if (!infinite_far) {
    A = (n * z.near_ndc - f * z.far_ndc) / (f - n);
    B = n * z.near_ndc + n * A;
    e.steps.push_back(text_step(
        "Depth is (A z + B)/(−z). Near z = −n → z_near: −nA + B = n z_near; far z = −f → z_far: "
        "−fA + B = f z_far. Subtracting, A = (n z_near − f z_far)/(f − n), then B = n z_near + nA:",
        {"−" + factor(n) + "·A + B = " + str(n * z.near_ndc) + ", −" + factor(f) + "·A + B = " +
             str(f * z.far_ndc),
         "A = (" + factor(n) + "·" + factor(z.near_ndc) + " − " + factor(f) + "·" + factor(z.far_ndc) + ")/(" +
             str(f - n) + ") = " + str(A),
         "B = " + factor(n) + "·" + factor(z.near_ndc) + " + " + factor(n) + "·" + factor(A) + " = " + str(B)}));
  } else {
    A = -z.far_ndc;
    B = n * (z.near_ndc - z.far_ndc);
    e.steps.push_back(text_step(
        "Depth is (A z + B)/(−z). Near z = −n → z_near gives −nA + B = n z_near; letting the far plane "
        "go to infinity, (A z + B)/(−z) → −A must be z_far. So A = −z_far and B = n (z_near − z_far):",
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
  const auto ndc_line = [](const std::string& what, const vec4<rational>& image, const std::vector<rational>& expected) {
    const std::vector<rational> ndc{image[0] / image[3], image[1] / image[3], image[2] / image[3]};
    return what + " -> " + vec_text(image) + ", NDC " + list_text(ndc) + " (" + holds(ndc == expected) + ")";
  };
  checks.push_back(ndc_line("near corner (l, b, −n) = " + list_text({l, b, -n}), M * make_point<rational>(l, b, rational(-n)),
                            {rational(-1), rational(-1), z.near_ndc}));
  if (!infinite_far) {
    const vec4<rational> corner = make_point<rational>(r * f / n, t * f / n, -f);
    checks.push_back(ndc_line("far corner (rf/n, tf/n, −f) = " + list_text(xyz(corner)), M * corner,
                              {rational(1), rational(1), z.far_ndc}));
  } else {
    const vec4<rational> direction = make_vec4<rational>(r / n, t / n, -1, 0);
    checks.push_back(ndc_line("direction (r/n, t/n, −1, 0) = " + vec_text(direction), M * direction,
                              {rational(1), rational(1), z.far_ndc}));
  }
  e.steps.push_back(text_step("Check opposite corners of the view volume:", checks));
  e.result_name = "frustum matrix M, as `shadowproof project frustum` prints it";
  e.result = M;
  return e;
}

// =============================================================================================
// Normal matrix

explanation explain_normal_matrix(const mat4<rational>& M) {
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
  e.result_name = "normal matrix G = (M⁻¹)ᵀ, as `shadowproof normal-matrix` prints it";
  e.result = G;
  return e;
}

// =============================================================================================
// Text

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
