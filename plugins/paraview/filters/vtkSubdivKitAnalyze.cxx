#include "vtkSubdivKitAnalyze.h"

#include <exception>

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkTable.h>

#include "analysis_output.h"
#include "analyze_job.h"
#include "framework/util/quoted_text.h"

vtkStandardNewMacro(vtkSubdivKitAnalyze);

vtkSubdivKitAnalyze::vtkSubdivKitAnalyze() : vtkSubdivKitSchemeAlgorithm("SubdivKit Analyze") {
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
}

int vtkSubdivKitAnalyze::FillOutputPortInformation(int port, vtkInformation* info) {
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkPolyData" : "vtkTable");
  return 1;
}

// A source: the outputs' types are fixed (vtkDataObjectAlgorithm's default copies the input's).
int vtkSubdivKitAnalyze::RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) {
  for (int port = 0; port < 2; ++port) {
    vtkInformation* info = out->GetInformationObject(port);
    if (info->Get(vtkDataObject::DATA_OBJECT())) continue;
    vtkDataObject* made = port == 0 ? static_cast<vtkDataObject*>(vtkPolyData::New())
                                    : static_cast<vtkDataObject*>(vtkTable::New());
    info->Set(vtkDataObject::DATA_OBJECT(), made);
    made->Delete();
  }
  return 1;
}

int vtkSubdivKitAnalyze::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) {
  vtkPolyData* maps = vtkPolyData::GetData(out, 0);
  vtkTable* spectrum = vtkTable::GetData(out, 1);
  maps->Initialize();
  spectrum->Initialize();
  try {
    subdiv::paraview::AnalyzeRequest request;
    request.scheme = this->SchemeToRun();
    request.parameters = this->ParametersToRun();
    request.min_valence = this->Valences[0];
    request.max_valence = this->Valences[1];
    request.vertices = static_cast<subdiv::paraview::AnalysedVertices>(this->Vertices);
    const auto analyses = subdiv::paraview::analyze_valences(request, this->Label);
    maps->ShallowCopy(subdiv::paraview::characteristic_maps_polydata(analyses));
    spectrum->ShallowCopy(subdiv::paraview::spectrum_table(analyses, this->Eigenvalues));
  } catch (const std::exception& e) {
    vtkErrorMacro(<< subdiv::terminal_safe(e.what()));  // SubdivKit's message, escaped; both outputs stay empty
    maps->Initialize();
    spectrum->Initialize();
  }
  return 1;
}

void vtkSubdivKitAnalyze::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Valences: " << this->Valences[0] << ".." << this->Valences[1] << "\n"
     << indent << "Eigenvalues: " << this->Eigenvalues << "\n"
     << indent << "Vertices: " << (this->Vertices == 0 ? "interior" : this->Vertices == 1 ? "boundary" : "crease")
     << "\n";
}
