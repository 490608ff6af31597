#include "vtkSubdivKitAnalyze.h"

#include <exception>
#include <fmt/format.h>

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include "analysis_output.h"
#include "analyze_job.h"
#include "scheme_choice.h"
#include "scheme_name_array.h"

namespace {
constexpr const char* kSource = "SubdivKit Analyze";
}

vtkStandardNewMacro(vtkSubdivKitAnalyze);

vtkSubdivKitAnalyze::vtkSubdivKitAnalyze() : SchemeNames(vtkStringArray::New()) {
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
}

vtkSubdivKitAnalyze::~vtkSubdivKitAnalyze() { this->SchemeNames->Delete(); }

vtkStringArray* vtkSubdivKitAnalyze::GetSchemeNames() {
  if (const std::string failed = subdiv::paraview::fill_scheme_names(*this->SchemeNames); !failed.empty())
    vtkErrorMacro(<< kSource << ": listing the schemes: " << failed);
  return this->SchemeNames;
}

int vtkSubdivKitAnalyze::FillOutputPortInformation(int port, vtkInformation* info) {
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkPolyData" : "vtkTable");
  return 1;
}

int vtkSubdivKitAnalyze::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) {
  vtkPolyData* maps = vtkPolyData::GetData(out, 0);
  vtkTable* spectrum = vtkTable::GetData(out, 1);
  maps->Initialize();
  spectrum->Initialize();
  try {
    subdiv::paraview::AnalyzeRequest request;
    request.scheme = subdiv::paraview::chosen_scheme(this->Scheme, this->SchemeFile);
    // The widgets belong to the drop-down's scheme; a scheme file takes the text field only.
    request.parameters =
        (this->SchemeFile.empty() ? this->TypedParameters.words_for(this->Scheme) : "") + this->Parameters;
    request.min_valence = this->Valences[0];
    request.max_valence = this->Valences[1];
    const auto analyses = subdiv::paraview::analyze_valences(request, kSource);
    maps->ShallowCopy(subdiv::paraview::characteristic_maps_polydata(analyses));
    spectrum->ShallowCopy(subdiv::paraview::spectrum_table(analyses, this->Eigenvalues));
  } catch (const std::exception& e) {
    vtkErrorMacro(<< e.what());  // SubdivKit's message; both outputs stay empty
    maps->Initialize();
    spectrum->Initialize();
  }
  return 1;
}

void vtkSubdivKitAnalyze::SetSchemeParameter(const char* key, double value) {
  if (this->TypedParameters.set(key ? key : "", fmt::format("{}", value))) this->Modified();
}

void vtkSubdivKitAnalyze::SetSchemeWholeParameter(const char* key, int value) {
  if (this->TypedParameters.set(key ? key : "", std::to_string(value))) this->Modified();
}

void vtkSubdivKitAnalyze::SetSchemeChoice(const char* key, const char* value) {
  if (this->TypedParameters.set(key ? key : "", value ? value : "")) this->Modified();
}

void vtkSubdivKitAnalyze::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scheme: " << this->Scheme << "\n" << indent << "SchemeFile: " << this->SchemeFile << "\n"
     << indent << "Valences: " << this->Valences[0] << ".." << this->Valences[1] << "\n";
}
