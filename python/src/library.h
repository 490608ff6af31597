#pragma once
// Every SubdivKit header the Python module uses, in one place: when the library's folders
// move (framework/engine/refiner.h to framework/engine/, the analysis and VTK files into
// their own folders), this list is the one to fix.
#include "framework/analysis/curve/curve_scheme_analysis.h"
#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/surface_analysis.h"
#include "framework/curve/curve_level.h"
#include "framework/curve/curve_refine.h"
#include "framework/interpolation/curve_limits.h"
#include "framework/interpolation/limit_selection.h"
#include "framework/interpolation/progressive.h"
#include "framework/io/formats.h"
#include "framework/io/mesh_data.h"
#include "framework/io/mesh_level.h"
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_validate.h"
#include "framework/io/mesh_write.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/plugin/plugin_loader.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_loader.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/scheme/scheme_sequence.h"
#include "framework/stencil/stencil_table.h"
#include "framework/topology/level.h"
#include "framework/util/error.h"
#include "memory_guard.h"  // tools/subdiv: the command line's check that a refinement fits in memory
