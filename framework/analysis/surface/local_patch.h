#pragma once
// Local neighbourhoods for the surface analysis: synthetic patches around one vertex of
// valence n (or one n-gon face) with everything else regular, a canonical labelling of the
// vertices around a centre that depends on the combinatorics only (so that a parent patch
// and its refinement, or a synthetic patch and a real mesh, are labelled alike), and the
// extraction of a real mesh's neighbourhood as a small stand-alone level.
#include <compare>
#include <span>
#include <string>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

// What the analysis is centred on: a vertex (primal schemes, sqrt3) or a face (dual
// schemes: Doo-Sabin, mid-edge, whose invariant structures are faces).
enum class CentreKind : std::uint8_t { Vertex, Face };

// The cells of a synthetic patch: quads (quad and dual splits), triangles (triangle and
// sqrt3 splits).
enum class PatchCells : std::uint8_t { Quads, Triangles };

// The combinatorial situation at the centre. Everything else in a synthetic patch is
// regular: valence 4 (quads) or 6 (triangles), a straight boundary, straight creases.
struct LocalConfig {
  CentreKind centre = CentreKind::Vertex;
  int valence = 4;         // ring edges of the centre vertex, or the size of the centre face
  bool boundary = false;   // the centre vertex lies on a boundary (valence - 1 faces)
  std::vector<int> sharp;  // ring positions of infinitely sharp interior edges (creases)
  bool corner = false;     // the centre vertex is tagged infinitely sharp
  int first_step = 0;      // the level the next step refines (sqrt3 parity, formulas' l)

  auto operator<=>(const LocalConfig&) const = default;
  std::string describe() const;  // "valence 5", "boundary valence 3", "crease valence 4 (0, 2)"...
};

// A level with planar positions and a marked centre.
struct Patch {
  Level level;
  std::vector<double> xy;  // 2 per vertex
  CentreKind centre_kind = CentreKind::Vertex;
  Index centre = 0;        // vertex, or face
  int start = 0;           // ring edge (vertex centre) or corner (face centre) labelled first
};

// Valences a synthetic patch is built for. The local matrix grows as n (6n + 1 rows for a
// quad vertex's 2-ring) and its eigenvalues of frequencies 1 and 2 draw together as
// cos(2 pi/n) does cos(4 pi/n): at Catmull-Clark's valence 1024 they are 7.6e-6 apart
// (relative), below the analysis' tolerance for equal eigenvalues (1e-5, surface_analysis.cpp),
// at 512 3e-5.
inline constexpr int kMaxPatchValence = 512;
// Above this valence only a centre of n equal sectors (interior, no crease, no tag) is
// analysed, its matrix split by the sector rotation (rotation_blocks.h); any other would
// need a dense eigen-decomposition of a few thousand rows (minutes).
inline constexpr int kMaxDenseValence = 64;

// Synthetic patch for a vertex configuration: n sectors of a regular grid around the
// centre, `rings` rings deep, positions a u_s + b u_{s+1} on rays u_s at equal angles
// (2 pi/n inside; spread over at most pi on a boundary). Crease rays are tagged infinitely
// sharp all the way out, the centre too when config.corner.
Patch make_vertex_patch(PatchCells cells, const LocalConfig& config, int rings);

// Synthetic patch for an n-gon face surrounded by quads, all other vertices of valence 4:
// the dual of the quad vertex patch of valence n. Positions are the primal face centroids.
Patch make_face_patch(int n, int rings);

// The canonical labelling of the vertices around a centre. Breadth-first over the
// "shares a face" relation: the centre vertex is label 0 (a face centre: its corners from
// `start` are labels 0..n-1), each vertex's faces are scanned CCW starting with the face
// it was reached through, each face's corners CCW after the vertex. The distance is the
// face-ring distance: 1 for every vertex of a face touching the centre, and so on; for a
// face centre, 0 for its own corners.
struct Labelling {
  std::vector<Index> vertices;   // label -> vertex
  std::vector<int> distance;     // label -> face-ring distance from the centre
  std::vector<Index> label_of;   // vertex -> label, or kNone beyond the radius
  std::vector<double> signature; // the combinatorics and tags within the radius (see .cpp)
  std::vector<int> entry;        // workspace: per label, the ring face its scan starts with
  // Workspace of the grid check (quad_grid_labelled): faces met, marked per face of the level.
  std::vector<char> face_met;
  std::vector<Index> faces_met;

  int count_within(int k) const;  // labels at distance <= k (labels are sorted by distance)
};

// Labels every vertex within `radius`. The signature records, for every vertex closer than
// the radius, its valence, face count, boundary flag, sharpness, and for each of its faces
// the size, the labels of the corners and the sharpness of the face's edges; for the
// vertices at the radius, their valence, boundary flag and sharpness. Two neighbourhoods
// with equal signatures are the same up to the radius.
Labelling label_neighbourhood(const Level& level, CentreKind kind, Index centre, int start, int radius);
// The same into a reused labelling (of any level; label_of may be longer than the level,
// the extra entries kNone): only the entries set by its last use are cleared, so labelling
// every vertex of a large level costs nothing per vertex beyond its neighbourhood.
void label_neighbourhood(Labelling& reuse, const Level& level, CentreKind kind, Index centre, int start, int radius);
// Labels into `reuse` and compares with a signature as it goes (stopping at the first
// difference; the labelling is then incomplete). True when the neighbourhood has it.
bool matches_neighbourhood(Labelling& reuse, const Level& level, CentreKind kind, Index centre, int start, int radius,
                           const std::vector<double>& signature);

// Labels into `reuse` (without the signature) the vertices within `radius` face rings of
// quad `face`, and says whether they are a piece of the plane's regular quad grid with
// nothing on it: every vertex closer than the radius interior with four quads around it,
// no hole, no sharpness on any vertex or edge of those faces, and no two paths of the grid
// meeting again within the radius (the count of vertices is the plane's). Such a face's
// extract_neighbourhood at that radius is the same level as every other such face's, up to
// the labelling (so it has the same signature), found without extracting or signing it.
bool quad_grid_labelled(Labelling& reuse, const Level& level, Index face, int radius);
// The same check, with the same vertices at the same distances (sorted by distance) but in
// another order within each ring: for callers that read only the distances (faster).
bool quad_grid_distances(Labelling& reuse, const Level& level, Index face, int radius);

// Where the labelling of a vertex starts by convention: ring edge 0 on a boundary (the
// boundary edge), the first infinitely sharp edge on a crease, dart or corner, else 0.
int conventional_start(const Level& level, Index v);

// The configuration a real vertex is in, with its ring positions counted from
// conventional_start. `semi_sharp` is set when a sharpness between 0 and infinite is found
// at the vertex or its ring edges (no stationary configuration describes it yet).
LocalConfig vertex_config(const Level& level, Index v, int first_step, bool* semi_sharp);

// The faces within `radius` of a centre (every face with a vertex closer than the radius)
// as a stand-alone level with the tags of the original, and the vertex map.
struct Extracted {
  Level level;
  std::vector<Index> original;  // new vertex -> original vertex
  std::vector<Index> face_original;  // new face -> original face

  Index local(Index original_vertex) const;  // the new vertex, or kNone (a linear search)
};
// Costs the neighbourhood only, not the level: scratch arrays over the level are kept per
// thread and cleared entry by entry, so extracting around every face is linear overall.
Extracted extract_neighbourhood(const Level& level, CentreKind kind, Index centre, int radius);

}  // namespace subdiv
