#pragma once
// What both SubdivKit filters share: the scheme they run (the drop-down of registered
// schemes, a .json file, the typed widgets of the built-in schemes' parameters and the
// Parameters text field) and the list the drop-down shows. Not a filter by itself.
#include <string>

#include "SubdivKitParaViewFiltersModule.h"
#include "typed_parameters.h"
#include "vtkDataObjectAlgorithm.h"

class vtkStringArray;

class SUBDIVKITPARAVIEWFILTERS_EXPORT vtkSubdivKitSchemeAlgorithm : public vtkDataObjectAlgorithm {
public:
  vtkTypeMacro(vtkSubdivKitSchemeAlgorithm, vtkDataObjectAlgorithm);
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

  // Every registered surface scheme, for the Scheme drop-down.
  vtkStringArray* GetSchemeNames();

protected:
  explicit vtkSubdivKitSchemeAlgorithm(const char* label);
  ~vtkSubdivKitSchemeAlgorithm() override;

  // The name or path to run, and its parameters as "name=value ..." words: the widgets'
  // (for a scheme from the drop-down), then the text field's, which win.
  std::string SchemeToRun() const;
  std::string ParametersToRun() const;
  const char* Label;  // "SubdivKit Refine": names the filter in messages

private:
  vtkSubdivKitSchemeAlgorithm(const vtkSubdivKitSchemeAlgorithm&) = delete;
  void operator=(const vtkSubdivKitSchemeAlgorithm&) = delete;

  std::string Scheme = "catmull-clark";
  std::string SchemeFile;
  std::string Parameters;
  subdiv::paraview::TypedParameters TypedParameters;
  vtkStringArray* SchemeNames;
};
