#include "framework/util/byte_size_text.h"

#include <cmath>
#include <fmt/format.h>

namespace subdiv {
namespace {

struct Unit {
  double scale;
  const char* name;
};

// Bytes, KiB, MiB, GiB, TiB, PiB: 30 levels of a cube read "1.84e+06 PiB", not
// "1932735283200.0 GiB".
Unit unit_for(double bytes) {
  constexpr double KiB = 1024.0, MiB = KiB * KiB, GiB = MiB * KiB, TiB = GiB * KiB, PiB = TiB * KiB;
  const double b = std::fabs(bytes);
  if (b >= PiB) return {PiB, "PiB"};
  if (b >= TiB) return {TiB, "TiB"};
  if (b >= GiB) return {GiB, "GiB"};
  if (b >= MiB) return {MiB, "MiB"};
  if (b >= KiB) return {KiB, "KiB"};
  return {1.0, "bytes"};
}

// `digits` decimals in a fixed unit; beyond 1024 PiB, `digits` + 2 significant digits.
std::string in_unit(double bytes, Unit unit, int digits) {
  const double value = bytes / unit.scale;
  if (unit.scale == 1.0) return fmt::format("{:.0f} {}", value, unit.name);
  if (value >= 1024) return fmt::format("{:.{}g} {}", value, digits + 2, unit.name);
  return fmt::format("{:.{}f} {}", value, digits, unit.name);
}

}  // namespace

std::string byte_size_text(double bytes) { return in_unit(bytes, unit_for(bytes), 1); }

std::pair<std::string, std::string> byte_sizes_compared(double need, double have) {
  const Unit unit = unit_for(std::fmax(std::fabs(need), std::fabs(have)));
  // Sizes units apart each in their own: 6e18 points would need "1.28e+06 PiB", but only
  // "0.0 PiB" was available read as if nothing was.
  if (std::fmin(std::fabs(need), std::fabs(have)) < unit.scale / 1024) return {byte_size_text(need), byte_size_text(have)};
  std::pair<std::string, std::string> texts;
  // 17 digits tell any two doubles apart; whole bytes are the last resort below that.
  for (int digits = 1; digits <= 17; ++digits) {
    texts = {in_unit(need, unit, digits), in_unit(have, unit, digits)};
    if (texts.first != texts.second || need == have) return texts;
  }
  return {fmt::format("{} bytes", need), fmt::format("{} bytes", have)};
}

}  // namespace subdiv
