#pragma once
// `subdiv interpolate` for polylines: the outputs of a curve scheme's progressive
// interpolation (framework/pipeline/interpolate_request.h runs it): the new control
// polylines, and optionally their refinement with where each limit point ended.
#include <cstdint>
#include <string>
#include <vector>

#include "framework/io/mesh_data.h"
#include "framework/pipeline/interpolate_request.h"
#include "progress.h"

namespace subdiv::cli {

struct CurveInterpolationOutput {
  std::string output, refined;
  int levels = 3;                    // for `refined`
  std::vector<std::uint8_t> moving;  // the request's flags (empty: all)
};

// Refuses, before any work, outputs that cannot hold polylines.
void check_curve_outputs(const std::string& output, const std::string& refined);

// Writes -o and --refined for the interpolation of `mesh`'s polylines.
void write_curve_interpolation(const CurveInterpolationOutput& outputs, const InterpolateResult& result,
                               const MeshData& mesh, Progress& progress);

}  // namespace subdiv::cli
