#include "framework/pipeline/approximation_request.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/limit/refined_control_mesh.h"
#include "framework/limit/tessellation.h"
#include "framework/limit/unit_normal.h"
#include "framework/util/error.h"
#include "framework/util/memory_limit.h"
#include "framework/util/option_spelling.h"

namespace subdiv {
namespace {

double distance(std::span<const double> a, std::span<const double> b, size_t i) {
  const double x = a[3 * i] - b[3 * i], y = a[3 * i + 1] - b[3 * i + 1], z = a[3 * i + 2] - b[3 * i + 2];
  return std::hypot(x, y, z);
}

// Distances at the points (face, u, v) whose approximated positions are `approximated`.
ApproximationDistances measure(const PreparedEvaluation& prepared, std::span<const Index> faces,
                               std::span<const double> uv, std::span<const double> approximated) {
  const EvaluatedPoints exact = evaluate_limit_points(prepared, faces, uv, 0);
  ApproximationDistances d;
  d.per_face.assign(prepared.surface->base().face_offsets.size() - 1, 0.0);
  d.samples = Index(faces.size());
  double sum = 0;
  for (size_t i = 0; i < faces.size(); ++i) {
    const double e = distance(approximated, exact.position, i);
    d.per_point.push_back(e);
    double& face = d.per_face[size_t(faces[i])];
    face = std::max(face, e);
    sum += e;
    d.largest = std::max(d.largest, e);
  }
  // The first face within round-off of the largest: faces that are alike by symmetry (the
  // cube's) report the same face whatever their last bits.
  for (size_t f = 0; f < d.per_face.size() && !faces.empty(); ++f)
    if (d.per_face[f] >= d.largest * (1 - 1e-9)) {
      d.largest_face = Index(f);
      break;
    }
  d.mean = faces.empty() ? 0.0 : sum / double(faces.size());
  return d;
}

LimitSample as_sample(const PatchSample& s) {
  LimitSample out;
  out.position.assign(s.position.begin(), s.position.end());
  out.du.assign(s.du.begin(), s.du.end());
  out.dv.assign(s.dv.begin(), s.dv.end());
  out.has_derivatives = true;
  return out;
}

DataArray index_array(const char* name, const std::vector<Index>& indices) {
  DataArray a{name, 1, {}, true};
  a.values.assign(indices.begin(), indices.end());
  return a;
}

// The scheme's limit position and normal at every vertex of the patches' control mesh (its
// limit masks: the refined level's limit is the base mesh's).
VertexLimits vertex_limits(const Scheme& scheme, const RefinedControlMesh& mesh, const FeatureOptions& features) {
  LimitOptions options;
  options.features = features;
  options.first_step = mesh.steps();
  LimitResult limits = limit_positions(scheme, mesh.level(), mesh.positions(), options);
  // A vertex no face uses (a polyline's) is no patch's corner: its limit does not matter.
  for (Index v = 0; v < Index(limits.exact.size()); ++v)
    if (!limits.exact[size_t(v)] && mesh.level().incident_face_count(v) > 0)
      throw Error(fmt::format("vertex {}: its limit position is only approximated ({}), while the patches' corners "
                              "must be the exact limit; mend the mesh there, or evaluate the exact limit instead",
                              v, limits.approximate_reasons.empty() ? "no mask" : limits.approximate_reasons[0]));
  for (Index v = 0; v < Index(limits.normal_exact.size()); ++v)
    if (!limits.normal_exact[size_t(v)])  // estimated normals are not used: the masks' tangents stay
      std::fill_n(limits.normals.begin() + 3 * std::ptrdiff_t(v), 3, 0.0);
  return {std::move(limits.positions), std::move(limits.normals)};
}

bool has_boundary_or_crease(const Level& level) {
  for (Index e = 0; e < level.edge_count(); ++e)
    if (level.edge_on_boundary(e) || level.edge_sharp(e) > 0.f) return true;
  return !level.vertex_sharpness.empty();
}

// What neither approximation covers, refused naming `option`, a placeholder each front-end
// spells ({approximate_bezier}: "--approximate bezier" on the command line,
// "approximate_bezier()" in Python):
// the scheme, a sequence, rational weights, and with boundaries or creases a scheme
// that does not refine them as the masks assume.
void check_approximable(const PreparedEvaluation& prepared, const char* option) {
  const std::string why = bezier_approximation_unsupported(prepared.scheme);
  if (!why.empty())
    throw OptionError(fmt::format("{}: scheme {} cannot be approximated by bicubic patches reproducing its regular "
                            "B-spline patch: {}",
                            option, prepared.scheme_label, why));
  if (prepared.sequence_head)
    throw OptionError(fmt::format("{}: a sequence's limit is its tail's over the mesh its head makes, while the patches' "
                            "masks read the base mesh; refine the head first (subdiv refine) and approximate that "
                            "mesh",
                            option));
  if (!prepared.weights.empty())
    throw OptionError(fmt::format("{}: the mesh has rational weights; the patches are built from the polynomial "
                            "limit's masks (drop the weights)",
                            option));
  if (has_boundary_or_crease(prepared.surface->base()))
    if (const std::string why = bezier_features_unsupported(prepared.scheme, prepared.surface->options().features);
        !why.empty())
      throw OptionError(fmt::format("{}: the mesh has boundaries or creases, and scheme {} does not refine them as the "
                              "patches' masks assume: {}",
                              option, prepared.scheme_label, why));
}

// Points of the approximation sampled by `sample(face, u, v)` at the given parameters.
template <typename Sample>
ApproximatedPoints sample_points(const PreparedEvaluation& prepared, const Sample& sample, std::span<const Index> faces,
                                 std::span<const double> uv) {
  ApproximatedPoints out;
  out.positions.resize(3 * faces.size());
  out.normals.resize(3 * faces.size());
  const double negligible = negligible_tangent(prepared.mesh.positions);
  for (size_t i = 0; i < faces.size(); ++i) {
    const PatchSample s = sample(faces[i], uv[2 * i], uv[2 * i + 1]);
    const std::array<double, 3> n = unit_normal(s.du, s.dv, negligible);
    for (size_t c = 0; c < 3; ++c) {
      out.positions[3 * i + c] = s.position[c];
      out.normals[3 * i + c] = n[c];
    }
  }
  out.distances = measure(prepared, faces, uv, out.positions);
  return out;
}

template <typename Sample>
MeshData sampled_mesh(const PreparedEvaluation& prepared, const Sample& sample, int segments,
                      ApproximationDistances& distances) {
  const auto patch_sample = [&sample](Index face, double u, double v, LimitSample& out) {
    out = as_sample(sample(face, u, v));
  };
  Tessellation t = tessellate(*prepared.surface, segments, patch_sample, negligible_tangent(prepared.mesh.positions));
  distances = measure(prepared, t.uv_face, t.uv, t.positions);
  std::vector<double> cell_distance;
  cell_distance.reserve(t.base_face.size());
  for (Index f : t.base_face) cell_distance.push_back(distances.per_face[size_t(f)]);
  MeshData m;
  if (std::string w = zero_normals_warning(t.normals, t.uv_face, t.uv); !w.empty()) m.warnings.push_back(std::move(w));
  m.point_data = {DataArray{"Normals", 3, std::move(t.normals), false, ArrayRole::Normals},
                  index_array("base_face", t.uv_face), DataArray{"uv", 2, std::move(t.uv), false},
                  DataArray{"limit_distance", 1, distances.per_point, false}};
  m.cell_data = {index_array("base_face", t.base_face), DataArray{"limit_distance", 1, std::move(cell_distance), false}};
  m.positions = std::move(t.positions);
  m.face_offsets.assign(t.face_offsets.begin(), t.face_offsets.end());
  m.face_vertices.assign(t.face_vertices.begin(), t.face_vertices.end());
  return m;
}

// The most patches an approximation builds: a semi-sharp tag of sharpness s puts them ceil(s)
// levels down, 4^ceil(s) per quad, which a sharpness near 10 would make millions of.
constexpr double kMostPatches = double(1 << 20);

void check_patch_count(const Level& base, int steps, const char* option) {
  if (steps == 0) return;
  double patches = 0;  // after the first step one quad per corner, then four per quad and step
  for (Index f = 0; f < base.face_count(); ++f) patches += base.face_size(f) == 4 ? 4 : base.face_size(f);
  patches *= std::pow(4.0, steps - 1);
  if (patches > kMostPatches)
    throw OptionError(fmt::format("{}: the patches would be built on level {} (where the semi-sharp tags have decayed): "
                            "{:.3g} patches, more than {:.3g}; make tags that sharp infinitely sharp (10), or "
                            "evaluate the exact limit instead of {}",
                            option, steps, patches, kMostPatches, option));
}

// Where the patches' control mesh is not the base mesh, what a refusal's face and vertex
// numbers refer to.
// Why the patches' control mesh is a refined level, in both messages that name it.
constexpr const char* kWhyRefined = "so that every face is a quad and semi-sharp tags have decayed";

std::string refined_level_prefix(int steps) {
  if (steps == 0) return {};
  return fmt::format("on level {} (the mesh refined {} time{} {}; numbered as `subdiv refine -l {}` writes it): ", steps,
                     steps, steps == 1 ? "" : "s", kWhyRefined, steps);
}

// The patches `build` makes of the base mesh, or of the level a few uniform steps make where
// the base has faces that are not quads or semi-sharp tags, after the checks both kinds
// share; its refusals named with `option`.
template <typename Patch, typename Build>
Approximation<Patch> built_patches(const PreparedEvaluation& prepared, const char* option, Build build) {
  check_approximable(prepared, option);
  const Level& base = prepared.surface->base();
  const FeatureOptions& features = prepared.surface->options().features;
  Approximation<Patch> a;
  a.steps = steps_to_quads_without_semi_sharp(base);
  check_patch_count(base, a.steps, option);
  try {
    a.mesh = std::make_shared<const RefinedControlMesh>(*prepared.scheme, base, prepared.mesh.positions, features,
                                                        a.steps);
    a.patches = build(a.mesh->level(), a.mesh->positions(), features.boundary,
                      vertex_limits(*prepared.scheme, *a.mesh, features));
  } catch (const Error& e) {
    throw OptionError(fmt::format("{}: {}{}", option, refined_level_prefix(a.steps), e.what()));
  }
  for (Index f = 0; f < Index(a.patches.size()); ++f) {
    a.base_face.push_back(a.mesh->base_face(f));
    a.in_hole.push_back(base.is_hole(a.base_face.back()));
  }
  return a;
}

PatchSample sample_patch(const BezierPatch& p, double u, double v) { return evaluate_patch(p, u, v); }
PatchSample sample_patch(const GregoryPatch& p, double u, double v) { return evaluate_gregory(p, u, v); }

// Derivatives along a patch's (s, t) as derivatives along the base face's (u, v).
Point3 along_base(const Point3& ds, const Point3& dt, double ds_dw, double dt_dw) {
  return {ds[0] * ds_dw + dt[0] * dt_dw, ds[1] * ds_dw + dt[1] * dt_dw, ds[2] * ds_dw + dt[2] * dt_dw};
}

// sample(face, u, v) at the base mesh's (face, u, v): the patch holding the point.
template <typename Patch>
auto sampler(const Approximation<Patch>& a) {
  return [&a](Index f, double u, double v) {
    const FacePoint p = a.mesh->locate(f, u, v);
    PatchSample s = sample_patch(a.patches[size_t(p.face)], p.st[0], p.st[1]);
    if (a.steps == 0) return s;
    const Jacobian& j = p.jacobian;
    const PatchSample st = s;
    s.du = along_base(st.du, st.dv, j[0][0], j[1][0]);
    s.dv = along_base(st.du, st.dv, j[0][1], j[1][1]);
    s.geometry_du = along_base(st.geometry_du, st.geometry_dv, j[0][0], j[1][0]);
    s.geometry_dv = along_base(st.geometry_du, st.geometry_dv, j[0][1], j[1][1]);
    return s;
  };
}

}  // namespace

BezierApproximation approximation_patches(const PreparedEvaluation& prepared) {
  return built_patches<BezierPatch>(prepared, "{approximate_bezier}", bezier_patches);
}

GregoryApproximation gregory_approximation_patches(const PreparedEvaluation& prepared) {
  return built_patches<GregoryPatch>(prepared, "{approximate_gregory}", gregory_patches);
}

ApproximatedPoints approximate_points(const PreparedEvaluation& prepared, const BezierApproximation& patches,
                                      std::span<const Index> faces, std::span<const double> uv) {
  return sample_points(prepared, sampler(patches), faces, uv);
}

ApproximatedPoints approximate_points(const PreparedEvaluation& prepared, const GregoryApproximation& patches,
                                      std::span<const Index> faces, std::span<const double> uv) {
  return sample_points(prepared, sampler(patches), faces, uv);
}

MeshData approximated_limit_mesh(const PreparedEvaluation& prepared, const BezierApproximation& patches,
                                 int segments, ApproximationDistances& distances) {
  return advising_when_out_of_memory(fmt::format("sampling the patches with {} segments per face edge", segments),
                                     kFewerSamplesAdvice,
                                     [&] { return sampled_mesh(prepared, sampler(patches), segments, distances); });
}

MeshData approximated_limit_mesh(const PreparedEvaluation& prepared, const GregoryApproximation& patches,
                                 int segments, ApproximationDistances& distances) {
  return advising_when_out_of_memory(fmt::format("sampling the patches with {} segments per face edge", segments),
                                     kFewerSamplesAdvice,
                                     [&] { return sampled_mesh(prepared, sampler(patches), segments, distances); });
}

std::string approximation_level_note(int steps, size_t patches) {
  if (steps == 0) return {};
  return fmt::format("the patches are built on level {} ({} uniform step{} {}; the same limit): {} patches", steps,
                     steps, steps == 1 ? "" : "s", kWhyRefined, patches);
}

std::string approximation_summary(const ApproximationDistances& d, ApproximationKind kind) {
  return fmt::format("{} against the exact limit: largest distance {:.3e} (face {}), mean {:.3e} over {} samples",
                     kind == ApproximationKind::Gregory ? "Gregory patches (Loop, Schaefer, Ni & Castaño 2009)"
                                                        : "bicubic patches (Loop & Schaefer 2008)",
                     d.largest, d.largest_face, d.mean, d.samples);
}

std::string bezier_control_net_vtu(const BezierApproximation& approximation, std::span<const double> limit_distance) {
  const std::vector<BezierPatch>& patches = approximation.patches;
  // VTK's order for a Lagrange/Bézier quadrilateral of degree (3, 3): the corners (0,0),
  // (3,0), (3,3), (0,3); the edges i = 1, 2 at j = 0, then j = 1, 2 at i = 3, then i = 1, 2
  // at j = 3, then j = 1, 2 at i = 0 (each in increasing order); then the interior, i fastest.
  static constexpr int order[16][2] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}, {1, 0}, {2, 0}, {3, 1}, {3, 2},
                                       {1, 3}, {2, 3}, {0, 1}, {0, 2}, {1, 1}, {2, 1}, {1, 2}, {2, 2}};
  std::string points, connectivity, offsets, types, degrees, faces, distances;
  size_t written = 0;
  for (size_t p = 0; p < patches.size(); ++p) {
    if (approximation.in_hole[p]) continue;
    const size_t cell = written++;
    for (int k = 0; k < 16; ++k) {
      const Point3& b = patches[p].geometry[size_t(order[k][1] * 4 + order[k][0])];
      points += fmt::format("{} {} {}\n", b[0], b[1], b[2]);
      connectivity += fmt::format("{} ", 16 * cell + size_t(k));
    }
    offsets += fmt::format("{} ", 16 * (cell + 1));
    types += "77 ";  // VTK_BEZIER_QUADRILATERAL
    degrees += "3 3 0 ";
    const Index base = approximation.base_face[p];
    faces += fmt::format("{} ", base);
    if (!limit_distance.empty()) distances += fmt::format("{} ", limit_distance[size_t(base)]);
  }
  std::string cells = fmt::format(
      "<DataArray type=\"Int32\" Name=\"HigherOrderDegrees\" NumberOfComponents=\"3\" format=\"ascii\">{}</DataArray>\n"
      "<DataArray type=\"Int64\" Name=\"base_face\" format=\"ascii\">{}</DataArray>\n",
      degrees, faces);
  if (!limit_distance.empty())
    cells += fmt::format("<DataArray type=\"Float64\" Name=\"limit_distance\" format=\"ascii\">{}</DataArray>\n",
                         distances);
  return fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"2.2\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "<UnstructuredGrid>\n<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n"
      "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n{}</DataArray>\n</Points>\n"
      "<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">{}</DataArray>\n"
      "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">{}</DataArray>\n"
      "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">{}</DataArray>\n</Cells>\n"
      "<CellData HigherOrderDegrees=\"HigherOrderDegrees\">\n{}</CellData>\n"
      "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n",
      16 * written, written, points, connectivity, offsets, types, cells);
}

}  // namespace subdiv
