#pragma once
// OpenSubdiv's regression shapes (tests/data/osd-shapes) as far_regression sets them up
// (regression/common/far_utils.h, GetSdcOptions), for the tests of this folder.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "framework/io/mesh_data.h"
#include "unit/topology/osd_compare.h"

namespace subdiv::nonmanifold_test {

inline const std::filesystem::path kShapes = std::filesystem::path(SUBDIV_SOURCE_DIR) / "tests/data/osd-shapes";

inline std::vector<std::filesystem::path> shape_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(kShapes))
    if (entry.path().extension() == ".obj") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// The scheme far_regression gives a shape: the prefix of its name.
inline std::string scheme_of(const std::string& shape) {
  if (shape.starts_with("loop_")) return "loop";
  if (shape.starts_with("bilinear_")) return "bilinear";
  return "catmull-clark";
}

// GetSdcOptions: the tags, else edges only and uniform creases.
inline Setup setup_of(const MeshOptions& tags) {
  Setup s{BoundaryInterpolation::EdgesOnly, CreaseMethod::Uniform};
  if (tags.interpolate_boundary)
    s.boundary = *tags.interpolate_boundary == 0   ? BoundaryInterpolation::None
                 : *tags.interpolate_boundary == 1 ? BoundaryInterpolation::EdgesAndCorners
                                                   : BoundaryInterpolation::EdgesOnly;
  if (tags.crease_method == "chaikin") s.method = CreaseMethod::Chaikin;
  return s;
}

}  // namespace subdiv::nonmanifold_test
