#pragma once
// The limit surface sampled on a uniform grid per base face, as a crack-free mesh: points
// on a base vertex or a base edge are evaluated once and shared by every face that has
// them, so neighbouring faces meet exactly.
//
// `segments` N: a quad face becomes N x N quads at (i/N, j/N); a triangle (triangle splits)
// N^2 triangles at (i/N, j/N), i + j <= N; another face of a quad split its n sub-faces
// (Bfr's QUAD_SUBFACES) with N/2 x N/2 quads each, so that its edges too have N segments
// (N must then be even).
#include <array>
#include <functional>
#include <span>
#include <string>
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
  // Per face corner: its (u, v) in its face's base face (base_face), so that data that jump
  // across base edges (face-varying seams) are evaluated from the face's own side.
  std::vector<double> corner_uv;

  Index point_count() const { return Index(uv_face.size()); }
  Index face_count() const { return Index(face_offsets.size()) - 1; }
};

// A point of the surface to tessellate, written to `out` (LimitSurface::evaluate_into): its
// position (3 values) and first derivatives (has_derivatives false where they do not exist).
using SurfaceSample = std::function<void(Index face, double u, double v, LimitSample& out)>;

// The unit normal at the point `p` that `sample` just gave at (face, u, v): where its
// derivatives do not exist (an extraordinary vertex, where the parameterisation is
// singular) the limit of the normals of the face's points towards it (sampled a step of
// 1e-9 towards the middle of the face or of its sub-face); (0, 0, 0) where there is none
// (du x dv vanishes, or the scheme gives no derivatives at all; tangents up to `negligible`
// long count as zero, unit_normal.h). `p` may be overwritten.
std::array<double, 3> limit_normal(const LimitSurface& surface, const SurfaceSample& sample, LimitSample& p,
                                   Index face, double u, double v, double negligible = 0);

// The most segments per face edge a front-end may ask for (`subdiv evaluate --samples`,
// Python's tessellate, ParaView's Samples): 1024 already makes a million points per quad.
inline constexpr int kMaxSegments = 1024;
// Why N segments per face edge are refused (the range and the reason for the cap), or empty
// for 1 to kMaxSegments: for the front-ends' own messages.
std::string segments_out_of_range(int N);
// Refuses (OptionError naming {samples}: "{samples} N: " + segments_out_of_range(N)) N
// outside 1 to kMaxSegments.
void check_segments(int N);

// Refuses (OptionError naming {samples}), before any work, a grid of N segments per edge over
// `base` that would not fit in memory with `face_varying_channels` channels sampled on it too
// (sampled_limit_mesh); tessellation_grid checks its own grid alone.
void check_samples_fit(const Level& base, bool triangles, int N, size_t face_varying_channels = 0);

// The advice ending an out-of-memory message while sampling (advising_when_out_of_memory,
// util/memory_limit.h), with the front-ends' spelling of the option.
inline constexpr const char* kFewerSamplesAdvice = "ask for fewer {samples} (segments per face edge)";

// Throws subdiv::Error for N < 1, or an odd N on a mesh with sub-faces.
// `negligible`: the tangent length below which a point has no normal (negligible_tangent of
// the control points, unit_normal.h).
Tessellation tessellate(const LimitSurface& surface, int segments, const SurfaceSample& sample,
                        double negligible = 0);
// The surface of `positions` (the polynomial surface: sample is surface.evaluate).
Tessellation tessellate(const LimitSurface& surface, std::span<const double> positions, int segments);

// What a front-end warns about when some of the unit `normals` (xyz per point) are zero:
// the surface has no normal there (du x dv vanishes where control points coincide or the
// surface folds flat, or the scheme gives no derivatives). How many, and the first one's
// face and (u, v) (`faces`, `uv`: per point). Empty when none is. The normals stay
// (0, 0, 0), which every reader takes (OBJ's vn and our readers refuse NaN) and ParaView
// shades as unlit.
std::string zero_normals_warning(std::span<const double> normals, std::span<const Index> faces,
                                 std::span<const double> uv);

// The grid alone, nothing evaluated (positions and normals empty): its faces, and per
// point the face and (u, v) to evaluate it at. `topology` gives the faces' corners and
// edges: the surface's base level, or a face-varying channel's value mesh (whose faces are
// the base's, corner for corner: the grid's point numbers are then the channel's values,
// shared exactly where the channel is continuous across an edge). `base` gives the holes.
Tessellation tessellation_grid(const Level& topology, const Level& base, bool triangles, int segments);

}  // namespace subdiv
