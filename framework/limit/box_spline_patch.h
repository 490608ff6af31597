#pragma once
// The three-direction quartic box spline over one triangle of its regular triangulation:
// twelve basis functions, each a quartic in the triangle's barycentric coordinates (Stam
// 1998, "Evaluation of Loop subdivision surfaces", appendix; Lai 1992, "Fortran subroutines
// for B-nets of box splines on three- and four-directional meshes"). A node whose sampled
// quartic patch (triangle_patch.h) is this box spline's is evaluated from these closed
// forms: about half the operations of the lattice form.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "framework/limit/face_domain.h"

namespace subdiv {

constexpr int kBoxSplineFunctions = 12;

// Which label of a patch's rows is which basis function (label[f]); the labels no function
// takes have all-zero rows.
struct BoxSplineLabels {
  std::array<std::uint8_t, kBoxSplineFunctions> label{};
  std::uint8_t labels = 0;  // the rows' length
  // The functions in their labels' order (label[by_label[k]] increases with k): the order in
  // which a sum over the rows' labels meets them.
  std::array<std::uint8_t, kBoxSplineFunctions> by_label{};
};

// The labels of a quartic patch given by its rows at the principal lattice
// (quartic_lattice_point) when every label's lattice values are one basis function's to
// 1e-12 (each function taken once) or all zero; empty otherwise. Both are quartics, so
// agreeing at the lattice they agree everywhere.
std::optional<BoxSplineLabels> box_spline_labels(const std::vector<std::vector<double>>& lattice);

// The first `count` rows (position, d/ds, d/dt, d2/ds2, d2/dsdt, d2/dt2: 1, 3 or 6) of the
// box spline at (s, t), written to out[n][0 .. labels) in the labels' order.
void box_spline_rows(const BoxSplineLabels& labels, const Uv& st, int count, double* const* out);

// The same first `count` rows per basis function, w[n][f], before they are placed at the
// labels (box_spline_rows writes w[n][f] at out[n][label[f]] and zero elsewhere).
using BoxSplineWeights = std::array<std::array<double, kBoxSplineFunctions>, 6>;
void box_spline_weights(const Uv& st, int count, BoxSplineWeights& w);

}  // namespace subdiv
