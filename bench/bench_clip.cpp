// Exact shadow regions of meshes against Clipper's union of the same triangles, in one run.
//
//   bench_clip [--data DIR] [--quick] [--skip-meshes] [--only NAME] [--no-clipper] [--arrangement]
//   (--quick: without the 1M-triangle meshes; --skip-meshes: without the 1k-50k spheres and tori;
//   --no-clipper: the exact runs only, for profiling them; no ratio is printed; --arrangement:
//   the silhouette builder with CGAL's arrangement instead of its own sweep)
//   bench_clip --write-off DIR
//   (writes DIR/sphere-1M.off, the 1M-triangle sphere with its coordinates as exact decimals,
//   and DIR/sphere-1M.json, its scene, for bench/bench_clip_cli.sh)
//
// Cases (each over a square receiver under a directional light):
// - UV spheres and tori of about 1k, 10k, 50k and 1M triangles, vertices snapped to multiples
//   of 2^-16 so the meshes are closed and exactly rational;
// - the Debian libcgal-demo models armadillo, bunny00, elephant and ChineseDragon-10kv (OFF
//   files in DIR, default $SHADOWPROOF_BENCH_DATA; scripts/bench-data.sh installs them), over a
//   ground plane below each model;
// - a soup of 10k separate triangles (no shared edge: nothing cancels, the worst case);
// - one convex and one star-shaped 4096-gon crossing the receiver plane (the face cap), and
//   convex 1024- and 2048-gons to show the growth with n.
// Exact: compute_shadow_region (the silhouette builder) on the light-facing triangles, and on
// the whole mesh; Clipper (Debian libpolyclipping 6.4): the light-facing triangles projected
// in double, snapped to 64-bit integers, united with the non-zero rule and intersected with the
// receiver. Each measurement runs in its own forked process, so its peak resident memory
// (ru_maxrss: the scene, the mesh and the computation) is its own. Times are medians of
// repeated runs, wall clock and process CPU time (steadier on a loaded machine).
#include <clipper.hpp>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "shadowproof/clip/shadow_region.h"
#include "shadowproof/core/vec3.h"

using namespace shadowproof;

namespace {

const double pi = 3.14159265358979323846;

clip_method exact_method = clip_method::automatic;  // --arrangement: clip_method::arrangement

// A mesh in doubles (every coordinate exactly what the rational mesh holds).
struct dmesh {
  std::vector<std::array<double, 3>> v;
  std::vector<std::vector<std::size_t>> f;
};

// A bench case: the mesh, the receiver plane's "up" axis and height, the light.
struct bench_case {
  std::string name;
  std::function<dmesh()> make;
  int up = 2;                              // receiver plane x_up = height
  std::array<double, 4> light{1, 2, 5, 0};  // towards the light, directional
  double height = 0;
  double half = 4;                         // receiver half-width around `centre`
  std::array<double, 2> centre{0, 0};      // in the two other axes (up+1, up+2)
};

double snap(double x) { return std::ldexp(std::nearbyint(std::ldexp(x, 16)), -16); }

dmesh uv_sphere(int slices, int stacks) {
  dmesh m;
  const double r = 1.5, cz = 2.5;
  m.v.push_back({0, 0, snap(cz + r)});
  for (int i = 1; i < stacks; ++i) {
    const double th = pi * i / stacks;
    for (int j = 0; j < slices; ++j) {
      const double ph = 2 * pi * j / slices;
      m.v.push_back({snap(r * std::sin(th) * std::cos(ph)), snap(r * std::sin(th) * std::sin(ph)), snap(cz + r * std::cos(th))});
    }
  }
  m.v.push_back({0, 0, snap(cz - r)});
  const auto ring = [&](int i, int j) { return static_cast<std::size_t>(1 + (i - 1) * slices + (j % slices)); };
  const std::size_t south = m.v.size() - 1;
  for (int j = 0; j < slices; ++j) m.f.push_back({0, ring(1, j), ring(1, j + 1)});
  for (int i = 1; i + 1 < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      m.f.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      m.f.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  for (int j = 0; j < slices; ++j) m.f.push_back({south, ring(stacks - 1, j + 1), ring(stacks - 1, j)});
  return m;
}

dmesh torus(int u, int w) {
  dmesh m;
  const double R = 1.6, r = 0.6, cz = 2.0;
  for (int i = 0; i < u; ++i)
    for (int j = 0; j < w; ++j) {
      const double a = 2 * pi * i / u, b = 2 * pi * j / w;
      m.v.push_back({snap((R + r * std::cos(b)) * std::cos(a)), snap((R + r * std::cos(b)) * std::sin(a)), snap(cz + r * std::sin(b))});
    }
  const auto id = [&](int i, int j) { return static_cast<std::size_t>((i % u) * w + (j % w)); };
  for (int i = 0; i < u; ++i)
    for (int j = 0; j < w; ++j) {
      m.f.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.f.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

// 10k triangles, each with its own three vertices, small and scattered: nothing cancels.
dmesh soup(std::size_t n) {
  dmesh m;
  std::uint64_t x = 88172645463325252ull;
  const auto next = [&] {  // xorshift64, uniform in [0, 1) on a 2^-16 grid
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    return static_cast<double>(x >> 48) / 65536.0;
  };
  for (std::size_t t = 0; t < n; ++t) {
    const double cx = -3 + 6 * next(), cy = -3 + 6 * next(), h = 0.5 + 2.5 * next();
    for (int k = 0; k < 3; ++k) m.v.push_back({snap(cx + 0.3 * next()), snap(cy + 0.3 * next()), snap(h + 0.2 * next())});
    m.f.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  }
  return m;
}

// One n-gon in the plane z = 1 + x/4 (crossing the receiver z = 0 at x = −4): convex (on a
// parabola) or a star (alternating radii, not convex).
dmesh big_face(bool convex, int n) {
  dmesh m;
  m.f.emplace_back();
  for (int i = 0; i < n; ++i) {
    double x, y;
    if (convex) {  // (t, t²) for t in [−3, 3): strictly convex, closed by the top chord
      const double t = -3 + 6.0 * i / n;
      x = t;
      y = t * t / 3 - 1.5;
    } else {
      const double a = 2 * pi * i / n, r = (i % 2 == 0) ? 3.0 : 2.0;
      x = r * std::cos(a);
      y = r * std::sin(a);
    }
    m.v.push_back({snap(x), snap(y), 0});
    m.f.back().push_back(static_cast<std::size_t>(i));
  }
  if (convex) std::reverse(m.f.back().begin(), m.f.back().end());
  for (auto& p : m.v) p[2] = 1 + p[0] / 4;  // exact: x/4 of a 2^-16 multiple
  return m;
}

// A model from an OFF file, in doubles (the nearest double of each decimal; the exact run
// reads the decimals themselves).
dmesh read_off_doubles(const std::string& path) {
  std::ifstream in(path);
  std::string head;
  std::size_t nv = 0, nf = 0, ne = 0;
  in >> head >> nv >> nf >> ne;
  dmesh m;
  m.v.resize(nv);
  for (auto& p : m.v) in >> p[0] >> p[1] >> p[2];
  m.f.resize(nf);
  for (auto& f : m.f) {
    std::size_t k = 0;
    in >> k;
    f.resize(k);
    for (auto& i : f) in >> i;
  }
  if (!in) {
    std::fprintf(stderr, "bench_clip: cannot read %s (run scripts/bench-data.sh)\n", path.c_str());
    std::exit(1);
  }
  return m;
}

double plane_value_d(const bench_case& c, const std::array<double, 3>& p) { return p[static_cast<std::size_t>(c.up)] - c.height; }

// The light-facing faces (n·l > 0 for the face's normal by its vertex order): Newell's normal
// in double with a forward error bound, exact rationals only when the bound cannot decide
// (the snapped meshes never need them; a million faces in well under a second).
std::vector<std::size_t> facing_faces(const bench_case& c, const dmesh& m, const std::vector<point3>& exact) {
  std::vector<std::size_t> out;
  const point3 l{exact_value(c.light[0]), exact_value(c.light[1]), exact_value(c.light[2])};
  std::vector<std::array<double, 3>> v(exact.size());
  std::vector<bool> exact_double(exact.size());
  for (std::size_t i = 0; i < exact.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      v[i][k] = exact[i][k].get_d();
      exact_double[i] = (k == 0 || exact_double[i]) && rational(v[i][k]) == exact[i][k];
    }
  const auto& d = c.light;
  const double eps = std::ldexp(1.0, -50);
  for (std::size_t f = 0; f < m.f.size(); ++f) {
    const auto& face = m.f[f];
    // Σ a×b over the edges, then ·l: each term's rounding error is below eps times the sum
    // of the absolute values (a loose bound for faces of fewer than 2^40 vertices).
    double s = 0, bound = 0;
    bool doubles = true;
    for (std::size_t i = 0; i < face.size(); ++i) {
      const auto &a = v[face[i]], &b = v[face[(i + 1) % face.size()]];
      doubles = doubles && exact_double[face[i]];
      const double t[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      const double ta[3] = {std::fabs(a[1] * b[2]) + std::fabs(a[2] * b[1]), std::fabs(a[2] * b[0]) + std::fabs(a[0] * b[2]),
                            std::fabs(a[0] * b[1]) + std::fabs(a[1] * b[0])};
      for (int k = 0; k < 3; ++k) {
        s += t[k] * d[static_cast<std::size_t>(k)];
        bound += ta[k] * std::fabs(d[static_cast<std::size_t>(k)]);
      }
    }
    bound *= eps * static_cast<double>(face.size() + 4);
    if (doubles && s > bound) {
      out.push_back(f);
      continue;
    }
    if (doubles && s < -bound) continue;
    point3 n{rational(0), rational(0), rational(0)};
    for (std::size_t i = 0; i < face.size(); ++i) n = sum(n, cross(exact[face[i]], exact[face[(i + 1) % face.size()]]));
    if (dot(n, l) > 0) out.push_back(f);
  }
  return out;
}

scene make_scene(const bench_case& c, const std::vector<point3>& v, std::vector<std::vector<std::size_t>> faces) {
  scene s;
  const auto corner = [&](double a, double b) {
    point3 p;
    p[static_cast<std::size_t>(c.up)] = exact_value(c.height);
    p[static_cast<std::size_t>((c.up + 1) % 3)] = exact_value(c.centre[0] + a);
    p[static_cast<std::size_t>((c.up + 2) % 3)] = exact_value(c.centre[1] + b);
    return p;
  };
  s.receiver.outer.vertices = {corner(-c.half, -c.half), corner(c.half, -c.half), corner(c.half, c.half), corner(-c.half, c.half)};
  s.light_source = make_light(exact_value(c.light[0]), exact_value(c.light[1]), exact_value(c.light[2]), exact_value(c.light[3]));
  caster k;
  k.name = "/casters/0/mesh";
  k.vertices = v;
  k.faces = std::move(faces);
  s.casters.push_back(std::move(k));
  return s;
}

// What a measurement reports back through the pipe.
struct result {
  double wall_ms = 0, cpu_ms = 0, area = 0;
  std::size_t silhouette = 0, faces = 0;
  long maxrss_kb = 0;
};

double cpu_now_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

double median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  return x.empty() ? 0 : x[x.size() / 2];
}

// Runs `body` in a child process `reps` times; the child reports medians, the parent adds the
// child's peak memory. A child over `cpu_limit_s` seconds of CPU is stopped (SIGXCPU) and its
// times are reported as negative: "did not finish".
result measure(int reps, const std::function<void(result&)>& setup, const std::function<void(result&)>& body,
               int cpu_limit_s = 600) {
  int fd[2];
  if (pipe(fd) != 0) std::exit(1);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    const rlimit limit{static_cast<rlim_t>(cpu_limit_s), static_cast<rlim_t>(cpu_limit_s)};
    setrlimit(RLIMIT_CPU, &limit);
    result r;
    setup(r);
    std::vector<double> wall, cpu;
    for (int i = 0; i < reps; ++i) {
      const auto w0 = std::chrono::steady_clock::now();
      const double c0 = cpu_now_ms();
      body(r);
      cpu.push_back(cpu_now_ms() - c0);
      wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - w0).count());
    }
    r.wall_ms = median(wall);
    r.cpu_ms = median(cpu);
    if (write(fd[1], &r, sizeof r) != static_cast<ssize_t>(sizeof r)) _exit(1);
    _exit(0);
  }
  close(fd[1]);
  result r;
  if (read(fd[0], &r, sizeof r) != static_cast<ssize_t>(sizeof r)) r.wall_ms = r.cpu_ms = -1;  // stopped
  close(fd[0]);
  int status = 0;
  rusage use{};
  wait4(pid, &status, 0, &use);
  r.maxrss_kb = use.ru_maxrss;
  return r;
}

std::vector<point3> to_exact(const dmesh& m) {
  std::vector<point3> v;
  v.reserve(m.v.size());
  for (const auto& p : m.v) v.push_back({exact_value(p[0]), exact_value(p[1]), exact_value(p[2])});
  return v;
}

// The exact shadow of `faces` (all, or the light-facing ones).
result run_exact(const bench_case& c, bool facing_only, int reps, const std::string& off_path) {
  scene s;
  return measure(
      reps,
      [&](result& r) {
        if (!off_path.empty()) {
          // The model's decimals read exactly, as `shadowproof clip` does.
          caster k = read_mesh_file(off_path, "/casters/0/mesh");
          dmesh m;
          m.f = k.faces;
          std::vector<std::vector<std::size_t>> faces = k.faces;
          if (facing_only) {
            std::vector<std::vector<std::size_t>> kept;
            for (auto f : facing_faces(c, m, k.vertices)) kept.push_back(k.faces[f]);
            faces = std::move(kept);
          }
          s = make_scene(c, k.vertices, std::move(faces));
        } else {
          const dmesh m = c.make();
          const auto v = to_exact(m);
          std::vector<std::vector<std::size_t>> faces;
          if (facing_only) {
            for (auto f : facing_faces(c, m, v)) faces.push_back(m.f[f]);
          } else {
            faces = m.f;
          }
          s = make_scene(c, v, std::move(faces));
        }
        r.faces = s.casters[0].faces.size();
      },
      [&](result& r) {
        clip_options o;
        o.keep_projected = false;
        o.detect_overlap = false;
        o.method = exact_method;
        const shadow_region region = compute_shadow_region(s, o);
        r.area = approximate_area(region);
        r.silhouette = region.silhouette_edges;
      });
}

// Clipper's union of the light-facing faces projected in double.
result run_clipper(const bench_case& c, int reps, const std::string& off_path, int cpu_limit_s) {
  dmesh m;
  std::vector<ClipperLib::Path> faces;
  ClipperLib::Path receiver;
  double scale = 1;
  return measure(
      reps,
      [&](result& r) {
        m = off_path.empty() ? c.make() : read_off_doubles(off_path);
        // Light-facing test in double (exact for the snapped meshes, and for the models as
        // good as a float pipeline gets).
        const auto& l = c.light;
        double extent = 1;
        for (const auto& p : m.v) extent = std::max({extent, std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])});
        // 2^32 for coordinates up to 6 (the spheres), proportionally less for larger models.
        scale = std::ldexp(1.0, 32 - std::max(0, static_cast<int>(std::ceil(std::log2(extent / 6)))));
        const int up = c.up, i1 = (up + 1) % 3, i2 = (up + 2) % 3;
        const auto project = [&](const std::array<double, 3>& p) {
          const double k = plane_value_d(c, p) / l[static_cast<std::size_t>(up)];
          return ClipperLib::IntPoint(static_cast<ClipperLib::cInt>(std::llround((p[static_cast<std::size_t>(i1)] - k * l[static_cast<std::size_t>(i1)]) * scale)),
                                      static_cast<ClipperLib::cInt>(std::llround((p[static_cast<std::size_t>(i2)] - k * l[static_cast<std::size_t>(i2)]) * scale)));
        };
        for (const auto& f : m.f) {
          std::array<double, 3> n{0, 0, 0};
          for (std::size_t i = 0; i < f.size(); ++i) {
            const auto &a = m.v[f[i]], &b = m.v[f[(i + 1) % f.size()]];
            n[0] += a[1] * b[2] - a[2] * b[1];
            n[1] += a[2] * b[0] - a[0] * b[2];
            n[2] += a[0] * b[1] - a[1] * b[0];
          }
          if (n[0] * l[0] + n[1] * l[1] + n[2] * l[2] <= 0) continue;
          ClipperLib::Path p;
          for (auto i : f) p.push_back(project(m.v[i]));
          faces.push_back(std::move(p));
        }
        const auto e = [&](double a, double b) {
          return ClipperLib::IntPoint(static_cast<ClipperLib::cInt>(std::llround((c.centre[0] + a) * scale)),
                                      static_cast<ClipperLib::cInt>(std::llround((c.centre[1] + b) * scale)));
        };
        receiver = {e(-c.half, -c.half), e(c.half, -c.half), e(c.half, c.half), e(-c.half, c.half)};
        r.faces = faces.size();
      },
      [&](result& r) {
        ClipperLib::Paths tris = faces;
        for (auto& p : tris)
          if (!ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);
        ClipperLib::Clipper u;
        u.AddPaths(tris, ClipperLib::ptSubject, true);
        ClipperLib::Paths uni;
        u.Execute(ClipperLib::ctUnion, uni, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
        ClipperLib::Clipper k;
        k.AddPaths(uni, ClipperLib::ptSubject, true);
        k.AddPath(receiver, ClipperLib::ptClip, true);
        ClipperLib::Paths out;
        k.Execute(ClipperLib::ctIntersection, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
        double area = 0;
        for (const auto& p : out) area += ClipperLib::Area(p);
        r.area = area / (scale * scale);
      },
      cpu_limit_s);
}

// The mesh as an OFF file with exact decimals (a multiple of 2^-16 has at most 16 decimal
// places, and printf prints the exact expansion), and a scene JSON with the bench's receiver
// and light.
void write_off(const bench_case& c, const std::string& dir, const std::string& stem) {
  const dmesh m = c.make();
  std::FILE* off = std::fopen((dir + "/" + stem + ".off").c_str(), "w");
  if (!off) {
    std::fprintf(stderr, "bench_clip: cannot write %s/%s.off\n", dir.c_str(), stem.c_str());
    std::exit(1);
  }
  std::fprintf(off, "OFF\n%zu %zu 0\n", m.v.size(), m.f.size());
  for (const auto& p : m.v) std::fprintf(off, "%.16f %.16f %.16f\n", p[0], p[1], p[2]);
  for (const auto& f : m.f) {
    std::fprintf(off, "%zu", f.size());
    for (auto i : f) std::fprintf(off, " %zu", i);
    std::fprintf(off, "\n");
  }
  std::fclose(off);
  std::ofstream json(dir + "/" + stem + ".json");
  const double h = c.half;
  json << "{\n  \"receiver\": {\"polygon\": [[" << -h << ", " << -h << ", 0], [" << h << ", " << -h << ", 0], [" << h
       << ", " << h << ", 0], [" << -h << ", " << h << ", 0]]},\n  \"light\": [" << c.light[0] << ", " << c.light[1] << ", "
       << c.light[2] << ", " << c.light[3] << "],\n  \"casters\": [{\"mesh\": {\"file\": \"" << stem << ".off\"}}]\n}\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::string data = std::getenv("SHADOWPROOF_BENCH_DATA") ? std::getenv("SHADOWPROOF_BENCH_DATA") : "";
  bool quick = false, skip_meshes = false, clipper = true;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--data") == 0 && i + 1 < argc) data = argv[++i];
    else if (std::strcmp(argv[i], "--quick") == 0) quick = true;
    else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc) only = argv[++i];
    else if (std::strcmp(argv[i], "--skip-meshes") == 0) skip_meshes = true;
    else if (std::strcmp(argv[i], "--no-clipper") == 0) clipper = false;
    else if (std::strcmp(argv[i], "--arrangement") == 0) exact_method = clip_method::arrangement;
    else if (std::strcmp(argv[i], "--write-off") == 0 && i + 1 < argc) {
      write_off({"sphere 1M", [] { return uv_sphere(708, 707); }}, argv[i + 1], "sphere-1M");
      return 0;
    }
    else {
      std::fprintf(stderr, "usage: bench_clip [--data DIR] [--quick] [--skip-meshes] [--only NAME] [--no-clipper] [--arrangement] | --write-off DIR\n");
      return 2;
    }
  }
  std::vector<bench_case> cases;
  if (!skip_meshes) {
    cases.push_back({"sphere 1k", [] { return uv_sphere(23, 23); }});
    cases.push_back({"sphere 10k", [] { return uv_sphere(72, 70); }});
    cases.push_back({"sphere 50k", [] { return uv_sphere(160, 157); }});
    cases.push_back({"torus 1k", [] { return torus(32, 16); }});
    cases.push_back({"torus 10k", [] { return torus(100, 50); }});
    cases.push_back({"torus 50k", [] { return torus(250, 100); }});
  }
  if (!quick) {
    cases.push_back({"sphere 1M", [] { return uv_sphere(708, 707); }});  // as --write-off
    cases.push_back({"torus 1M", [] { return torus(1000, 500); }});
  }
  cases.push_back({"soup 10k", [] { return soup(10000); }});
  cases.push_back({"convex 1024-gon", [] { return big_face(true, 1024); }});
  cases.push_back({"convex 2048-gon", [] { return big_face(true, 2048); }});
  cases.push_back({"convex 4096-gon", [] { return big_face(true, 4096); }});
  cases.push_back({"star 4096-gon", [] { return big_face(false, 4096); }});
  struct model {
    const char* name;
    const char* file;
    int up;
    double y_min, half, c0, c1;
  };
  // Ground planes just below each model (up axis y), receivers wide enough for the shadow.
  const model models[] = {{"armadillo", "armadillo.off", 1, -55, 200, 0, 0},
                          {"bunny", "bunny00.off", 1, -0.5, 2, 0, 0},
                          {"elephant", "elephant.off", 1, -0.5, 2, 0, 0},
                          {"Chinese dragon", "ChineseDragon-10kv.off", 1, -53, 250, -980, 0}};
  std::vector<std::string> files(cases.size());
  if (!data.empty())
    for (const auto& m : models) {
      bench_case c{m.name, nullptr, m.up, {1, 3, 2, 0}, m.y_min, m.half, {m.c0, m.c1}};
      cases.push_back(c);
      files.push_back(data + "/" + m.file);
    }
  std::printf("| case | faces | light-facing | silhouette edges | exact, light-facing (ms) | exact, whole mesh (ms) | Clipper (ms) "
              "| Clipper / exact | Clipper / exact whole | peak MB exact whole | peak MB Clipper | area exact | area Clipper |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto& c = cases[i];
    if (!only.empty() && c.name.find(only) == std::string::npos) continue;
    const bool large = c.name.find("1M") != std::string::npos;
    const int reps = large ? 3 : 7;
    const result front = run_exact(c, true, reps, files[i]);
    const result whole = run_exact(c, false, reps, files[i]);
    // Clipper's union slows down badly with many shared edges: one run, at most 15 CPU minutes.
    const int clip_limit = large ? 900 : 600;
    if (!clipper) {
      std::printf("| %s | %zu | %zu | %zu | %.1f wall, %.1f CPU | %.1f wall, %.1f CPU | - | - | - | %.0f | - | %.6g | - |\n",
                  c.name.c_str(), whole.faces, front.faces, whole.silhouette, front.wall_ms, front.cpu_ms, whole.wall_ms,
                  whole.cpu_ms, whole.maxrss_kb / 1024.0, whole.area);
      std::fflush(stdout);
      continue;
    }
    const result clip = run_clipper(c, large ? 1 : reps, files[i], clip_limit);
    std::printf("| %s | %zu | %zu | %zu | %.1f wall, %.1f CPU | %.1f wall, %.1f CPU | ", c.name.c_str(), whole.faces,
                front.faces, whole.silhouette, front.wall_ms, front.cpu_ms, whole.wall_ms, whole.cpu_ms);
    if (clip.cpu_ms < 0)
      std::printf("not done in %d s CPU | > %.0f | > %.0f | %.0f | %.0f | %.6g | - |\n", clip_limit, clip_limit * 1e3 / front.cpu_ms,
                  clip_limit * 1e3 / whole.cpu_ms, whole.maxrss_kb / 1024.0, clip.maxrss_kb / 1024.0, whole.area);
    else
      std::printf("%.1f wall, %.1f CPU | %.1f | %.1f | %.0f | %.0f | %.6g | %.6g |\n", clip.wall_ms, clip.cpu_ms,
                  clip.cpu_ms / front.cpu_ms, clip.cpu_ms / whole.cpu_ms, whole.maxrss_kb / 1024.0,
                  clip.maxrss_kb / 1024.0, whole.area, clip.area);
    std::fflush(stdout);
  }
  return 0;
}
