// Seidel's randomized incremental linear programming in dimension d <= 4
// (paper 5.2: the kernel of the surface in a cell is the feasible region of
// an LP whose constraints are the facets' half-spaces).
//
// Why hand-written rather than GLPK: the star test solves millions of tiny
// LPs (d <= 4, tens of constraints) from several threads; Seidel's method is
// expected O(d! n), allocation-light and re-entrant, while a general simplex
// library costs far more per call and GLPK's environment is not thread-safe.
// GLPK is the oracle this solver is tested against (Testing/Core).
//
// Floating point: the solver is used only to *find* a witness, which is then
// verified exactly (mesh facets) or by interval arithmetic (quadrics), so
// rounding can cost a witness but never make a wrong one pass.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace tpc
{

constexpr int MaxLpDimension = 4;
using LpVector = std::array<double, MaxLpDimension>;

/// The half-space A . x <= B (entries of A beyond the dimension are ignored).
struct LpHalfSpace
{
  LpVector A{};
  double B = 0.0;
};

struct LpSolution
{
  bool Feasible = false;
  LpVector X{};    ///< an optimal point when feasible
  double Value = 0.0; ///< C . X
};

/// Maximizes C . x subject to every half-space and Lo <= x <= Hi (the box
/// keeps the problem bounded). `seed` fixes the random order, so results
/// are reproducible.
LpSolution SolveSmallDimensionLp(int dimension, const std::vector<LpHalfSpace>& constraints,
  const LpVector& c, const LpVector& lo, const LpVector& hi, std::uint64_t seed = 1);

} // namespace tpc
