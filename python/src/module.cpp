// The _subdivkit extension module: SubdivKit's engine, scheme language and analysis over
// NumPy arrays. The public API is the `subdivkit` package (python/subdivkit/), which adds
// the Mesh class and SciPy matrices on top of what is bound here.
#include "bindings.h"
#include "framework/io/vtk/vtk_formats.h"
#include "framework/util/memory_limit.h"
#include "framework/util/quoted_text.h"

PYBIND11_MODULE(_subdivkit, m) {
  namespace py = pybind11;
  m.doc() = "SubdivKit's C++ engine for the subdivkit package; use `import subdivkit`.";
  // Every user-facing failure of the library (bad files, schemes, parameters, meshes) is a
  // subdiv::Error whose message names the place and the fix: the CLI's text, with the
  // options of an OptionError spelled as Python's arguments (python_option_spelling).
  static py::exception<subdiv::Error> error(m, "Error", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const subdiv::OutOfMemoryError& e) {  // MemoryError, with the fix in Python's keywords
      PyErr_SetString(PyExc_MemoryError, subdiv::terminal_safe(e.spelled(subdivkit::python_option_spelling())).c_str());
    } catch (const subdiv::OptionError& e) {  // the pipeline's words, spelled as Python's keywords
      error(subdiv::terminal_safe(e.spelled(subdivkit::python_option_spelling())).c_str());
    } catch (const subdiv::Error& e) {
      error(subdiv::terminal_safe(e.what()).c_str());
    }
  });
  error.attr("__doc__") =
      "A SubdivKit error: a bad file, scheme, parameter or mesh. The message is the one the `subdiv` command line "
      "prints, naming the place and the fix, with options named as Python's arguments. A subclass of ValueError.";
  error.attr("__module__") = "subdivkit";
  // User text (names, keys) in the messages the Python layer raises, escaped as the
  // library's own messages are (framework/util/quoted_text.h); bytes in, so that any str
  // reaches it (subdivkit.mesh._quoted encodes with surrogatepass).
  m.def("_quoted", [](const py::bytes& text) { return subdiv::quoted(std::string(text)); });
  m.def("_escaped", [](const py::bytes& text) { return subdiv::escaped(std::string(text)); });
  m.attr("__version__") = SUBDIV_VERSION;
  subdiv::register_vtk_formats();  // read_mesh/write_mesh handle .vtp, .vtk and .pvd
  subdivkit::bind_schemes(m);
  subdivkit::bind_mesh_io(m);
  subdivkit::bind_refine(m);
  subdivkit::bind_evaluator(m);
  subdivkit::bind_analysis(m);
  subdivkit::bind_limits(m);
  subdivkit::bind_plugins(m);
  subdivkit::bind_parameterize(m);
  subdivkit::bind_limit_surface(m);
  subdivkit::bind_adaptive(m);
}
