# The public API of SubdivKit: the headers `cmake --install` puts under
# include/subdivkit/framework/, relative to framework/. Everything else stays private to
# the library. The list is closed under #include: an installed header includes only
# installed ones (tests/architecture checks it) and no third-party header, so a user needs
# nothing but the package (tests/install/headers compiles each one alone against it).
#
# SUBDIV_PUBLIC_HEADERS: libsubdiv (SubdivKit::subdiv). First the documented entry points,
# then (marked) what they include.
set(SUBDIV_PUBLIC_HEADERS
  # Errors, and one mesh level.
  util/error.h util/option_spelling.h util/scratch_vector.h util/thread_count.h
  topology/level.h
  # Reading and writing meshes; a mesh file's data as an engine level.
  io/mesh_data.h io/mesh_read.h io/mesh_write.h io/mesh_level.h io/formats.h io/format_registry.h
  io/output_level.h
  # Schemes: finding and loading them by name or path, what a scheme holds, sequences.
  scheme/scheme_registry.h scheme/scheme.h scheme/curve_scheme.h scheme/parameter_spec.h
  scheme/scheme_sequence.h scheme/scheme_run.h scheme/scheme_validator.h scheme/scheme_loader.h
  # Shape options: boundaries and creases (OpenSubdiv's Sdc::Options).
  features/feature_options.h
  # The engine: refine, step values, the Evaluator; stencil tables; user data per level.
  engine/refiner.h engine/evaluator.h stencil/stencil_table.h
  primvar/level_data.h primvar/face_varying.h
  # Curves: polylines and polygons refined with a curve scheme.
  curve/curve_level.h curve/curve_refine.h
  # Analysis results and limit points.
  analysis/curve/curve_analysis.h analysis/curve/curve_scheme_analysis.h
  analysis/surface/surface_analysis.h analysis/surface/limit_evaluation.h
  interpolation/limit_evaluator.h interpolation/limit_selection.h interpolation/analysed_limit.h
  interpolation/progressive.h
  # The limit surface at any (face, u, v): evaluation, limit stencils, tessellation.
  limit/limit_surface.h limit/tessellation.h limit/face_domain.h limit/adaptive_refine.h
  limit/bezier_approximation.h
  limit/gregory_approximation.h
  # Texture coordinates for disc-like meshes: Tutte's embedding.
  parameterize/tutte.h parameterize/parameterize_mesh.h
  # The plugin ABI and what plugins build on (new splitters, C++ rules, mesh lines).
  plugin/plugin_api.h plugin/plugin_registry.h plugin/plugin_loader.h
  plugin/mesh_lines.h plugin/polyline_refine.h
  refine/splitter.h refine/child_origins.h refine/child_tags.h rules/code_rules.h
  # Included by the headers above (types in their signatures), not entry points of their own.
  features/context.h features/feature_context.h features/sharpness.h
  rules/rule.h rules/formula.h rules/row_paths.h scheme/step_rules.h curve/curve_rules.h
  analysis/curve/curve_mask.h analysis/curve/curve_laurent.h analysis/curve/curve_eigen.h
  analysis/curve/curve_contractivity.h analysis/curve/curve_local_matrix.h analysis/surface/local_patch.h
)

# The pipeline (framework/pipeline/): every header directly in that folder is public,
# found by a glob in framework/CMakeLists.txt. Name the ones that are not here:
# phase_progress.h is how the pipeline's .cpp files and the command line tell a bar.
set(SUBDIV_PIPELINE_PRIVATE_HEADERS pipeline/phase_progress.h)

# SUBDIV_VTKIO_PUBLIC_HEADERS: libsubdiv_vtkio (SubdivKit::vtkio). None includes a VTK
# header, so the package needs no find_dependency(VTK): VTK is linked privately.
set(SUBDIV_VTKIO_PUBLIC_HEADERS
  io/vtk/vtk_formats.h io/vtk/vtk_output.h
)
