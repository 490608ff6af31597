#include "vtkSubdivKitSchemeAlgorithm.h"

#include <exception>
#include <fmt/format.h>

#include <vtkStringArray.h>

#include "scheme_choice.h"
#include "framework/util/quoted_text.h"

vtkSubdivKitSchemeAlgorithm::vtkSubdivKitSchemeAlgorithm(const char* label)
    : Label(label), SchemeNames(vtkStringArray::New()) {}

vtkSubdivKitSchemeAlgorithm::~vtkSubdivKitSchemeAlgorithm() { this->SchemeNames->Delete(); }

vtkStringArray* vtkSubdivKitSchemeAlgorithm::GetSchemeNames() {
  this->SchemeNames->Initialize();
  try {
    for (const std::string& name : subdiv::paraview::surface_scheme_names()) this->SchemeNames->InsertNextValue(name);
  } catch (const std::exception& e) {  // a scheme folder that cannot be read
    vtkErrorMacro(<< this->Label << ": listing the schemes: " << subdiv::terminal_safe(e.what()));
  }
  return this->SchemeNames;
}

void vtkSubdivKitSchemeAlgorithm::SetSchemeParameter(const char* key, double value) {
  if (this->TypedParameters.set(key ? key : "", fmt::format("{}", value))) this->Modified();
}

void vtkSubdivKitSchemeAlgorithm::SetSchemeWholeParameter(const char* key, int value) {
  if (this->TypedParameters.set(key ? key : "", std::to_string(value))) this->Modified();
}

void vtkSubdivKitSchemeAlgorithm::SetSchemeChoice(const char* key, const char* value) {
  if (this->TypedParameters.set(key ? key : "", value ? value : "")) this->Modified();
}

std::string vtkSubdivKitSchemeAlgorithm::SchemeToRun() const {
  return subdiv::paraview::chosen_scheme(this->Scheme, this->SchemeFile);
}

std::string vtkSubdivKitSchemeAlgorithm::ParametersToRun() const {
  // The widgets belong to the drop-down's scheme; a scheme file takes the text field only.
  return (this->SchemeFile.empty() ? this->TypedParameters.words_for(this->Scheme, this->Parameters) : "") +
         this->Parameters;
}

void vtkSubdivKitSchemeAlgorithm::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scheme: " << this->Scheme << "\n"
     << indent << "SchemeFile: " << this->SchemeFile << "\n"
     << indent << "Parameters: " << this->Parameters << "\n";
}
