#pragma once
// Eigen-analysis of a surface scheme at an extraordinary vertex (or face, for dual
// schemes), done with the engine itself (Doo & Sabin 1978; Halstead, Kass & DeRose 1993; Reif 1995):
//
// 1. a synthetic patch around the centre (local_patch.h) is refined by the scheme's own
//    stencils, one step, or two for schemes whose step rotates the mesh (sqrt(3), mid-edge:
//    the second step undoes the rotation, Kobbelt 2000's R S^2);
// 2. the refined centre and its first ring neighbour are matched to the parent's by
//    position (the patch is symmetric), both neighbourhoods are labelled canonically, and
//    the k-ring that maps to itself is found from the stencils' supports: the minimal one
//    (k0; it carries the limit and tangent masks) and the next one (K), which also sees the
//    surface around the centre and is the one analysed, as in the curve case;
// 3. S (rows: children, columns: parents, in matching label order) is analysed with Eigen:
//    spectrum sorted by modulus; lambda_0 = 1 simple; lambda_1 = lambda_2 real, with two
//    eigenvectors, |lambda_3| < lambda_1; Peters & Reif 2004's condition on lambda_1^2 against
//    |lambda_3|; limit mask (left eigenvector of 1) and tangent masks (left eigenvectors of
//    lambda_1, lambda_2), Halstead, Kass & DeRose 1993;
// 4. the characteristic map (control points from the right eigenvectors of lambda_1,
//    lambda_2, refined a few levels) is checked to be regular (every face keeps its
//    orientation) and injective (the boundary of the region winds once around the centre).
#include <complex>
#include <string>
#include <vector>

#include "framework/analysis/surface/local_patch.h"
#include "framework/io/mesh_data.h"
#include "framework/features/feature_context.h"

namespace subdiv {

struct Scheme;

// The largest k-ring analyse_configuration grows max_ring to (subdiv analyze --max-ring's limit).
constexpr int kLargestAutomaticRing = 8;

struct SurfaceAnalysisOptions {
  FeatureOptions features;  // boundary interpolation and crease method, as in OpenSubdiv
  // Largest k-ring tried as invariant neighbourhood. analyse_configuration tries larger
  // ones, up to kLargestAutomaticRing, where none within it maps to itself but the
  // neighbourhood repeats: the stencils reach further (an even-degree quad B-spline's crease
  // of d = 12 needs the 6-ring).
  int max_ring = 5;
  int patch_rings = 0;                // rings of the synthetic patch; 0: max_ring + 3
  bool characteristic_map = true;     // compute and check it
  double characteristic_scale = 8.0;  // refine until the mesh is this much finer
  // Valences above this, at a centre whose neighbourhood is n equal sectors (interior, no
  // crease, no tag), have their eigen-structure computed from the sector rotation's Fourier
  // blocks (rotation_blocks.h; checked to commute with S, else the dense matrix is used):
  // n blocks of a sector's size instead of one dense matrix of n sectors.
  int fourier_above = 64;
};

struct CharacteristicMap {
  bool computed = false;
  std::string note;               // why it was not computed, or remarks
  bool regular = false;           // every face of the refined map has positive area
  bool injective = false;         // regular, and the boundary winds once around the centre
  bool winding_checked = false;   // interior centres only (a boundary centre lies on the rim)
  int winding = 0;
  int faces = 0, folded = 0;
  double min_area_ratio = 0;      // smallest signed area / mean area
  int refinement_steps = 0;
  MeshData mesh;                  // the refined map, z = 0, faces around the centre
  std::vector<double> ring;       // per point: face-ring distance from the centre
};

// The analysis's judgement, for code to act on; `SurfaceAnalysis::verdict` says it in words.
enum class Verdict {
  C1,          // every condition holds: C1 at the centre
  Unchecked,   // the eigenvalue conditions hold, the characteristic map was not checked
  Fails,       // the scheme fails a condition there (or the analysis could not run): `failure` says which
};

struct SurfaceAnalysis {
  std::string scheme, path;
  LocalConfig config;
  int steps = 1;                  // refinement steps per analysed step (2: R S^2)
  std::string error;              // the analysis could not run: why (rules fail, no invariant ring)
  bool stencils_reach_further = false;  // no k-ring maps to itself, but each has as many points as its child
  int max_ring = 0;               // the largest k-ring tried (options.max_ring, or grown)

  int minimal_ring = -1, ring = -1;   // k0 and K
  int minimal_size = 0, size = 0;     // their numbers of points
  std::vector<std::vector<double>> matrix;   // S on the K-ring, label order
  std::vector<int> distance;                 // label -> ring distance
  std::vector<Index> label_vertices;         // label -> vertex of the analysed patch
  std::vector<std::complex<double>> eigenvalues;          // of S, sorted by modulus
  std::vector<std::complex<double>> minimal_eigenvalues;  // on the k0-ring
  // A crease judged by its sides: the spectrum of S on the crease points, sorted by modulus,
  // when their rows read crease points only (the crease curve's own local matrix); else empty.
  std::vector<std::complex<double>> crease_eigenvalues;

  bool affine = false;                 // every row sums to 1
  double max_row_error = 0;
  bool lambda0_one = false;            // lambda_0 = 1, simple
  bool subdominant_real = false;       // lambda_1, lambda_2 real and positive
  bool subdominant_equal = false;      // lambda_1 = lambda_2
  bool subdominant_semisimple = false; // two independent eigenvectors
  bool subdominant_dominates = false;  // |lambda_3| < lambda_2
  int subdominant_multiplicity = 0;    // of lambda_1 (1 when lambda_1 != lambda_2)
  bool boundary_collapses = false;     // boundary centre: the subdominant pair misses the boundary curve
  double lambda1 = 0, lambda2 = 0, lambda3 = 0;  // lambda_1, lambda_2 (real parts), |lambda_3|
  std::string curvature;               // Peters & Reif 2004 case, as text

  CharacteristicMap characteristic_map;
  bool c1 = false;
  Verdict outcome = Verdict::Fails;
  std::string failure;                 // Fails: which condition, "lambda_1 != lambda_2 (...)"; else empty
  std::string verdict;                 // "C1 at valence 5", "fails: " + failure

  // Masks over labels 0 .. mask size - 1 (the labelled patch vertices, see label_vertices).
  bool has_limit_mask = false, has_tangent_masks = false;
  std::vector<double> limit_mask;          // sums to 1
  std::vector<double> tangent_u, tangent_v;  // the limit normal is (t_u . P) x (t_v . P)
  // For each ring neighbour of the centre in ring order from the start (each corner of a
  // face centre): the direction its descendants approach the limit point from, d . P. The
  // limit normal is the sum of d_q x d_{q+1} over the sectors (cyclic unless the centre is
  // on a boundary); at creases and corners each sector has its own tangent plane and the sum
  // averages them. Empty when the subdominant eigenspace is not real, semi-simple and
  // strictly dominant.
  std::vector<std::vector<double>> direction_masks;
  bool directions_cyclic = true;
  int tangent_dimension = 0;  // dimension of that eigenspace: 2 where smooth, 3 on a crease...
  // The eigenvalues of the direction masks, one per cluster they span, largest first.
  std::vector<double> direction_eigenvalues;
  // A basis of the left eigenspace of lambda_1^2 where lambda_1 = lambda_2 and lambda_1^2 is a
  // triple, semi-simple eigenvalue strictly above the rest (Peters & Reif 2004's case where
  // the curvature can be continuous): where the scheme generates quadratics, each mask applied
  // to P is a combination of the limit's second derivatives at the centre, and
  // limit/corner_limit.h normalises them by sampled quadratics. Empty otherwise. Over labels
  // like the other masks, trimmed to whole rings of their own.
  std::vector<std::vector<double>> quadratic_masks;

};

// Vertex for primal splits (quad, triangle, sqrt3), Face for dual ones (dual, mid-edge).
CentreKind analysis_centre(const Scheme& scheme);
// Quads unless the scheme refines triangles.
PatchCells analysis_cells(const Scheme& scheme);
// The split's period: 2 for splits that rotate the mesh (sqrt3, mid-edge), else 1.
int analysis_steps(const Scheme& scheme);
// How much the parameters around a fixed point contract per analysed step: scale^-period
// (1/2 for binary splits, 1/3 for the double sqrt3 step). The subdominant eigenvalues of a
// regular vertex must equal it for the limit to be differentiable in the face's parameters.
double analysis_parameter_scale(const Scheme& scheme);

// Analyses the scheme on a given patch (centre and start set in the patch).
SurfaceAnalysis analyse_patch(const Scheme& scheme, const Patch& patch, const LocalConfig& config,
                              const SurfaceAnalysisOptions& options = {});

// Builds the synthetic patch for the configuration (vertex or face centred as the
// configuration says) and analyses it. Never throws for a failing scheme: the reason is
// in `error` and `verdict`.
SurfaceAnalysis analyse_configuration(const Scheme& scheme, const LocalConfig& config,
                                      const SurfaceAnalysisOptions& options = {});

// The usual question: interior valence n (a vertex, or an n-gon face for dual schemes).
SurfaceAnalysis analyse_valence(const Scheme& scheme, int n, const SurfaceAnalysisOptions& options = {});

}  // namespace subdiv
