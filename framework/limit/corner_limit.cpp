#include "framework/limit/corner_limit.h"

#include <cmath>
#include <deque>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "framework/analysis/surface/surface_analysis.h"
#include "framework/features/sharpness.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

int position_in(std::span<const Index> list, Index x) {
  for (size_t k = 0; k < list.size(); ++k)
    if (list[k] == x) return int(k);
  return -1;
}

// A vertex where the parameterisation is regular: the regular number of faces inside, on a
// boundary or at a tagged corner, and, on an interior crease, two sharp edges straight
// across. Elsewhere (extraordinary vertices, darts, bent creases) the derivatives of the
// limit along the face's directions do not exist.
bool regular_vertex(const Level& L, Index v, bool triangles) {
  const int faces = L.incident_face_count(v);
  const auto ring = L.ring_edges(v);
  const int n = int(ring.size());
  std::vector<int> sharp;
  for (int j = 0; j < n; ++j)
    if (L.edge_sharp(ring[size_t(j)]) > 0 && !L.edge_on_boundary(ring[size_t(j)])) sharp.push_back(j);
  if (L.on_boundary(v)) {
    if (!sharp.empty()) return false;
    if (faces == (triangles ? 3 : 2)) return L.vertex_sharp(v) == 0;
    // A corner stays and its two boundary curves are independent, so data linear in the
    // unfolded (s, t) stays linear (a quad's or one or two triangles' worth of corner). A
    // smooth boundary vertex with other than the regular number of faces is extraordinary:
    // its boundary curve bends through it and the subdominant eigenvalue across the boundary
    // is not 1/2 (Loop with two triangles: 3/8), so d/ds and d/dt there are parallel or do not exist.
    return L.vertex_sharp(v) >= kInfinitelySharp && faces <= (triangles ? 2 : 1);
  }
  if (faces != (triangles ? 6 : 4) || L.vertex_sharp(v) > 0) return false;
  return sharp.empty() || (sharp.size() == 2 && sharp[1] - sharp[0] == n / 2);
}

double dot(const std::vector<double>& mask, const Labelling& lab, const std::vector<Uv>& at, int coord) {
  double s = 0;
  for (size_t l = 0; l < mask.size(); ++l)
    if (mask[l] != 0) s += mask[l] * at[size_t(lab.vertices[l])][size_t(coord)];
  return s;
}

// The ring position (counted from the labelling's start) of the edge from v to w.
int direction_of(const Level& L, Index v, Index w, int start) {
  const auto ring = L.ring_edges(v);
  const int n = int(ring.size());
  for (int j = 0; j < n; ++j)
    if (L.other_end(ring[size_t(j)], v) == w) return (j - start + n) % n;
  return -1;
}

void derivatives(const LimitMask& mask, const Labelling& lab, const Level& L, const FacePoint& p, int corner,
                 int start, bool triangles, CornerRows& rows) {
  const auto fv = L.face(p.face);
  const int k = int(fv.size());
  const Index c = fv[size_t(corner)];
  const int ja = direction_of(L, c, fv[size_t((corner + 1) % k)], start);
  const int jb = direction_of(L, c, fv[size_t((corner + k - 1) % k)], start);
  if (ja < 0 || jb < 0 || size_t(std::max(ja, jb)) >= mask.directions.size()) return;
  const auto& da = mask.directions[size_t(ja)];
  const auto& db = mask.directions[size_t(jb)];
  const std::vector<Uv> at = unfold(L, p.face, triangles);
  const double a00 = dot(da, lab, at, 0), a01 = dot(da, lab, at, 1);
  const double a10 = dot(db, lab, at, 0), a11 = dot(db, lab, at, 1);
  const double det = a00 * a11 - a01 * a10;
  if (!std::isfinite(det) || std::fabs(det) < 1e-14 * (std::fabs(a00 * a11) + std::fabs(a01 * a10))) return;
  rows.ds.assign(size_t(L.vertex_count), 0.0);
  rows.dt.assign(size_t(L.vertex_count), 0.0);
  for (size_t l = 0; l < std::max(da.size(), db.size()); ++l) {
    const double x = l < da.size() ? da[l] : 0.0, y = l < db.size() ? db[l] : 0.0;
    const size_t v = size_t(lab.vertices[l]);
    rows.ds[v] += (a11 * x - a01 * y) / det;
    rows.dt[v] += (a00 * y - a10 * x) / det;
  }
}

// A regular vertex whose subdominant eigenvalues are not the parameters' scale
// (eigenvalues_off_scale): the limit has no derivatives there.
std::string scale_mismatch(const LimitMask& mask, const Level& L, Index c, double scale) {
  const std::string off = eigenvalues_off_scale(mask.direction_eigenvalues, scale);
  if (off.empty()) return {};
  return fmt::format("at a regular {}vertex of valence {} {}", L.on_boundary(c) ? "boundary " : "", L.valence(c), off);
}

// The second-derivative rows at the face's corner (corner_rows with `second`): only at an
// interior regular vertex without sharpness, whose neighbourhood is the analysed one up to the
// masks' own radius and unfolds without conflict over their support.
void second_derivatives(const LimitMask& mask, const Level& L, const FacePoint& p, int corner, int start,
                        bool triangles, CornerRows& rows) {
  const Index c = L.face(p.face)[size_t(corner)];
  if (mask.quadratic.size() != 3 || rows.ds.empty() || L.on_boundary(c) || L.vertex_sharp(c) > 0) return;
  for (Index e : L.ring_edges(c))
    if (L.edge_sharp(e) > 0) return;
  Labelling lab;
  if (!matches_neighbourhood(lab, L, CentreKind::Vertex, c, start, mask.quadratic_radius, mask.quadratic_signature))
    return;
  const std::vector<Uv> at = unfold(L, p.face, triangles);
  const Uv o = at[size_t(c)];
  // a(i, j): mask i applied to the j-th sampled quadratic about the vertex (S²/2, S T, T²/2).
  double a[3][3] = {};
  for (size_t i = 0; i < 3; ++i)
    for (size_t l = 0; l < mask.quadratic[i].size(); ++l) {
      const double w = mask.quadratic[i][l];
      if (w == 0) continue;
      const Uv x = at[size_t(lab.vertices[l])];
      const double s = x[0] - o[0], t = x[1] - o[1];
      if (!std::isfinite(s) || !std::isfinite(t)) return;
      a[i][0] += w * s * s / 2, a[i][1] += w * s * t, a[i][2] += w * t * t / 2;
    }
  // Invert a by cofactors; refuse a nearly singular one (the masks then see no quadratics).
  double inv[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      inv[j][i] = a[(i + 1) % 3][(j + 1) % 3] * a[(i + 2) % 3][(j + 2) % 3] -
                  a[(i + 1) % 3][(j + 2) % 3] * a[(i + 2) % 3][(j + 1) % 3];
  const double det = a[0][0] * inv[0][0] + a[0][1] * inv[1][0] + a[0][2] * inv[2][0];
  double scale = 0;
  for (const auto& r : a)
    for (double x : r) scale = std::max(scale, std::fabs(x));
  if (!std::isfinite(det) || std::fabs(det) < 1e-10 * scale * scale * scale) return;
  std::vector<double>* out[3] = {&rows.dss, &rows.dst, &rows.dtt};
  for (size_t j = 0; j < 3; ++j) {
    out[j]->assign(size_t(L.vertex_count), 0.0);
    for (size_t i = 0; i < 3; ++i)
      for (size_t l = 0; l < mask.quadratic[i].size(); ++l)
        (*out[j])[size_t(lab.vertices[l])] += inv[j][i] / det * mask.quadratic[i][l];
  }
}

}  // namespace

// The parameter-space coordinates of the level's vertices with `face` at its own frame,
// the grid continued across edges through faces of the split's shape. A vertex reached by
// two paths that disagree (an irregular vertex in between) is NaN.
std::vector<Uv> unfold(const Level& L, Index face, bool triangles) {
  const int shape = triangles ? 3 : 4;
  std::vector<Uv> at(size_t(L.vertex_count), Uv{kNan, kNan});
  std::vector<char> conflict(size_t(L.vertex_count), 0), seen(size_t(L.face_count()), 0);
  auto put = [&](Index v, Uv x) {
    Uv& a = at[size_t(v)];
    if (std::isnan(a[0]) && !conflict[size_t(v)]) a = x;
    else if (std::fabs(a[0] - x[0]) + std::fabs(a[1] - x[1]) > 1e-9) conflict[size_t(v)] = 1;
  };
  if (L.face_size(face) != shape) return at;
  const Uv quad[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, tri[3] = {{0, 0}, {1, 0}, {0, 1}};
  for (int k = 0; k < shape; ++k) put(L.face(face)[size_t(k)], triangles ? tri[k] : quad[k]);
  std::deque<Index> queue{face};
  seen[size_t(face)] = 1;
  while (!queue.empty()) {
    const Index f = queue.front();
    queue.pop_front();
    const auto fv = L.face(f);
    const auto fe = L.face_edge_list(f);
    for (int k = 0; k < shape; ++k) {
      const Index e = fe[size_t(k)];
      if (L.edge_face_count(e) != 2) continue;
      const Index g = L.edge_faces[size_t(2 * e)] == f ? L.edge_faces[size_t(2 * e + 1)] : L.edge_faces[size_t(2 * e)];
      if (g == kNone || seen[size_t(g)] || L.face_size(g) != shape) continue;
      const Index a = fv[size_t(k)], b = fv[size_t((k + 1) % shape)];
      const Uv A = at[size_t(a)], B = at[size_t(b)];
      if (std::isnan(A[0]) || std::isnan(B[0])) continue;
      seen[size_t(g)] = 1;
      queue.push_back(g);
      const auto gv = L.face(g);
      const int ib = position_in(gv, b);
      if (triangles) {
        const Uv C = at[size_t(fv[size_t((k + 2) % 3)])];
        put(gv[size_t((ib + 2) % 3)], {A[0] + B[0] - C[0], A[1] + B[1] - C[1]});
      } else {
        const Uv C = at[size_t(fv[size_t((k + 2) % 4)])], D = at[size_t(fv[size_t((k + 3) % 4)])];
        put(gv[size_t((ib + 2) % 4)], {2 * A[0] - D[0], 2 * A[1] - D[1]});
        put(gv[size_t((ib + 3) % 4)], {2 * B[0] - C[0], 2 * B[1] - C[1]});
      }
    }
  }
  for (size_t v = 0; v < at.size(); ++v)
    if (conflict[v]) at[v] = {kNan, kNan};
  return at;
}

std::string not_c1(const Scheme& scheme, const std::string& why) {
  return fmt::format("scheme {} is not C1, so its limit has no derivatives or normals: {}; check its rules with "
                     "`subdiv analyze{} {}` (the l1=l2 column)",
                     subdiv::quoted(scheme.name), why, scheme_plugin_options(scheme), scheme_argument(scheme));
}

std::string not_c1_derivatives(const Scheme& scheme, const std::string& why) {
  return not_c1(scheme, why) + ", or evaluate positions only (`subdiv evaluate --at POINTS.csv --derivatives 0`; "
                               "Python: `derivatives=0`)";
}

std::string no_limit_mask(const Scheme& scheme, int steps, const NoLimitMask& why) {
  if (why.failure.empty())
    return fmt::format("no limit mask for the vertex reached after {} step(s){}{}", steps, why.verdict.empty() ? "" : ": ",
                       why.verdict);
  return fmt::format("scheme {} does not converge at the vertex the point reaches after {} step(s) ({}), so the "
                     "limit does not exist there; check its rules with `subdiv analyze{} {}` (the verdict per "
                     "valence) and make the vertex rule's weights give the eigenvalue 1 once and the others "
                     "smaller",
                     subdiv::quoted(scheme.name), steps, why.failure, scheme_plugin_options(scheme),
                     scheme_argument(scheme));
}

bool corner_rows(SchemeLimits& limits, const Level& L, const FacePoint& p, int corner, int step, bool triangles,
                 CornerRows& rows, NoLimitMask& mask_error, double scale, bool second) {
  if (p.sub_face >= 0) return false;  // an n-gon's sub-face is not a face of the level yet
  const Index c = L.face(p.face)[size_t(corner)];
  bool semi_sharp = false;
  const LocalConfig config = vertex_config(L, c, step, &semi_sharp);
  if (semi_sharp) return false;
  const auto mask = limits.mask(config);
  if (!mask->ok) {
    mask_error = {mask->error, mask->failure};
    return false;
  }
  const int start = conventional_start(L, c);
  Labelling lab;
  if (!matches_neighbourhood(lab, L, CentreKind::Vertex, c, start, mask->radius, mask->signature)) return false;
  rows = {};
  rows.position.assign(size_t(L.vertex_count), 0.0);
  for (size_t l = 0; l < mask->position.size(); ++l) rows.position[size_t(lab.vertices[l])] += mask->position[l];
  if (regular_vertex(L, c, triangles)) {
    rows.no_derivatives = scale_mismatch(*mask, L, c, scale);
    if (rows.no_derivatives.empty()) derivatives(*mask, lab, L, p, corner, start, triangles, rows);
  }
  if (second && rows.no_derivatives.empty()) second_derivatives(*mask, L, p, corner, start, triangles, rows);
  return true;
}

}  // namespace subdiv
