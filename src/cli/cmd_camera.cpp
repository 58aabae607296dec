// shadowproof camera: the exact camera matrices whose entries are irrational, a perspective
// from a field-of-view angle and a look-at view (or its inverse placement), each entry given
// exactly where it is rational and otherwise as its correct roundings to float and double
// with a 30-digit decimal, decided by MPFR enclosures (constructions/irrational.h).
#include <mpfr.h>

#include <nlohmann/json.hpp>

#include <iomanip>
#include <iostream>
#include <memory>

#include "command.h"
#include "shadowproof/constructions/handedness.h"
#include "shadowproof/constructions/irrational.h"
#include "shadowproof/constructions/look_at.h"
#include "shadowproof/constructions/project.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/ulp.h"

namespace shadowproof::cli {
namespace {

struct camera_options {
  std::string kind;
  std::string fovy, aspect, near_text, far_text, eye, target, up;
  bool degrees = false, infinite_far = false, json = false;
  std::string convention = "gl", hand = "right";
};

// One entry: exact (rational) or irrational with its correct roundings.
struct entry {
  bool defined = true;
  bool is_rational = true;
  rational value;  // the exact value, or a correctly rounding representative (f32, f64 only)
  std::string closed_form;
  enclosure tight;  // irrational: lo ≤ value ≤ hi at 256 bits, for the decimal
};

// 30 significant digits of a number known to within 2^-250 relative: the midpoint of its
// 256-bit enclosure (the last digit can be off by one only at a decimal rounding boundary).
std::string decimal30(const enclosure& e) {
  mpfr_t x;
  mpfr_init2(x, 256);
  const rational mid = (e.lo + e.hi) / 2;
  mpfr_set_q(x, mid.get_mpq_t(), MPFR_RNDN);
  char buffer[64];
  mpfr_snprintf(buffer, sizeof buffer, "%.30Rg", x);
  mpfr_clear(x);
  return buffer;
}

// A number that must be exactly a double: the camera's inputs are float or double values.
double input_double(const std::string& text, const char* flag, const number_limits& limits) {
  rational q;
  try {
    q = parse_number(text, limits);
  } catch (const error& e) {
    throw error(e.code(), std::string(flag) + ": " + e.what());
  }
  const double d = to_nearest_double(q);
  if (exact_value(d) != q)
    throw error(errc::number_malformed, std::string(flag) + ": " + text +
                                            " is not exactly a double (the camera commands take float or double "
                                            "inputs; write f64:" + text + " for the nearest double)");
  return d;
}

rational input_rational(const std::string& text, const char* flag, const number_limits& limits) {
  try {
    return parse_number(text, limits);
  } catch (const error& e) {
    throw error(e.code(), std::string(flag) + ": " + e.what());
  }
}

vec3<rational> input_vec3(const std::string& text, const char* flag, const number_limits& limits) {
  const auto v = parse_number_list(text, 3, flag, limits);
  return {v[0], v[1], v[2]};
}

std::array<entry, 16> perspective_entries(const camera_options& o, const number_limits& limits, std::string& title) {
  const angle_unit unit = o.degrees ? angle_unit::degrees : angle_unit::radians;
  const double fovy = input_double(o.fovy, "--fovy", limits);
  const rational aspect = input_rational(o.aspect, "--aspect", limits);
  const rational n = input_rational(o.near_text, "--near", limits);
  if (o.infinite_far == !o.far_text.empty())
    throw error(o.infinite_far ? errc::cli_unused_option : errc::cli_missing_option,
                "perspective needs exactly one of --far and --infinite-far");
  const rational f = o.infinite_far ? rational(0) : input_rational(o.far_text, "--far", limits);
  if (!field_of_view_in_range(fovy, unit))
    throw error(errc::project_focal_not_positive, "--fovy " + o.fovy + " " + std::string(to_string(unit)) +
                                                      " is not inside (0, " + (o.degrees ? "180" : "pi") +
                                                      "), so cot(fovy/2) is not positive");
  const depth_convention depth = parse_depth_convention(o.convention);
  const handedness hand = parse_handedness(o.hand);
  // The depth rows exactly; perspective() also checks aspect, near and far.
  mat4<rational> M = with_handedness(perspective(aspect, aspect, n, f, depth, o.infinite_far), hand);
  std::array<entry, 16> e;
  for (std::size_t i = 0; i < 16; ++i) e[i].value = M(i / 4, i % 4);
  auto cot = [&](const rational& divisor, const char* what) {
    return correctly_rounding_representative(
        [&](long p) {
          const enclosure c = cot_half_angle(fovy, unit, p);
          return enclosure{c.lo / divisor, c.hi / divisor};
        },
        what);
  };
  const enclosure c256 = cot_half_angle(fovy, unit, 256);
  if (unit == angle_unit::degrees && fovy == 90) {  // cot 45° = 1, the only rational case (Niven)
    e[0] = {true, true, rational(1) / aspect, "", {}};
    e[5] = {true, true, rational(1), "", {}};
  } else {
    e[0] = {true, false, cot(aspect, "cot(fovy/2)/aspect"), "cot(fovy/2)/aspect", {c256.lo / aspect, c256.hi / aspect}};
    e[5] = {true, false, cot(rational(1), "cot(fovy/2)"), "cot(fovy/2)", c256};
  }
  title = "perspective: fovy = " + to_string(exact_value(fovy)) + " " + std::string(to_string(unit)) + ", aspect = " +
          to_string(aspect) + ", near = " + to_string(n) + ", far = " + (o.infinite_far ? "infinity" : to_string(f)) +
          ", convention " + std::string(to_string(depth)) + ", " + std::string(to_string(hand)) + "-handed";
  return e;
}

std::array<entry, 16> look_at_view_entries(const camera_options& o, const number_limits& limits, std::string& title) {
  const vec3<rational> eye = input_vec3(o.eye, "--eye", limits), target = input_vec3(o.target, "--target", limits),
                       up = input_vec3(o.up, "--up", limits);
  const handedness hand = parse_handedness(o.hand);
  const bool placement = o.kind == "target-to";
  const auto roots = placement ? target_to_entries(eye, target, up, hand) : look_at_entries(eye, target, up, hand);
  const camera_frame<rational> frame = make_camera_frame(eye, target, up, hand);
  if (frame.ww == 0) throw error(errc::camera_degenerate_view, "--eye equals --target: the camera has no view direction");
  if (frame.xx == 0)
    throw error(errc::camera_degenerate_view,
                "--up is parallel to the view direction (or zero): the camera's x and y axes are undefined");
  std::array<entry, 16> e;
  for (std::size_t i = 0; i < 16; ++i) {
    const root_entry<rational>& r = roots[i];
    const rational square = r.numerator * r.numerator / r.radicand;
    const auto root = exact_sqrt(square);
    e[i].is_rational = root.has_value();
    e[i].value = signed_sqrt_representative(sgn(r.numerator), square);
    if (!root) {
      e[i].closed_form = to_string(r.numerator) + "/sqrt(" + to_string(r.radicand) + ")";
      const enclosure m = sqrt_enclosure(square, 256);
      e[i].tight = sgn(r.numerator) < 0 ? enclosure{-m.hi, -m.lo} : m;
    }
  }
  title = std::string(placement ? "target-to (camera placement, eye to world)" : "look-at view matrix (world to eye)") +
          ": eye = (" + to_string(eye[0]) + ", " + to_string(eye[1]) + ", " + to_string(eye[2]) + "), target = (" +
          to_string(target[0]) + ", " + to_string(target[1]) + ", " + to_string(target[2]) + "), up = (" +
          to_string(up[0]) + ", " + to_string(up[1]) + ", " + to_string(up[2]) + "), " + std::string(to_string(hand)) +
          "-handed";
  return e;
}

int run_camera(const camera_options& o, const global_options& g) {
  std::string title;
  const std::array<entry, 16> e =
      o.kind == "perspective" ? perspective_entries(o, g.limits, title) : look_at_view_entries(o, g.limits, title);
  if (o.json) {
    nlohmann::json doc;
    doc["camera"] = o.kind;
    doc["description"] = title;
    nlohmann::json entries = nlohmann::json::array();
    for (std::size_t i = 0; i < 16; ++i) {
      nlohmann::json j{{"row", i / 4}, {"column", i % 4}, {"rational", e[i].is_rational}};
      if (e[i].is_rational) j["exact"] = to_string(e[i].value);
      else j["closed_form"] = e[i].closed_form, j["decimal"] = decimal30(e[i].tight);
      j["f32"] = hex_string(static_cast<double>(to_nearest_float(e[i].value)));
      j["f64"] = hex_string(to_nearest_double(e[i].value));
      entries.push_back(j);
    }
    doc["entries"] = entries;
    std::cout << doc.dump(2) << '\n';
    return 0;
  }
  std::cout << title << "\n"
            << "entries (row, column): exact where rational; irrational ones as a closed form, 30 digits and their "
               "correct roundings to f32 and f64:\n";
  for (std::size_t i = 0; i < 16; ++i) {
    std::cout << "  (" << i / 4 << "," << i % 4 << ") ";
    if (e[i].is_rational) {
      std::cout << to_string(e[i].value) << '\n';
      continue;
    }
    std::cout << e[i].closed_form << " = " << decimal30(e[i].tight) << "...  f32 "
              << hex_string(static_cast<double>(to_nearest_float(e[i].value))) << "  f64 "
              << hex_string(to_nearest_double(e[i].value)) << '\n';
  }
  return 0;
}

const command_registration camera_registration{command{
    "camera",
    "camera matrices with irrational entries, correctly rounded: perspective from a field-of-view angle, look-at "
    "view, target-to placement",
    [](CLI::App& app, const global_options& g) -> std::function<int()> {
      auto o = std::make_shared<camera_options>();
      app.add_option("kind", o->kind, "perspective | look-at | target-to")
          ->required()
          ->check(CLI::IsMember({"perspective", "look-at", "target-to"}));
      app.add_option("--fovy", o->fovy, "perspective: vertical field of view, a float or double value");
      app.add_flag("--degrees", o->degrees, "perspective: --fovy is in degrees (default radians)");
      app.add_option("--aspect", o->aspect, "perspective: width/height");
      app.add_option("--near", o->near_text, "perspective: near distance (> 0)");
      app.add_option("--far", o->far_text, "perspective: far distance (> 0)");
      app.add_flag("--infinite-far", o->infinite_far, "perspective: the far plane at infinity");
      app.add_option("--convention", o->convention, "perspective: NDC depth gl, d3d or reverse-z")->capture_default_str();
      app.add_option("--eye", o->eye, "look-at, target-to: the camera's position x,y,z");
      app.add_option("--target", o->target, "look-at, target-to: the point looked at x,y,z");
      app.add_option("--up", o->up, "look-at, target-to: the up direction x,y,z");
      app.add_option("--handedness", o->hand, "right (looking down -z) or left (looking down +z)")->capture_default_str();
      app.add_flag("--json", o->json, "print one JSON object");
      return [o, &g] {
        const bool persp = o->kind == "perspective";
        const bool any_camera = !o->eye.empty() || !o->target.empty() || !o->up.empty();
        const bool any_persp = !o->fovy.empty() || !o->aspect.empty() || !o->near_text.empty() || !o->far_text.empty() ||
                               o->degrees || o->infinite_far;
        if (persp && any_camera) throw error(errc::cli_unused_option, "--eye, --target and --up do not apply to perspective");
        if (!persp && any_persp) throw error(errc::cli_unused_option, "perspective's options do not apply to " + o->kind);
        const std::vector<std::pair<const std::string*, const char*>> needed =
            persp ? std::vector<std::pair<const std::string*, const char*>>{{&o->fovy, "--fovy"}, {&o->aspect, "--aspect"}, {&o->near_text, "--near"}}
                  : std::vector<std::pair<const std::string*, const char*>>{{&o->eye, "--eye"}, {&o->target, "--target"}, {&o->up, "--up"}};
        for (const auto& [text, flag] : needed)
          if (text->empty()) throw error(errc::cli_missing_option, o->kind + " needs " + flag);
        return run_camera(*o, g);
      };
    }}};

}  // namespace
}  // namespace shadowproof::cli
