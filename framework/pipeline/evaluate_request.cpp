#include "framework/pipeline/evaluate_request.h"

#include <cmath>
#include <limits>
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "framework/io/mesh_read.h"
#include "framework/pipeline/refine_pipeline.h"
#include "framework/util/option_spelling.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// Unused vertices are dropped in order (io/mesh_cleanup.h): the used ones, ascending, are
// the prepared mesh's vertices.
std::vector<Index> used_vertices(const MeshData& mesh) {
  std::vector<char> used(size_t(mesh.vertex_count()), 0);
  for (Index v : mesh.face_vertices) used[size_t(v)] = 1;
  std::vector<Index> out;
  for (size_t v = 0; v < used.size(); ++v)
    if (used[v]) out.push_back(Index(v));
  return out;
}

void check_points(const PreparedEvaluation& p, std::span<const Index> faces, std::span<const double> uv) {
  if (uv.size() != 2 * faces.size())
    throw Error(fmt::format("{} faces but {} (u, v) values: give one (u, v) pair per face", faces.size(), uv.size()));
  for (size_t i = 0; i < faces.size(); ++i)
    if (const std::string why = p.surface->check(faces[i], uv[2 * i], uv[2 * i + 1]); !why.empty())
      throw Error(fmt::format("point {} (face {}, u {}, v {}): {}", i, faces[i], uv[2 * i], uv[2 * i + 1], why));
}

void check_order(int derivatives) {
  if (derivatives < 0 || derivatives > 2)
    throw OptionError(fmt::format("{{derivatives}} {}: give 0 (positions), 1 (also du, dv) or 2 (also duu, duv, dvv)",
                                  derivatives));
}

}  // namespace

PreparedEvaluation prepare_evaluation(EvaluateRequest request) {
  RefineRequest r;
  if (!request.mesh_file.empty()) {
    r.mesh = read_mesh(request.mesh_file);
    r.mesh_name = request.mesh_name.empty() ? request.mesh_file : request.mesh_name;
  } else {
    r.mesh = std::move(request.mesh);
    r.mesh_name = request.mesh_name.empty() ? "mesh" : request.mesh_name;
  }
  r.scheme = std::move(request.scheme);
  r.shape = request.shape;
  r.feature_file = request.feature_file;
  r.feature_angle = request.feature_angle;
  PreparedEvaluation out;
  out.request_vertex_count = r.mesh.vertex_count();
  out.request_vertex = used_vertices(r.mesh);
  PreparedRefinement p = prepare_refinement(r);
  if (p.sequence.schemes.size() != 1)
    throw Error(fmt::format("{}: '{}' is a sequence of schemes; limit evaluation takes one scheme (its limit is that "
                            "of the scheme that repeats; evaluating a sequence's tail after its head's levels is not "
                            "implemented yet)",
                            r.mesh_name, p.scheme_label));
  LimitSurfaceOptions options;
  options.features = p.options.features;
  try {
    out.surface = std::make_shared<const LimitSurface>(p.sequence.schemes.front(), std::move(p.base), options);
  } catch (const OptionError&) {
    throw;
  } catch (const Error& e) {
    throw Error(fmt::format("{}: {}", r.mesh_name, e.what()));
  }
  out.scheme_label = std::move(p.scheme_label);
  out.mesh = std::move(p.mesh);
  out.warnings = std::move(p.warnings);
  out.notes = std::move(p.notes);
  return out;
}

EvaluatedPoints evaluate_limit_points(const PreparedEvaluation& p, std::span<const Index> faces,
                                      std::span<const double> uv, int derivatives, std::span<const double> values,
                                      int channels) {
  check_order(derivatives);
  check_points(p, faces, uv);
  std::vector<double> own;
  if (values.empty()) {
    channels = 3;
    values = p.mesh.positions;
  } else {
    if (channels < 1 || values.size() != size_t(p.request_vertex_count) * size_t(channels))
      throw Error(fmt::format("{} values for {} vertices of {} column(s); give one row per vertex of the mesh",
                              values.size(), p.request_vertex_count, channels));
    own.resize(p.request_vertex.size() * size_t(channels));
    for (size_t v = 0; v < p.request_vertex.size(); ++v)
      for (int c = 0; c < channels; ++c)
        own[v * size_t(channels) + size_t(c)] = values[size_t(p.request_vertex[v]) * size_t(channels) + size_t(c)];
    values = own;
  }
  EvaluatedPoints out;
  out.count = Index(faces.size());
  out.channels = channels;
  const size_t n = faces.size() * size_t(channels);
  out.position.resize(n);
  if (derivatives >= 1) out.du.resize(n), out.dv.resize(n);
  if (derivatives >= 2) out.duu.resize(n), out.duv.resize(n), out.dvv.resize(n);
  tbb::parallel_for(size_t(0), faces.size(), [&](size_t i) {
    const LimitSample s = p.surface->evaluate(faces[i], uv[2 * i], uv[2 * i + 1], values, channels, derivatives);
    auto put = [&](std::vector<double>& to, const std::vector<double>& from, bool has) {
      for (size_t c = 0; c < size_t(channels); ++c) to[i * size_t(channels) + c] = has ? from[c] : kNan;
    };
    put(out.position, s.position, true);
    if (derivatives >= 1) put(out.du, s.du, s.has_derivatives), put(out.dv, s.dv, s.has_derivatives);
    if (derivatives >= 2) {
      put(out.duu, s.duu, s.has_second_derivatives);
      put(out.duv, s.duv, s.has_second_derivatives);
      put(out.dvv, s.dvv, s.has_second_derivatives);
    }
  });
  return out;
}

LimitStencilMatrices limit_stencil_matrices(const PreparedEvaluation& p, std::span<const Index> faces,
                                            std::span<const double> uv, int derivatives) {
  check_order(derivatives);
  check_points(p, faces, uv);
  std::vector<LimitStencil> stencils(faces.size());
  tbb::parallel_for(size_t(0), faces.size(),
                    [&](size_t i) { stencils[i] = p.surface->stencil(faces[i], uv[2 * i], uv[2 * i + 1], derivatives); });
  LimitStencilMatrices out;
  out.rows = Index(faces.size());
  out.columns = p.request_vertex_count;
  auto append = [&](LimitStencilMatrices::Matrix& m, const LimitStencil& s, const std::vector<double>& w, bool has) {
    if (has)
      for (size_t k = 0; k < s.vertices.size(); ++k) {
        m.columns.push_back(p.request_vertex[size_t(s.vertices[k])]);
        m.weights.push_back(w[k]);
      }
    m.offsets.push_back(Index(m.columns.size()));
  };
  for (const LimitStencil& s : stencils) {
    append(out.position, s, s.position, true);
    out.has_first.push_back(s.has_derivatives);
    out.has_second.push_back(s.has_second_derivatives);
    if (derivatives >= 1) append(out.du, s, s.du, s.has_derivatives), append(out.dv, s, s.dv, s.has_derivatives);
    if (derivatives >= 2) {
      append(out.duu, s, s.duu, s.has_second_derivatives);
      append(out.duv, s, s.duv, s.has_second_derivatives);
      append(out.dvv, s, s.dvv, s.has_second_derivatives);
    }
  }
  return out;
}

}  // namespace subdiv
