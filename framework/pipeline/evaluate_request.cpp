#include "framework/pipeline/evaluate_request.h"

#include <span>
#include <cmath>
#include <limits>
#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>

#include "framework/engine/refiner.h"
#include "framework/io/mesh_read.h"
#include "framework/limit/face_domain.h"
#include "framework/pipeline/refine_pipeline.h"
#include "framework/pipeline/scheme_source.h"
#include "framework/util/option_spelling.h"
#include "framework/util/error.h"
#include "framework/util/memory_limit.h"
#include "framework/util/parallel_for_all.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// Vertices used by no face or polyline are dropped in order (io/mesh_cleanup.h): the used
// ones, ascending, are the prepared mesh's vertices.
std::vector<Index> used_vertices(const MeshData& mesh) {
  std::vector<char> used(size_t(mesh.vertex_count()), 0);
  for (std::span<const Index> list : {std::span<const Index>(mesh.face_vertices), std::span<const Index>(mesh.line_vertices)})
    for (Index v : list)
      if (v >= 0 && v < mesh.vertex_count()) used[size_t(v)] = 1;
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

// The limit surface of the request's scheme, or of a sequence: its last scheme repeats over
// the mesh its head makes (limit/sequence_head.h).
std::shared_ptr<const LimitSurface> limit_surface_of(const SchemeSequence& sequence, Level level,
                                                     const LimitSurfaceOptions& options) {
  if (sequence.schemes.size() == 1)
    return std::make_shared<const LimitSurface>(sequence.schemes.front(), std::move(level), options);
  auto shared = [&](const Scheme* s) {
    for (const auto& p : sequence.schemes)
      if (p.get() == s) return p;
    throw Error("internal: a run of the sequence names no loaded scheme");
  };
  std::vector<LimitHeadRun> head;
  for (size_t i = 0; i + 1 < sequence.runs.size(); ++i)
    head.push_back({shared(sequence.runs[i].scheme), sequence.runs[i].levels});
  return std::make_shared<const LimitSurface>(std::move(head), shared(sequence.runs.back().scheme), std::move(level),
                                              options);
}

// The levels a sequence's own counts fix (its head's, and its last scheme's when it has
// one): the limit needs no more, and a scheme without :N takes none of its own.
int fixed_levels(const SchemeSource& source) {
  if (source.is_json_text || source.text.find(',') == std::string::npos) return 1;
  constexpr int kOpen = 1 << 20;
  const SchemeSequence s = load_surface_sequence(source, kOpen, source.parameters);
  int fixed = 0;
  for (size_t i = 0; i + 1 < s.runs.size(); ++i) fixed += s.runs[i].levels;
  const int last = s.runs.empty() ? 0 : s.runs.back().levels;
  return fixed + (last >= kOpen - fixed ? 0 : last);
}

// The channels' value meshes, each with its own limit surface (the mode All: bilinear).
std::vector<FaceVaryingSurface> face_varying_surfaces(const PreparedRefinement& p, const Level& base,
                                                      const std::string& mesh_name, std::vector<std::string>& notes) {
  std::vector<FaceVaryingSurface> out;
  for (const FaceVaryingArray& a : p.mesh.face_varying) {
    if (a.role == ArrayRole::Normals) {
      notes.push_back(fmt::format("face-varying array {} holds normals, which are not evaluated (a mix of unit "
                                  "normals is no normal)",
                                  subdiv::quoted(a.name)));
      continue;
    }
    FaceVaryingValueMesh m =
        face_varying_value_mesh(base, {a.values, a.indices}, a.components, p.face_varying, p.options.features.boundary);
    FaceVaryingSurface s;
    s.name = a.name;
    s.components = a.components;
    s.role = a.role;
    s.mode = p.face_varying;
    s.values = std::move(m.values.values);
    s.level = std::move(m.level);
    if (s.mode != FaceVaryingLinear::All) {
      LimitSurfaceOptions o;
      o.features = p.options.features;
      o.features.boundary = BoundaryInterpolation::EdgesOnly;  // seams and corners are tagged on the value mesh
      try {
        s.surface = limit_surface_of(p.sequence, s.level, o);
      } catch (const Error& e) {
        throw Error(fmt::format("{}: face-varying array {}: {}", mesh_name, subdiv::quoted(a.name), e.what()));
      }
    }
    out.push_back(std::move(s));
  }
  return out;
}

// The mode All: the channel bilinear over the face (a quad), linear (a triangle), or over
// the point's sub-face (an n-gon of a quad scheme), with derivatives in (u, v).
LimitSample bilinear(const FaceVaryingSurface& s, const FacePoint& p, int derivatives) {
  const auto corners = s.level.face(p.face);
  const size_t n = corners.size(), C = size_t(s.components);
  auto value = [&](size_t k) { return &s.values[size_t(corners[k % n]) * C]; };
  std::vector<std::vector<double>> c(4, std::vector<double>(C, 0.0));
  const bool triangle = p.sub_face < 0 && n == 3;
  if (p.sub_face < 0) {
    for (size_t k = 0; k < n; ++k)
      for (size_t j = 0; j < C; ++j) c[k][j] = value(k)[j];
  } else {
    const size_t i = size_t(p.sub_face);
    for (size_t j = 0; j < C; ++j) {
      double centroid = 0;
      for (size_t k = 0; k < n; ++k) centroid += value(k)[j] / double(n);
      c[0][j] = value(i)[j];
      c[1][j] = 0.5 * (value(i)[j] + value(i + 1)[j]);
      c[2][j] = centroid;
      c[3][j] = 0.5 * (value(i + n - 1)[j] + value(i)[j]);
    }
  }
  const double x = p.st[0], y = p.st[1];
  const auto& J = p.jacobian;
  LimitSample out;
  out.has_derivatives = derivatives >= 1;
  out.has_second_derivatives = derivatives >= 2;
  for (size_t j = 0; j < C; ++j) {
    double P, Ps, Pt, Pst;
    if (triangle) {
      P = (1 - x - y) * c[0][j] + x * c[1][j] + y * c[2][j];
      Ps = c[1][j] - c[0][j], Pt = c[2][j] - c[0][j], Pst = 0;
    } else {
      P = (1 - x) * (1 - y) * c[0][j] + x * (1 - y) * c[1][j] + x * y * c[2][j] + (1 - x) * y * c[3][j];
      Ps = (1 - y) * (c[1][j] - c[0][j]) + y * (c[2][j] - c[3][j]);
      Pt = (1 - x) * (c[3][j] - c[0][j]) + x * (c[2][j] - c[1][j]);
      Pst = c[0][j] - c[1][j] + c[2][j] - c[3][j];
    }
    out.position.push_back(P);
    out.du.push_back(J[0][0] * Ps + J[1][0] * Pt);
    out.dv.push_back(J[0][1] * Ps + J[1][1] * Pt);
    out.duu.push_back(2 * J[0][0] * J[1][0] * Pst);
    out.duv.push_back((J[0][0] * J[1][1] + J[1][0] * J[0][1]) * Pst);
    out.dvv.push_back(2 * J[0][1] * J[1][1] * Pst);
  }
  return out;
}

void check_order(int derivatives) {
  if (derivatives < 0 || derivatives > 2)
    throw OptionError(fmt::format("{{derivatives}} {}: give 0 (positions), 1 (also du, dv) or 2 (also duu, duv, dvv)",
                                  derivatives));
}

// Runs `sample(i, s)` for every point in parallel, into one sample per thread whose memory
// is reused point after point, and lays the samples out, NaN where a derivative does not
// exist.
template <class F>
EvaluatedPoints evaluate_samples_in(size_t count, int channels, int derivatives, F&& sample) {
  EvaluatedPoints out;
  out.count = Index(count);
  out.channels = channels;
  const size_t n = count * size_t(channels);
  out.position.resize(n);
  if (derivatives >= 1) out.du.resize(n), out.dv.resize(n);
  if (derivatives >= 2) out.duu.resize(n), out.duv.resize(n), out.dvv.resize(n);
  tbb::enumerable_thread_specific<LimitSample> samples;
  parallel_for_all(count, [&](size_t i) {
    LimitSample& s = samples.local();
    sample(i, s);
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
  }, LoopProgress::Told);
  return out;
}

// The same, an allocation failure told with the fix for points (advising_when_out_of_memory).
template <class F>
EvaluatedPoints evaluate_samples(size_t count, int channels, int derivatives, F&& sample) {
  return advising_when_out_of_memory(fmt::format("evaluating {} points", count),
                                     "evaluate fewer points at a time, or ask for fewer {derivatives}",
                                     [&] { return evaluate_samples_in(count, channels, derivatives, sample); });
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
  r.levels = fixed_levels(r.scheme);
  r.shape = request.shape;
  r.feature_file = request.feature_file;
  r.feature_angle = request.feature_angle;
  PreparedEvaluation out;
  out.mesh_name = r.mesh_name;
  out.request_vertex_count = r.mesh.vertex_count();
  out.request_vertex = used_vertices(r.mesh);
  PreparedRefinement p = prepare_refinement(r);  // refuses a triangle scheme on quads, naming the mesh
  LimitSurfaceOptions options;
  options.features = p.options.features;
  if (request.progress) request.progress("preparing the limit surface");
  out.surface = naming_the_mesh(out, [&] { return limit_surface_of(p.sequence, std::move(p.base), options); });
  out.face_varying = face_varying_surfaces(p, out.surface->base(), r.mesh_name, p.notes);
  out.scheme = p.sequence.schemes.back();  // a sequence's last scheme: the one that repeats
  for (const auto& scheme : p.sequence.schemes)
    if (!p.sequence.runs.empty() && scheme.get() == p.sequence.runs.back().scheme) out.scheme = scheme;
  out.scheme_label = std::move(p.scheme_label);
  out.sequence_head = p.sequence.runs.size() > 1;
  out.mesh = std::move(p.mesh);
  if (p.rational)
    for (const DataArray& a : out.mesh.point_data)
      if (a.name == p.weights_name) out.weights = a.values;
  out.warnings = std::move(p.warnings);
  out.notes = std::move(p.notes);
  return out;
}

namespace {

// The rational surface from its homogeneous limit (X, W) (Piegl & Tiller 1997, "The NURBS
// Book", eq. 4.8 and its derivative): P = X / W, P_u = (X_u - P W_u) / W, and
// P_uv = (X_uv - P_u W_v - P_v W_u - P W_uv) / W. Into `out`, its memory kept.
void project(const LimitSample& h, LimitSample& out) {
  out.has_derivatives = h.has_derivatives;
  out.has_second_derivatives = h.has_second_derivatives;
  out.steps = h.steps;
  auto sized = [](const std::vector<double>& from, std::vector<double>& to) { to.assign(from.empty() ? 0 : 3, 0.0); };
  sized(h.position, out.position), sized(h.du, out.du), sized(h.dv, out.dv);
  sized(h.duu, out.duu), sized(h.duv, out.duv), sized(h.dvv, out.dvv);
  const double W = h.position[3];
  for (size_t c = 0; c < 3; ++c) {
    const double P = h.position[c] / W;
    out.position[c] = P;
    if (!h.has_derivatives || h.du.empty()) continue;
    const double Pu = (h.du[c] - P * h.du[3]) / W, Pv = (h.dv[c] - P * h.dv[3]) / W;
    out.du[c] = Pu, out.dv[c] = Pv;
    if (!h.has_second_derivatives || h.duu.empty()) continue;
    out.duu[c] = (h.duu[c] - 2 * Pu * h.du[3] - P * h.duu[3]) / W;
    out.dvv[c] = (h.dvv[c] - 2 * Pv * h.dv[3] - P * h.dvv[3]) / W;
    out.duv[c] = (h.duv[c] - Pu * h.dv[3] - Pv * h.du[3] - P * h.duv[3]) / W;
  }
}

// (w·p, w) per vertex of the prepared mesh.
std::vector<double> homogeneous_positions(const PreparedEvaluation& p) {
  std::vector<double> out(p.weights.size() * 4);
  for (size_t v = 0; v < p.weights.size(); ++v) {
    for (int c = 0; c < 3; ++c) out[4 * v + size_t(c)] = p.weights[v] * p.mesh.positions[3 * v + size_t(c)];
    out[4 * v + 3] = p.weights[v];
  }
  return out;
}

}  // namespace

EvaluatedPoints evaluate_limit_points(const PreparedEvaluation& p, std::span<const Index> faces,
                                      std::span<const double> uv, int derivatives, std::span<const double> values,
                                      int channels) {
  check_order(derivatives);
  check_points(p, faces, uv);
  std::vector<double> own;
  if (values.empty() && !p.weights.empty()) {  // the rational surface
    own = homogeneous_positions(p);
    tbb::enumerable_thread_specific<LimitSample> homogeneous;
    return naming_the_mesh(p, [&] {
      return evaluate_samples(faces.size(), 3, derivatives, [&](size_t i, LimitSample& s) {
        LimitSample& h = homogeneous.local();
        p.surface->evaluate_into(faces[i], uv[2 * i], uv[2 * i + 1], own, 4, derivatives, h);
        project(h, s);
      });
    });
  }
  if (values.empty()) {
    channels = 3;
    values = p.mesh.positions;
  } else {
    if (channels < 1 || values.size() != size_t(p.request_vertex_count) * size_t(channels))
      throw Error(fmt::format("{} values for {} vertices of {} column(s); give one row per vertex of the mesh",
                              values.size(), p.request_vertex_count, channels));
    // As the mesh's own positions are checked when read: NaN would come out as a limit point.
    for (size_t i = 0; i < values.size(); ++i)
      if (!std::isfinite(values[i]))
        throw Error(fmt::format("vertex {} has a non-finite value ({}) in column {}; give finite values",
                                i / size_t(channels), values[i], i % size_t(channels)));
    own.resize(p.request_vertex.size() * size_t(channels));
    for (size_t v = 0; v < p.request_vertex.size(); ++v)
      for (int c = 0; c < channels; ++c)
        own[v * size_t(channels) + size_t(c)] = values[size_t(p.request_vertex[v]) * size_t(channels) + size_t(c)];
    values = own;
  }
  return naming_the_mesh(p, [&] {
    return evaluate_samples(faces.size(), channels, derivatives, [&](size_t i, LimitSample& s) {
      p.surface->evaluate_into(faces[i], uv[2 * i], uv[2 * i + 1], values, channels, derivatives, s);
    });
  });
}

SurfaceSample limit_sampler(const PreparedEvaluation& p) {
  const LimitSurface* surface = p.surface.get();
  if (p.weights.empty()) {
    std::span<const double> positions = p.mesh.positions;
    return [surface, positions](Index face, double u, double v, LimitSample& out) {
      surface->evaluate_into(face, u, v, positions, 3, 1, out);
    };
  }
  auto homogeneous = std::make_shared<const std::vector<double>>(homogeneous_positions(p));
  return [surface, homogeneous](Index face, double u, double v, LimitSample& out) {
    thread_local LimitSample h;  // the homogeneous point, its memory reused
    surface->evaluate_into(face, u, v, *homogeneous, 4, 1, h);
    project(h, out);
  };
}

EvaluatedPoints evaluate_face_varying(const PreparedEvaluation& p, size_t channel, std::span<const Index> faces,
                                      std::span<const double> uv, int derivatives) {
  check_order(derivatives);
  check_points(p, faces, uv);
  if (channel >= p.face_varying.size())
    throw Error(fmt::format("face-varying channel {}: the mesh has {}", channel, p.face_varying.size()));
  const FaceVaryingSurface& s = p.face_varying[channel];
  const Level& base = p.surface->base();
  const bool triangles = p.surface->triangles();
  return evaluate_samples(faces.size(), s.components, derivatives, [&](size_t i, LimitSample& out) {
    if (s.surface)
      return s.surface->evaluate_into(faces[i], uv[2 * i], uv[2 * i + 1], s.values, s.components, derivatives, out);
    const char* why = "";
    out = bilinear(s, *base_face_point(base, faces[i], uv[2 * i], uv[2 * i + 1], triangles, &why), derivatives);
  });
}

LimitStencilMatrices limit_stencil_matrices(const PreparedEvaluation& p, std::span<const Index> faces,
                                            std::span<const double> uv, int derivatives) {
  check_order(derivatives);
  if (!p.weights.empty())
    throw Error("limit stencils are fixed linear weights over the control points, and a rational surface's point "
                "X/W is not linear in them: evaluate the points instead (they follow the weights), or drop the "
                "'weight' array to get the stencils of the polynomial surface");
  check_points(p, faces, uv);
  std::vector<LimitStencil> stencils(faces.size());
  parallel_for_all(faces.size(), [&](size_t i) {
    stencils[i] = p.surface->stencil(faces[i], uv[2 * i], uv[2 * i + 1], derivatives);
  }, LoopProgress::Told);
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
