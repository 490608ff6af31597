#include "vtkSubdivKitLimit.h"

#include <exception>

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include "filter_input.h"
#include "framework/io/vtk/polydata_conversion.h"
#include "framework/pipeline/level_description.h"
#include "framework/util/quoted_text.h"
#include "limit_job.h"

namespace {

constexpr const char* kSource = "SubdivKit Limit";

}  // namespace

vtkStandardNewMacro(vtkSubdivKitLimit);

vtkSubdivKitLimit::vtkSubdivKitLimit() : vtkSubdivKitSchemeAlgorithm(kSource) {
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

int vtkSubdivKitLimit::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkSubdivKitLimit::FillOutputPortInformation(int, vtkInformation* info) {
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkPolyData");
  return 1;
}

int vtkSubdivKitLimit::RequestData(vtkInformation*, vtkInformationVector** in, vtkInformationVector* out) {
  vtkPolyData* input = vtkPolyData::GetData(in[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(out, 0);
  output->Initialize();
  if (!input) return 1;
  try {
    subdiv::paraview::LimitSettings settings;
    settings.scheme = this->SchemeToRun();
    settings.parameters = this->ParametersToRun();
    settings.features = subdiv::paraview::filter_features(this->BoundaryInterpolation, this->CreaseMethod);
    settings.feature_angle = this->UseFeatureAngle ? this->FeatureAngle : -1.0;
    settings.threads = this->Threads;
    settings.mode = this->Mode == 1 ? subdiv::paraview::LimitMode::Adaptive : subdiv::paraview::LimitMode::Samples;
    settings.samples = this->Samples;
    settings.adaptive_levels = this->AdaptiveLevels;
    settings.tolerance = this->Tolerance;
    settings.limit_positions = this->LimitPositions;
    settings.triangle_transitions = this->Transitions == 1;
    subdiv::paraview::LimitMesh limit = subdiv::paraview::limit_mesh(
        subdiv::paraview::filter_input_mesh(*input, this->CreaseArray, kSource), settings, kSource);
    for (const std::string& note : limit.notes) vtkWarningMacro(<< kSource << ": " << subdiv::terminal_safe(note));
    const subdiv::OutputLevel level = subdiv::output_level(limit.mesh, 0);
    output->ShallowCopy(subdiv::polydata_from_level(level, kSource));
  } catch (const std::exception& e) {
    // SubdivKit's message, as `subdiv evaluate` prints it; the output stays empty and the
    // pipeline goes on, as "SubdivKit Refine" does.
    vtkErrorMacro(<< subdiv::terminal_safe(e.what()));  // user text escaped, as the CLI prints it
    output->Initialize();
  }
  return 1;
}

void vtkSubdivKitLimit::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->Mode << "\n"
     << indent << "Samples: " << this->Samples << "\n"
     << indent << "AdaptiveLevels: " << this->AdaptiveLevels << "\n"
     << indent << "Tolerance: " << this->Tolerance << "\n"
     << indent << "Transitions: " << this->Transitions << "\n";
}
