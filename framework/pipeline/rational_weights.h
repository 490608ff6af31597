#pragma once
// Rational (homogeneous) subdivision, for every linear scheme at once: a control point p
// with a weight w > 0 is the homogeneous point (w·p, w) in R^4; the scheme's own rules
// refine those four coordinates like any point data, and each refined point is projected
// back, p' = (w·p)' / w'. This is how NURBS draw conics and quadrics exactly (Piegl &
// Tiller 1997, "The NURBS Book", ch. 4; Farin 1999, "NURBS: From Projective Geometry to
// Practical Use"): a scheme whose polynomial limit reproduces a quadratic Bezier or
// B-spline piece in R^4 reproduces the rational piece after projection. Projection is done
// after the linear steps, so limits and derivatives follow by the quotient rule.
//
// Where the weights come from: OBJ's `v x y z w` (the reader's point array "weight"), a
// point array the user names (--weights NAME; default "weight" in .vtp/.ply), Python's
// weights=. The refined weights are written as the point array "weight" (unless another
// array has that name), which OBJ writes as the fourth coordinate. Used by the surface pipeline (refine_pipeline.cpp) and by the curve
// loops of the front-ends, which call the same functions.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "framework/io/mesh_data.h"

namespace subdiv {

// The default name of the weights array in .vtp and .ply files (and OBJ's fourth coordinate).
inline constexpr const char* kWeightArrayName = "weight";

// The index in `point_data` of the rational weights: the array named `name` when one is
// named (refused, naming `source` and the arrays there are, when it is missing), else the
// one named "weight"; nullopt when there is none. The array found must have one component
// and positive finite values (refused naming `source` and the vertex); it is refined as
// doubles (an integer array is made a double one).
std::optional<size_t> find_rational_weights(std::vector<DataArray>& point_data, const std::string& name,
                                            const std::string& source);

// Whether every weight is exactly 1: the refinement is then the plain one, bit for bit,
// and the pipeline takes the plain path (only the weights array is refined as data).
bool all_weights_one(std::span<const double> weights);

// xyz[v] *= w[v]: the Cartesian part of the homogeneous points.
void to_homogeneous(std::span<double> xyz, std::span<const double> weights);

// xyz[v] /= w[v]: the projection back to R^3.
void from_homogeneous(std::span<double> xyz, std::span<const double> weights);

}  // namespace subdiv
