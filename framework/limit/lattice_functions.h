#pragma once
// A patch given by its rows at a lattice recognised as a fixed set of basis functions': which
// label carries which function (box_spline_patch.h over a triangle, tensor_patch.h's bicubic
// B-spline over a quad).
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace subdiv {

// label[f] for each of F functions when every label's lattice values (lattice[q][label], q
// below the lattice's size) are one function's, reference(q, f), to `tolerance`, each
// function taken once, or all zero; empty otherwise.
template <size_t F, class Reference>
std::optional<std::array<size_t, F>> lattice_functions(const std::vector<std::vector<double>>& lattice,
                                                        Reference reference, double tolerance) {
  const size_t L = lattice.front().size();
  std::array<size_t, F> label{};
  std::array<bool, F> taken{};
  for (size_t l = 0; l < L; ++l) {
    const auto off = [&](auto value) {
      double worst = 0;
      for (size_t q = 0; q < lattice.size(); ++q) worst = std::max(worst, std::fabs(lattice[q][l] - value(q)));
      return worst;
    };
    if (off([](size_t) { return 0.0; }) <= tolerance) continue;
    size_t f = 0;
    while (f < F && off([&](size_t q) { return reference(q, f); }) > tolerance) ++f;
    if (f == F || taken[f]) return std::nullopt;
    taken[f] = true;
    label[f] = l;
  }
  if (std::find(taken.begin(), taken.end(), false) != taken.end()) return std::nullopt;
  return label;
}

}  // namespace subdiv
