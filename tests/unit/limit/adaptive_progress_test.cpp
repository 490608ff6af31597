// The bar's shares of an adaptive refinement's levels (limit/adaptive_progress.h): when every
// level has four times the faces of the one before (a tolerance near 0), the levels' shares
// are in the ratio of their faces once the growth is seen (from the first level on when the
// guess is right), and the shares tile [0, 1].
#include <doctest/doctest.h>

#include <cmath>

#include "framework/limit/adaptive_progress.h"

namespace subdiv {

TEST_CASE("adaptive progress: geometric growth gives each level its share of the faces") {
  for (const double guess : {1.0, 2.0, 4.0}) {
    CAPTURE(guess);
    constexpr int kLevels = 6;
    AdaptiveProgress progress(kLevels, false, guess);
    double total = 0;
    for (int l = 0; l < kLevels; ++l) total += std::pow(4.0, l);
    double end_before = 0, share_before = 0;
    for (int l = 0; l < kLevels; ++l) {
      const auto [begin, end] = progress.level_span(l, 10 * std::pow(4.0, l));
      CHECK(begin == doctest::Approx(end_before));
      // The first level's share rests on the guess; from the second the growth is seen.
      if (guess == 4.0) CHECK(end - begin == doctest::Approx(std::pow(4.0, l) / total).epsilon(1e-12));
      if (l > 1) CHECK((end - begin) / share_before == doctest::Approx(4.0).epsilon(1e-12));
      share_before = end - begin;
      end_before = end;
    }
    CHECK(end_before == doctest::Approx(1.0));
  }
}

TEST_CASE("adaptive progress: the bar never goes back and the limit phase takes the rest") {
  AdaptiveProgress progress(5, true, 2.0);
  double last = 0;
  // Growth that rises, falls and stops: shares stay ordered.
  for (int l = 0; const double faces : {100.0, 400.0, 120.0, 120.0, 0.0}) {
    const auto [begin, end] = progress.level_span(l++, faces);
    CHECK(begin >= last);
    CHECK(end >= begin);
    CHECK(end < 1.0);
    last = end;
  }
  const auto [begin, end] = progress.limit_span();
  CHECK(begin == last);
  CHECK(end == 1.0);
}

}  // namespace subdiv
