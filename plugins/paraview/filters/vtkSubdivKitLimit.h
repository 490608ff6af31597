#pragma once
// "SubdivKit Limit": the limit surface of polygonal input under any linear SubdivKit scheme,
// as a mesh: sampled on a uniform grid of Samples x Samples per face (crack-free, with the
// limit normals and the (face, u, v) of every point), or refined adaptively — only around
// extraordinary vertices, creases and irregular faces, up to Adaptive Levels, plus where the
// surface is farther than Tolerance from its faces — with its points on the limit surface.
// The same meshes as `subdiv evaluate --samples N` and `--adaptive L [--limit]`. SubdivKit's
// errors go to ParaView's output window and leave the output empty.
#include <string>

#include "SubdivKitParaViewFiltersModule.h"
#include "vtkSubdivKitSchemeAlgorithm.h"

class SUBDIVKITPARAVIEWFILTERS_EXPORT vtkSubdivKitLimit : public vtkSubdivKitSchemeAlgorithm {
public:
  static vtkSubdivKitLimit* New();
  vtkTypeMacro(vtkSubdivKitLimit, vtkSubdivKitSchemeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetClampMacro(Mode, int, 0, 1);  // 0 samples, 1 adaptive
  vtkGetMacro(Mode, int);
  vtkSetClampMacro(Samples, int, 1, 256);
  vtkGetMacro(Samples, int);
  vtkSetClampMacro(AdaptiveLevels, int, 0, 12);
  vtkGetMacro(AdaptiveLevels, int);
  vtkSetClampMacro(Tolerance, double, 0.0, 1e300);
  vtkGetMacro(Tolerance, double);
  vtkSetMacro(LimitPositions, bool);
  vtkGetMacro(LimitPositions, bool);
  vtkSetClampMacro(Transitions, int, 0, 1);  // 0 polygons, 1 triangles and quads
  vtkGetMacro(Transitions, int);
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

protected:
  vtkSubdivKitLimit();
  ~vtkSubdivKitLimit() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkSubdivKitLimit(const vtkSubdivKitLimit&) = delete;
  void operator=(const vtkSubdivKitLimit&) = delete;
  int Mode = 0;
  int Samples = 4;
  int AdaptiveLevels = 4;
  double Tolerance = 0.0;
  bool LimitPositions = true;
  int Transitions = 0;
  int BoundaryInterpolation = 0;
  int CreaseMethod = 0;
  std::string CreaseArray;
  bool UseFeatureAngle = false;
  double FeatureAngle = 30.0;
  int Threads = 0;
};
