#pragma once
// "SubdivKit Analyze": a source that analyses a surface scheme at interior extraordinary
// vertices of a range of valences, as `subdiv analyze` does. Output port 0: the
// characteristic maps as polydata, side by side along x (point arrays valence, ring,
// radius); port 1: the spectrum as a table, one row per valence (valence, lambda_0 ...
// the moduli of the leading eigenvalues, lambda_1 squared, c1, verdict), for a line chart
// of eigenvalue moduli against valence.
#include <string>

#include "SubdivKitParaViewFiltersModule.h"
#include "typed_parameters.h"
#include "vtkPolyDataAlgorithm.h"

class vtkStringArray;

class SUBDIVKITPARAVIEWFILTERS_EXPORT vtkSubdivKitAnalyze : public vtkPolyDataAlgorithm {
public:
  static vtkSubdivKitAnalyze* New();
  vtkTypeMacro(vtkSubdivKitAnalyze, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetStdStringFromCharMacro(Scheme);
  vtkGetCharFromStdStringMacro(Scheme);
  vtkSetStdStringFromCharMacro(SchemeFile);  // a .json scheme; wins over Scheme when set
  vtkGetCharFromStdStringMacro(SchemeFile);
  vtkSetStdStringFromCharMacro(Parameters);  // "name=value ...", as --param; wins over the widgets'
  vtkGetCharFromStdStringMacro(Parameters);
  // The typed widgets of the built-in schemes' parameters; key "scheme:name".
  void SetSchemeParameter(const char* key, double value);
  void SetSchemeWholeParameter(const char* key, int value);
  void SetSchemeChoice(const char* key, const char* value);
  vtkSetVector2Macro(Valences, int);         // first and last valence
  vtkGetVector2Macro(Valences, int);
  vtkSetClampMacro(Eigenvalues, int, 1, 64);  // leading moduli in the table
  vtkGetMacro(Eigenvalues, int);

  vtkStringArray* GetSchemeNames();  // for the Scheme drop-down

protected:
  vtkSubdivKitAnalyze();
  ~vtkSubdivKitAnalyze() override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkSubdivKitAnalyze(const vtkSubdivKitAnalyze&) = delete;
  void operator=(const vtkSubdivKitAnalyze&) = delete;

  std::string Scheme = "catmull-clark";
  std::string SchemeFile;
  std::string Parameters;
  subdiv::paraview::TypedParameters TypedParameters;
  int Valences[2] = {3, 12};
  int Eigenvalues = 8;
  vtkStringArray* SchemeNames;
};
