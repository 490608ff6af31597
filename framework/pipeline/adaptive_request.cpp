#include "framework/pipeline/adaptive_request.h"

#include <cmath>
#include <fmt/format.h>
#include <new>
#include <optional>
#include <string_view>

#include "framework/features/base_tags.h"
#include "framework/io/mesh_read.h"
#include "framework/limit/limit_surface.h"
#include "framework/pipeline/phase_progress.h"
#include "framework/pipeline/rational_weights.h"
#include "framework/pipeline/refine_pipeline.h"
#include "framework/primvar/face_varying.h"
#include "framework/util/memory_limit.h"
#include "framework/util/option_spelling.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

void check_request(const AdaptiveRequest& r) {
  if (r.refine.levels < 0 || r.refine.levels > kMaxAdaptiveLevel)
    throw OptionError(fmt::format("{{levels}} {}: adaptive refinement goes to level 0 to {}", r.refine.levels,
                                  kMaxAdaptiveLevel));
  if (!(r.tolerance >= 0) || !std::isfinite(r.tolerance))
    throw OptionError(fmt::format("{{tolerance}} {}: give a distance >= 0 (0: split only around features)",
                                  r.tolerance));
  // Refused rather than ignored: the adaptive stages take the scheme's parameters for the
  // whole mesh, and write no limit normals.
  if (!r.refine.vertex_parameters.empty() || !r.refine.vertex_parameter_files.empty())
    throw OptionError("{vertex_param}: adaptive refinement takes a scheme parameter for the whole mesh only (not "
                      "per vertex); give one value with {param}, or refine uniformly");
  if (r.refine.limit_normals)
    throw OptionError("{normals}: adaptive refinement writes no limit normals; leave out {normals} (with {limit} "
                      "every vertex is on the limit surface), or refine uniformly");
}

std::span<const double> weights_of(const MeshData& mesh, const std::string& name) {
  for (const DataArray& a : mesh.point_data)
    if (a.name == name) return a.values;
  throw Error(fmt::format("the weights array {} is missing", subdiv::quoted(name)));
}

// xyz /= w per vertex of the adaptive mesh, w its data channel `channel`.
void project_adaptive(AdaptiveMesh& mesh, int channel) {
  const size_t V = mesh.positions.size() / 3, D = size_t(mesh.data_channels);
  std::vector<double> w(V);
  for (size_t v = 0; v < V; ++v) w[v] = mesh.data[v * D + size_t(channel)];
  from_homogeneous(mesh.positions, w);
}

// The same mesh, scheme and shape options, as a request to evaluate.
EvaluateRequest evaluation_of(const RefineRequest& r) {
  EvaluateRequest e;
  e.mesh = r.mesh;
  e.mesh_name = r.mesh_name;
  e.scheme = r.scheme;
  e.shape = r.shape;
  e.feature_file = r.feature_file;
  e.feature_angle = r.feature_angle;
  return e;
}

// Each face-varying channel at every corner of the adaptive mesh: its limit at the corner's
// (base face, u, v), one value per corner (seams stay seams). In the mode All the channel is
// bilinear in each face (sub-face), at every level as at the limit, so this is also the
// value the corner's level gives it.
std::vector<FaceVaryingArray> limit_face_varying(const PreparedEvaluation& prepared, const AdaptiveMesh& mesh) {
  std::vector<Index> faces(mesh.corner_uv.size());
  std::vector<double> uv(2 * mesh.corner_uv.size());
  for (size_t f = 0; f + 1 < mesh.face_offsets.size(); ++f)
    for (Index c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c) {
      faces[size_t(c)] = mesh.base_face[f];
      uv[2 * size_t(c)] = mesh.corner_uv[size_t(c)][0];
      uv[2 * size_t(c) + 1] = mesh.corner_uv[size_t(c)][1];
    }
  std::vector<FaceVaryingArray> out;
  for (size_t channel = 0; channel < prepared.face_varying.size(); ++channel) {
    const FaceVaryingSurface& s = prepared.face_varying[channel];
    FaceVaryingArray a{s.name, s.components, evaluate_face_varying(prepared, channel, faces, uv, 0).position, {}, s.role};
    a.indices.resize(faces.size());
    for (size_t c = 0; c < faces.size(); ++c) a.indices[c] = Index(c);
    out.push_back(std::move(a));
  }
  return out;
}

// The channels refined with the faces (without limit positions): each channel's value mesh
// as uniform face-varying refinement starts from it (primvar/face_varying.h). Normals are left
// out with a note, as refinement leaves them.
struct ValueMeshes {
  ValueMeshes() = default;
  ValueMeshes(ValueMeshes&&) = default;  // `channels` point into `meshes`: moved, never copied
  ValueMeshes& operator=(ValueMeshes&&) = default;
  std::vector<const FaceVaryingArray*> arrays;
  std::vector<FaceVaryingValueMesh> meshes;
  std::vector<AdaptiveValueMesh> channels;
};

ValueMeshes value_meshes(const PreparedRefinement& p, std::vector<std::string>& notes) {
  ValueMeshes out;
  // The base with the tags refinement gives it first (features/base_tags.h), as uniform
  // face-varying refinement reads them: boundary corners stay corners of the values too.
  Level tagged = p.base;
  tag_base_level(tagged, p.options.features.boundary);
  for (const FaceVaryingArray& a : p.mesh.face_varying) {
    if (a.role == ArrayRole::Normals) {
      notes.push_back(fmt::format("face-varying array {} holds normals, which refinement does not carry (a mix of "
                                  "unit normals is no normal)",
                                  subdiv::quoted(a.name)));
      continue;
    }
    out.arrays.push_back(&a);
    out.meshes.push_back(face_varying_value_mesh(tagged, {a.values, a.indices}, a.components, p.face_varying,
                                                 p.options.features.boundary));
  }
  for (size_t k = 0; k < out.meshes.size(); ++k)
    out.channels.push_back({&out.meshes[k].level, out.meshes[k].values.values, out.arrays[k]->components,
                            p.face_varying == FaceVaryingLinear::Boundaries, p.face_varying == FaceVaryingLinear::All});
  return out;
}

std::vector<FaceVaryingArray> refined_face_varying(const ValueMeshes& in, AdaptiveMesh& mesh) {
  std::vector<FaceVaryingArray> out;
  for (size_t k = 0; k < in.arrays.size(); ++k) {
    AdaptiveFaceVarying& a = mesh.face_varying[k];
    out.push_back({in.arrays[k]->name, a.components, std::move(a.values), std::move(a.indices), in.arrays[k]->role});
  }
  return out;
}

}  // namespace

AdaptiveResult refine_adaptive_request(AdaptiveRequest request) {
  check_request(request);
  RefineRequest& r = request.refine;
  if (!r.mesh_file.empty()) {
    r.mesh = read_mesh(r.mesh_file);
    if (r.mesh_name.empty()) r.mesh_name = r.mesh_file;
    r.mesh_file.clear();
  }
  if (r.mesh_name.empty()) r.mesh_name = "mesh";
  const int levels = r.levels;
  r.levels_given = false;  // a sequence is refused below in its own words
  // With limit positions, face-varying channels are evaluated on their limit at the corners'
  // (face, u, v), from an evaluation of the same mesh and options; without, they are refined
  // with the faces (value_meshes).
  std::optional<EvaluateRequest> face_varying_source;
  if (request.limit && !r.mesh.face_varying.empty()) face_varying_source = evaluation_of(r);
  PreparedRefinement p = prepare_refinement(r);
  if (p.sequence.schemes.size() != 1)
    throw Error(fmt::format("{}: {} is a sequence of schemes; adaptive refinement takes one scheme", r.mesh_name,
                            subdiv::quoted(p.scheme_label)));
  if (p.rational && request.tolerance > 0)
    throw OptionError(fmt::format("{{tolerance}} {}: the tolerance is measured between bilinear patches and the "
                                  "limit in R^3, and a rational mesh (weights in {}) is refined in homogeneous "
                                  "coordinates, where that distance is not the one in R^3; refine it adaptively "
                                  "without a tolerance, or uniformly",
                                  request.tolerance, subdiv::quoted(p.weights_name)));
  AdaptiveOptions o;
  o.levels = levels;
  o.features = p.options.features;
  o.first_step = p.options.first_step;
  o.limit = request.limit;
  o.tolerance = request.tolerance;
  o.uniform = request.uniform;
  o.transitions = request.transitions;
  AdaptiveResult out;
  try {
    // With face-varying channels on the limit, the evaluation of the same mesh brings the
    // surface along.
    std::optional<PreparedEvaluation> evaluation;
    if (face_varying_source) evaluation = prepare_evaluation(std::move(*face_varying_source));
    ValueMeshes values;
    if (!request.limit) values = value_meshes(p, p.notes);
    o.face_varying = values.channels;
    std::shared_ptr<const LimitSurface> surface;
    if (evaluation) {
      surface = evaluation->surface;
    } else if (o.limit || o.tolerance > 0) {
      LimitSurfaceOptions lo;
      lo.features = p.options.features;
      surface = std::make_shared<const LimitSurface>(p.sequence.schemes.front(), p.base, lo);
    }
    o.surface = surface.get();
    // Point arrays ride along with the positions (interpolated like them).
    std::vector<const DataArray*> carried;
    int channels = 0;
    for (const DataArray& a : p.mesh.point_data) {
      if (a.role == ArrayRole::Normals) {  // as refinement: a mix of unit normals is no normal
        p.notes.push_back(fmt::format("point array {} holds normals, which refinement does not carry (a mix of unit "
                                      "normals is no normal)",
                                      subdiv::quoted(a.name)));
        continue;
      }
      if (a.integer) {
        p.notes.push_back(fmt::format("point array {} holds whole numbers and is not carried to the adaptive mesh",
                                      subdiv::quoted(a.name)));
        continue;
      }
      carried.push_back(&a);
      channels += a.components;
      out.point_arrays.push_back({a.name, a.components, {}, false, a.role});
    }
    const Index V = p.base.vertex_count;
    std::vector<double> data(size_t(V) * size_t(channels));
    int at = 0, weight_channel = -1;
    for (const DataArray* a : carried) {
      if (p.rational && a->name == p.weights_name) weight_channel = at;
      for (Index v = 0; v < V; ++v)
        for (int c = 0; c < a->components; ++c)
          data[size_t(v) * size_t(channels) + size_t(at + c)] = a->values[size_t(v) * size_t(a->components) + size_t(c)];
      at += a->components;
    }
    // Rational meshes (rational_weights.h): the homogeneous points (w·p, w) are refined — and
    // with `limit` evaluated on the limit — like any point data, then projected.
    std::vector<double> positions = p.mesh.positions;
    if (p.rational) to_homogeneous(positions, weights_of(p.mesh, p.weights_name));
    {
      const PhaseProgress bar(r.progress, r.progress_fraction, fmt::format("refining adaptively to level {}", levels));
      out.mesh = refine_adaptive(*p.sequence.schemes.front(), p.base, positions, o, data, channels);
    }
    if (p.rational) project_adaptive(out.mesh, weight_channel);
    if (evaluation) out.face_varying = limit_face_varying(*evaluation, out.mesh);
    else out.face_varying = refined_face_varying(values, out.mesh);
  } catch (const OptionError&) {
    throw;
  } catch (const Error& e) {
    // The evaluation behind face-varying limits (prepare_evaluation) names the mesh itself.
    if (std::string_view(e.what()).starts_with(r.mesh_name + ": ")) throw;
    throw Error(fmt::format("{}: {}", r.mesh_name, e.what()));
  } catch (const std::bad_alloc&) {
    throw OutOfMemoryError(out_of_memory_message(fmt::format("refining {} adaptively to level {}", r.mesh_name, levels),
                                                 "ask for fewer {levels} or a larger {tolerance}"));
  }
  out.scheme_label = std::move(p.scheme_label);
  out.levels = levels;
  out.warnings = std::move(p.warnings);
  out.notes = std::move(p.notes);
  return out;
}

AdaptiveTransitions transitions_from_name(const std::string& name) {
  if (name == "polygons") return AdaptiveTransitions::Polygons;
  if (name == "triangles") return AdaptiveTransitions::Triangles;
  throw OptionError(fmt::format("{{transitions}} {}: give polygons (a coarse face next to finer ones as one polygon "
                                "with their vertices along its edges) or triangles (that polygon as triangles and "
                                "quads)",
                                subdiv::quoted(name)));
}

AdaptiveRequest adaptive_request_from(EvaluateRequest e, int levels, double tolerance, bool limit) {
  AdaptiveRequest a;
  a.refine.mesh_file = std::move(e.mesh_file);
  a.refine.mesh = std::move(e.mesh);
  a.refine.mesh_name = std::move(e.mesh_name);
  a.refine.scheme = std::move(e.scheme);
  a.refine.shape = e.shape;
  a.refine.feature_file = std::move(e.feature_file);
  a.refine.feature_angle = e.feature_angle;
  a.refine.levels = levels;
  a.refine.progress = std::move(e.progress);
  a.refine.progress_fraction = std::move(e.progress_fraction);
  a.tolerance = tolerance;
  a.limit = limit;
  return a;
}

MeshData adaptive_mesh_data(AdaptiveMesh&& a, std::vector<DataArray> point_arrays,
                            std::vector<FaceVaryingArray> face_varying) {
  MeshData m;
  m.face_varying = std::move(face_varying);
  const size_t V = a.positions.size() / 3, D = size_t(a.data_channels);
  size_t at = 0;
  for (DataArray& array : point_arrays) {
    const size_t C = size_t(array.components);
    array.values.resize(V * C);
    for (size_t v = 0; v < V; ++v)
      for (size_t c = 0; c < C; ++c) array.values[v * C + c] = a.data[v * D + at + c];
    at += C;
    m.point_data.push_back(std::move(array));
  }
  m.positions = std::move(a.positions);
  m.face_offsets.assign(a.face_offsets.begin(), a.face_offsets.end());
  m.face_vertices.assign(a.face_vertices.begin(), a.face_vertices.end());
  DataArray level{"face_level", 1, {}, true}, face{"base_face", 1, {}, true};
  for (int l : a.face_level) level.values.push_back(double(l));
  for (Index f : a.base_face) face.values.push_back(double(f));
  m.cell_data = {std::move(level), std::move(face)};
  return m;
}

std::string adaptive_summary(const AdaptiveResult& r) {
  const AdaptiveMesh& m = r.mesh;
  std::string split;
  for (Index n : m.split_faces) split += fmt::format(" {}", n);
  return fmt::format("{} faces, {} vertices (uniform level {}: {} faces); faces split per level:{}",
                     m.face_offsets.size() - 1, m.positions.size() / 3, r.levels, m.uniform_faces,
                     split.empty() ? " none" : split);
}

}  // namespace subdiv
