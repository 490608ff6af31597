#pragma once
// Limit positions and limit normals of every vertex of a mesh level, for any linear scheme.
//
// The masks come from the surface analysis (surface_analysis.h): the left eigenvector of 1
// gives the limit position, the left eigenvectors of the subdominant pair give two tangents
// (Halstead, Kass & DeRose 1993), the normal is their cross product. They are computed
// once per configuration (valence, boundary, crease positions, level parity where the scheme
// alternates) on a synthetic patch and cached.
//
// A vertex uses a cached mask only when its neighbourhood is the synthetic one, compared
// exactly up to the radius the mask depends on (valences, face sizes, boundary, sharpness).
// Otherwise (two extraordinary vertices close together, a triangle in a Catmull-Clark
// control mesh, a semi-sharp crease, a corner nearby) its neighbourhood is cut out and
// refined until it is in a known configuration, and the mask of that configuration is
// applied to the refined points, which is exact because the limit of a vertex is the limit
// of its child. Dual schemes (Doo-Sabin, mid-edge) have no vertex that maps to a vertex:
// a vertex's limit is the limit point of the face it becomes (its V-face), an n-gon whose
// refinements converge to one point.
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "framework/analysis/surface/local_patch.h"
#include "framework/features/feature_context.h"
#include "framework/stencil/stencil_table.h"

namespace subdiv {

struct Scheme;

struct LimitOptions {
  FeatureOptions features;  // boundary interpolation and crease method, as in OpenSubdiv
  int first_step = 0;  // how many steps made the level (sqrt3's alternation, formulas' l)
  int max_steps = 12;  // refinements tried before a vertex is given an approximation
};

// A limit mask for one configuration, over the canonical labels of the neighbourhood
// (local_patch.h), and the signature of the neighbourhood it is valid for.
struct LimitMask {
  bool ok = false;
  std::string error;    // no mask: the analysis's verdict in words (SurfaceAnalysis::verdict)
  std::string failure;  // no mask because the scheme fails a condition there (Verdict::Fails): which
  CentreKind centre = CentreKind::Vertex;
  int radius = 0;                   // labelling radius of the signature
  std::vector<double> signature;
  std::vector<double> position;     // sums to 1
  // Directions towards the ring neighbours (SurfaceAnalysis::direction_masks); the normal
  // is the sum of the sector normals. Empty: no tangent plane was found.
  std::vector<std::vector<double>> directions;
  std::vector<double> direction_eigenvalues;  // SurfaceAnalysis::direction_eigenvalues
  bool cyclic = true;
  // Second-derivative masks (SurfaceAnalysis::quadratic_masks), valid where the neighbourhood
  // matches `quadratic_signature` up to `quadratic_radius`; empty where the analysis has none.
  std::vector<std::vector<double>> quadratic;
  int quadratic_radius = 0;
  std::vector<double> quadratic_signature;
};

struct LimitResult {
  std::vector<double> positions;  // xyz per vertex
  std::vector<double> normals;    // unit xyz per vertex (0 where none exists)
  std::vector<std::uint8_t> exact;         // 1: the position is exact; 0: approximated
  std::vector<std::uint8_t> normal_exact;  // 1: the normal comes from exact tangent masks
  int configurations = 0;         // masks computed
  int refined_vertices = 0;       // vertices whose neighbourhood was refined first
  int approximate = 0;            // positions approximated
  int approximate_normals = 0;    // exact positions whose normal is estimated from nearby limit points
  std::vector<std::string> approximate_reasons;  // distinct reasons, for messages
};

// The limit points as a linear operator: row v is vertex v's limit point over the level's
// control points (progressive interpolation iterates with it).
struct LimitStencils {
  StencilTable position;
  std::vector<std::uint8_t> exact;  // 1: row v is the exact limit mask
  int approximate = 0;              // rows that are approximations
  Index first_approximate = kNone;  // the lowest such vertex, and why
  std::string first_reason;
};

// The limits of one scheme on any mesh level; masks are cached across levels and calls.
class SchemeLimits {
public:
  explicit SchemeLimits(const Scheme& scheme, const LimitOptions& options = {});
  ~SchemeLimits();

  LimitResult evaluate(const Level& level, std::span<const double> positions);
  // The limits of a rational surface: `positions` are the homogeneous points' first three
  // coordinates (w·p) and `weights` their w. The limit is projected after the linear masks,
  // P = X/W, and each tangent by the quotient rule, (D X - P D W)/W (pipeline/rational_weights.h).
  LimitResult evaluate(const Level& level, std::span<const double> positions, std::span<const double> weights);
  LimitStencils stencils(const Level& level);            // the level made by options.first_step steps
  LimitStencils stencils(const Level& level, int step);  // ... by `step` steps

  // The mask of a configuration (cached). For dual schemes a vertex configuration's mask
  // is that of its V-face, written over the vertex's own neighbourhood.
  std::shared_ptr<const LimitMask> mask(const LocalConfig& config);

  // Why the limit has no derivatives or normals where the mesh is regular, or empty: the
  // regular interior configuration's subdominant eigenvalues against the parameters' scale
  // (eigenvalues_off_scale; valence 4 or 6, or a face of 4 or 3 for a dual scheme).
  std::string regular_not_c1();

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

LimitResult limit_positions(const Scheme& scheme, const Level& level, std::span<const double> positions,
                            const LimitOptions& options = {});

// Near a regular vertex the parameters contract by `scale` per analysed step
// (analysis_parameter_scale) and the limit by the subdominant eigenvalues (Reif 1995, "A
// unified approach to subdivision algorithms near extraordinary vertices"): the limit is
// differentiable there only when they equal it. Otherwise a difference quotient grows or
// decays like (eigenvalue / scale)^k, and tangent masks give a finite number that is no
// derivative. Says "its subdominant eigenvalues are 0.569161, 0.5, where a surface
// differentiable in the face's parameters needs 0.5 (...)", or empty when each equals `scale`
// (or there are none, or scale <= 0).
std::string eigenvalues_off_scale(const std::vector<double>& eigenvalues, double scale);

// True when a weight formula of the scheme (or its curve scheme) uses the level l.
bool scheme_is_level_dependent(const Scheme& scheme);

}  // namespace subdiv
