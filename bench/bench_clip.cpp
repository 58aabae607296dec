// Exact shadow region of closed meshes versus Clipper's union of the same projected triangles.
//
// Meshes: a UV sphere and a torus with about 1k, 10k and 50k triangles, vertices snapped to
// multiples of 2^-16 (so the mesh is closed and exactly rational), above the square receiver
// [-4, 4]² on z = 0, lit by the directional light (1, 2, 5, 0). For a closed, outward-oriented
// mesh only the triangles facing the light (n·l > 0) bound the shadow, so both sides receive
// only those. Exact: compute_shadow_region (3D clip, exact projection, CGAL aggregate union,
// receiver intersection). Clipper: the same triangles projected in double, snapped to 64-bit
// integers (scale 2^32), union with the non-zero rule, then intersection with the receiver.
// Both run in the same process; the summary prints the ratio of their mean times.
#include <benchmark/benchmark.h>
#include <clipper.hpp>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "shadowproof/clip/shadow_region.h"

using namespace shadowproof;

namespace {

rational snap(double x) {
  return rational(static_cast<long>(std::llround(x * 65536.0)), 65536);
}

struct mesh_case {
  std::string name;
  caster front;  // light-facing triangles only
  std::size_t total_triangles = 0;
};

const double pi = 3.14159265358979323846;

// Keeps the triangles whose outward normal has n·l > 0 (exact test on the snapped vertices).
caster front_facing(const std::vector<point3>& v, const std::vector<std::array<std::size_t, 3>>& tris,
                    const light<rational>& L) {
  caster c;
  c.name = "/casters/0/mesh";
  c.vertices = v;
  for (const auto& t : tris) {
    const point3 &a = v[t[0]], &b = v[t[1]], &d = v[t[2]];
    const rational ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const rational wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
    const rational nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
    if (nx * L.l[0] + ny * L.l[1] + nz * L.l[2] > 0) c.faces.push_back({t[0], t[1], t[2]});
  }
  return c;
}

mesh_case make_sphere(int slices, int stacks, const light<rational>& L) {
  std::vector<point3> v;
  std::vector<std::array<std::size_t, 3>> t;
  const double r = 1.5, cz = 2.5;
  v.push_back({rational(0), rational(0), snap(cz + r)});  // north pole
  for (int i = 1; i < stacks; ++i) {
    const double th = pi * i / stacks;
    for (int j = 0; j < slices; ++j) {
      const double ph = 2 * pi * j / slices;
      v.push_back({snap(r * std::sin(th) * std::cos(ph)), snap(r * std::sin(th) * std::sin(ph)), snap(cz + r * std::cos(th))});
    }
  }
  v.push_back({rational(0), rational(0), snap(cz - r)});  // south pole
  const auto ring = [&](int i, int j) { return static_cast<std::size_t>(1 + (i - 1) * slices + (j % slices)); };
  const std::size_t south = v.size() - 1;
  for (int j = 0; j < slices; ++j) t.push_back({0, ring(1, j), ring(1, j + 1)});
  for (int i = 1; i + 1 < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      t.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      t.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  for (int j = 0; j < slices; ++j) t.push_back({south, ring(stacks - 1, j + 1), ring(stacks - 1, j)});
  return {"sphere", front_facing(v, t, L), t.size()};
}

mesh_case make_torus(int u, int w, const light<rational>& L) {
  std::vector<point3> v;
  std::vector<std::array<std::size_t, 3>> t;
  const double R = 1.6, r = 0.6, cz = 2.0;
  for (int i = 0; i < u; ++i)
    for (int j = 0; j < w; ++j) {
      const double a = 2 * pi * i / u, b = 2 * pi * j / w;
      v.push_back({snap((R + r * std::cos(b)) * std::cos(a)), snap((R + r * std::cos(b)) * std::sin(a)),
                   snap(cz + r * std::sin(b))});
    }
  const auto id = [&](int i, int j) { return static_cast<std::size_t>((i % u) * w + (j % w)); };
  for (int i = 0; i < u; ++i)
    for (int j = 0; j < w; ++j) {
      t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return {"torus", front_facing(v, t, L), t.size()};
}

light<rational> bench_light() { return make_light<rational>(1, 2, 5, 0); }

scene make_bench_scene(const caster& c) {
  scene s;
  s.receiver.outer.vertices = {{rational(-4), rational(-4), rational(0)}, {rational(4), rational(-4), rational(0)},
                               {rational(4), rational(4), rational(0)}, {rational(-4), rational(4), rational(0)}};
  s.light_source = bench_light();
  s.casters = {c};
  return s;
}

const mesh_case& cached(const std::string& kind, int size) {
  static std::map<std::string, mesh_case> cache;
  const std::string key = kind + std::to_string(size);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  const auto L = bench_light();
  // Triangle counts: sphere 2·s·(t−1), torus 2·u·w.
  mesh_case m;
  if (kind == "sphere") m = size == 1 ? make_sphere(23, 23, L) : size == 10 ? make_sphere(72, 70, L) : make_sphere(160, 157, L);
  else m = size == 1 ? make_torus(32, 16, L) : size == 10 ? make_torus(100, 50, L) : make_torus(250, 100, L);
  return cache.emplace(key, std::move(m)).first->second;
}

void set_counters(benchmark::State& state, const mesh_case& m) {
  state.counters["triangles"] = static_cast<double>(m.total_triangles);
  state.counters["front"] = static_cast<double>(m.front.faces.size());
}

void bm_exact(benchmark::State& state, const std::string& kind) {
  const mesh_case& m = cached(kind, static_cast<int>(state.range(0)));
  const scene s = make_bench_scene(m.front);
  clip_options o;
  o.keep_projected = false;
  o.detect_overlap = false;
  rational area;
  for (auto _ : state) {
    const shadow_region r = compute_shadow_region(s, o);
    area = r.chart_area;
    benchmark::DoNotOptimize(area);
  }
  set_counters(state, m);
  state.counters["area"] = to_nearest_double(area);
}

void bm_clipper(benchmark::State& state, const std::string& kind) {
  const mesh_case& m = cached(kind, static_cast<int>(state.range(0)));
  const double scale = 4294967296.0;  // 2^32
  const double l[3] = {1, 2, 5};
  // Chart of z = 0 is (x, y); the directional shadow of V is V − (z / l_z) l.
  std::vector<std::array<double, 3>> vd;
  for (const auto& p : m.front.vertices)
    vd.push_back({to_nearest_double(p[0]), to_nearest_double(p[1]), to_nearest_double(p[2])});
  const auto project = [&](std::size_t i) {
    const auto& p = vd[i];
    const double k = p[2] / l[2];
    return ClipperLib::IntPoint(static_cast<ClipperLib::cInt>(std::llround((p[0] - k * l[0]) * scale)),
                                static_cast<ClipperLib::cInt>(std::llround((p[1] - k * l[1]) * scale)));
  };
  const ClipperLib::cInt e = static_cast<ClipperLib::cInt>(4 * scale);
  const ClipperLib::Path receiver{{-e, -e}, {e, -e}, {e, e}, {-e, e}};
  double area = 0;
  for (auto _ : state) {
    ClipperLib::Paths tris;
    tris.reserve(m.front.faces.size());
    for (const auto& f : m.front.faces) {
      ClipperLib::Path p{project(f[0]), project(f[1]), project(f[2])};
      if (!ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);
      tris.push_back(std::move(p));
    }
    ClipperLib::Clipper u;
    u.AddPaths(tris, ClipperLib::ptSubject, true);
    ClipperLib::Paths uni;
    u.Execute(ClipperLib::ctUnion, uni, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    ClipperLib::Clipper c;
    c.AddPaths(uni, ClipperLib::ptSubject, true);
    c.AddPath(receiver, ClipperLib::ptClip, true);
    ClipperLib::Paths out;
    c.Execute(ClipperLib::ctIntersection, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    area = 0;
    for (const auto& p : out) area += ClipperLib::Area(p);
    benchmark::DoNotOptimize(area);
  }
  set_counters(state, m);
  state.counters["area"] = area / (scale * scale);
}

// Collects mean real time per benchmark name for the ratio table.
class ratio_reporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs)
      if (r.run_type == Run::RT_Iteration) times[r.benchmark_name()] = r.GetAdjustedRealTime();
    ConsoleReporter::ReportRuns(runs);
  }
  std::map<std::string, double> times;  // in the run's time unit (ms below)
};

}  // namespace

int main(int argc, char** argv) {
  for (const char* kind : {"sphere", "torus"}) {
    const std::string k = kind;
    benchmark::RegisterBenchmark(("exact/" + k).c_str(), [k](benchmark::State& s) { bm_exact(s, k); })
        ->Arg(1)->Arg(10)->Arg(50)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
    benchmark::RegisterBenchmark(("clipper/" + k).c_str(), [k](benchmark::State& s) { bm_clipper(s, k); })
        ->Arg(1)->Arg(10)->Arg(50)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
  }
  benchmark::Initialize(&argc, argv);
  ratio_reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf("\nmesh        k-triangles  exact (ms)  clipper (ms)  exact/clipper\n");
  for (const char* kind : {"sphere", "torus"})
    for (int size : {1, 10, 50}) {
      const std::string suffix = std::string(kind) + "/" + std::to_string(size) + "/process_time/real_time";
      const auto e = reporter.times.find("exact/" + suffix);
      const auto c = reporter.times.find("clipper/" + suffix);
      if (e == reporter.times.end() || c == reporter.times.end()) continue;
      std::printf("%-10s  %11d  %10.2f  %12.2f  %13.1f\n", kind, size, e->second, c->second, e->second / c->second);
    }
  return 0;
}
