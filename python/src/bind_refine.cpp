// refine and stencils: the engine's refinement (topology once, then values per level) for
// surface meshes and, with curve schemes, for polylines. The GIL is released while the
// library works, so other Python threads run meanwhile.
#include <cmath>
#include <fmt/format.h>
#include <optional>

#include "bindings.h"

namespace subdivkit {
namespace {

struct RefinedLevel {
  subdiv::MeshData mesh;
  std::vector<subdiv::DataArray> point_data, cell_data;
  std::vector<subdiv::FaceVaryingArray> face_varying;
};

struct RefineInput {
  subdiv::MeshData mesh;
  std::string name;
  std::vector<subdiv::DataArray> point_data, cell_data;
  std::vector<subdiv::FaceVaryingArray> face_varying;
  subdiv::FaceVaryingLinear fvar_mode = subdiv::FaceVaryingLinear::All;
};

subdiv::FaceVaryingLinear fvar_mode_from(const std::string& name) {
  for (int m = 0; m <= 5; ++m)
    if (name == subdiv::face_varying_linear_name(subdiv::FaceVaryingLinear(m))) return subdiv::FaceVaryingLinear(m);
  throw subdiv::Error(fmt::format("fvar_boundary='{}': choose one of none, corners-only, corners-plus1, "
                                  "corners-plus2, boundaries, all", name));
}

RefineInput input_from(py::handle mesh, py::handle point_data, py::handle cell_data, py::handle face_varying = py::none(),
                       const std::string& fvar_boundary = "all") {
  RefineInput in;
  in.mesh = mesh_from_python(mesh);
  in.name = mesh_name(mesh);
  in.point_data = data_arrays_from(point_data, in.mesh.vertex_count(), "point data");
  in.cell_data = data_arrays_from(cell_data, in.mesh.face_count(), "cell data");
  in.face_varying = face_varying_from(face_varying, Index(in.mesh.face_vertices.size()));
  in.fvar_mode = fvar_mode_from(fvar_boundary);
  for (const auto& a : in.face_varying)
    for (size_t c = 0; c < a.indices.size(); ++c)
      if (a.indices[c] < 0 || a.indices[c] >= a.value_count())
        throw subdiv::Error(fmt::format("face-varying '{}': face corner {} uses value {}, but there are {} values",
                                        a.name, c, a.indices[c], a.value_count()));
  return in;
}

}  // namespace

std::optional<tbb::global_control> thread_limit(int threads) {
  std::optional<tbb::global_control> limit;
  if (threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, size_t(threads));
  return limit;
}

subdiv::Level surface_base(const subdiv::MeshData& mesh, const std::string& name, const SchemeChoice& c) {
  if (mesh.face_count() == 0)
    throw subdiv::Error(fmt::format("{}: the mesh has no faces to refine{}", name,
                                    mesh.line_count() ? "; its polylines need a curve scheme (e.g. 'chaikin')" : ""));
  subdiv::Level base = subdiv::level_from_mesh(mesh, name);
  subdiv::cli::check_fits_in_memory(*c.sequence.schemes.front(), base, c.sequence.total_levels);
  return base;
}

namespace {

subdiv::CurveLevel curve_base(const RefineInput& in, const subdiv::CurveScheme& curve, int levels) {
  if (curve.nonlinear)
    throw subdiv::Error(fmt::format("'{}' is a non-linear curve scheme (a plugin rule); the Python module refines "
                                    "polylines with linear curve schemes only (use `subdiv refine` for this one)",
                                    curve.name));
  subdiv::CurveLevel base = subdiv::curve_level_from_mesh(in.mesh, in.name);
  const double points = double(base.vertices.size() + 2 * size_t(base.polyline_count())) *
                        std::pow(double(curve.arity), levels);
  if (points > 2.0e9)
    throw subdiv::Error(fmt::format("{} levels would make about {:.3g} points, more than the 2^31 a level can "
                                    "index; ask for fewer levels", levels, points));
  return base;
}

// Hole faces are left out of the output (mesh_from_level, OpenSubdiv's holes): so are their cell values.
std::vector<subdiv::DataArray> cells_outside_holes(const subdiv::Level& L, std::vector<subdiv::DataArray> cells) {
  if (L.face_hole.empty()) return cells;
  for (auto& a : cells) {
    size_t row = 0;
    for (Index f = 0; f < L.face_count(); ++f) {
      if (L.is_hole(f)) continue;
      std::copy_n(&a.values[size_t(f) * a.components], a.components, &a.values[row * a.components]);
      ++row;
    }
    a.values.resize(row * a.components);
  }
  return cells;
}

// The user's arrays through the levels as the command line carries them (framework/primvar):
// point arrays with the positions by the scheme's rules, integer ones by origin, normals
// left out (named in `dropped`), cell arrays inherited, face-varying arrays by
// refine_face_varying.
std::vector<RefinedLevel> refine_surface(RefineInput& in, const SchemeChoice& c, const subdiv::RefineOptions& o,
                                         bool all_levels, std::vector<std::string>& dropped) {
  const subdiv::SchemeSequence& seq = c.sequence;
  subdiv::Hierarchy h = subdiv::refine_topology(seq.runs, surface_base(in.mesh, in.name, c), o);
  subdiv::LevelData level{std::move(in.mesh.positions), subdiv::carried_point_arrays(in.point_data, &dropped),
                          std::move(in.cell_data)};
  subdiv::check_finite_arrays(level, in.name);
  std::vector<subdiv::FaceVaryingArray> carried;
  std::vector<std::vector<subdiv::FaceVaryingLevel>> fvar;
  for (auto& a : in.face_varying) {
    if (a.role == subdiv::ArrayRole::Normals) {
      dropped.push_back(a.name);
      continue;
    }
    fvar.push_back(subdiv::refine_face_varying(seq.runs, h, {a.values, a.indices}, a.components, in.fvar_mode, o));
    carried.push_back(std::move(a));
  }
  std::vector<RefinedLevel> out;
  auto keep = [&](int l) {
    const subdiv::Level& L = h.levels[l];
    std::vector<subdiv::FaceVaryingArray> uv;
    for (size_t k = 0; k < fvar.size(); ++k) {
      const auto& a = carried[k];
      const subdiv::FaceVaryingLevel& at = fvar[k][size_t(l)];
      uv.push_back({a.name, a.components, at.values, corners_outside_holes(L, at.indices), a.role});
    }
    out.push_back({subdiv::mesh_from_level(L, level.positions), level.point_data, cells_outside_holes(L, level.cell_data),
                   std::move(uv)});
  };
  if (all_levels || seq.total_levels == 0) keep(0);
  for (int l = 0; l < seq.total_levels; ++l) {
    level = subdiv::next_level_data(seq.runs, h, l, level, o);
    if (all_levels || l + 1 == seq.total_levels) keep(l + 1);
  }
  return out;
}

std::vector<RefinedLevel> refine_curve(RefineInput& in, const subdiv::CurveScheme& curve, int levels,
                                       bool all_levels) {
  if (!in.cell_data.empty())
    throw subdiv::Error("cell data: curve refinement carries point data only (polylines have no faces)");
  subdiv::CurveHierarchy h = subdiv::refine_curves(curve, curve_base(in, curve, levels), levels);
  std::vector<double> positions = std::move(in.mesh.positions);
  std::vector<subdiv::DataArray> points = std::move(in.point_data);
  // Polylines have no element origins to take labels by: every point array is interpolated.
  for (auto& p : points) p.integer = false;
  if (!in.face_varying.empty())
    throw subdiv::Error("face-varying data: polylines have no faces to carry it; curve refinement carries point data");
  std::vector<RefinedLevel> out;
  auto keep = [&](int l) { out.push_back({subdiv::mesh_from_curve_level(h.levels[l], positions), points, {}}); };
  if (all_levels || levels == 0) keep(0);
  for (int l = 0; l < levels; ++l) {
    positions = h.stencils[l].apply(positions, 3);
    for (auto& p : points) p.values = h.stencils[l].apply(p.values, p.components);
    if (all_levels || l + 1 == levels) keep(l + 1);
  }
  return out;
}

py::list refine(py::handle mesh, py::handle scheme, py::handle params, int levels, const std::string& boundary,
                const std::string& crease_method, int threads, bool all_levels, int start_level,
                py::handle point_data, py::handle cell_data, py::handle face_varying, const std::string& fvar_boundary) {
  check_levels(levels);
  const subdiv::RefineOptions options = refine_options(boundary, crease_method, threads, start_level);
  RefineInput in = input_from(mesh, point_data, cell_data, face_varying, fvar_boundary);
  const SchemeChoice choice = scheme_choice_from(scheme, levels, params);
  std::vector<RefinedLevel> result;
  std::vector<std::string> dropped;
  {
    py::gil_scoped_release unlocked;
    const auto limit = thread_limit(threads);
    result = choice.is_curve() ? refine_curve(in, *choice.single->curve, levels, all_levels)
                               : refine_surface(in, choice, options, all_levels, dropped);
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
    const auto limit = thread_limit(threads);
    if (choice.is_curve()) {
      tables = subdiv::refine_curves(*choice.single->curve, curve_base(in, *choice.single->curve, levels), levels)
                   .stencils;
    } else {
      subdiv::Hierarchy h = subdiv::refine(choice.sequence.runs, surface_base(in.mesh, in.name, choice), options);
      if (!h.linear())
        throw subdiv::Error(fmt::format("'{}' has a non-linear step (a plugin rule): no matrix can say it; use "
                                        "refine() instead", choice.label));
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

void bind_refine(py::module_& m) {
  m.def("_refine", &refine, py::arg("mesh"), py::arg("scheme"), py::arg("params"), py::arg("levels"), py::arg("boundary"),
        py::arg("crease_method"), py::arg("threads"), py::arg("all_levels"), py::arg("start_level"),
        py::arg("point_data"), py::arg("cell_data"), py::arg("face_varying"), py::arg("fvar_boundary"),
        "Refined levels as dicts of arrays (subdivkit.refine wraps them in Meshes).");
  m.def("_stencils", &stencils, py::arg("mesh"), py::arg("scheme"), py::arg("params"), py::arg("levels"), py::arg("composed"),
        py::arg("boundary"), py::arg("crease_method"), py::arg("threads"), py::arg("start_level"),
        "Stencil tables as CSR arrays (subdivkit.stencils makes scipy.sparse.csr_matrix of them).");
}

}  // namespace subdivkit
