#pragma once
// "SubdivKit Analyze": a source that analyses a surface scheme at extraordinary vertices
// of a range of valences — interior, boundary or crease vertices — as `subdiv analyze` does. Output port 0: the
// characteristic maps as polydata, side by side along x (point arrays valence, ring,
// radius); port 1: the spectrum as a table, one row per valence (valence, lambda_0 ...
// the moduli of the leading eigenvalues, lambda_1 squared, c1, verdict), for a line chart
// of eigenvalue moduli against valence.
#include "SubdivKitParaViewFiltersModule.h"
#include "vtkSubdivKitSchemeAlgorithm.h"

class SUBDIVKITPARAVIEWFILTERS_EXPORT vtkSubdivKitAnalyze : public vtkSubdivKitSchemeAlgorithm {
public:
  static vtkSubdivKitAnalyze* New();
  vtkTypeMacro(vtkSubdivKitAnalyze, vtkSubdivKitSchemeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetVector2Macro(Valences, int);  // first and last valence
  vtkGetVector2Macro(Valences, int);
  vtkSetClampMacro(Eigenvalues, int, 1, 64);  // leading moduli in the table
  vtkGetMacro(Eigenvalues, int);
  vtkSetClampMacro(Vertices, int, 0, 2);  // 0 interior, 1 boundary, 2 crease
  vtkGetMacro(Vertices, int);

protected:
  vtkSubdivKitAnalyze();
  ~vtkSubdivKitAnalyze() override = default;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkSubdivKitAnalyze(const vtkSubdivKitAnalyze&) = delete;
  void operator=(const vtkSubdivKitAnalyze&) = delete;

  int Valences[2] = {3, 12};
  int Eigenvalues = 8;
  int Vertices = 0;
};
