#pragma once
// The "SubdivKit Analyze" source's two outputs made from its analyses.
#include <vector>

#include <vtkSmartPointer.h>

#include "framework/analysis/surface/surface_analysis.h"

class vtkPolyData;
class vtkTable;

namespace subdiv::paraview {

// Every computed characteristic map in one polydata, side by side along x in valence
// order (each centred on its own centre, z = 0); point arrays "valence", "ring" (face-ring
// distance from the centre) and "radius" (distance from the centre), as `subdiv analyze
// --vtk` writes them one file per valence.
vtkSmartPointer<vtkPolyData> characteristic_maps_polydata(const std::vector<SurfaceAnalysis>& analyses);

// One row per valence: "valence"; "lambda_0" ... "lambda_<shown-1>", the moduli of the
// leading eigenvalues (sorted by modulus, as `subdiv analyze --json` lists them; NaN past
// the last); "lambda_1^2"; "c1" (1 when C1); "verdict".
vtkSmartPointer<vtkTable> spectrum_table(const std::vector<SurfaceAnalysis>& analyses, int shown);

}  // namespace subdiv::paraview
