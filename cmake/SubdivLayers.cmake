# The layers of libsubdiv, bottom first, and the layers each may include (its own folder
# always). framework/CMakeLists.txt builds one object library per layer from this table,
# and tests/architecture checks every #include "framework/..." against it, so a file in a
# lower layer cannot include a higher one. docs/architecture.md draws the same table.
set(SUBDIV_LAYERS util topology features stencil refine rules scheme engine io primvar analysis curve
    interpolation limit plugin parameterize pipeline)
set(SUBDIV_LAYER_USES_util "")
set(SUBDIV_LAYER_USES_topology util)
set(SUBDIV_LAYER_USES_features util topology)
set(SUBDIV_LAYER_USES_stencil util topology)
set(SUBDIV_LAYER_USES_refine util topology features)
set(SUBDIV_LAYER_USES_rules util topology features stencil refine)
set(SUBDIV_LAYER_USES_scheme util topology features refine rules)
set(SUBDIV_LAYER_USES_engine util topology features stencil refine rules scheme)
set(SUBDIV_LAYER_USES_io util topology)
set(SUBDIV_LAYER_USES_primvar util topology features refine scheme engine io)
set(SUBDIV_LAYER_USES_analysis util topology features stencil refine rules scheme engine io)
set(SUBDIV_LAYER_USES_curve util topology stencil rules scheme io analysis)
set(SUBDIV_LAYER_USES_interpolation util topology features stencil refine rules scheme engine analysis curve)
set(SUBDIV_LAYER_USES_limit util topology features stencil refine rules scheme engine analysis)
set(SUBDIV_LAYER_USES_plugin util topology features refine rules scheme engine)
# Tutte's embedding of disc-like meshes (texture coordinates for meshes without them).
set(SUBDIV_LAYER_USES_parameterize util topology io)
# The product path once, for every front-end (command line, Python, ParaView): requests in,
# levels with their data and descriptions out.
set(SUBDIV_LAYER_USES_pipeline util topology features stencil refine rules scheme engine io primvar analysis curve
    interpolation limit plugin)
# Rooms inside a layer, bottom first: a room may include the rooms before it, not after.
# Surface analysis uses curve analysis (boundaries follow curve schemes), never the reverse.
set(SUBDIV_ROOMS_analysis curve surface)
# VTK file IO is a library of its own (subdiv_vtkio) on top of io: the engine links no VTK.
set(SUBDIV_VTKIO_USES util topology io)
