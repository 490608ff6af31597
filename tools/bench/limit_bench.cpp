// subdiv-limit-bench: limit evaluation at random (face, u, v), SubdivKit's exact evaluation
// (framework/limit) against OpenSubdiv's Bfr with its default approximation levels (Catmull-
// Clark and Loop), one
// thread, warm (every face evaluated once first), same run. A program, not a test; the
// numbers are in docs/limit.md.
//
//   subdiv-limit-bench [points]        (run it under `taskset -c 0` for one core)
//   subdiv-limit-bench issue [points]  issue 29's scenario: 1M random points (by default) on
//                                      the 1M-face torus and on a 960k-quad mesh with 480k
//                                      extraordinary vertices, in alternating rounds
//   subdiv-limit-bench issue [points] [n]  the same on the n x n torus (and the split
//                                      (0.4 n)^2 one); the preparation (the constructor and
//                                      the first point of every face) in alternating rounds too,
//                                      CPU time per face (flat in n: local_patch.h)
//   subdiv-limit-bench issue points n torus|split  one of the two meshes (for profiling)
//   subdiv-limit-bench loop [points] [order]  Loop's regular triangles only (for profiling)
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <memory>
#include <random>
#include <vector>

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme_registry.h"

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }
// The process's CPU time (all threads): on a shared machine the wall time grows with the
// load, the CPU time much less.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct Mesh {
  const char* name = "";
  bool loop = false;  // Loop on triangles, else Catmull-Clark
  int vertices = 0;
  std::vector<int> sizes, corners;
  std::vector<double> xyz;
};

Mesh torus(int nu, int nv, bool triangles = false) {
  Mesh m;
  m.name = triangles ? "Loop, triangulated torus (regular)" : "Catmull-Clark, torus (regular)";
  m.loop = triangles;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double a = 2 * M_PI * i / nu, b = 2 * M_PI * j / nv;
      m.xyz.insert(m.xyz.end(), {(3 + std::cos(b)) * std::cos(a), (3 + std::cos(b)) * std::sin(a), std::sin(b)});
    }
  m.vertices = nu * nv;
  auto id = [&](int i, int j) { return (j % nv) * nu + (i % nu); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      if (triangles) {
        m.sizes.insert(m.sizes.end(), {3, 3});
        m.corners.insert(m.corners.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        m.sizes.push_back(4);
        m.corners.insert(m.corners.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  return m;
}

Mesh cube() {
  Mesh m;
  m.name = "Catmull-Clark, cube (8 valence-3 vertices)";
  for (int i = 0; i < 8; ++i) m.xyz.insert(m.xyz.end(), {double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  m.vertices = 8;
  m.sizes.assign(6, 4);
  m.corners = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
  return m;
}

// A triangulated nu x nv torus with every triangle split into three quads at its centroid
// (and edge midpoints): the centroids have valence 3, the torus's vertices valence 6 — an
// extraordinary vertex in every quad.
Mesh split_triangulated_torus(int nu, int nv) {
  const Mesh t = torus(nu, nv, true);
  Mesh m;
  m.name = "Catmull-Clark, triangulated torus split into quads (valences 3 and 6)";
  m.xyz = t.xyz;
  m.vertices = t.vertices;
  std::vector<std::array<int, 3>> mid_key;
  std::vector<int> mid_id;
  auto point = [&](double x, double y, double z) {
    m.xyz.insert(m.xyz.end(), {x, y, z});
    return m.vertices++;
  };
  // Edge midpoints, found through a sorted (a, b) -> id table built first.
  std::vector<std::pair<std::pair<int, int>, int>> edges;
  for (size_t f = 0; f < t.sizes.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = t.corners[3 * f + size_t(k)], b = t.corners[3 * f + size_t((k + 1) % 3)];
      edges.push_back({{std::min(a, b), std::max(a, b)}, -1});
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end(), [](const auto& x, const auto& y) { return x.first == y.first; }),
              edges.end());
  for (auto& e : edges) {
    const int a = e.first.first, b = e.first.second;
    e.second = point((t.xyz[3 * size_t(a)] + t.xyz[3 * size_t(b)]) / 2, (t.xyz[3 * size_t(a) + 1] + t.xyz[3 * size_t(b) + 1]) / 2,
                     (t.xyz[3 * size_t(a) + 2] + t.xyz[3 * size_t(b) + 2]) / 2);
  }
  auto mid = [&](int a, int b) {
    const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
    return std::lower_bound(edges.begin(), edges.end(), std::pair{key, -1})->second;
  };
  for (size_t f = 0; f < t.sizes.size(); ++f) {
    const int* c = &t.corners[3 * f];
    double x[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) x[d] += t.xyz[3 * size_t(c[k]) + size_t(d)] / 3;
    const int centre = point(x[0], x[1], x[2]);
    for (int k = 0; k < 3; ++k) {
      m.sizes.push_back(4);
      m.corners.insert(m.corners.end(), {c[k], mid(c[k], c[(k + 1) % 3]), centre, mid(c[(k + 2) % 3], c[k])});
    }
  }
  return m;
}

double load_average() {
  double l[1] = {0};
  return getloadavg(l, 1) == 1 ? l[0] : -1;
}

// Issue 29's scenario: preparation (every face's first point) and `points` random points,
// position and first derivatives, ours and Bfr in alternating rounds of the same points'
// quarters, so that a change of load hits both; the largest difference between the two.
// OpenSubdiv's refiner of `m` (Catmull-Clark, or Loop for triangle meshes), boundaries as
// SubdivKit's default (edges and corners). The caller owns it.
OpenSubdiv::Far::TopologyRefiner* osd_refiner(const Mesh& m) {
  using namespace OpenSubdiv;
  Far::TopologyDescriptor desc;
  desc.numVertices = m.vertices;
  desc.numFaces = int(m.sizes.size());
  desc.numVertsPerFace = m.sizes.data();
  desc.vertIndicesPerFace = m.corners.data();
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  return Factory::Create(desc, Factory::Options(m.loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, sdc));
}

// Bfr's side of a preparation: the refiner and its factory, kept together.
struct BfrPrepared {
  std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> refiner;
  std::unique_ptr<OpenSubdiv::Bfr::RefinerSurfaceFactory<>> factory;
};

// One side's preparation, the first point of every face included, in CPU and wall seconds.
struct PreparationTime {
  double cpu = 0, wall = 0;
};

template <class Prepare>
PreparationTime timed(Prepare&& prepare) {
  const auto t0 = Clock::now();
  const double c0 = cpu_seconds();
  prepare();
  return {cpu_seconds() - c0, seconds(t0, Clock::now())};
}

double median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  return x[x.size() / 2];
}

void run_alternating(const Mesh& m, int points, int rounds) {
  using namespace OpenSubdiv;
  const int faces = int(m.sizes.size());
  std::vector<subdiv::Index> offsets{0};
  for (int s : m.sizes) offsets.push_back(offsets.back() + s);
  const std::vector<subdiv::Index> corners(m.corners.begin(), m.corners.end());
  const double load_before = load_average();
  Bfr::Surface<double> surface;
  Bfr::Surface<double>::PointDescriptor d(3);
  std::vector<double> patch;
  double p[3], du[3], dv[3], sum = 0;
  std::unique_ptr<subdiv::LimitSurface> ours_ptr;
  BfrPrepared theirs;
  auto bfr_point = [&](int f, double u, double v, double* xyz, double* dxyz_u, double* dxyz_v) {
    theirs.factory->InitVertexSurface(f, &surface);
    patch.resize(3 * size_t(surface.GetNumPatchPoints()));
    surface.PreparePatchPoints(m.xyz.data(), d, patch.data(), d);
    const double uv[2] = {u, v};
    surface.Evaluate(uv, patch.data(), d, xyz, dxyz_u, dxyz_v);
  };
  auto prepare_ours = [&] {
    ours_ptr.reset();
    ours_ptr = std::make_unique<subdiv::LimitSurface>(subdiv::load_scheme("catmull-clark"),
                                                      subdiv::build_level(m.vertices, offsets, corners));
    // Into one kept sample, as Bfr's side keeps its surface and patch points from face to face.
    subdiv::LimitSample s;
    for (int f = 0; f < faces; ++f) ours_ptr->evaluate_into(f, 0.3, 0.2, m.xyz, 3, 1, s), sum += s.position[0];
  };
  auto prepare_bfr = [&] {
    theirs.factory.reset();  // before the refiner it reads
    theirs.refiner.reset();
    theirs.refiner.reset(osd_refiner(m));
    theirs.factory = std::make_unique<Bfr::RefinerSurfaceFactory<>>(*theirs.refiner);
    for (int f = 0; f < faces; ++f) bfr_point(f, 0.3, 0.2, p, du, dv), sum += p[0];
  };
  // The preparations alternate too, the order swapped every round, so that neither side
  // always meets the fresh heap (page faults) and neither always reuses the other's memory.
  std::vector<double> ours_cpu, bfr_cpu, ours_wall, bfr_wall;
  const int preparation_rounds = 2 * rounds;
  for (int r = 0; r < preparation_rounds; ++r) {
    PreparationTime a, b;
    if (r % 2 == 0) {
      a = timed(prepare_ours), b = timed(prepare_bfr);
    } else {
      b = timed(prepare_bfr), a = timed(prepare_ours);
    }
    ours_cpu.push_back(a.cpu), ours_wall.push_back(a.wall), bfr_cpu.push_back(b.cpu), bfr_wall.push_back(b.wall);
    std::printf("%s, %d faces: preparation round %d (%s first): ours CPU %.3g s (wall %.3g s), Bfr CPU %.3g s (wall "
                "%.3g s); ours / Bfr CPU %.2f\n",
                m.name, faces, r + 1, r % 2 == 0 ? "ours" : "Bfr's", a.cpu, a.wall, b.cpu, b.wall, a.cpu / b.cpu);
    std::fflush(stdout);
  }
  const double ours_prep = median(ours_cpu), bfr_prep = median(bfr_cpu);
  const double ours_best = *std::min_element(ours_cpu.begin(), ours_cpu.end());
  const double bfr_best = *std::min_element(bfr_cpu.begin(), bfr_cpu.end());
  std::printf("%s, %d faces: preparation in %d alternating rounds, CPU per face: median ours %.3g us (wall %.3g s), "
              "Bfr %.3g us (wall %.3g s), ratio %.2f; best ours %.3g us, Bfr %.3g us, ratio %.2f\n",
              m.name, faces, preparation_rounds, ours_prep / faces * 1e6, median(ours_wall), bfr_prep / faces * 1e6,
              median(bfr_wall), ours_prep / bfr_prep, ours_best / faces * 1e6, bfr_best / faces * 1e6,
              ours_best / bfr_best);
  std::fflush(stdout);
  const subdiv::LimitSurface& ours = *ours_ptr;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<std::array<double, 3>> at;
  for (int i = 0; i < points; ++i) {
    const double u = unit(rng), v = unit(rng);
    at.push_back({double(rng() % unsigned(faces)), u, v});
  }
  std::vector<double> ours_xyz(3 * size_t(points)), bfr_xyz(3 * size_t(points));
  double ours_s = 0, bfr_s = 0;
  subdiv::LimitSample s;  // reused point after point, as a caller evaluating many points does
  for (int r = 0; r < rounds; ++r) {
    const size_t first = size_t(points) * size_t(r) / size_t(rounds), last = size_t(points) * size_t(r + 1) / size_t(rounds);
    const auto a = Clock::now();
    for (size_t i = first; i < last; ++i) {
      ours.evaluate_into(subdiv::Index(at[i][0]), at[i][1], at[i][2], m.xyz, 3, 1, s);
      std::copy(s.position.begin(), s.position.end(), &ours_xyz[3 * i]);
      sum += s.du[0];
    }
    const auto b = Clock::now();
    for (size_t i = first; i < last; ++i) {
      bfr_point(int(at[i][0]), at[i][1], at[i][2], &bfr_xyz[3 * i], du, dv);
      sum += du[0];
    }
    const auto c = Clock::now();
    ours_s += seconds(a, b);
    bfr_s += seconds(b, c);
  }
  double largest = 0;
  for (size_t i = 0; i < bfr_xyz.size(); ++i) largest = std::max(largest, std::abs(ours_xyz[i] - bfr_xyz[i]));
  std::printf("%s, %d faces: %d random points in %d alternating rounds, position + first derivatives: ours %.2f "
              "us/point, Bfr %.2f us/point, ratio %.2f; largest |ours - Bfr| %.3g; load average %.2f before, %.2f "
              "after (checksum %g)\n",
              m.name, faces, points, rounds, ours_s / points * 1e6,
              bfr_s / points * 1e6, ours_s / bfr_s, largest, load_before, load_average(), sum);
}

void run(const Mesh& m, int points, int order) {
  using namespace OpenSubdiv;
  const int faces = int(m.sizes.size());
  std::vector<subdiv::Index> offsets{0};
  for (int s : m.sizes) offsets.push_back(offsets.back() + s);
  const std::vector<subdiv::Index> corners(m.corners.begin(), m.corners.end());

  const auto t0 = Clock::now();
  const subdiv::LimitSurface ours(subdiv::load_scheme(m.loop ? "loop" : "catmull-clark"), subdiv::build_level(m.vertices, offsets, corners));
  for (int f = 0; f < faces; ++f) ours.evaluate(f, 0.3, 0.2, m.xyz, 3);
  const auto t1 = Clock::now();
  OpenSubdiv::Far::TopologyRefiner* refiner = osd_refiner(m);
  Bfr::RefinerSurfaceFactory<> factory(*refiner);
  Bfr::Surface<double> surface;
  Bfr::Surface<double>::PointDescriptor d(3);
  std::vector<double> patch;
  double duu[3], duv[3], dvv[3];
  auto bfr = [&](int f, double u, double v, double* p, double* du, double* dv) {
    factory.InitVertexSurface(f, &surface);
    patch.resize(3 * size_t(surface.GetNumPatchPoints()));
    surface.PreparePatchPoints(m.xyz.data(), d, patch.data(), d);
    const double uv[2] = {u, v};
    if (order == 2)
      surface.Evaluate(uv, patch.data(), d, p, du, dv, duu, duv, dvv);
    else
      surface.Evaluate(uv, patch.data(), d, p, du, dv);
  };
  double p[3], du[3], dv[3], sum = 0;
  for (int f = 0; f < faces; ++f) bfr(f, 0.3, 0.2, p, du, dv);
  const auto t2 = Clock::now();

  std::mt19937 rng(1);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<std::array<double, 3>> at;
  for (int i = 0; i < points; ++i) {
    double u = unit(rng), v = unit(rng);
    if (m.loop && u + v > 1) u = 1 - u, v = 1 - v;
    at.push_back({double(rng() % unsigned(faces)), u, v});
  }
  subdiv::LimitSample s;  // reused point after point, as a caller evaluating many points does
  const auto t3 = Clock::now();
  for (const auto& q : at) {
    ours.evaluate_into(subdiv::Index(q[0]), q[1], q[2], m.xyz, 3, order, s);
    sum += s.position[0] + s.du[0] + (s.has_second_derivatives ? s.duu[0] : 0.0);
  }
  const auto t4 = Clock::now();
  for (const auto& q : at) {
    bfr(int(q[0]), q[1], q[2], p, du, dv);
    sum += p[0] + du[0] + (order == 2 ? duu[0] : 0.0);
  }
  const auto t5 = Clock::now();
  delete refiner;
  std::printf("%s, %d faces: first point per face (preparation) ours %.3g ms, Bfr %.3g ms; %d random points, "
              "position + %s derivatives: ours %.2f us/point, Bfr %.2f us/point, ratio %.2f (checksum %g)\n",
              m.name, faces, seconds(t0, t1) * 1e3, seconds(t1, t2) * 1e3, points,
              order == 2 ? "first and second" : "first", seconds(t3, t4) / points * 1e6,
              seconds(t4, t5) / points * 1e6, seconds(t3, t4) / seconds(t4, t5), sum);
}

}  // namespace

int main(int argc, char** argv) {
  // subdiv-limit-bench [points] [order]: order 1 (default) position and first derivatives,
  // 2 also the second derivatives.
  if (argc > 1 && std::strcmp(argv[1], "issue") == 0) {
    // subdiv-limit-bench issue [points] [n]: the n x n torus (1000: 1M faces) and the split
    // triangulated (0.4 n) x (0.4 n) torus (0.96 n^2 quads).
    const int points = argc > 2 ? std::atoi(argv[2]) : 1000000;
    const int n = argc > 3 ? std::atoi(argv[3]) : 1000;
    const char* only = argc > 4 ? argv[4] : "";
    if (std::strcmp(only, "split") != 0) run_alternating(torus(n, n), points, 4);
    if (std::strcmp(only, "torus") != 0) run_alternating(split_triangulated_torus(2 * n / 5, 2 * n / 5), points, 4);
    return 0;
  }
  if (argc > 1 && std::strcmp(argv[1], "loop") == 0) {
    // subdiv-limit-bench loop [points] [order]: Loop's regular triangles only (for profiling).
    run(torus(32, 24, true), argc > 2 ? std::atoi(argv[2]) : 20000, argc > 3 && std::atoi(argv[3]) == 2 ? 2 : 1);
    return 0;
  }
  const int points = argc > 1 ? std::atoi(argv[1]) : 20000;
  const int order = argc > 2 && std::atoi(argv[2]) == 2 ? 2 : 1;
  run(torus(32, 24), points, order);
  run(torus(32, 24, true), points, order);
  run(cube(), points, order);
}
