#pragma once
// "SubdivKit Refine": polygonal input refined with any SubdivKit scheme (a registered one or
// a .json file). Output: the finest level with the input's point and cell arrays refined as
// the library does and SubdivKit's arrays (origin, valence, level, vertex_class,
// parent_face, base_face), as `subdiv refine` writes them; or, with AllLevels, every level
// as a multiblock (block k: level k). SubdivKit's errors go to ParaView's output window
// and leave the output empty.
#include <string>

#include "SubdivKitParaViewFiltersModule.h"
#include "vtkSubdivKitSchemeAlgorithm.h"

namespace subdiv {
namespace paraview {  // (VTK's wrapper tools read this header: no C++17 nested namespaces)
struct RefineSettings;  // refine_job.h
}  // namespace paraview
}  // namespace subdiv

class SUBDIVKITPARAVIEWFILTERS_EXPORT vtkSubdivKitRefine : public vtkSubdivKitSchemeAlgorithm {
public:
  static vtkSubdivKitRefine* New();
  vtkTypeMacro(vtkSubdivKitRefine, vtkSubdivKitSchemeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetClampMacro(Levels, int, 0, 30);
  vtkGetMacro(Levels, int);
  vtkSetClampMacro(BoundaryInterpolation, int, 0, 2);  // 0 edges-and-corners, 1 edges, 2 none
  vtkGetMacro(BoundaryInterpolation, int);
  vtkSetClampMacro(CreaseMethod, int, 0, 1);  // 0 uniform, 1 chaikin
  vtkGetMacro(CreaseMethod, int);
  vtkSetStdStringFromCharMacro(CreaseArray);  // a cell array, or "" / "None"
  vtkGetCharFromStdStringMacro(CreaseArray);
  vtkSetMacro(UseFeatureAngle, bool);
  vtkGetMacro(UseFeatureAngle, bool);
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  vtkSetClampMacro(Threads, int, 0, 1024);  // 0: all cores
  vtkGetMacro(Threads, int);
  vtkSetMacro(LimitPositions, bool);
  vtkGetMacro(LimitPositions, bool);
  vtkSetMacro(AllLevels, bool);
  vtkGetMacro(AllLevels, bool);
  // With AllLevels: level l moved by l x LevelSpacing x the input's diagonal along x (0: in place).
  vtkSetClampMacro(LevelSpacing, double, 0.0, 100.0);
  vtkGetMacro(LevelSpacing, double);

protected:
  vtkSubdivKitRefine();
  ~vtkSubdivKitRefine() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  // The properties as the refinement's options.
  subdiv::paraview::RefineSettings Request() const;

private:
  vtkSubdivKitRefine(const vtkSubdivKitRefine&) = delete;
  void operator=(const vtkSubdivKitRefine&) = delete;

  int Levels = 2;
  int BoundaryInterpolation = 0;
  int CreaseMethod = 0;
  std::string CreaseArray;
  bool UseFeatureAngle = false;
  double FeatureAngle = 30.0;
  int Threads = 0;
  bool LimitPositions = false;
  bool AllLevels = false;
  double LevelSpacing = 0.0;
};
