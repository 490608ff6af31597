#include "framework/io/feature_angle.h"

#include <array>
#include <cmath>
#include <fmt/format.h>

#include "framework/util/error.h"
#include "framework/util/option_spelling.h"

namespace subdiv {
namespace {

using Vec = std::array<double, 3>;

// Newell's method: twice the vector area of the polygon.
Vec face_normal(const Level& level, std::span<const double> xyz, Index f) {
  Vec n{0, 0, 0};
  const auto vs = level.face(f);
  for (size_t i = 0; i < vs.size(); ++i) {
    const double* a = &xyz[3 * size_t(vs[i])];
    const double* b = &xyz[3 * size_t(vs[(i + 1) % vs.size()])];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}

constexpr float kInfinitelySharpTag = 10.f;

}  // namespace

double dihedral_angle_degrees(const Level& level, std::span<const double> xyz, Index e) {
  if (level.edge_on_boundary(e)) return -1;
  const Vec a = face_normal(level, xyz, level.edge_faces[2 * e]);
  const Vec b = face_normal(level, xyz, level.edge_faces[2 * e + 1]);
  const Vec c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double la = std::hypot(a[0], a[1], a[2]), lb = std::hypot(b[0], b[1], b[2]);
  if (!(la > 0) || !(lb > 0)) return -1;
  // atan2 of |a x b| and a . b is accurate at small and large angles alike.
  const double angle = std::atan2(std::hypot(c[0], c[1], c[2]), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
  return angle * 180.0 / std::acos(-1.0);
}

std::vector<Index> edges_sharper_than(const Level& level, std::span<const double> xyz, double degrees) {
  if (!(degrees >= 0 && degrees <= 180))
    throw OptionError(fmt::format("{{feature_angle}} {}: the angle must be between 0 and 180 degrees (edges whose faces "
                            "meet at a larger angle between their normals become sharp creases)",
                            degrees));
  if (xyz.size() != 3 * size_t(level.vertex_count))
    throw Error(fmt::format("feature detection: {} coordinates for {} vertices", xyz.size(), level.vertex_count));
  std::vector<Index> sharp;
  for (Index e = 0; e < level.edge_count(); ++e)
    if (dihedral_angle_degrees(level, xyz, e) > degrees) sharp.push_back(e);
  return sharp;
}

Index tag_edges_sharper_than(Level& level, std::span<const double> xyz, double degrees) {
  const std::vector<Index> sharp = edges_sharper_than(level, xyz, degrees);
  if (sharp.empty()) return 0;
  if (level.edge_sharpness.empty()) level.edge_sharpness.assign(level.edge_count(), 0.f);
  for (Index e : sharp) level.edge_sharpness[e] = std::max(level.edge_sharpness[e], kInfinitelySharpTag);
  return Index(sharp.size());
}

}  // namespace subdiv
