// subdiv-adaptive-bench: feature-adaptive refinement, SubdivKit's (framework/limit/
// adaptive_refine.h: topology and points of the faces it splits, the watertight output
// mesh) against OpenSubdiv's Far::TopologyRefiner::RefineAdaptive + PatchTableFactory::Create
// (the patches a renderer draws) + PrimvarRefiner::Interpolate of the points over the levels,
// Catmull-Clark, on the same meshes, same run, one thread. Rounds alternate between the two;
// the best round of each is reported with the ratio and the load average, by wall time and
// by CPU time (user + system, which a shared machine's waits for a core do not inflate).
// Ours twice: as one call pays (its weight tables compiled), and with the tables kept
// between calls (AdaptiveTables). A program, not a test; the numbers are in docs/limit.md.
//
//   subdiv-adaptive-bench [levels] [rounds] [mesh.obj ...]   (run it under `taskset -c 0`)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include "framework/io/mesh_read.h"
#include "framework/limit/adaptive_refine.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// The process's CPU time (user + system, all threads): on a machine shared with other work
// it counts what this process ran, where the wall time also counts the waits for a core.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct Mesh {
  std::string name;
  int vertices = 0;
  std::vector<int> sizes, corners;
  std::vector<double> xyz;
};

Mesh cube() {
  Mesh m;
  m.name = "cube (8 valence-3 vertices)";
  for (int i = 0; i < 8; ++i) m.xyz.insert(m.xyz.end(), {double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  m.vertices = 8;
  m.sizes.assign(6, 4);
  m.corners = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
  return m;
}

// A torus of nu x nv quads with `merges` pairs of neighbouring quads merged into hexagons
// (each leaves two valence-3 vertices), spread over the torus.
Mesh torus(int nu, int nv, int merges) {
  Mesh m;
  m.name = "torus " + std::to_string(nu) + " x " + std::to_string(nv) + " with " + std::to_string(2 * merges) +
           " valence-3 vertices";
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double a = 2 * M_PI * i / nu, b = 2 * M_PI * j / nv;
      m.xyz.insert(m.xyz.end(), {(3 + std::cos(b)) * std::cos(a), (3 + std::cos(b)) * std::sin(a), std::sin(b)});
    }
  m.vertices = nu * nv;
  auto id = [&](int i, int j) { return (j % nv) * nu + (i % nu); };
  std::vector<char> merged(size_t(nu * nv), 0);
  for (int k = 0; k < merges; ++k) merged[size_t((k * 7919) % (nu * nv) / 4 * 4)] = 1;  // every other pair at most
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      if (i + 1 < nu && merged[size_t(j * nu + i)]) {
        m.sizes.push_back(6);
        m.corners.insert(m.corners.end(),
                         {id(i, j), id(i + 1, j), id(i + 2, j), id(i + 2, j + 1), id(i + 1, j + 1), id(i, j + 1)});
        ++i;
        continue;
      }
      m.sizes.push_back(4);
      m.corners.insert(m.corners.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

Mesh from_file(const std::string& path) {
  const subdiv::MeshData d = subdiv::read_mesh(path);
  Mesh m;
  m.name = path;
  m.vertices = int(d.vertex_count());
  m.xyz = d.positions;
  for (size_t f = 0; f + 1 < d.face_offsets.size(); ++f) m.sizes.push_back(d.face_offsets[f + 1] - d.face_offsets[f]);
  m.corners.assign(d.face_vertices.begin(), d.face_vertices.end());
  return m;
}

struct Round {
  double seconds = 0;  // wall
  double cpu = 0;      // user + system
  long faces = 0;
};

// `tables`: weight tables kept from earlier calls (warm), or null (compiled in the call, as
// one `subdiv refine --adaptive` does).
Round ours(const Mesh& m, const subdiv::Scheme& scheme, int levels, subdiv::AdaptiveTables* tables) {
  const auto t0 = Clock::now();
  const double c0 = cpu_seconds();
  std::vector<subdiv::Index> offsets{0};
  for (int s : m.sizes) offsets.push_back(offsets.back() + s);
  const subdiv::Level base =
      subdiv::build_level(m.vertices, offsets, std::vector<subdiv::Index>(m.corners.begin(), m.corners.end()));
  subdiv::AdaptiveOptions o;
  o.levels = levels;
  o.tables = tables;
  const subdiv::AdaptiveMesh a = subdiv::refine_adaptive(scheme, base, m.xyz, o);
  return {seconds(t0, Clock::now()), cpu_seconds() - c0, long(a.face_offsets.size()) - 1};
}

struct Point {
  double x[3];
  void Clear() { x[0] = x[1] = x[2] = 0; }
  void AddWithWeight(const Point& p, float w) {
    for (int k = 0; k < 3; ++k) x[k] += double(w) * p.x[k];
  }
};

Round opensubdiv(const Mesh& m, int levels) {
  using namespace OpenSubdiv;
  const auto t0 = Clock::now();
  const double c0 = cpu_seconds();
  Far::TopologyDescriptor desc;
  desc.numVertices = m.vertices;
  desc.numFaces = int(m.sizes.size());
  desc.numVertsPerFace = m.sizes.data();
  desc.vertIndicesPerFace = m.corners.data();
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  Far::TopologyRefiner* refiner = Factory::Create(desc, Factory::Options(Sdc::SCHEME_CATMARK, sdc));
  refiner->RefineAdaptive(Far::TopologyRefiner::AdaptiveOptions(levels));
  Far::PatchTable* patches = Far::PatchTableFactory::Create(*refiner);
  std::vector<Point> points(size_t(refiner->GetNumVerticesTotal()));
  for (int v = 0; v < m.vertices; ++v)
    for (int k = 0; k < 3; ++k) points[size_t(v)].x[k] = m.xyz[size_t(3 * v + k)];
  Far::PrimvarRefiner primvar(*refiner);
  Point* src = points.data();
  for (int l = 1; l <= refiner->GetMaxLevel(); ++l) {
    Point* dst = src + refiner->GetLevel(l - 1).GetNumVertices();
    primvar.Interpolate(l, src, dst);
    src = dst;
  }
  const long count = long(patches->GetNumPatchesTotal());
  delete patches;
  delete refiner;
  return {seconds(t0, Clock::now()), cpu_seconds() - c0, count};
}

// The best wall time and the best CPU time over the rounds (each its own minimum).
struct Best {
  double wall = 1e300, cpu = 1e300;
  long faces = 0;
  void take(const Round& r) {
    wall = std::min(wall, r.seconds), cpu = std::min(cpu, r.cpu), faces = r.faces;
  }
};

}  // namespace

int main(int argc, char** argv) {
  const int levels = argc > 1 ? std::atoi(argv[1]) : 6;
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 5;
  std::vector<Mesh> meshes = {cube(), torus(8, 6, 2), torus(256, 192, 40)};
  for (int k = 3; k < argc; ++k) meshes.push_back(from_file(argv[k]));
  const auto scheme = subdiv::load_scheme("catmull-clark");
  double load[3] = {0, 0, 0};
  getloadavg(load, 3);
  std::printf("adaptive Catmull-Clark to level %d, best of %d alternating rounds, load average %.2f %.2f %.2f\n",
              levels, rounds, load[0], load[1], load[2]);
  subdiv::AdaptiveTables tables(*scheme);
  for (const Mesh& m : meshes) {
    Best a, w, b;
    for (int r = 0; r < rounds; ++r) {
      a.take(ours(m, *scheme, levels, nullptr));
      w.take(ours(m, *scheme, levels, &tables));
      b.take(opensubdiv(m, levels));
    }
    std::printf("%s, %zu faces: ours %.3f ms (cpu %.3f), with weight tables kept %.3f ms (cpu %.3f) (%ld faces out); "
                "OpenSubdiv RefineAdaptive + PatchTable + points %.3f ms (cpu %.3f) (%ld patches); ours / OpenSubdiv "
                "%.2f (cpu %.2f), kept %.2f (cpu %.2f)\n",
                m.name.c_str(), m.sizes.size(), a.wall * 1e3, a.cpu * 1e3, w.wall * 1e3, w.cpu * 1e3, a.faces,
                b.wall * 1e3, b.cpu * 1e3, b.faces, a.wall / b.wall, a.cpu / b.cpu, w.wall / b.wall, w.cpu / b.cpu);
  }
  getloadavg(load, 3);
  std::printf("load average after: %.2f %.2f %.2f\n", load[0], load[1], load[2]);
}
