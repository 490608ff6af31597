#include "framework/analysis/surface/surface_analysis.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <optional>

#include "framework/analysis/surface/dual_sector_patch.h"
#include "framework/analysis/surface/rim_rules.h"
#include "framework/analysis/surface/rotation_blocks.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

using Matrix = Eigen::MatrixXd;
using Vector = Eigen::VectorXd;
using Complex = std::complex<double>;

const double kPi = std::acos(-1.0);
constexpr double kWeightZero = 1e-14;   // stencil weights below this are no dependence
constexpr double kRealTolerance = 1e-7; // relative: imaginary parts below this are real
constexpr double kClusterTolerance = 1e-5;  // relative: equal eigenvalues (defective ones carry ~eps^(1/k))
constexpr double kCurvatureTie = 1e-6;  // lambda_1^2 against |lambda_3| (defective ones carry ~1e-8)
constexpr double kNullTolerance = 1e-9; // singular values below this (relative) span a null space
constexpr double kMaskZero = 1e-11;     // relative: mask entries below this are zero

// ---------------------------------------------------------------------------------------------
// Refinement of a patch and the correspondence of its centre.

StencilTable composed_table(const Hierarchy& h) {
  StencilTable t = h.stencils.front();
  for (size_t i = 1; i < h.stencils.size(); ++i) t = compose(t, h.stencils[i]);
  return t;
}

Index child_of_vertex(const ChildOrigins& o, Index v) {
  for (size_t c = 0; c < o.kind.size(); ++c)
    if (o.kind[c] == OriginKind::Vertex && o.parent[c] == v) return Index(c);
  return kNone;
}

void centroid(const Level& L, const std::vector<double>& xy, Index f, double& x, double& y) {
  x = y = 0;
  for (Index v : L.face(f)) x += xy[size_t(2 * v)], y += xy[size_t(2 * v + 1)];
  x /= L.face_size(f), y /= L.face_size(f);
}

// The child face at the same place as face f: same size, made inside f, nearest centroid.
Index child_of_face(const Level& parent, const std::vector<double>& pxy, const ChildOrigins& o, const Level& child,
                    const std::vector<double>& cxy, Index f) {
  double px, py;
  centroid(parent, pxy, f, px, py);
  Index best = kNone;
  double best_d = 0;
  for (Index g = 0; g < child.face_count(); ++g) {
    if (o.parent_face[size_t(g)] != f || child.face_size(g) != parent.face_size(f)) continue;
    double x, y;
    centroid(child, cxy, g, x, y);
    const double d = std::hypot(x - px, y - py);
    if (best == kNone || d < best_d) best = g, best_d = d;
  }
  return best;
}

// Positions (2 channels) of every level of a hierarchy.
std::vector<std::vector<double>> level_positions(const Hierarchy& h, const std::vector<double>& xy, int channels) {
  std::vector<std::vector<double>> out{xy};
  for (const auto& t : h.stencils) out.push_back(t.apply(out.back(), channels));
  return out;
}

// The centre after all steps of the hierarchy (kNone if it has none).
Index follow_centre(const Hierarchy& h, const std::vector<std::vector<double>>& xy, CentreKind kind, Index c,
                    int channels) {
  for (size_t s = 0; s < h.origins.size() && c != kNone; ++s) {
    if (kind == CentreKind::Vertex) {
      c = child_of_vertex(h.origins[s], c);
      continue;
    }
    // child_of_face works on 2D positions; take x, y of each point.
    auto planar = [&](const std::vector<double>& p) {
      if (channels == 2) return p;
      std::vector<double> q(p.size() / size_t(channels) * 2);
      for (size_t i = 0; i < q.size() / 2; ++i) q[2 * i] = p[size_t(channels) * i], q[2 * i + 1] = p[size_t(channels) * i + 1];
      return q;
    };
    c = child_of_face(h.levels[s], planar(xy[s]), h.origins[s], h.levels[s + 1], planar(xy[s + 1]), c);
  }
  return c;
}

double angle_between(double ax, double ay, double bx, double by) {
  double d = std::atan2(by, bx) - std::atan2(ay, ax);
  while (d <= -kPi) d += 2 * kPi;
  while (d > kPi) d -= 2 * kPi;
  return d;
}

struct Axis {
  double cx = 0, cy = 0;  // centre point
  double ax = 0, ay = 0;  // direction of the first labelled neighbour (or corner)
};

Axis axis_of(const Level& L, const std::vector<double>& xy, CentreKind kind, Index c, int start, Index* first) {
  Axis a;
  Index p;
  if (kind == CentreKind::Vertex) {
    a.cx = xy[size_t(2 * c)], a.cy = xy[size_t(2 * c + 1)];
    p = L.other_end(L.ring_edges(c)[size_t(start)], c);
  } else {
    centroid(L, xy, c, a.cx, a.cy);
    p = L.face(c)[size_t(start)];
  }
  a.ax = xy[size_t(2 * p)] - a.cx, a.ay = xy[size_t(2 * p + 1)] - a.cy;
  if (first) *first = p;
  return a;
}

// The ring edge (or corner) of the child centre nearest in direction to the parent's start.
int aligned_start(const Axis& parent, const Level& C, const std::vector<double>& cxy, CentreKind kind, Index cc,
                  double* offset) {
  const int count = kind == CentreKind::Vertex ? C.valence(cc) : C.face_size(cc);
  int best = 0;
  double best_angle = 1e9;
  for (int i = 0; i < count; ++i) {
    const Axis a = axis_of(C, cxy, kind, cc, i, nullptr);
    const double d = std::abs(angle_between(parent.ax, parent.ay, a.ax, a.ay));
    if (d < best_angle) best = i, best_angle = d;
  }
  if (offset) *offset = best_angle;
  return best;
}

// ---------------------------------------------------------------------------------------------
// Invariant neighbourhoods.

bool maps_to_itself(const StencilTable& t, const Labelling& parent, const Labelling& child, int k) {
  const int cp = parent.count_within(k), cc = child.count_within(k);
  if (cp != cc || cp == 0) return false;
  for (int i = 0; i < cc; ++i) {
    const Index row = child.vertices[size_t(i)];
    for (Index e = t.offsets[size_t(row)]; e < t.offsets[size_t(row) + 1]; ++e) {
      if (std::abs(t.weights[size_t(e)]) <= kWeightZero) continue;
      const Index label = parent.label_of[size_t(t.indices[size_t(e)])];
      if (label == kNone || label >= cp) return false;
    }
  }
  return true;
}

Matrix local_matrix(const StencilTable& t, const Labelling& parent, const Labelling& child, int m) {
  Matrix s = Matrix::Zero(m, m);
  for (int i = 0; i < m; ++i) {
    const Index row = child.vertices[size_t(i)];
    for (Index e = t.offsets[size_t(row)]; e < t.offsets[size_t(row) + 1]; ++e) {
      const Index label = parent.label_of[size_t(t.indices[size_t(e)])];
      if (label != kNone && label < m) s(i, label) += t.weights[size_t(e)];
    }
  }
  return s;
}

// ---------------------------------------------------------------------------------------------
// Eigen structure.

std::vector<Complex> sorted(std::vector<Complex> v) {
  for (auto& z : v)
    if (std::abs(z.imag()) < 1e-13) z = Complex(z.real(), 0.0);
  std::stable_sort(v.begin(), v.end(), [](Complex x, Complex y) {
    const double ax = std::abs(x), ay = std::abs(y);
    if (std::abs(ax - ay) > 1e-12 * std::max(1.0, ax)) return ax > ay;
    if (std::abs(x.real() - y.real()) > 1e-12) return x.real() > y.real();
    return x.imag() > y.imag();
  });
  return v;
}

std::vector<Complex> sorted_eigenvalues(const Matrix& s) {
  Eigen::EigenSolver<Matrix> solver(s, false);
  if (solver.info() != Eigen::Success) throw Error("the eigenvalue solver did not converge on the local subdivision matrix");
  return sorted(std::vector<Complex>(solver.eigenvalues().data(), solver.eigenvalues().data() + solver.eigenvalues().size()));
}

// Orthonormal basis of the null space of a (columns), by SVD.
Matrix null_space(const Matrix& a) {
  Eigen::BDCSVD<Matrix> svd(a, Eigen::ComputeFullV);
  const Vector& sigma = svd.singularValues();
  const Eigen::Index n = a.cols();
  const double scale = std::max(1.0, sigma.size() ? sigma(0) : 0.0);
  Eigen::Index dim = 0;
  for (Eigen::Index i = sigma.size() - 1; i >= 0 && sigma(i) <= kNullTolerance * scale; --i) ++dim;
  dim += n - sigma.size();
  return svd.matrixV().rightCols(dim);
}

Matrix left_null(const Matrix& s, double lambda) {
  return null_space(s.transpose() - lambda * Matrix::Identity(s.rows(), s.cols()));
}
Matrix right_null(const Matrix& s, double lambda) {
  return null_space(s - lambda * Matrix::Identity(s.rows(), s.cols()));
}

// S on the first m labels as sparse rows (rotation_blocks.h).
LocalRows local_rows(const StencilTable& t, const Labelling& parent, const Labelling& child, int m) {
  LocalRows rows(static_cast<size_t>(m));
  for (int i = 0; i < m; ++i) {
    const Index row = child.vertices[size_t(i)];
    for (Index e = t.offsets[size_t(row)]; e < t.offsets[size_t(row) + 1]; ++e) {
      const Index label = parent.label_of[size_t(t.indices[size_t(e)])];
      if (label != kNone && label < m) rows[size_t(i)].emplace_back(int(label), t.weights[size_t(e)]);
    }
  }
  return rows;
}

bool is_real(Complex z) { return std::abs(z.imag()) <= kRealTolerance * std::max(1.0, std::abs(z)); }
bool ties(double a, double b, double tol);
bool ties(double a, double b, double tol) { return std::abs(a - b) <= tol * std::max(1.0, std::abs(a)); }

std::string number(double x) { return fmt::format("{:.6g}", std::abs(x) < 5e-13 ? 0.0 : x); }
std::string complex_text(Complex z) {
  if (std::abs(z.imag()) < 1e-7 * std::max(1.0, std::abs(z))) return number(z.real());
  return fmt::format("{}{}{}i", number(z.real()), z.imag() < 0 ? "-" : "+", number(std::abs(z.imag())));
}

std::string curvature_text(const std::vector<Complex>& ev, double l1) {
  const double sq = l1 * l1;
  const double l3 = ev.size() > 3 ? std::abs(ev[3]) : 0.0;
  int mult = 0;
  for (size_t i = 3; i < ev.size(); ++i)
    if (ties(std::abs(ev[i]), sq, kCurvatureTie)) ++mult;
  if (ties(sq, l3, kCurvatureTie)) {
    const double next = ev.size() > 3 + size_t(mult) ? std::abs(ev[3 + size_t(mult)]) : 0.0;
    if (mult == 3 && next < sq)
      return "lambda_1^2 = lambda_3 = lambda_4 = lambda_5 > |lambda_6|: curvature bounded, can be continuous "
             "(case 3: C2 possible)";
    return fmt::format("lambda_1^2 = |lambda_3| ({} eigenvalue{} of that modulus): curvature bounded but may "
                       "split (case 2)",
                       mult, mult == 1 ? "" : "s");
  }
  if (sq < l3) return "lambda_1^2 < |lambda_3|: curvature unbounded (case 1: C1 at best)";
  return "lambda_1^2 > |lambda_3|: curvature tends to zero (case 4: a flat spot)";
}

// ---------------------------------------------------------------------------------------------
// Characteristic map.

struct AnalysisRun {
  // A constructor, not aggregate initialisation: GCC 12 -O3 warns falsely that the
  // aggregate's RefineOptions may be destroyed uninitialized (-Wmaybe-uninitialized).
  AnalysisRun(const Scheme& s, const Patch& p, const LocalConfig& c, const SurfaceAnalysisOptions& o, int step_count)
      : scheme(s), patch(p), config(c), options(o), steps(step_count) {}
  const Scheme& scheme;
  const Patch& patch;
  const LocalConfig& config;
  const SurfaceAnalysisOptions& options;
  RefineOptions refine;
  int steps = 1;
  StencilTable table;
  Labelling parent, child;
  // Label -> the label of its image under the rotation by one sector (the same on the parent
  // and the child labelling); empty where no rotation is used (rotation_blocks.h).
  std::vector<int> turn;
};

// S on the first m labels, for its eigenvalues and null spaces: split into the rotation's
// Fourier blocks where the run has a rotation and S commutes with it (checked), else dense.
struct LocalSpectrum {
  Matrix dense;
  std::optional<RotationBlocks> blocks;

  Eigen::Index rows() const { return blocks ? blocks->size() : dense.rows(); }
  std::vector<Complex> eigenvalues() const { return blocks ? sorted(blocks->eigenvalues()) : sorted_eigenvalues(dense); }
  Matrix left(double lambda) const { return blocks ? blocks->left_null(lambda, kNullTolerance) : left_null(dense, lambda); }
  Matrix right(double lambda) const {
    return blocks ? blocks->right_null(lambda, kNullTolerance) : right_null(dense, lambda);
  }
};

// Above kMaxDenseValence a matrix that does not split by the rotation is refused: its dense
// eigen-decomposition (thousands of rows) would take minutes.
void refuse_dense(const AnalysisRun& cx, int m) {
  const LocalConfig& c = cx.config;
  if (c.valence <= kMaxDenseValence) return;
  const bool symmetric = !c.boundary && c.sharp.empty() && !c.corner;
  throw Error(fmt::format(
      "{} cannot be analysed: above valence {} only interior vertices without creases or corner tags are, whose "
      "local matrix splits into one small block per sector{}; this one would need a dense eigen-decomposition of {} "
      "rows. Bring the valence within {} (split the vertex's fan with extra edges)",
      c.describe(), kMaxDenseValence,
      symmetric ? " (here the scheme's weights do not repeat from sector to sector)" : "", m, kMaxDenseValence));
}

// `dense`, when given, is S on those labels already built.
LocalSpectrum spectrum_of(const AnalysisRun& cx, int m, const Matrix* dense = nullptr) {
  LocalSpectrum sp;
  if (!cx.turn.empty() && m <= int(cx.turn.size())) {
    const std::vector<int> turn(cx.turn.begin(), cx.turn.begin() + m);
    sp.blocks = RotationBlocks::split(local_rows(cx.table, cx.parent, cx.child, m), turn, cx.config.valence);
  }
  if (!sp.blocks) refuse_dense(cx, m);
  if (!sp.blocks) sp.dense = dense ? *dense : local_matrix(cx.table, cx.parent, cx.child, m);
  return sp;
}

// The subdominant eigenvectors on a ring wider than the analysed one (so that the refined
// region near the centre is exact), fitted to the analysed ring's eigenvectors `rp`.
struct EigenvectorNet {
  Matrix values;  // two columns: the map's x and y per label
  int ring = 0;   // the ring the net covers
};

EigenvectorNet widen_eigenvectors(const AnalysisRun& cx, int K, const Matrix& rp, double l1, double l2, bool equal,
                                  CharacteristicMap& cm) {
  EigenvectorNet net;
  net.ring = K;
  while (net.ring < K + 2 && net.ring < cx.options.max_ring &&
         maps_to_itself(cx.table, cx.parent, cx.child, net.ring + 1))
    ++net.ring;
  const int mb = cx.parent.count_within(net.ring);
  const LocalSpectrum sb = spectrum_of(cx, mb);
  Matrix basis = sb.right(l1);
  if (!equal) {
    const Matrix n1 = basis, n2 = sb.right(l2);
    basis.resize(mb, n1.cols() + n2.cols());
    basis << n1, n2;
  }
  const int m = int(rp.rows());
  net.values = Matrix::Zero(mb, 2);
  net.values.topRows(m) = rp;
  if (basis.cols() >= 2) {
    const Matrix fit = basis.topRows(m).colPivHouseholderQr().solve(rp);
    if ((basis.topRows(m) * fit - rp).norm() <= 1e-7 * std::max(1.0, rp.norm())) net.values = basis * fit;
    else cm.note = "wider eigenvectors did not match; the map uses the analysed ring only";
  }
  return net;
}

// The net refined until the region around the centre has grown by the split's scale to
// options.characteristic_scale; `centre` is kNone when it could not be followed.
struct RefinedNet {
  Hierarchy hierarchy;
  std::vector<double> positions;  // the finest level, xyz with z = 0
  Index centre = kNone;
  int steps = 0;
  int rings = 0;  // the refined region's ring count around the centre
};

RefinedNet refine_net(const AnalysisRun& cx, const EigenvectorNet& net) {
  const Patch& p = cx.patch;
  const int mb = int(net.values.rows());
  Extracted e = extract_neighbourhood(p.level, p.centre_kind, p.centre, net.ring + 1);
  std::vector<double> pos(size_t(3 * e.level.vertex_count), 0.0);
  for (Index v = 0; v < e.level.vertex_count; ++v) {
    const Index label = cx.parent.label_of[size_t(e.original[size_t(v)])];
    if (label != kNone && label < mb) pos[size_t(3 * v)] = net.values(label, 0), pos[size_t(3 * v + 1)] = net.values(label, 1);
  }
  Index centre = kNone;
  if (p.centre_kind == CentreKind::Vertex) centre = e.local(p.centre);
  else
    for (size_t f = 0; f < e.face_original.size(); ++f)
      if (e.face_original[f] == p.centre) centre = Index(f);
  const double s = splitter_info(cx.scheme.split()).scale;
  RefinedNet out;
  out.steps = cx.steps;
  while (std::pow(s, out.steps) < cx.options.characteristic_scale - 1e-9) out.steps += cx.steps;
  out.rings = std::max(1, int(std::floor(std::pow(s, out.steps) + 1e-9)));
  RefineOptions ro = cx.refine;
  ro.levels = out.steps;
  out.hierarchy = refine(cx.scheme, e.level, ro);
  auto positions = level_positions(out.hierarchy, pos, 3);
  out.centre = follow_centre(out.hierarchy, positions, p.centre_kind, centre, 3);
  out.positions = std::move(positions.back());
  return out;
}

// Faces with every corner labelled (within the region).
std::vector<Index> faces_within(const Level& L, const Labelling& lab) {
  std::vector<Index> kept;
  for (Index f = 0; f < L.face_count(); ++f) {
    bool inside = true;
    for (Index v : L.face(f)) inside = inside && lab.label_of[size_t(v)] != kNone;
    if (inside) kept.push_back(f);
  }
  return kept;
}

double signed_area(const Level& L, const std::vector<double>& X, Index f) {
  double a = 0;
  const auto vs = L.face(f);
  for (size_t i = 0; i < vs.size(); ++i) {
    const Index u = vs[i], w = vs[(i + 1) % vs.size()];
    a += X[size_t(3 * u)] * X[size_t(3 * w + 1)] - X[size_t(3 * w)] * X[size_t(3 * u + 1)];
  }
  return 0.5 * a;
}

// Regular: the Jacobian keeps one sign, so every face has the orientation of the majority
// (a map may mirror the patch; the normalisation fixes only two points).
void measure_orientation(const Level& L, const std::vector<double>& X, const std::vector<Index>& kept,
                         CharacteristicMap& cm) {
  std::vector<double> areas;
  double total = 0;
  for (Index f : kept) areas.push_back(signed_area(L, X, f)), total += std::abs(areas.back());
  const double mean = kept.empty() ? 1.0 : total / double(kept.size());
  int positive = 0, negative = 0;
  for (double a : areas) positive += a > 1e-9 * mean, negative += a < -1e-9 * mean;
  const int sign = positive >= negative ? 1 : -1;
  cm.folded = int(kept.size()) - (sign > 0 ? positive : negative);
  double smallest = 1e300;  // in the majority's orientation
  for (double a : areas) smallest = std::min(smallest, sign * a);
  cm.min_area_ratio = kept.empty() ? 0.0 : smallest / mean;
  cm.regular = !kept.empty() && cm.folded == 0;
}

// How many times the region's boundary winds around the limit point (the origin).
int boundary_winding(const Level& L, const std::vector<double>& X, const std::vector<Index>& kept) {
  std::map<std::pair<Index, Index>, int> directed;
  for (Index f : kept) {
    const auto vs = L.face(f);
    for (size_t i = 0; i < vs.size(); ++i) directed[{vs[i], vs[(i + 1) % vs.size()]}]++;
  }
  std::map<Index, Index> next;
  for (const auto& [edge, count] : directed)
    if (!directed.count({edge.second, edge.first})) next[edge.first] = edge.second;
  double turns = 0;
  std::map<Index, bool> seen;
  for (const auto& [a0, b0] : next) {
    if (seen[a0]) continue;
    Index a = a0;
    for (size_t guard = 0; guard <= next.size() && !seen[a]; ++guard) {
      seen[a] = true;
      const Index b = next[a];
      turns += angle_between(X[size_t(3 * a)], X[size_t(3 * a + 1)], X[size_t(3 * b)], X[size_t(3 * b + 1)]);
      a = b;
    }
  }
  return int(std::lround(turns / (2 * kPi)));
}

// The refined map as a planar mesh, with each vertex's ring distance from the centre.
void store_map_mesh(const Level& L, const std::vector<double>& X, const std::vector<Index>& kept, const Labelling& lab,
                    CharacteristicMap& cm) {
  std::vector<Index> index(size_t(L.vertex_count), kNone);
  MeshData& mesh = cm.mesh;
  for (Index f : kept) {
    for (Index v : L.face(f)) {
      if (index[size_t(v)] == kNone) {
        index[size_t(v)] = mesh.vertex_count();
        mesh.positions.insert(mesh.positions.end(), {X[size_t(3 * v)], X[size_t(3 * v + 1)], 0.0});
        cm.ring.push_back(lab.distance[size_t(lab.label_of[size_t(v)])]);
      }
      mesh.face_vertices.push_back(index[size_t(v)]);
    }
    mesh.face_offsets.push_back(Index(mesh.face_vertices.size()));
  }
}

// Reif 1995: the characteristic map of the subdominant eigenvectors must be regular
// and injective. Stages: widen the eigenvectors, refine them as a net, keep the region
// around the centre, measure its orientation and winding, store it as a mesh.
void check_characteristic_map(const AnalysisRun& cx, int K, const Matrix& rp, double l1, double l2, bool equal,
                              SurfaceAnalysis& out) {
  CharacteristicMap& cm = out.characteristic_map;
  const EigenvectorNet net = widen_eigenvectors(cx, K, rp, l1, l2, equal, cm);
  const RefinedNet refined = refine_net(cx, net);
  if (refined.centre == kNone) {
    cm.note = "the centre could not be followed through the refinement";
    return;
  }
  const Level& L = refined.hierarchy.levels.back();
  const std::vector<double>& X = refined.positions;
  const Labelling lab = label_neighbourhood(L, cx.patch.centre_kind, refined.centre, 0, refined.rings);
  const std::vector<Index> kept = faces_within(L, lab);
  cm.computed = true;
  cm.refinement_steps = refined.steps;
  cm.faces = int(kept.size());
  measure_orientation(L, X, kept, cm);
  if (!out.config.boundary) {
    cm.winding = boundary_winding(L, X, kept);
    cm.winding_checked = true;
    cm.injective = cm.regular && std::abs(cm.winding) == 1;
  } else {
    cm.injective = cm.regular;
    cm.note += cm.note.empty() ? "" : "; ";
    cm.note += "boundary centre: injectivity taken from regularity (the centre lies on the rim)";
  }
  store_map_mesh(L, X, kept, lab, cm);
}

// ---------------------------------------------------------------------------------------------

void finish_verdict(SurfaceAnalysis& r) {
  const bool dual_feature = r.config.centre == CentreKind::Face && (r.config.boundary || !r.config.sharp.empty());
  const std::string where = dual_feature ? r.config.describe()
                            : r.config.centre == CentreKind::Face ? fmt::format("faces of size {}", r.config.valence)
                            : r.config.boundary || !r.config.sharp.empty() || r.config.corner
                                ? r.config.describe()
                                : fmt::format("valence {}", r.config.valence);
  const bool interior = !r.config.boundary && r.config.sharp.empty() && !r.config.corner;
  auto ev = [&](size_t i) { return i < r.eigenvalues.size() ? complex_text(r.eigenvalues[i]) : std::string("-"); };
  r.c1 = false;
  r.failure.clear();
  if (!r.error.empty()) r.failure = r.error;
  else if (!r.affine) r.failure = fmt::format("weights not affine (a row of S sums to 1 {:+.3g})", r.max_row_error);
  else if (!r.lambda0_one) r.failure = fmt::format("lambda_0 = 1 is not the simple dominant eigenvalue (lambda_0 = {}, lambda_1 = {})", ev(0), ev(1));
  else if (!r.subdominant_real) r.failure = fmt::format("lambda_1, lambda_2 are not real and positive ({}, {})", ev(1), ev(2));
  else if (interior && !r.subdominant_equal) r.failure = fmt::format("lambda_1 != lambda_2 ({} vs {})", ev(1), ev(2));
  else if (!r.subdominant_dominates && r.subdominant_equal && r.subdominant_multiplicity > 2)
    r.failure = fmt::format("lambda_1 = lambda_2 = |lambda_3| = {}: the subdominant eigenvalue has multiplicity {} (more than 2)",
                            number(r.lambda1), r.subdominant_multiplicity);
  else if (!r.subdominant_dominates && r.subdominant_equal)
    // Another eigenvalue of the same modulus (Catmull-Clark at interior valence 2: -1/4
    // beside 1/4, 1/4): its eigenfunction shrinks as fast as the tangent pair's, so the
    // normal does not converge at the centre (Karciauskas & Peters 2009).
    r.failure = fmt::format("|lambda_3| = lambda_1 = lambda_2 = {} (lambda_3 = {}): a third eigenvalue of the "
                            "subdominant modulus, so the limit has no tangent plane at the centre",
                            number(r.lambda1), ev(3));
  else if (!r.subdominant_dominates) r.failure = fmt::format("|lambda_3| = {} is not below lambda_2 = {}", number(r.lambda3), number(r.lambda2));
  else if (!r.subdominant_semisimple) r.failure = "lambda_1 = lambda_2 has one eigenvector only (Jordan block)";
  else if (r.boundary_collapses)
    r.failure = "the boundary's tangent is not in the subdominant pair (interior eigenvalues exceed the boundary "
                "curve's 1/2; the characteristic map collapses the boundary)";
  else if (!r.characteristic_map.computed) {
    r.outcome = Verdict::Unchecked;
    r.verdict = fmt::format("eigenvalue conditions hold at {}; characteristic map not checked{}", where,
                            r.characteristic_map.note.empty() ? "" : " (" + r.characteristic_map.note + ")");
  } else if (!r.characteristic_map.regular)
    r.failure = fmt::format("characteristic map not regular ({} of {} faces folded)", r.characteristic_map.folded,
                            r.characteristic_map.faces);
  else if (!r.characteristic_map.injective)
    r.failure = fmt::format("characteristic map not injective (winding number {})", r.characteristic_map.winding);
  else {
    r.c1 = true;
    r.outcome = Verdict::C1;
    r.verdict = fmt::format("C1 at {}", where);
  }
  if (!r.failure.empty()) r.outcome = Verdict::Fails, r.verdict = "fails: " + r.failure;
}

// Direction masks: the subdominant eigenspace (lambda_1's cluster, and lambda_2's when
// lambda_1 is simple, semi-simple, real, positive, strictly above the rest) written as, for
// each ring neighbour q of the centre in ring order (each corner of a face centre), the
// mask d_q = sum_k r_k(q) t_k, with t_k the left eigenvectors dual to the right ones r_k.
// d_q . P is the direction in which q's descendants approach the limit point: the sector
// normals d_q x d_{q+1} add up to the limit normal, also at creases and corners, where the
// eigenspace has more than two dimensions and each sector has its own tangent plane.
void add_direction_masks(const LocalSpectrum& s, const std::vector<Complex>& ev, const AnalysisRun& cx,
                         SurfaceAnalysis& out) {
  const Eigen::Index n = s.rows();
  Matrix lb(n, 0), rb(n, 0);
  size_t i = 1;
  double last = 0;
  std::vector<double> clusters;
  while (lb.cols() < 2 && i < ev.size()) {
    size_t j = i + 1;
    while (j < ev.size() && std::abs(ev[j] - ev[i]) <= kClusterTolerance * std::max(1.0, std::abs(ev[i]))) ++j;
    Complex z = 0;
    for (size_t k = i; k < j; ++k) z += ev[k];
    z /= double(j - i);
    if (!is_real(z) || z.real() <= 0) return;
    const Matrix a = s.left(z.real()), b = s.right(z.real());
    if (a.cols() != Eigen::Index(j - i) || b.cols() != Eigen::Index(j - i)) return;  // defective
    Matrix l2(n, lb.cols() + a.cols()), r2(n, rb.cols() + b.cols());
    l2 << lb, a;
    r2 << rb, b;
    lb = l2, rb = r2;
    last = z.real();
    clusters.push_back(last);
    i = j;
  }
  if (lb.cols() < 2) return;
  if (i < ev.size() && std::abs(ev[i]) >= last * (1 - kClusterTolerance)) return;
  const Matrix g = lb.transpose() * rb;
  Eigen::FullPivLU<Matrix> lu(g);
  if (!lu.isInvertible()) return;
  const Matrix t = lu.inverse() * lb.transpose();  // rows dual to the columns of rb
  const Patch& p = cx.patch;
  std::vector<Index> ring;
  if (p.centre_kind == CentreKind::Vertex) {
    const auto edges = p.level.ring_edges(p.centre);
    for (size_t k = 0; k < edges.size(); ++k)
      ring.push_back(p.level.other_end(edges[(size_t(p.start) + k) % edges.size()], p.centre));
  } else {
    const auto corners = p.level.face(p.centre);
    for (size_t k = 0; k < corners.size(); ++k) ring.push_back(corners[(size_t(p.start) + k) % corners.size()]);
  }
  out.direction_masks.clear();
  for (Index q : ring) {
    const Index label = cx.parent.label_of[size_t(q)];
    if (label == kNone || label >= n) {
      out.direction_masks.clear();
      return;
    }
    const Vector d = t.transpose() * rb.row(label).transpose();
    out.direction_masks.emplace_back(d.data(), d.data() + d.size());
  }
  out.directions_cyclic = p.centre_kind == CentreKind::Face || !p.level.on_boundary(p.centre);
  out.tangent_dimension = int(lb.cols());
  out.direction_eigenvalues = clusters;
}

// Second-derivative masks (SurfaceAnalysis::quadratic_masks): the left eigenspace of
// lambda_1^2 = lambda_3 = lambda_4 = lambda_5 > |lambda_6| with lambda_1 = lambda_2. Under
// the double step's scaling by 1/lambda_1 about the centre a quadratic's second derivatives
// scale by lambda_1^2, so a C2 limit's second derivatives at the centre are functionals in
// this eigenspace (Peters & Reif 2004; Kobbelt 2000 derives sqrt3's regular weights from it).
void add_quadratic_masks(const LocalSpectrum& s, const std::vector<Complex>& ev, SurfaceAnalysis& out) {
  if (!out.subdominant_equal || ev.size() < 6) return;
  const double mu = out.lambda1 * out.lambda1;
  for (size_t k = 3; k < 6; ++k)
    if (!is_real(ev[k]) || std::abs(ev[k].real() - mu) > kClusterTolerance * std::max(1.0, mu)) return;
  if (ev.size() > 6 && std::abs(ev[6]) >= mu * (1 - kClusterTolerance)) return;
  const Matrix a = s.left(mu), b = s.right(mu);
  if (a.cols() != 3 || b.cols() != 3) return;  // defective
  for (Eigen::Index c = 0; c < a.cols(); ++c) out.quadratic_masks.emplace_back(a.col(c).data(), a.col(c).data() + a.rows());
}

// Stage 1: refine the patch until the centre's neighbourhood repeats. A step that leaves
// the centre's ring turned by about half a sector (sqrt3, mid-edge, plugin splits with a
// period) is repeated; the split's own period is the first guess.
struct RefinedPatch {
  Hierarchy hierarchy;
  Index centre = kNone;  // the centre's counterpart on the finest level
  int start = 0;         // its ring position aligned with the patch's start
  Axis parent_axis;
  Index first_neighbour = kNone;
};

RefinedPatch refine_patch(AnalysisRun& cx) {
  const Patch& p = cx.patch;
  RefinedPatch r;
  r.parent_axis = axis_of(p.level, p.xy, p.centre_kind, p.centre, p.start, &r.first_neighbour);
  for (;;) {
    cx.refine.levels = cx.steps;
    r.hierarchy = refine(cx.scheme, p.level, cx.refine);
    const auto xy = level_positions(r.hierarchy, p.xy, 2);
    r.centre = follow_centre(r.hierarchy, xy, p.centre_kind, p.centre, 2);
    const Level& fine = r.hierarchy.levels.back();
    if (r.centre == kNone) throw Error("the centre has no counterpart after refinement (is this the right kind of centre for the split?)");
    if (p.centre_kind == CentreKind::Vertex &&
        (fine.valence(r.centre) != p.level.valence(p.centre) || fine.on_boundary(r.centre) != p.level.on_boundary(p.centre)))
      throw Error(fmt::format("after {} step(s) the centre has valence {} where it had {}: the split does not "
                              "reproduce the neighbourhood, so there is no local subdivision matrix",
                              cx.steps, fine.valence(r.centre), p.level.valence(p.centre)));
    double offset = 0;
    r.start = aligned_start(r.parent_axis, fine, xy.back(), p.centre_kind, r.centre, &offset);
    const int count = p.centre_kind == CentreKind::Vertex ? p.level.valence(p.centre) : p.level.face_size(p.centre);
    const double sector = 2 * kPi / std::max(count, 1);
    if (offset < 0.25 * sector || cx.steps >= 2) return r;
    cx.steps = 2;
  }
}

// Stage 2: the smallest k-ring that maps to itself (k0), and the ring analysed (K): at least
// the 2-ring of a vertex (the support of the regular basis functions over the faces at the
// centre for Catmull-Clark and Loop), the 1-ring of a face.
void choose_rings(const AnalysisRun& cx, SurfaceAnalysis& out) {
  int k0 = -1, K = -1;
  for (int k = 0; k <= cx.options.max_ring; ++k) {
    if (!maps_to_itself(cx.table, cx.parent, cx.child, k)) continue;
    if (k0 < 0) k0 = k;
    const int k_min = std::max(k0 + 1, cx.patch.centre_kind == CentreKind::Vertex ? 2 : 1);
    if (k >= k_min) {
      K = k;
      break;
    }
  }
  out.max_ring = cx.options.max_ring;
  if (k0 < 0) {
    // Every k-ring has as many points as the child's: the neighbourhood repeats, so only
    // the stencils' reach can keep it from mapping to itself (analyse_configuration grows).
    out.stencils_reach_further = true;
    for (int k = 0; k <= cx.options.max_ring; ++k)
      out.stencils_reach_further = out.stencils_reach_further && cx.parent.count_within(k) == cx.child.count_within(k);
    const bool largest = cx.options.max_ring >= kLargestAutomaticRing;
    throw Error(fmt::format("no k-ring (k <= {}) around the centre maps to itself: the scheme's stencils reach "
                            "further, or its rules here change from level to level{}",
                            cx.options.max_ring,
                            largest ? "" : fmt::format("; a larger max ring (`subdiv analyze --max-ring {}`) may find one",
                                                       cx.options.max_ring + 1)));
  }
  if (K < 0) K = k0;
  out.minimal_ring = k0, out.ring = K;
  out.minimal_size = cx.parent.count_within(k0);
  out.size = cx.parent.count_within(K);
}

// Stage 3: S on the K-ring, in label order.
Matrix record_local_matrix(const AnalysisRun& cx, SurfaceAnalysis& out) {
  const int m = out.size;
  const Matrix s = local_matrix(cx.table, cx.parent, cx.child, m);
  out.matrix.assign(size_t(m), std::vector<double>(size_t(m)));
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) out.matrix[size_t(i)][size_t(j)] = s(i, j);
  out.distance.assign(cx.parent.distance.begin(), cx.parent.distance.begin() + m);
  out.label_vertices.assign(cx.parent.vertices.begin(), cx.parent.vertices.begin() + m);
  return s;
}

// Stage 4: affinity and the eigenvalue conditions (Reif 1995): lambda_0 = 1 simple,
// lambda_1 = lambda_2 real, |lambda_3| below them. Eigenvalues within kClusterTolerance of
// each other are one (a defective eigenvalue of multiplicity k is computed only to about
// eps^(1/k)).
void check_eigenvalues(const AnalysisRun& cx, const Matrix& s, const LocalSpectrum& sp, SurfaceAnalysis& out) {
  out.max_row_error = 0;
  for (Eigen::Index i = 0; i < s.rows(); ++i) {
    const double e = s.row(i).sum() - 1.0;
    if (std::abs(e) > std::abs(out.max_row_error)) out.max_row_error = e;
  }
  out.affine = std::abs(out.max_row_error) <= 1e-9;
  const auto& ev = out.eigenvalues = sp.eigenvalues();
  const Matrix minimal = s.topLeftCorner(out.minimal_size, out.minimal_size);
  out.minimal_eigenvalues = spectrum_of(cx, out.minimal_size, &minimal).eigenvalues();
  out.lambda0_one = !ev.empty() && std::abs(ev[0] - 1.0) <= 1e-9 && (ev.size() < 2 || std::abs(ev[1]) < 1.0 - 1e-9);
  if (ev.size() < 3) return;
  auto cluster = [&](size_t first) {
    size_t end = first + 1;
    while (end < ev.size() && std::abs(ev[end] - ev[first]) <= kClusterTolerance * std::max(1.0, std::abs(ev[first]))) ++end;
    return end;
  };
  auto mean_of = [&](size_t a, size_t b) {
    Complex z = 0;
    for (size_t i = a; i < b; ++i) z += ev[i];
    return z / double(b - a);
  };
  const size_t c1 = cluster(1);
  const Complex z1 = mean_of(1, c1);
  size_t after = c1;
  Complex z2 = z1;
  if (c1 - 1 >= 2) {
    out.subdominant_equal = true;
  } else {
    const size_t c2 = cluster(2);
    z2 = mean_of(2, c2);
    after = c2;
  }
  out.lambda1 = z1.real(), out.lambda2 = z2.real();
  out.lambda3 = after < ev.size() ? std::abs(ev[after]) : 0.0;
  out.subdominant_real = is_real(z1) && is_real(z2) && z1.real() > 0 && z2.real() > 0;
  if (!out.subdominant_real) out.subdominant_equal = false;
  // Two eigenvalues exactly: lambda_1 = lambda_2 of multiplicity 2, or two simple ones.
  const size_t subdominant_count = out.subdominant_equal ? c1 - 1 : after - 1;
  out.subdominant_multiplicity = int(out.subdominant_equal ? c1 - 1 : c1 - 1 == 1 && after - 2 > 1 ? after - 2 : 1);
  if (subdominant_count > 2) out.lambda3 = std::abs(ev[3]);
  out.subdominant_dominates = subdominant_count == 2 && out.lambda3 < std::abs(z2) * (1 - kClusterTolerance);
  if (out.subdominant_real && out.subdominant_equal && out.subdominant_dominates)
    out.curvature = curvature_text(ev, out.lambda1);
}

// Stage 5: the limit mask, the left eigenvector of 1 scaled to sum 1 (Halstead,
// Kass & DeRose 1993).
void add_limit_mask(const LocalSpectrum& s, SurfaceAnalysis& out) {
  const Matrix l0 = s.left(1.0);
  if (l0.cols() != 1 || std::abs(l0.col(0).sum()) <= 1e-12) return;
  const Vector l = l0.col(0) / l0.col(0).sum();
  out.limit_mask.assign(l.data(), l.data() + l.size());
  out.has_limit_mask = true;
}

// Stage 6: left and right eigenvectors of lambda_1 and lambda_2 (two columns each), or
// empty matrices when the subdominant pair is not semi-simple.
struct SubdominantBases {
  Matrix left, right;
};

SubdominantBases subdominant_bases(const LocalSpectrum& s, const SurfaceAnalysis& out) {
  SubdominantBases b;
  const double l1 = out.lambda1, l2 = out.lambda2;
  if (out.subdominant_equal) {
    const double lambda = 0.5 * (l1 + l2);
    b.left = s.left(lambda), b.right = s.right(lambda);
    return b;
  }
  const Matrix a = s.left(l1), c = s.left(l2), d = s.right(l1), e = s.right(l2);
  if (a.cols() == 1 && c.cols() == 1 && d.cols() == 1 && e.cols() == 1) {
    b.left.resize(s.rows(), 2), b.right.resize(s.rows(), 2);
    b.left << a, c;
    b.right << d, e;
  }
  return b;
}

// The patch's second labelled neighbour (after the start): with the first it fixes the
// characteristic map's orientation.
Index second_neighbour(const Patch& p) {
  if (p.centre_kind == CentreKind::Vertex) {
    const auto ring = p.level.ring_edges(p.centre);
    return p.level.other_end(ring[size_t((p.start + 1) % int(ring.size()))], p.centre);
  }
  const auto corners = p.level.face(p.centre);
  return corners[size_t((p.start + 1) % int(corners.size()))];
}

// On a boundary the boundary curve refines on its own: eigenvectors of the interior's
// eigenvalues vanish on it. If the subdominant pair has no component on the boundary
// neighbours, the characteristic map collapses the boundary and there is no C1 limit there.
bool boundary_collapses(const AnalysisRun& cx, const Matrix& right, Index first_label) {
  const Patch& p = cx.patch;
  const auto ring = p.level.ring_edges(p.centre);
  const Index last = cx.parent.label_of[size_t(p.level.other_end(ring.back(), p.centre))];
  double largest = 0;
  for (Eigen::Index i = 0; i < right.rows(); ++i) largest = std::max(largest, right.row(i).norm());
  return right.row(first_label).norm() <= 1e-9 * largest && right.row(last).norm() <= 1e-9 * largest;
}

// Stage 7: tangent masks, the left eigenvectors of lambda_1, lambda_2 normalised against the
// right eigenvectors (the characteristic map) so that the first neighbour sits at (1, 0)
// and the next at (cos phi, sin phi), phi being their angle in the patch. Returns the
// normalised right eigenvectors (the characteristic map's coordinates), or an empty matrix.
Matrix add_tangent_masks(const AnalysisRun& cx, const RefinedPatch& refined, const SubdominantBases& b,
                         SurfaceAnalysis& out) {
  const Patch& p = cx.patch;
  const int m = out.size;
  const Index second = second_neighbour(p);
  const Index la = cx.parent.label_of[size_t(refined.first_neighbour)], lbl = cx.parent.label_of[size_t(second)];
  if (p.centre_kind == CentreKind::Vertex && p.level.on_boundary(p.centre))
    out.boundary_collapses = boundary_collapses(cx, b.right, la);
  const Axis& axis = refined.parent_axis;
  double phi = std::atan2(p.xy[size_t(2 * second + 1)] - axis.cy, p.xy[size_t(2 * second)] - axis.cx) -
               std::atan2(axis.ay, axis.ax);
  while (phi <= 0) phi += 2 * kPi;
  while (phi > 2 * kPi) phi -= 2 * kPi;
  Eigen::Matrix2d at, want;
  at << b.right(la, 0), b.right(la, 1), b.right(lbl, 0), b.right(lbl, 1);
  want << 1, 0, std::cos(phi), std::sin(phi);
  Matrix rp = b.right;
  if (std::abs(at.determinant()) > 1e-12 * std::max(1.0, at.norm() * at.norm())) rp = b.right * (at.inverse() * want);
  const Eigen::Matrix2d g = b.left.transpose() * rp;
  if (std::abs(g.determinant()) < 1e-14) return {};
  const Matrix t = g.inverse() * b.left.transpose();  // 2 x m, t * rp = I
  out.tangent_u.assign(size_t(m), 0.0), out.tangent_v.assign(size_t(m), 0.0);
  for (int j = 0; j < m; ++j) out.tangent_u[size_t(j)] = t(0, j), out.tangent_v[size_t(j)] = t(1, j);
  out.has_tangent_masks = true;
  return rp;
}

// The rotation by one sector as a permutation of the labels within the labelling's radius:
// the labelling started one ring edge (corner) further labels every vertex's image alike,
// when the neighbourhood has the same signature from there, on the parent and on the child.
// Empty when the configuration is not rotationally symmetric (a boundary, a crease, a tag),
// its valence is within options.fourier_above, or the labellings disagree.
std::vector<int> sector_rotation(const AnalysisRun& cx, const RefinedPatch& refined, int radius) {
  const LocalConfig& c = cx.config;
  if (c.boundary || !c.sharp.empty() || c.corner || c.valence <= cx.options.fourier_above) return {};
  const Patch& p = cx.patch;
  const Labelling parent = label_neighbourhood(p.level, p.centre_kind, p.centre, p.start + 1, radius);
  const Labelling child =
      label_neighbourhood(refined.hierarchy.levels.back(), p.centre_kind, refined.centre, refined.start + 1, radius);
  if (parent.signature != cx.parent.signature || child.signature != cx.child.signature) return {};
  const size_t m = std::min(parent.vertices.size(), child.vertices.size());
  std::vector<int> turn(m);
  for (size_t j = 0; j < m; ++j) {
    const Index a = cx.parent.label_of[size_t(parent.vertices[j])];
    const Index b = cx.child.label_of[size_t(child.vertices[j])];
    if (a != b || a == kNone) return {};
    turn[j] = int(a);
  }
  return turn;
}

void analyse(AnalysisRun& cx, SurfaceAnalysis& out) {
  const Patch& p = cx.patch;
  const int radius = cx.options.max_ring + 2;
  const RefinedPatch refined = refine_patch(cx);
  out.steps = cx.steps;
  cx.table = composed_table(refined.hierarchy);
  cx.parent = label_neighbourhood(p.level, p.centre_kind, p.centre, p.start, radius);
  cx.child = label_neighbourhood(refined.hierarchy.levels.back(), p.centre_kind, refined.centre, refined.start, radius);

  cx.turn = sector_rotation(cx, refined, radius);

  choose_rings(cx, out);
  if (cx.turn.empty()) refuse_dense(cx, out.size);
  const Matrix s = record_local_matrix(cx, out);
  const LocalSpectrum sp = spectrum_of(cx, out.size, &s);
  check_eigenvalues(cx, s, sp, out);
  if (out.eigenvalues.size() < 3 || !out.lambda0_one || !out.subdominant_real) return;
  add_limit_mask(sp, out);
  add_direction_masks(sp, out.eigenvalues, cx, out);
  add_quadratic_masks(sp, out.eigenvalues, out);
  const SubdominantBases bases = subdominant_bases(sp, out);
  out.subdominant_semisimple = bases.left.cols() == 2 && bases.right.cols() == 2;
  if (!out.subdominant_semisimple) return;
  const Matrix rp = add_tangent_masks(cx, refined, bases, out);
  if (rp.size() > 0 && cx.options.characteristic_map && out.subdominant_dominates)
    check_characteristic_map(cx, out.ring, rp, out.lambda1, out.lambda2, out.subdominant_equal, out);
}

// The second-derivative masks to the smallest whole ring that holds them (their own, so that
// the other masks and the radius their signatures compare keep their size).
void trim_quadratic_masks(SurfaceAnalysis& r) {
  int used = 0;
  for (const auto& q : r.quadratic_masks) {
    double largest = 0;
    for (double w : q) largest = std::max(largest, std::abs(w));
    for (int i = 0; i < int(q.size()); ++i)
      if (std::abs(q[size_t(i)]) > kMaskZero * largest) used = std::max(used, i + 1);
  }
  if (used == 0) return;
  const int d = r.distance[size_t(used - 1)];
  size_t size = 0;
  while (size < r.distance.size() && r.distance[size] <= d) ++size;
  for (auto& q : r.quadratic_masks) {
    double largest = 0;
    for (double w : q) largest = std::max(largest, std::abs(w));
    q.resize(size);
    for (double& w : q)
      if (std::abs(w) <= 1e-15 * largest) w = 0.0;
  }
}

// Masks are left eigenvectors of the K-ring matrix; they vanish beyond the minimal ring
// for any sensible scheme. Trim them to the smallest ring that holds them.
void trim_masks(SurfaceAnalysis& r) {
  auto extent = [&](const std::vector<double>& mask) {
    double largest = 0;
    for (double w : mask) largest = std::max(largest, std::abs(w));
    int last = -1;
    for (int i = 0; i < int(mask.size()); ++i)
      if (std::abs(mask[size_t(i)]) > kMaskZero * largest) last = i;
    return last + 1;
  };
  int used = 0;
  if (r.has_limit_mask) used = std::max(used, extent(r.limit_mask));
  if (r.has_tangent_masks) used = std::max({used, extent(r.tangent_u), extent(r.tangent_v)});
  for (const auto& d : r.direction_masks) used = std::max(used, extent(d));
  if (used == 0) return;
  const int d = r.distance[size_t(used - 1)];
  int size = 0;
  while (size < int(r.distance.size()) && r.distance[size_t(size)] <= d) ++size;
  auto cut = [&](std::vector<double>& mask) {
    if (mask.empty()) return;
    double largest = 0;
    for (double w : mask) largest = std::max(largest, std::abs(w));
    mask.resize(size_t(size));
    for (double& w : mask)
      if (std::abs(w) <= 1e-15 * largest) w = 0.0;
  };
  cut(r.limit_mask), cut(r.tangent_u), cut(r.tangent_v);
  for (auto& d : r.direction_masks) cut(d);
  trim_quadratic_masks(r);
}

}  // namespace

// What the split says of itself (SplitterInfo), so that plugin splits are analysed alike.
CentreKind analysis_centre(const Scheme& scheme) {
  return splitter_info(scheme.split()).primal ? CentreKind::Vertex : CentreKind::Face;
}

PatchCells analysis_cells(const Scheme& scheme) {
  const bool triangles = splitter_info(scheme.split()).required_face_size == 3 || scheme.required_face_size == 3;
  return triangles ? PatchCells::Triangles : PatchCells::Quads;
}

int analysis_steps(const Scheme& scheme) { return splitter_info(scheme.split()).period; }

double analysis_parameter_scale(const Scheme& scheme) {
  const SplitterInfo& info = splitter_info(scheme.split());
  return std::pow(info.scale, -info.period);
}

SurfaceAnalysis analyse_patch(const Scheme& scheme, const Patch& patch, const LocalConfig& config,
                              const SurfaceAnalysisOptions& options) {
  SurfaceAnalysis out;
  out.scheme = scheme.name;
  out.path = scheme.path;
  out.config = config;
  AnalysisRun cx(scheme, patch, config, options, analysis_steps(scheme));
  cx.refine.features = options.features;
  cx.refine.first_step = config.first_step;
  out.steps = cx.steps;
  try {
    analyse(cx, out);
    trim_masks(out);
  } catch (const Error& e) {
    out.error = e.what();
  }
  finish_verdict(out);
  return out;
}

namespace {

// A vertex inside the surface with two or more infinitely sharp ring edges: a crease (two) or
// a corner (three or more), whose sectors lie between consecutive sharp edges.
bool sectored_feature(const LocalConfig& c) { return !c.boundary && !c.corner && c.sharp.size() >= 2; }

// The number of faces of each sector, counterclockwise from the first sharp ring edge (for a
// dual centre, the first sector is the one whose face is analysed).
std::vector<int> sector_faces(const LocalConfig& c) {
  if (c.centre == CentreKind::Face) return {first_sector_faces(c), c.valence - first_sector_faces(c)};
  std::vector<int> faces;
  for (size_t i = 0; i < c.sharp.size(); ++i)
    faces.push_back((i + 1 < c.sharp.size() ? c.sharp[i + 1] : c.sharp[0] + c.valence) - c.sharp[i]);
  return faces;
}

// Whether S is block triangular with respect to the crease curves: no point off them in one
// sector has weight on a point off them in another. The sectors are the components of the
// patch without its crease vertices (those on an edge of sharpness >= 1); there must be
// `sectors` of them.
bool sides_decoupled(const Patch& p, const SurfaceAnalysis& a, int sectors) {
  const Level& L = p.level;
  std::vector<int> side(size_t(L.vertex_count), -1);  // -1 unvisited, -2 crease
  for (Index v = 0; v < L.vertex_count; ++v)
    for (Index e : L.ring_edges(v))
      if (!L.edge_on_boundary(e) && L.edge_sharp(e) >= 1.f) side[size_t(v)] = -2;
  int sides = 0;
  for (Index s0 = 0; s0 < L.vertex_count; ++s0) {
    if (side[size_t(s0)] != -1) continue;
    std::vector<Index> stack{s0};
    side[size_t(s0)] = sides;
    while (!stack.empty()) {
      const Index v = stack.back();
      stack.pop_back();
      for (Index e : L.ring_edges(v)) {
        const Index w = L.other_end(e, v);
        if (side[size_t(w)] == -1) side[size_t(w)] = sides, stack.push_back(w);
      }
    }
    ++sides;
  }
  if (sides != sectors) return false;
  for (size_t i = 0; i < a.matrix.size(); ++i)
    for (size_t j = 0; j < a.matrix.size(); ++j) {
      const int si = side[size_t(a.label_vertices[i])], sj = side[size_t(a.label_vertices[j])];
      if (si >= 0 && sj >= 0 && si != sj && std::abs(a.matrix[i][j]) > kWeightZero) return false;
    }
  return true;
}

// The labels of S's points on the crease (a vertex of an interior edge of sharpness >= 1).
std::vector<int> crease_labels(const Patch& p, const SurfaceAnalysis& a) {
  std::vector<int> out;
  for (size_t i = 0; i < a.matrix.size(); ++i) {
    const Index v = a.label_vertices[i];
    for (Index e : p.level.ring_edges(v))
      if (!p.level.edge_on_boundary(e) && p.level.edge_sharp(e) >= 1.f) {
        out.push_back(int(i));
        break;
      }
  }
  return out;
}

// The spectrum of S on the crease points, when their rows read crease points only (the
// crease then refines as a curve of its own, by the crease curve's rule); else empty.
std::vector<Complex> crease_spectrum(const Patch& p, const SurfaceAnalysis& a) {
  const std::vector<int> crease = crease_labels(p, a);
  const int m = int(crease.size());
  if (m == 0) return {};
  std::vector<bool> on(a.matrix.size(), false);
  for (int i : crease) on[size_t(i)] = true;
  Matrix block(m, m);
  for (int r = 0; r < m; ++r) {
    const auto& row = a.matrix[size_t(crease[size_t(r)])];
    for (size_t j = 0; j < row.size(); ++j)
      if (!on[j] && std::abs(row[j]) > kWeightZero) return {};
    for (int c = 0; c < m; ++c) block(r, c) = row[size_t(crease[size_t(c)])];
  }
  return sorted_eigenvalues(block);
}

// "1, 0.5, 0.25, 0.125, ..." (the first few).
std::string leading_text(const std::vector<Complex>& ev, size_t count) {
  std::string s;
  for (size_t i = 0; i < std::min(count, ev.size()); ++i) s += (i ? ", " : "") + complex_text(ev[i]);
  return ev.size() > count ? s + ", ..." : s;
}

// A crease cuts the neighbourhood into two sides, a corner into one sector per pair of
// consecutive sharp edges; when S is block triangular (checked by sides_decoupled) they share
// only the crease points, refined by the crease curve's rule on their own. Each sector is
// then refined as a surface whose boundary is its two crease curves — exactly so where the
// scheme's crease rules are its boundary rules — and the smoothness up to the crease is each
// sector's boundary analysis (a sector of k faces: boundary valence k + 1; at a corner, whose
// point stays, a boundary vertex tagged as a corner). The whole characteristic map is no test
// here: its subdominant eigenvalues mix the sectors (at a corner, each crease curve brings
// its own). Along the crease curves, the spectrum of the crease points' own block
// (crease_eigenvalues).
void judge_by_sectors(const Scheme& scheme, const SurfaceAnalysisOptions& options, SurfaceAnalysis& out) {
  const std::vector<int> sectors = sector_faces(out.config);
  std::string failed, sizes;
  for (size_t i = 0; i < sectors.size(); ++i) {
    const int k = sectors[i];
    sizes += fmt::format("{}{}", i == 0 ? "" : i + 1 == sectors.size() ? " and " : ", ", k);
    LocalConfig side;
    side.centre = out.config.centre;
    side.boundary = true;
    side.valence = k + 1;
    side.corner = sectors.size() > 2;  // a corner's point stays: a boundary vertex tagged as a corner
    side.first_step = out.config.first_step;
    const SurfaceAnalysis b = analyse_configuration(scheme, side, options);
    const std::string why = b.outcome == Verdict::Fails ? b.failure : b.verdict;
    if (!b.c1 && failed.empty())
      failed = fmt::format("the {} of {} faces ({}): {}", sectors.size() == 2 ? "side" : "sector", k,
                           b.config.describe(), why);
  }
  out.c1 = failed.empty();
  const bool crease = sectors.size() == 2;
  const std::string along =
      out.crease_eigenvalues.empty()
          ? std::string()
          : fmt::format(" (its points refine among themselves: {})",
                        leading_text(out.crease_eigenvalues, crease ? 4 : 5));
  out.outcome = out.c1 ? Verdict::C1 : Verdict::Fails;
  out.failure = failed;
  if (!out.c1) out.verdict = "fails: " + failed;
  else if (crease)
    out.verdict = fmt::format("C1 on both sides of the crease (sides of {} faces, each as at a boundary); "
                              "along it the crease curve's{}",
                              sizes, along);
  else
    out.verdict = fmt::format("C1 in each of the corner's {} sectors (sectors of {} faces, each as at a boundary "
                              "corner); along its crease curves the curve rule's{}",
                              sectors.size(), sizes, along);
}

SurfaceAnalysis analyse_crease_or_other(const Scheme& scheme, const Patch& patch, const LocalConfig& config,
                                        const SurfaceAnalysisOptions& options) {
  SurfaceAnalysis out = analyse_patch(scheme, patch, config, options);
  if (sectored_feature(config) && out.error.empty() && !out.matrix.empty() &&
      sides_decoupled(patch, out, int(sector_faces(config).size()))) {
    out.crease_eigenvalues = crease_spectrum(patch, out);
    judge_by_sectors(scheme, options, out);
  }
  return out;
}

SurfaceAnalysis analyse_configuration_once(const Scheme& given, const LocalConfig& config,
                                           const SurfaceAnalysisOptions& options) {
  const int rings = options.patch_rings > 0 ? options.patch_rings : options.max_ring + 3;
  std::shared_ptr<const Scheme> with_rim;
  const Scheme& scheme = scheme_for_patch_rim(given, config, with_rim);
  try {
    if (config.centre == CentreKind::Face) {
      if (analysis_cells(scheme) != PatchCells::Quads)
        throw Error("face-centred analysis needs a scheme for quads");
      if (config.boundary || !config.sharp.empty() || config.corner)
        return analyse_crease_or_other(scheme, make_dual_sector_patch(scheme, config, rings, options.features), config,
                                       options);
      return analyse_patch(scheme, make_face_patch(config.valence, rings), config, options);
    }
    if (analysis_centre(scheme) == CentreKind::Face)
      throw Error(fmt::format("scheme {} is dual: a vertex of valence n becomes an n-gon face; analyse faces",
                              subdiv::quoted(scheme.name)));
    return analyse_crease_or_other(scheme, make_vertex_patch(analysis_cells(scheme), config, rings), config, options);
  } catch (const Error& e) {
    SurfaceAnalysis out;
    out.scheme = scheme.name, out.path = scheme.path, out.config = config;
    out.error = e.what();
    finish_verdict(out);
    return out;
  }
}

}  // namespace

SurfaceAnalysis analyse_configuration(const Scheme& scheme, const LocalConfig& config,
                                      const SurfaceAnalysisOptions& options) {
  SurfaceAnalysis out = analyse_configuration_once(scheme, config, options);
  SurfaceAnalysisOptions grown = options;
  while (out.stencils_reach_further && grown.patch_rings == 0 && grown.max_ring < kLargestAutomaticRing) {
    ++grown.max_ring;
    out = analyse_configuration_once(scheme, config, grown);
  }
  return out;
}

SurfaceAnalysis analyse_valence(const Scheme& scheme, int n, const SurfaceAnalysisOptions& options) {
  LocalConfig c;
  c.centre = analysis_centre(scheme);
  c.valence = n;
  return analyse_configuration(scheme, c, options);
}

}  // namespace subdiv
