#pragma once
// The points `subdiv evaluate --at POINTS.csv` evaluates: the header `face,u,v` (any case,
// names and fields possibly in double quotes, as spreadsheets and R write them), then one
// point per row, each checked by the caller (LimitSurface::check: the face exists, (u, v)
// lies in its parameter domain) before anything is evaluated, so a bad row stops the
// command with its line. Parsed from text, so that a fuzzer can drive it without files.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

struct SurfacePoints {
  std::vector<Index> faces;
  std::vector<double> uv;  // u, v per point
  size_t size() const { return faces.size(); }
};

// Why (face, u, v) cannot be evaluated; empty when it can.
using PointCheck = std::function<std::string(Index face, double u, double v)>;

// Throws subdiv::Error naming `file`, the line and the row: a missing or wrong header, a
// row without three fields, a face that is not a whole number, a u or v that is not a
// number, a point `check` refuses, or no point at all.
SurfacePoints parse_points(std::string_view text, const std::string& file, const PointCheck& check);

// The same, read line by line from `file`; refused naming the file when it cannot be read
// or is no regular file (check_input_file: a FIFO, a device, a directory). `fraction`, when
// given, is told the share of the file read (0 to 1) now and then, for a front-end's bar.
SurfacePoints read_points_file(const std::string& file, const PointCheck& check,
                               const std::function<void(double done)>& fraction = {});

}  // namespace subdiv
