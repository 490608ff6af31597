#pragma once
// The limit surface sampled on a uniform grid per base face, as a crack-free mesh: points
// on a base vertex or a base edge are evaluated once and shared by every face that has
// them, so neighbouring faces meet exactly.
//
// `segments` N: a quad face becomes N x N quads at (i/N, j/N); a triangle (triangle splits)
// N^2 triangles at (i/N, j/N), i + j <= N; another face of a quad split its n sub-faces
// (Bfr's QUAD_SUBFACES) with N/2 x N/2 quads each, so that its edges too have N segments
// (N must then be even).
#include <span>
#include <vector>

#include "framework/limit/limit_surface.h"

namespace subdiv {

struct Tessellation {
  std::vector<double> positions;  // xyz per point
  std::vector<double> normals;    // unit xyz per point (the limit normal du x dv)
  std::vector<Index> face_offsets{0}, face_vertices;
  std::vector<Index> base_face;   // per face of the tessellation
  std::vector<double> uv;         // per point: the (u, v) it was evaluated at in ...
  std::vector<Index> uv_face;     // ... this base face

  Index point_count() const { return Index(positions.size() / 3); }
  Index face_count() const { return Index(face_offsets.size()) - 1; }
};

// Throws subdiv::Error for N < 1, or an odd N on a mesh with sub-faces.
Tessellation tessellate(const LimitSurface& surface, std::span<const double> positions, int segments);

}  // namespace subdiv
