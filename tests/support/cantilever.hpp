// The gmsh-made cantilever of the results tests (tests/data/results/cantilever.msh, made by
// scripts/make_result_fixtures.py): its length and the closed-form deflection its views carry.
#pragma once

#include "lancer/mesh/msh_reader.hpp"
#include "support/files.hpp"

namespace lancer::test {

inline constexpr double kCantileverLength = 10;

// Euler-Bernoulli deflection of a cantilever under a tip load, scaled so that the tip moves down by t.
inline double cantileverDeflection(double x, double t) {
  constexpr double kL = kCantileverLength;
  return t * x * x * (3 * kL - x) / (2 * kL * kL * kL);
}

inline Mesh cantilever() { return readMsh(dataFile("results/cantilever.msh")); }

}  // namespace lancer::test
