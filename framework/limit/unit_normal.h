#pragma once
// The unit normal of a surface point from its first derivatives, for any scale of the mesh.
#include <array>
#include <span>

namespace subdiv {

// du x dv divided by its length, without overflow or underflow however large or small the
// coordinates (each tangent is first divided by its largest component); zero where du and
// dv are parallel or zero, a degenerate point without a normal. A tangent no longer than
// `negligible` (its largest component) counts as zero, and so do tangents at an angle whose
// sine is below 1e-12: what is left of a zero derivative after round-off (all control points
// equal, a surface folded flat) has a direction, but it means nothing.
std::array<double, 3> unit_normal(std::span<const double> du, std::span<const double> dv, double negligible = 0);

// The `negligible` tangent length for a surface of these control values (xyz per point):
// the round-off of a derivative's weighted sum, 64 ulps of the largest coordinate.
double negligible_tangent(std::span<const double> positions);

}  // namespace subdiv
