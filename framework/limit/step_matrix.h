#pragma once
// One step of a descent as a sparse matrix (rows: the vertices after the step, columns:
// those before), and derivative rows pulled back through a chain of steps.
#include <array>
#include <memory>
#include <span>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

struct StencilTable;

struct StepMatrix {
  Index source_count = 0;
  std::vector<Index> offsets{0}, columns;
  std::vector<double> weights;
  // The factor by which the step scales the parameter: 2 for a refinement step (children's
  // coordinates are twice their parent's), 1 for a renumbering.
  int scale = 2;
  // Where set, derivative rows are pulled back through this matrix instead (with its own
  // scale): a power of the step taken at once, whose derivative form differs (limit_nodes.h).
  const StepMatrix* backward = nullptr;
  const StepMatrix* backward2 = nullptr;  // the same for second derivatives

  Index rows() const { return Index(offsets.size()) - 1; }
  // out (rows x channels) = this x in (source_count x channels).
  void apply(std::span<const double> in, std::span<double> out, int channels) const;
};

// The step that a refinement's stencil table makes, restricted to `rows` (the children kept,
// in their order) over `source_count` parents.
StepMatrix step_matrix(const StencilTable& table, const std::vector<Index>& rows, Index source_count);

// A row of weights over vertices applied to their values (`channels` per vertex).
std::vector<double> applied(const std::vector<double>& row, std::span<const double> values, int channels);

// A derivative row over the last step's vertices, for d/du scaled by 2^-k (k the
// refinement steps), pulled back to the first step's sources: every step's factor keeps the
// entries of order one, and each step removes the row's sum, which is zero for a
// derivative: rounding in the sum would otherwise double at every step. `order` 2: a row of
// a second derivative (scaled by 4^-k), each step's factor squared.
std::vector<double> pulled_back(std::vector<double> row, std::span<const StepMatrix* const> steps, int order = 1);
// The same for several rows at once (each as pulled_back takes it, bit for bit), in place.
void pull_back_rows(std::span<std::vector<double>* const> rows, std::span<const StepMatrix* const> steps, int order);

// The powers M^(2^j), j < count, of a square step M — a self-similar run of steps taken one
// binary digit at a time — each with the forms derivative rows are pulled back through
// (`backward`): factor (M - 1 e_0), which acts on zero-sum rows as factor M does and sends
// every row to a zero-sum one, so rounding in the sum never grows with the power (factor: the
// step's scale, 2 for a binary split, 3 for two sqrt3 steps); with `second`, also
// factor^2 (M - 1 e_0) for second-derivative rows (`backward2`). Throws subdiv::Error
// ("internal") for a step that is not square.
struct StepPowers {
  // Room for every power is reserved when made: an element's address never changes, so
  // the `backward` pointers and descents that hold a power stay valid as more are made.
  std::vector<StepMatrix> forward, backward, backward2;
  struct Squares;  // the dense powers to square next; null once all are made
  std::unique_ptr<Squares> next;
  StepPowers();
  ~StepPowers();
};
std::unique_ptr<StepPowers> step_powers(const StepMatrix& step, double factor, int count, bool second);
// The same with room for `count` powers and none made yet (step_powers makes them all at
// once and keeps no room for more); more_powers makes the first
// `count` (and with `second` their second-derivative forms) when not made already. A power
// is the same bits whenever it is made (the same squarings from the same matrix), so a
// descent of m levels need square only up to the highest binary digit of m: the powers of a
// vertex of valence n are dense matrices of about 2n rows (n^3 work each).
// The vertices' (s, t) in a face's frame where the steps keep sampled affine functions affine
// (linear precision), and the labels of the face's corners at (0, 0), (1, 0), (0, 1). A
// second-derivative row annihilates those functions; pulled back with factor^2 per step its
// rounding along them grows by factor^2 lambda_1 (3 for sqrt3's double step), so there the
// second-derivative forms drop that part: factor^2 (M - M Pi), Pi the projector onto the
// affine functions through the corners' values (the same on rows that annihilate them).
struct AffineFrame {
  std::vector<std::array<double, 2>> at;
  std::array<Index, 3> corners{};
};
std::unique_ptr<StepPowers> lazy_step_powers(const StepMatrix& step, double factor, int count,
                                             const AffineFrame* frame = nullptr);
void more_powers(StepPowers& powers, int count, bool second);

// The rows of d/du and d/dv over the first step's sources, from rows `ds`, `dt` along a
// node's own coordinates and the point's Jacobian J (J[a][d] = d(s, t)_a / d(u, v)_d, as
// FacePoint has it): the chain rule, then pulled_back through `steps`.
struct FirstDerivativeRows {
  std::vector<double> du, dv;
};
FirstDerivativeRows first_derivative_rows(std::span<const double> ds, std::span<const double> dt,
                                          const std::array<std::array<double, 2>, 2>& J,
                                          std::span<const StepMatrix* const> steps);
// The same for the second derivatives d2/du2, d2/dudv, d2/dv2 from rows d2/ds2, d2/dsdt,
// d2/dt2 (each step's factor squared).
struct SecondDerivativeRows {
  std::vector<double> duu, duv, dvv;
};
SecondDerivativeRows second_derivative_rows(std::span<const double> dss, std::span<const double> dst,
                                            std::span<const double> dtt, const std::array<std::array<double, 2>, 2>& J,
                                            std::span<const StepMatrix* const> steps);

}  // namespace subdiv
