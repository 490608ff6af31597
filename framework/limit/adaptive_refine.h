#pragma once
// Feature-adaptive refinement (OpenSubdiv's RefineAdaptive; Nießner, Loop, Meyer & DeRose
// 2012, "Feature-adaptive GPU rendering of Catmull-Clark subdivision surfaces"): only the
// faces that touch what is irregular — an extraordinary vertex, a crease, a sharp or
// semi-sharp vertex, a hole, a face of another shape than the split makes — are split, level
// after level up to L; with a tolerance, also every face whose bilinear (linear, for
// triangles) patch through its corners' limit points is farther than the tolerance from the
// limit surface. Regular regions within tolerance stay coarse.
//
// The work is local (adaptive_stage.h): each level refines only the faces to split, a few
// rings around them (so the next level's faces to split have their neighbourhood) and the
// ghost rings the scheme's rules read, so its cost grows with the number of features, not
// with 4^L.
//
// The mesh is watertight: a coarse face next to finer ones takes the finer vertices along
// its edges as corners of its own (a transition polygon), so no edge ends in the middle of
// another (no T-junction) and every interior edge has exactly two faces. A vertex is placed
// where the finest level that computed it puts it (every vertex of uniform level L when all
// faces are split), or on the limit surface with `limit`.
//
// A non-manifold mesh is refined on its own levels, as uniform refinement refines it: its
// non-manifold edges are infinitely sharp and its non-manifold vertices corners (or on a
// non-manifold crease) by the base tags (features/base_tags.h), and they are features, so
// every face around them is split to level L and the fans share their vertices.
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "framework/features/feature_options.h"
#include "framework/topology/level.h"

namespace subdiv {

struct Scheme;
class LimitSurface;
class WeightTableCache;

// A face-varying channel (texture coordinates with seams) to carry through adaptive
// refinement: its value mesh as primvar/face_varying.h builds it (face_varying_value_mesh:
// the base's faces, in the same order, over the values; seams are boundaries; the vertex
// mesh's sharpness and the interpolation mode's corners tagged), refined with the scheme and
// the boundary rule EdgesOnly as uniform face-varying refinement refines it.
struct AdaptiveValueMesh {
  const Level* level = nullptr;
  std::span<const double> values;  // `components` per vertex of `level`
  int components = 1;
  // The modes whose tags are renewed at every level: every value on the value mesh's
  // boundary a corner (OpenSubdiv's linear boundaries), or every value and edge sharp (all).
  bool linear_boundaries = false;
  bool linear_everywhere = false;
};

// A scheme's weight tables kept from one adaptive refinement for the next: each call
// otherwise compiles them once (muParser over the scheme's formulas, about 2 ms, most of a
// small mesh's time). The scheme must outlive it; a call with another scheme is refused.
class AdaptiveTables {
public:
  explicit AdaptiveTables(const Scheme& scheme);
  ~AdaptiveTables();
  AdaptiveTables(const AdaptiveTables&) = delete;
  AdaptiveTables& operator=(const AdaptiveTables&) = delete;

  const Scheme& scheme() const { return *scheme_; }
  WeightTableCache& cache() { return *cache_; }

private:
  const Scheme* scheme_;
  std::unique_ptr<WeightTableCache> cache_;
};

// How a coarse face next to finer ones is written: one polygon with the finer vertices along
// its edges as corners, or tessellated into triangles and quads of the same vertices
// (adaptive_transitions.h), as OpenSubdiv's transition patterns.
enum class AdaptiveTransitions { Polygons, Triangles };

struct AdaptiveOptions {
  int levels = 0;            // the cap L, 0..12
  FeatureOptions features;   // as for refinement
  int first_step = 0;        // steps the input has already been through
  bool limit = false;        // every vertex on the limit surface (needs `surface`)
  // > 0: also split a face (below level L) while the largest distance between its
  // bilinear/linear patch through its corners' limit points and the limit surface, at the
  // 5 x 5 points (i/4, j/4) of the face (15 on a triangle), exceeds it (needs `surface`).
  double tolerance = 0;
  // The caller's tolerance splits every face (the uniform level L, as --level-distance asks):
  // the last stage's size is checked against memory before the first stage is made, not after
  // L - 1 stages.
  bool uniform = false;
  // The exact evaluator of the same scheme, base level and features (limit_surface.h).
  const LimitSurface* surface = nullptr;
  // Weight tables kept between calls with the same scheme, or null (compiled for this call).
  AdaptiveTables* tables = nullptr;
  // Face-varying channels refined with the faces (not moved to the limit by `limit`; the
  // pipeline evaluates their limit itself): AdaptiveMesh::face_varying, in this order.
  std::span<const AdaptiveValueMesh> face_varying;
  AdaptiveTransitions transitions = AdaptiveTransitions::Polygons;
};

// A face-varying channel on the adaptive mesh: each face corner's value is the value its
// face's side has at the corner's vertex (seams stay seams), where the finest level that
// computed that value puts it. Across a seam that can be a coarser level than the vertex's
// position: a vertex is placed by the finest level that computed any face around it, a value
// by the finest that computed a face of its own side.
struct AdaptiveFaceVarying {
  int components = 1;
  std::vector<double> values;    // `components` per value
  std::vector<Index> indices;    // per face corner (face_vertices' order): its value
  std::vector<int> value_level;  // per value: the level it comes from
};

struct AdaptiveMesh {
  std::vector<double> positions;  // xyz per vertex
  // The point arrays carried like the positions (refine_adaptive's `data`): data_channels
  // per vertex, in the order given.
  std::vector<double> data;
  int data_channels = 0;
  std::vector<Index> face_offsets{0}, face_vertices;
  std::vector<int> face_level;    // per face: the level it comes from
  std::vector<Index> base_face;   // per face: the base face it lies in
  // Per face corner (face_vertices' order): its (u, v) in the face's base face (Bfr's
  // parameterisation, face_domain.h), and 1 where it is a corner of the level's face, 0
  // where it is a finer vertex along one of its edges (a transition polygon's, or with
  // AdaptiveTransitions::Triangles one of its triangles' and quads').
  std::vector<std::array<double, 2>> corner_uv;
  std::vector<std::uint8_t> corner_is_face_corner;
  Index uniform_faces = 0;            // faces of the uniform level L, for comparison
  std::vector<Index> split_faces;     // per level < L: faces split for the output
  std::vector<Index> computed_faces;  // per level 1..L: child faces computed (the work)
  std::vector<AdaptiveFaceVarying> face_varying;  // AdaptiveOptions::face_varying's channels
};

// Throws subdiv::Error for a split other than the binary quad and triangle splits, `tables`
// of another scheme, levels outside 0..12, a non-manifold mesh with a face that repeats a
// vertex, a triangle split of a mesh with other faces, and `limit` or `tolerance` without a surface, and a face-varying value mesh whose faces are
// not the base's.
// `data` (data_channels per base vertex): point arrays placed like the positions — refined
// with the same stencils, and with `limit` evaluated on the limit as well.
AdaptiveMesh refine_adaptive(const Scheme& scheme, const Level& base, std::span<const double> positions,
                             const AdaptiveOptions& options, std::span<const double> data = {},
                             int data_channels = 0);

}  // namespace subdiv
