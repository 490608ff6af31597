#include "vtkSubdivKitRefine.h"

#include <exception>

#include <vtkCompositeDataSet.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "framework/io/vtk/polydata_conversion.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"
#include "filter_input.h"
#include "refine_job.h"

namespace {

constexpr const char* kSource = "SubdivKit Refine";

// One level as polydata, checked as write_vtp checks it (array names and lengths).
vtkSmartPointer<vtkPolyData> level_polydata(const subdiv::OutputLevel& level) {
  return subdiv::polydata_from_level(level, kSource);
}

// Level l moved by l * dx along x, so that the levels stand side by side.
void move_along_x(vtkPolyData& level, double dx) {
  vtkPoints* points = level.GetPoints();
  if (!points || dx == 0) return;
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
    double p[3];
    points->GetPoint(i, p);
    p[0] += dx;
    points->SetPoint(i, p);
  }
}

// Block l: level l, named "level l"; `spacing` apart along x.
void set_level_blocks(vtkMultiBlockDataSet& blocks, const subdiv::paraview::RefinedLevels& refined, double spacing) {
  blocks.SetNumberOfBlocks(unsigned(refined.levels.size()));
  for (unsigned l = 0; l < refined.levels.size(); ++l) {
    vtkSmartPointer<vtkPolyData> level = level_polydata(refined.levels[l]);
    move_along_x(*level, l * spacing);
    blocks.SetBlock(l, level);
    blocks.GetMetaData(l)->Set(vtkCompositeDataSet::NAME(), ("level " + std::to_string(l)).c_str());
  }
}

}  // namespace

vtkStandardNewMacro(vtkSubdivKitRefine);

vtkSubdivKitRefine::vtkSubdivKitRefine() : vtkSubdivKitSchemeAlgorithm(kSource) {
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

int vtkSubdivKitRefine::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkSubdivKitRefine::FillOutputPortInformation(int, vtkInformation* info) {
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");  // polydata, or a multiblock of levels
  return 1;
}

int vtkSubdivKitRefine::RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) {
  vtkInformation* info = out->GetInformationObject(0);
  vtkDataObject* current = info->Get(vtkDataObject::DATA_OBJECT());
  const char* wanted = this->AllLevels ? "vtkMultiBlockDataSet" : "vtkPolyData";
  if (current && current->IsA(wanted)) return 1;
  vtkDataObject* made = this->AllLevels ? static_cast<vtkDataObject*>(vtkMultiBlockDataSet::New())
                                        : static_cast<vtkDataObject*>(vtkPolyData::New());
  info->Set(vtkDataObject::DATA_OBJECT(), made);
  made->Delete();
  return 1;
}

subdiv::paraview::RefineSettings vtkSubdivKitRefine::Request() const {
  subdiv::paraview::RefineSettings request;
  request.scheme = this->SchemeToRun();
  request.levels = this->Levels;
  request.parameters = this->ParametersToRun();
  request.features = subdiv::paraview::filter_features(this->BoundaryInterpolation, this->CreaseMethod);
  request.feature_angle = this->UseFeatureAngle ? this->FeatureAngle : -1.0;
  request.threads = this->Threads;
  request.limit = this->LimitPositions;
  return request;
}

int vtkSubdivKitRefine::RequestData(vtkInformation*, vtkInformationVector** in, vtkInformationVector* out) {
  vtkPolyData* input = vtkPolyData::GetData(in[0], 0);
  vtkDataObject* output = vtkDataObject::GetData(out, 0);
  output->Initialize();
  if (!input) return 1;
  try {
    subdiv::paraview::RefineSettings settings = this->Request();
    settings.progress = [this](double done) { this->UpdateProgress(done); };  // ParaView's progress bar
    const subdiv::paraview::RefinedLevels refined =
        subdiv::paraview::refine_levels(subdiv::paraview::filter_input_mesh(*input, this->CreaseArray, kSource),
                                        settings, kSource);
    for (const std::string& note : refined.notes) vtkWarningMacro(<< kSource << ": " << subdiv::terminal_safe(note));
    if (auto* blocks = vtkMultiBlockDataSet::SafeDownCast(output))
      set_level_blocks(*blocks, refined, this->LevelSpacing * input->GetLength());
    else
      output->ShallowCopy(level_polydata(refined.levels.back()));
  } catch (const std::exception& e) {
    // SubdivKit's message, as `subdiv refine` prints it; the output stays empty and the
    // pipeline goes on (returning 0 would also stop the filters downstream with a second message).
    vtkErrorMacro(<< subdiv::terminal_safe(e.what()));  // user text escaped, as the CLI prints it
    output->Initialize();
  }
  return 1;
}

void vtkSubdivKitRefine::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Levels: " << this->Levels << "\n" << indent << "AllLevels: " << this->AllLevels << "\n"
     << indent << "LevelSpacing: " << this->LevelSpacing << "\n";
}
