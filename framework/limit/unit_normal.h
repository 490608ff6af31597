#pragma once
// The unit normal of a surface point from its first derivatives, for any scale of the mesh.
#include <array>
#include <span>

namespace subdiv {

// du x dv divided by its length, without overflow or underflow however large or small the
// coordinates (each tangent is first divided by its largest component); zero where du and
// dv are parallel or zero, a degenerate point without a normal.
std::array<double, 3> unit_normal(std::span<const double> du, std::span<const double> dv);

}  // namespace subdiv
