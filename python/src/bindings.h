#pragma once
// Shared pieces of the _subdivkit extension: NumPy conversion, the mesh and scheme values
// passed between Python and the library, option parsing, and one bind_* function per file.
#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "library.h"

namespace subdivkit {

namespace py = pybind11;
using subdiv::Index;

// ---- arrays.cpp: NumPy <-> std::vector ---------------------------------------------------

// A NumPy array that owns `values` (moved, not copied) with the given shape.
py::array_t<double> adopt(std::vector<double>&& values, std::vector<py::ssize_t> shape);
py::array_t<std::int32_t> adopt(std::vector<std::int32_t>&& values, std::vector<py::ssize_t> shape);
py::array_t<std::int32_t> adopt(subdiv::ScratchVector<std::int32_t>&& values, std::vector<py::ssize_t> shape);
py::array_t<std::uint8_t> adopt(std::vector<std::uint8_t>&& values, std::vector<py::ssize_t> shape);

// The values of any array-like, converted to C-contiguous float64 / int32 (the Python layer
// has already refused what must not be converted, such as float face indices). `what`
// names the argument in messages.
std::vector<double> doubles_from(py::handle array, const std::string& what);
std::vector<Index> indices_from(py::handle array, const std::string& what);

// ---- class_guard.cpp: classes whose objects only the library makes -----------------------

// pybind11 lets `Cls.__new__(Cls)` make an object whose C++ value was never constructed:
// its methods would read uninitialised memory. Classes whose objects come from factory
// functions refuse that (a TypeError saying `how` to get one); the factories allocate
// through the type's tp_alloc, not __new__, and still work.
void refuse_bare_new(py::handle cls, const std::string& how);

// ---- mesh_conversion.cpp: subdivkit.Mesh <-> MeshData ------------------------------------

// Reads a subdivkit.Mesh's arrays and checks them as the file readers do
// (validate_mesh_data), naming the mesh by its `name`.
subdiv::MeshData mesh_from_python(py::handle mesh);
// The name a Mesh gives messages: the file it was read from, or "mesh".
std::string mesh_name(py::handle mesh);
// The arrays subdivkit.Mesh._from_arrays takes (points, face_indices, face_offsets, ...).
py::dict mesh_to_python(subdiv::MeshData&& mesh);

// Per-vertex (or per-face) arrays riding along with a mesh: name, values, columns.
// A point or cell array's role as Python names it ("data", "normals",
// "texture_coordinates", "color"), and back; an unknown name is refused with the list.
const char* role_name(subdiv::ArrayRole role);
subdiv::ArrayRole role_from_name(const std::string& name, const std::string& array);
// Point or cell arrays from (name, 2-d float64 array, integer, role name) tuples, as
// subdivkit/mesh.py's _data_arrays makes them; `rows` tuples each.
std::vector<subdiv::DataArray> data_arrays_from(py::handle items, Index rows, const std::string& what);
// A dict name -> (rows, components) array: int32 for integer arrays, else float64.
py::dict data_arrays_to_python(std::vector<subdiv::DataArray>&& arrays);
// A dict name -> role name of the arrays whose role is not plain data.
py::dict roles_to_python(const std::vector<subdiv::DataArray>& arrays);

// Face-varying arrays from (name, (m, k) float64 values, corner indices) triples, checked
// against the mesh's corner count; and back as a dict name -> (values, indices).
std::vector<subdiv::FaceVaryingArray> face_varying_from(py::handle triples, Index corners);
py::dict face_varying_to_python(std::vector<subdiv::FaceVaryingArray>&& arrays);

// ---- options.cpp: the keyword arguments the library's option structs are made from ------
// (Keeping them here means one file to touch when the option structs change.)

// Python's spelling of the pipeline's option names in messages: its keywords ("{levels}" reads "levels").
const subdiv::OptionSpelling& python_option_spelling();
// The same where parameters are keyword arguments (Scheme.load(name, gamma=1)), not params=.
const subdiv::OptionSpelling& python_keyword_spelling();
subdiv::BoundaryInterpolation boundary_from(const std::string& text);
subdiv::CreaseMethod crease_method_from(const std::string& text);
subdiv::RefineOptions refine_options(const std::string& boundary, const std::string& crease_method, int threads,
                                     int first_step);
subdiv::SurfaceAnalysisOptions analysis_options(const std::string& boundary, int max_ring, bool characteristic_map);
subdiv::LimitOptions limit_options(const std::string& boundary, const std::string& crease_method, int first_step);
subdiv::LimitSelectionOptions limit_selection_options(const std::string& boundary, int first_step);
// Refuses level counts the command line refuses (0..30).
void check_levels(int levels);

// ---- scheme_handle.cpp: the subdivkit.Scheme class ---------------------------------------

// A loaded surface or curve scheme, and what it was loaded from, so that new parameter
// values can load it again.
struct SchemeHandle {
  std::string kind;  // "surface" or "curve"
  std::shared_ptr<const subdiv::Scheme> surface;
  std::shared_ptr<const subdiv::CurveScheme> curve;
  std::string source;  // name, path, or JSON text
  bool from_text = false;
  std::string label;  // the name messages give JSON text
  subdiv::ParameterOverrides overrides;

  const std::string& name() const;
};

SchemeHandle load_scheme_handle(const std::string& source, bool from_text, const std::string& label,
                                const subdiv::ParameterOverrides& overrides);
// Keyword arguments to --param style overrides: numbers at full precision, strings as given.
subdiv::ParameterOverrides overrides_from(py::handle kwargs);  // a dict, or None

// What refine and stencils run: a Scheme, or a string naming a scheme, a .json path or a
// sequence "A:1,B:3" (then `levels` completes it, as --levels does). `params` (a dict or
// None) are parameter values as --param gives them: to the Scheme, or to every scheme of a
// sequence that has the parameter.
struct SchemeChoice {
  std::shared_ptr<const SchemeHandle> single;  // set for one scheme (surface or curve)
  subdiv::SchemeSequence sequence;             // surface schemes
  std::string label;                           // for messages
  bool is_curve() const { return single && single->kind == "curve"; }
};
SchemeChoice scheme_choice_from(py::handle scheme, int levels, py::handle params);
// Whether `scheme` (a Scheme or a name) is one curve scheme, found without loading it.
bool names_curve_scheme(py::handle scheme);
// The same scheme as the pipeline's SchemeSource (framework/pipeline/refine_request.h).
subdiv::SchemeSource scheme_source_from(py::handle scheme, py::handle params);

// ---- bind_refine.cpp: what refine and the Evaluator share ----------------------------------

// The base level of a surface refinement, refused as `subdiv refine` refuses it (no faces,
// more levels than fit in memory). Call it without the GIL: it builds the level's topology.
subdiv::Level surface_base(const subdiv::MeshData& mesh, const std::string& name, const SchemeChoice& c);

// ---- bind_*.cpp ---------------------------------------------------------------------------
// progress(phase, done) as the request's progress callbacks (bind_refine.cpp): the phase as
// it starts (done None), then the share of the long work done, 0 to 1.
void report_progress(subdiv::RefineRequest& request, py::handle progress);
// The same two callbacks for work the front-end runs in a PhaseProgress (pipeline/phase_progress.h).
void progress_callbacks(py::handle progress, std::function<void(const std::string&)>& say,
                        std::function<void(double)>& fraction);

void bind_schemes(py::module_& m);
void bind_mesh_io(py::module_& m);
void bind_refine(py::module_& m);
void bind_evaluator(py::module_& m);
void bind_analysis(py::module_& m);
void bind_limits(py::module_& m);
void bind_plugins(py::module_& m);
void bind_parameterize(py::module_& m);
void bind_limit_surface(py::module_& m);
void bind_adaptive(py::module_& m);  // bind_adaptive.cpp

}  // namespace subdivkit
