// Dual schemes next to boundaries and creases (features.md, "Creases in dual schemes").
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "framework/analysis/surface/surface_analysis.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"

using namespace subdiv;

TEST_CASE("probe") {
  const auto scheme = load_scheme("doo-sabin");
  for (int n = 3; n <= 6; ++n) {
    LocalConfig c;
    c.centre = CentreKind::Face;
    c.valence = n;
    c.boundary = true;
    const SurfaceAnalysis a = analyse_configuration(*scheme, c);
    MESSAGE(n, " ", a.verdict, " k0=", a.minimal_size, " K=", a.size);
    std::string s;
    for (size_t i = 0; i < std::min<size_t>(16, a.eigenvalues.size()); ++i) s += std::to_string(a.eigenvalues[i].real()) + " ";
    MESSAGE(s);
  }
  for (int n = 4; n <= 6; ++n) {
    LocalConfig c;
    c.centre = CentreKind::Face;
    c.valence = n;
    c.sharp = {0, 2};
    const SurfaceAnalysis a = analyse_configuration(*scheme, c);
    MESSAGE(n, " ", a.verdict, " k0=", a.minimal_size, " K=", a.size);
    std::string s;
    for (size_t i = 0; i < std::min<size_t>(16, a.eigenvalues.size()); ++i) s += std::to_string(a.eigenvalues[i].real()) + " ";
    MESSAGE(s);
  }
}
