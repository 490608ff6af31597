// The OpenSubdiv side of subdiv-bench: Far's uniform refinement and primvar interpolation.
#include <algorithm>
#include <memory>
#include <stdexcept>

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include "bench_common.h"
#include "bench_memory.h"
#include "framework/util/scratch_vector.h"

namespace subdiv_bench {
namespace {

using namespace OpenSubdiv;

// The vertex type PrimvarRefiner interpolates: xyz in doubles, laid out like our arrays,
// so the base positions are used in place.
struct Xyz {
  double p[3];
  void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0; }
  void AddWithWeight(const Xyz& s, double w) {
    p[0] += w * s.p[0];
    p[1] += w * s.p[1];
    p[2] += w * s.p[2];
  }
};
static_assert(sizeof(Xyz) == 3 * sizeof(double));

// Keys of level `l + 1` from keys of level `l`. OpenSubdiv numbers the child vertices of a
// uniform refinement (UniformOptions::orderVerticesFromFacesFirst = false, the default)
// as children of vertices [0, V), then of faces [V, V + F) -- none for Loop --, then of
// edges, each block in parent index order (Vtr::Refinement::populateParentChildIndices).
std::vector<std::uint64_t> child_keys(const Far::TopologyLevel& parent, int child_vertex_count,
                                      bool face_children, const std::vector<std::uint64_t>& keys) {
  const int V = parent.GetNumVertices(), E = parent.GetNumEdges(), F = parent.GetNumFaces();
  const int FC = face_children ? F : 0;
  if (child_vertex_count != V + FC + E)
    throw std::runtime_error("OpenSubdiv child vertex count is not V + F + E as expected");
  std::vector<std::uint64_t> out(static_cast<size_t>(child_vertex_count));
  for (int v = 0; v < V; ++v) out[v] = key_of_vertex_child(keys[v]);
  for (int f = 0; f < FC; ++f) {
    auto fv = parent.GetFaceVertices(f);
    std::uint64_t sum = 0;
    for (int i = 0; i < fv.size(); ++i) sum += key_face_term(keys[fv[i]]);
    out[V + f] = key_of_face_child(sum, fv.size());
  }
  for (int e = 0; e < E; ++e) {
    auto ev = parent.GetEdgeVertices(e);
    out[V + FC + e] = key_of_edge_child(keys[ev[0]], keys[ev[1]]);
  }
  return out;
}

// The cold repetition's results: memory peak (before anything else is allocated), counts,
// and origin-keyed positions for the parent's check.
void report_results(const Job& job, const Mesh& mesh, const Far::TopologyRefiner& refiner, bool loop,
                    std::span<const Xyz> xyz, std::uint64_t digest, WorkerReport& report) {
  report.peak_rss_bytes = peak_rss_bytes();
  const auto& last = refiner.GetLevel(job.level);
  report.vertices = last.GetNumVertices();
  report.faces = last.GetNumFaces();
  report.digest = digest;
  report.check_modulus = check_modulus_for(report.vertices, job.check_max);
  if (report.check_modulus == 0) return;
  std::vector<std::uint64_t> keys(size_t(mesh.vertex_count));
  for (std::int32_t v = 0; v < mesh.vertex_count; ++v) keys[v] = key_base(v);
  for (int l = 0; l < job.level; ++l)
    keys = child_keys(refiner.GetLevel(l), refiner.GetLevel(l + 1).GetNumVertices(), !loop, keys);
  for (size_t i = 0; i < keys.size(); ++i)
    if (keys[i] % report.check_modulus == 0)
      report.records.push_back({keys[i], {xyz[i].p[0], xyz[i].p[1], xyz[i].p[2]}});
}

using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;

// --mode update: RefineUniform and StencilTableFactory once (the table from the base
// vertices straight to the last level, OpenSubdiv's way to re-evaluate an animated mesh);
// each repetition is one UpdateValues.
WorkerReport run_osd_updates(const Job& job, const Mesh& mesh, const Far::TopologyDescriptor& desc,
                             const Factory::Options& factory_options, bool loop) {
  Timings once;
  Stopwatch clock;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, factory_options));
  if (!refiner) throw std::runtime_error("OpenSubdiv could not build the base level");
  Far::TopologyRefiner::UniformOptions uniform(job.level);
  uniform.fullTopologyInLastLevel = job.osd_full_topology;
  refiner->RefineUniform(uniform);
  once.topo = clock.lap();
  Far::StencilTableFactoryReal<double>::Options options;
  options.generateIntermediateLevels = false;
  options.generateOffsets = true;
  std::unique_ptr<const Far::StencilTableReal<double>> table(
      Far::StencilTableFactoryReal<double>::Create(*refiner, options));
  once.stencil = clock.lap();
  const Xyz* base = reinterpret_cast<const Xyz*>(mesh.xyz.data());
  // Kept between repetitions, as an animation keeps it (and as SubdivKit's side does).
  std::vector<Xyz> values(size_t(table->GetNumStencils()));
  return repeat_cold_and_warm(job, [&](Timings& t, WorkerReport* report) {
    t = once;
    Stopwatch evaluation;
    table->UpdateValues(base, values.data());
    t.apply = evaluation.lap();
    const std::uint64_t digest = digest_of({&values[0].p[0], 3 * values.size()});
    if (report) report_results(job, mesh, *refiner, loop, values, digest, *report);
    return digest;
  });
}

}  // namespace

WorkerReport run_osd(const Job& job, const Mesh& mesh) {
  const bool loop = job.scheme == "loop";
  if (!loop && job.scheme != "catmull-clark") throw std::runtime_error("OpenSubdiv side: unknown scheme " + job.scheme);

  Far::TopologyDescriptor desc;
  desc.numVertices = mesh.vertex_count;
  desc.numFaces = mesh.face_count();
  desc.numVertsPerFace = mesh.face_sizes.data();
  desc.vertIndicesPerFace = mesh.face_vertices.data();

  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  sdc.SetCreasingMethod(Sdc::Options::CREASE_UNIFORM);
  const Factory::Options factory_options(loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, sdc);

  if (job.update) return run_osd_updates(job, mesh, desc, factory_options, loop);
  return repeat_cold_and_warm(job, [&](Timings& t, WorkerReport* report) {
    Stopwatch clock;
    std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, factory_options));
    if (!refiner) throw std::runtime_error("OpenSubdiv could not build the base level");
    t.setup = clock.lap();
    // OpenSubdiv's default leaves out the last level's edges and vertex rings, which
    // Interpolate does not need; --osd-full-topology asks for them.
    Far::TopologyRefiner::UniformOptions uniform(job.level);
    uniform.fullTopologyInLastLevel = job.osd_full_topology;
    refiner->RefineUniform(uniform);
    t.topo = clock.lap();
    // Level by level, keeping only the current and next positions (as the SubdivKit side),
    // in vectors that do not zero-fill what Interpolate writes.
    Far::PrimvarRefinerReal<double> primvar(*refiner);
    subdiv::ScratchVector<Xyz> src, dst;
    const Xyz* base = reinterpret_cast<const Xyz*>(mesh.xyz.data());
    for (int l = 1; l <= job.level; ++l) {
      dst.resize(size_t(refiner->GetLevel(l).GetNumVertices()));
      if (l == 1)
        primvar.Interpolate(1, base, dst);
      else
        primvar.Interpolate(l, src, dst);
      std::swap(src, dst);
      subdiv::ScratchVector<Xyz>().swap(dst);
    }
    t.apply = clock.lap();
    const std::uint64_t digest = digest_of({&src[0].p[0], 3 * src.size()});
    if (report) report_results(job, mesh, *refiner, loop, src, digest, *report);
    return digest;
  });
}

}  // namespace subdiv_bench
