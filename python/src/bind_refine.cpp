// refine and stencils: the engine's refinement (topology once, then values per level) for
// surface meshes and, with curve schemes, for polylines. The GIL is released while the
// library works, so other Python threads run meanwhile.
#include <cmath>
#include <fmt/format.h>
#include <optional>

#include "bindings.h"
#include "framework/util/quoted_text.h"

namespace subdivkit {
namespace {

struct RefinedLevel {
  std::vector<subdiv::DataArray> point_data, cell_data;
  std::vector<subdiv::FaceVaryingArray> face_varying;
  subdiv::MeshData mesh;  // faces and positions (the arrays are above)
};

struct RefineInput {
  subdiv::MeshData mesh;
  std::string name;
  std::vector<subdiv::DataArray> point_data, cell_data;
  std::vector<subdiv::FaceVaryingArray> face_varying;
  subdiv::FaceVaryingLinear fvar_mode = subdiv::FaceVaryingLinear::All;
};

RefineInput input_from(py::handle mesh, py::handle point_data, py::handle cell_data, py::handle face_varying = py::none(),
                       const std::string& fvar_boundary = "all") {
  RefineInput in;
  in.mesh = mesh_from_python(mesh);
  in.name = mesh_name(mesh);
  in.point_data = data_arrays_from(point_data, in.mesh.vertex_count(), "point data");
  in.cell_data = data_arrays_from(cell_data, in.mesh.face_count(), "cell data");
  in.face_varying = face_varying_from(face_varying, Index(in.mesh.face_vertices.size()));
  in.fvar_mode = subdiv::face_varying_from_name(fvar_boundary, "fvar_boundary=");
  for (const auto& a : in.face_varying)
    for (size_t c = 0; c < a.indices.size(); ++c)
      if (a.indices[c] < 0 || a.indices[c] >= a.value_count())
        throw subdiv::Error(fmt::format("face-varying {}: face corner {} uses value {}, but there are {} values",
                                        subdiv::quoted(a.name), c, a.indices[c], a.value_count()));
  return in;
}

}  // namespace

subdiv::Level surface_base(const subdiv::MeshData& mesh, const std::string& name, const SchemeChoice& c) {
  if (mesh.face_count() == 0)
    throw subdiv::Error(fmt::format("{}: the mesh has no faces to refine{}", name,
                                    mesh.line_count() ? "; its polylines need a curve scheme (e.g. 'chaikin')" : ""));
  subdiv::Level base = subdiv::level_from_mesh(mesh, name);
  subdiv::check_fits_in_memory(*c.sequence.schemes.front(), base, c.sequence.total_levels);
  return base;
}

namespace {

subdiv::CurveLevel curve_base(const RefineInput& in, const subdiv::CurveScheme& curve, int levels) {
  if (curve.nonlinear)
    throw subdiv::Error(fmt::format("{} is a non-linear curve scheme (a plugin rule): no matrix can say it; use "
                                    "refine() instead",
                                    subdiv::quoted(curve.name)));
  subdiv::CurveLevel base = subdiv::curve_level_from_mesh(in.mesh, in.name);
  subdiv::check_curve_size(base, curve.arity, levels);
  return base;
}

// The user's arrays through the levels as the command line carries them: one pipeline
// request (framework/pipeline/refine_pipeline.h), each kept level described as a mesh with
// its arrays (hole faces left out, as OpenSubdiv leaves them out) and SubdivKit's arrays
// that `described` asks for, as the CLI writes them to .vtp (level_description.h).
std::vector<RefinedLevel> refine_surface(RefineInput& in, subdiv::RefineRequest request,
                                         const subdiv::ArraySelection& described, std::vector<std::string>& dropped,
                                         std::vector<std::string>& warnings) {
  request.mesh = std::move(in.mesh);
  request.mesh.point_data = std::move(in.point_data);
  request.mesh.cell_data = std::move(in.cell_data);
  request.mesh.face_varying = std::move(in.face_varying);
  request.mesh_name = in.name;
  request.shape.face_varying = in.fvar_mode;
  request.described_arrays = described;
  subdiv::RefineResult result = subdiv::refine_mesh(std::move(request));
  dropped = std::move(result.dropped_arrays);
  warnings = std::move(result.warnings);
  const subdiv::Hierarchy& h = result.hierarchy;
  std::vector<RefinedLevel> out;
  std::vector<double> base_face;  // of level l, while asked for
  for (size_t l = 0; l < result.levels.size(); ++l) {
    if (described.has("base_face")) base_face = subdiv::base_faces_of(h, int(l), base_face);
    if (result.levels[l].positions.empty() && l + 1 < result.levels.size()) continue;  // not kept
    subdiv::MeshData mesh =
        subdiv::described_level_mesh(h, int(l), std::move(result.levels[l]), result.features, base_face, described);
    RefinedLevel level{std::move(mesh.point_data), std::move(mesh.cell_data), std::move(mesh.face_varying), {}};
    mesh.point_data.clear(), mesh.cell_data.clear(), mesh.face_varying.clear();
    level.mesh = std::move(mesh);
    out.push_back(std::move(level));
  }
  return out;
}

// Polylines through the curve pipeline (framework/pipeline/curve_pipeline.h), as `subdiv
// refine` runs them.
std::vector<RefinedLevel> refine_curve(RefineInput& in, subdiv::SchemeSource scheme, int levels, bool all_levels,
                                       std::vector<std::string>& warnings) {
  if (!in.face_varying.empty())
    throw subdiv::Error("face-varying data: polylines have no faces to carry it; curve refinement carries point data");
  subdiv::CurveRefineRequest request;
  request.mesh = std::move(in.mesh);
  request.mesh.point_data = std::move(in.point_data);
  request.mesh.cell_data = std::move(in.cell_data);
  request.mesh_name = in.name;
  request.scheme = std::move(scheme);
  request.levels = levels;
  request.keep_all_levels = all_levels;
  subdiv::CurveRefineResult result = subdiv::refine_curve_request(std::move(request));
  warnings = std::move(result.notes);
  std::vector<RefinedLevel> out;
  for (auto& level : result.levels) {
    RefinedLevel r{std::move(level.mesh.point_data), {}, {}, std::move(level.mesh)};
    r.mesh.point_data.clear();
    out.push_back(std::move(r));
  }
  return out;
}

py::list refine(py::handle mesh, py::handle scheme, py::handle params, int levels, const std::string& boundary,
                const std::string& crease_method, int threads, bool all_levels, int start_level,
                py::handle point_data, py::handle cell_data, py::handle face_varying, const std::string& fvar_boundary,
                const std::string& arrays, py::handle progress) {
  check_levels(levels);
  const subdiv::ArraySelection described = subdiv::ArraySelection::parse(arrays);
  const subdiv::RefineOptions options = refine_options(boundary, crease_method, threads, start_level);
  RefineInput in = input_from(mesh, point_data, cell_data, face_varying, fvar_boundary);
  const bool curve = names_curve_scheme(scheme);
  subdiv::RefineRequest request;
  request.scheme = scheme_source_from(scheme, params);
  request.levels = levels;
  request.start_level = start_level;
  request.shape.boundary = options.features.boundary;
  request.shape.crease_method = options.features.crease_method;
  request.keep_all_levels = all_levels;
  if (!progress.is_none()) report_progress(request, progress);
  std::vector<RefinedLevel> result;
  std::vector<std::string> dropped, warnings;
  {
    py::gil_scoped_release unlocked;
    const subdiv::ThreadLimit limit(threads);
    result = curve ? refine_curve(in, std::move(request.scheme), levels, all_levels, warnings)
                   : refine_surface(in, std::move(request), described, dropped, warnings);
  }
  py::list out;
  for (auto& level : result) {
    py::dict d = mesh_to_python(std::move(level.mesh));
    d["point_roles"] = roles_to_python(level.point_data);
    d["cell_roles"] = roles_to_python(level.cell_data);
    d["point_data"] = data_arrays_to_python(std::move(level.point_data));
    d["cell_data"] = data_arrays_to_python(std::move(level.cell_data));
    d["face_varying"] = face_varying_to_python(std::move(level.face_varying));
    d["dropped"] = dropped;
    d["warnings"] = warnings;
    out.append(d);
  }
  return out;
}

py::dict table_to_python(subdiv::StencilTable&& t) {
  py::dict d;
  const auto rows = py::ssize_t(t.row_count()), entries = py::ssize_t(t.weights.size());
  d["shape"] = py::make_tuple(rows, py::ssize_t(t.source_count));
  d["indptr"] = adopt(std::move(t.offsets), {rows + 1});
  d["indices"] = adopt(std::move(t.indices), {entries});
  d["data"] = adopt(std::move(t.weights), {entries});
  return d;
}

py::list stencils(py::handle mesh, py::handle scheme, py::handle params, int levels, bool composed, const std::string& boundary,
                  const std::string& crease_method, int threads, int start_level) {
  check_levels(levels);
  const subdiv::RefineOptions options = refine_options(boundary, crease_method, threads, start_level);
  RefineInput in = input_from(mesh, py::none(), py::none());
  const SchemeChoice choice = scheme_choice_from(scheme, levels, params);
  std::vector<subdiv::StencilTable> tables;
  {
    py::gil_scoped_release unlocked;
    const subdiv::ThreadLimit limit(threads);
    if (choice.is_curve()) {
      tables = subdiv::refine_curves(*choice.single->curve, curve_base(in, *choice.single->curve, levels), levels)
                   .stencils;
    } else {
      subdiv::Hierarchy h = subdiv::refine(choice.sequence.runs, surface_base(in.mesh, in.name, choice), options);
      if (!h.linear())
        throw subdiv::Error(fmt::format("{} has a non-linear step (a plugin rule): no matrix can say it; use "
                                        "refine() instead", subdiv::quoted(choice.label)));
      tables = std::move(h.stencils);
    }
    if (composed && !tables.empty()) {
      subdiv::StencilTable total = std::move(tables.front());
      for (size_t l = 1; l < tables.size(); ++l) total = subdiv::compose(total, tables[l]);
      tables = {std::move(total)};
    }
    if (composed && tables.empty()) {  // zero levels: the identity
      subdiv::StencilTable identity;
      identity.source_count = in.mesh.vertex_count();
      for (Index v = 0; v < identity.source_count; ++v) {
        identity.indices.push_back(v), identity.weights.push_back(1.0);
        identity.offsets.push_back(v + 1);
      }
      tables = {std::move(identity)};
    }
  }
  py::list out;
  for (auto& t : tables) out.append(table_to_python(std::move(t)));
  return out;
}

}  // namespace

// progress(phase, done): the phase as it starts (done None), then the share of the long
// work done, 0 to 1. Called on the calling thread with the GIL taken; the callable outlives
// the call, so the handle holds no reference (no refcounting without the GIL).
void progress_callbacks(py::handle progress, std::function<void(const std::string&)>& say,
                        std::function<void(double)>& fraction) {
  auto phase = std::make_shared<std::string>();
  say = [progress, phase](const std::string& now) {
    *phase = now;
    py::gil_scoped_acquire gil;
    progress(now, py::none());
  };
  fraction = [progress, phase](double done) {
    py::gil_scoped_acquire gil;
    progress(*phase, done);
  };
}

void report_progress(subdiv::RefineRequest& request, py::handle progress) {
  progress_callbacks(progress, request.progress, request.progress_fraction);
}

void bind_refine(py::module_& m) {
  m.def("_refine", &refine, py::arg("mesh"), py::arg("scheme"), py::arg("params"), py::arg("levels"), py::arg("boundary"),
        py::arg("crease_method"), py::arg("threads"), py::arg("all_levels"), py::arg("start_level"),
        py::arg("point_data"), py::arg("cell_data"), py::arg("face_varying"), py::arg("fvar_boundary"),
        py::arg("arrays") = "none", py::arg("progress") = py::none(),
        "Refined levels as dicts of arrays (subdivkit.refine wraps them in Meshes).");
  m.def("_stencils", &stencils, py::arg("mesh"), py::arg("scheme"), py::arg("params"), py::arg("levels"), py::arg("composed"),
        py::arg("boundary"), py::arg("crease_method"), py::arg("threads"), py::arg("start_level"),
        "Stencil tables as CSR arrays (subdivkit.stencils makes scipy.sparse.csr_matrix of them).");
}

}  // namespace subdivkit
