#include "framework/limit/tensor_patch.h"

#include <array>

#include "framework/limit/lattice_functions.h"
#include "framework/limit/triangle_patch.h"

namespace subdiv {
namespace {

constexpr int kDegree = 4;

// The Lagrange basis of the nodes 0, 1/4, ..., 1 at s, with first and second derivatives in
// s: L_i(z) = l_i(z) l_{4-i}(4 - z) with z = 4 s (the one-dimensional case of the
// triangle's barycentric product).
void basis(double s, std::array<double, 5>& value, std::array<double, 5>& first, std::array<double, 5>& second) {
  const double z = kDegree * s;
  for (int i = 0; i <= kDegree; ++i) {
    double a, da, dda, b, db, ddb;
    lagrange_factor(i, z, a, da, dda);
    lagrange_factor(kDegree - i, kDegree - z, b, db, ddb);
    value[size_t(i)] = a * b;
    first[size_t(i)] = kDegree * (da * b - a * db);
    second[size_t(i)] = kDegree * kDegree * (dda * b - 2 * da * db + a * ddb);
  }
}

// out[k][l] += w[k] row[l] for the rows asked for (a count known here, the row's entry read
// once): the same products added in the same order as a loop over k.
template <int Count>
void add_weighted(const double* row, size_t labels, const double (&w)[6], double* const (&out)[6]) {
  for (size_t l = 0; l < labels; ++l) {
    const double x = row[l];
    if (x == 0) continue;
    for (int k = 0; k < Count; ++k) out[k][l] += w[k] * x;
  }
}

}  // namespace

Uv tensor_lattice_point(int q) { return {double(q % (kDegree + 1)) / kDegree, double(q / (kDegree + 1)) / kDegree}; }

CornerRows tensor_rows(const std::vector<std::vector<double>>& rows, const Uv& st, int order) {
  const size_t labels = rows.front().size();
  CornerRows r;
  // Position; then d/ds, d/dt; then the second derivatives.
  const int count = order >= 2 ? 6 : order == 1 ? 3 : 1;
  std::vector<double>* all[6] = {&r.position, &r.ds, &r.dt, &r.dss, &r.dst, &r.dtt};
  double* out[6] = {};
  for (int k = 0; k < count; ++k) all[k]->assign(labels, 0.0), out[k] = all[k]->data();
  std::array<double, 5> bs, ds, dss, bt, dt, dtt;
  basis(st[0], bs, ds, dss);
  basis(st[1], bt, dt, dtt);
  for (int q = 0; q < kTensorLattice; ++q) {
    const size_t i = size_t(q % (kDegree + 1)), j = size_t(q / (kDegree + 1));
    const double w[6] = {bs[i] * bt[j], ds[i] * bt[j], bs[i] * dt[j], dss[i] * bt[j], ds[i] * dt[j], bs[i] * dtt[j]};
    const double* row = rows[size_t(q)].data();
    if (count == 1) add_weighted<1>(row, labels, w, out);
    if (count == 3) add_weighted<3>(row, labels, w, out);
    if (count == 6) add_weighted<6>(row, labels, w, out);
  }
  return r;
}

std::optional<BicubicLabels> bicubic_lattice_labels(const std::vector<std::vector<double>>& lattice) {
  if (lattice.size() != size_t(kTensorLattice)) return std::nullopt;
  // The B-spline functions' values at the lattice.
  std::array<BsplineWeights, kTensorLattice> reference;
  for (int q = 0; q < kTensorLattice; ++q) reference[size_t(q)] = bspline_weights(tensor_lattice_point(q));
  const auto label =
      lattice_functions<16>(lattice, [&](size_t q, size_t k) { return reference[q].position[k]; }, 1e-12);
  if (!label) return std::nullopt;
  std::array<Index, 16> grid{};
  for (size_t k = 0; k < 16; ++k) grid[k] = Index((*label)[k]);
  return bicubic_labels(grid);
}

PolynomialPatch tensor_patch(std::vector<std::vector<double>> lattice) {
  PolynomialPatch p;
  if (lattice.empty()) return p;
  p.bicubic = bicubic_lattice_labels(lattice);
  p.lattice = std::move(lattice);
  return p;
}

}  // namespace subdiv
