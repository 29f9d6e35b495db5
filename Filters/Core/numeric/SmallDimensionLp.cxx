#include "SmallDimensionLp.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tpc
{
namespace
{
/// Slack under which a constraint counts as satisfied: relative to the
/// magnitudes involved, so scaling the problem does not change the answer.
double Slack(const LpHalfSpace& h, const double* x, int d)
{
  double scale = std::fabs(h.B);
  for (int j = 0; j < d; ++j)
  {
    scale += std::fabs(h.A[j] * x[j]);
  }
  return 1e-11 * scale + 1e-300;
}

double Dot(const LpHalfSpace& h, const double* x, int d)
{
  double s = 0.0;
  for (int j = 0; j < d; ++j)
  {
    s += h.A[j] * x[j];
  }
  return s;
}

bool SolveOneDimension(const LpHalfSpace* cons, std::size_t n, double c, double lo, double hi, double& x)
{
  double low = lo, high = hi;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double a = cons[i].A[0];
    const double b = cons[i].B;
    const double bound = std::max(std::fabs(low), std::fabs(high));
    if (std::fabs(a) * bound <= 1e-14 * std::fabs(b) || a == 0.0)
    {
      if (b < -(1e-11 * std::fabs(a) * bound + 1e-300))
      {
        return false;
      }
      continue;
    }
    if (a > 0.0)
    {
      high = std::min(high, b / a);
    }
    else
    {
      low = std::max(low, b / a);
    }
  }
  if (low > high)
  {
    if (low - high > 1e-11 * (std::fabs(low) + std::fabs(high)) + 1e-300)
    {
      return false;
    }
    x = 0.5 * (low + high);
    return true;
  }
  x = c > 0.0 ? high : c < 0.0 ? low : 0.5 * (low + high);
  return true;
}

/// The reduced constraints of each dimension's subproblems, kept across
/// Seidel's recursion: a subproblem is built only after the one before it
/// in that dimension is solved, so one buffer per dimension serves them all
/// (a vector per violated constraint was a tenth of the turbine's kernel
/// LPs' instructions).
struct ReducedConstraints
{
  std::vector<LpHalfSpace> ByDimension[MaxLpDimension - 1]; ///< [d - 2]: the subproblems of dimension d - 1
};

bool Solve(int d, const LpHalfSpace* cons, std::size_t n, const double* c, const double* lo,
  const double* hi, double* x, ReducedConstraints& reduced);

/// The hyperplane a.x = b solved for its variable of largest coefficient k:
/// on it, x_k = Beta - sum_j Gamma_j x_j.
struct Elimination
{
  int D = 0, K = 0;
  double Gamma[MaxLpDimension] = {};
  double Beta = 0.0;

  /// False for a zero normal.
  bool Of(const LpHalfSpace& h, int d)
  {
    this->D = d;
    this->K = 0;
    for (int j = 1; j < d; ++j)
    {
      if (std::fabs(h.A[j]) > std::fabs(h.A[this->K]))
      {
        this->K = j;
      }
    }
    if (h.A[this->K] == 0.0)
    {
      return false;
    }
    for (int j = 0; j < d; ++j)
    {
      this->Gamma[j] = j == this->K ? 0.0 : h.A[j] / h.A[this->K];
    }
    this->Beta = h.B / h.A[this->K];
    return true;
  }
  /// The half-space a.x <= b on the hyperplane, in the other d - 1 variables.
  LpHalfSpace Reduce(const double* a, double b) const
  {
    LpHalfSpace out;
    int m = 0;
    for (int j = 0; j < this->D; ++j)
    {
      if (j != this->K)
      {
        out.A[m++] = a[j] - a[this->K] * this->Gamma[j];
      }
    }
    out.B = b - a[this->K] * this->Beta;
    return out;
  }
};

/// The optimum of the box and cons[0 .. i) on the boundary of cons[i]: the
/// problem restricted to that hyperplane, one dimension lower. False when
/// infeasible.
bool OptimumOnBoundary(int d, const LpHalfSpace* cons, std::size_t i, const double* c, const double* lo,
  const double* hi, double* x, ReducedConstraints& reduced)
{
  Elimination e;
  if (!e.Of(cons[i], d))
  {
    return false; // 0 <= B < 0
  }
  const int k = e.K;
  std::vector<LpHalfSpace>& sub = reduced.ByDimension[d - 2];
  sub.clear();
  double unit[MaxLpDimension] = {};
  unit[k] = 1.0;
  sub.push_back(e.Reduce(unit, hi[k])); // x_k <= hi_k
  unit[k] = -1.0;
  sub.push_back(e.Reduce(unit, -lo[k])); // -x_k <= -lo_k
  for (std::size_t g = 0; g < i; ++g)
  {
    sub.push_back(e.Reduce(cons[g].A.data(), cons[g].B));
  }
  double subC[MaxLpDimension] = {}, subLo[MaxLpDimension] = {}, subHi[MaxLpDimension] = {};
  int m = 0;
  for (int j = 0; j < d; ++j)
  {
    if (j != k)
    {
      subC[m] = c[j] - c[k] * e.Gamma[j];
      subLo[m] = lo[j];
      subHi[m] = hi[j];
      ++m;
    }
  }
  double y[MaxLpDimension] = {};
  if (!Solve(d - 1, sub.data(), sub.size(), subC, subLo, subHi, y, reduced))
  {
    return false;
  }
  double xk = e.Beta;
  m = 0;
  for (int j = 0; j < d; ++j)
  {
    if (j != k)
    {
      x[j] = y[m++];
      xk -= e.Gamma[j] * x[j];
    }
  }
  x[k] = xk;
  return true;
}

/// Seidel's recursion: keep the optimum of the constraints seen so far; when
/// a new constraint is violated, the new optimum lies on its boundary (even
/// when optima are not unique, by convexity), so solve the problem restricted
/// to that hyperplane, one dimension lower.
bool Solve(int d, const LpHalfSpace* cons, std::size_t n, const double* c, const double* lo,
  const double* hi, double* x, ReducedConstraints& reduced)
{
  if (d == 1)
  {
    return SolveOneDimension(cons, n, c[0], lo[0], hi[0], x[0]);
  }
  for (int j = 0; j < d; ++j)
  {
    x[j] = c[j] > 0.0 ? hi[j] : c[j] < 0.0 ? lo[j] : 0.5 * (lo[j] + hi[j]);
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (Dot(cons[i], x, d) > cons[i].B + Slack(cons[i], x, d) &&
      !OptimumOnBoundary(d, cons, i, c, lo, hi, x, reduced))
    {
      return false;
    }
  }
  return true;
}
} // namespace

LpSolution SolveSmallDimensionLp(int dimension, const std::vector<LpHalfSpace>& constraints,
  const LpVector& c, const LpVector& lo, const LpVector& hi, std::uint64_t seed)
{
  LpSolution result;
  if (dimension < 1 || dimension > MaxLpDimension)
  {
    return result;
  }
  for (int j = 0; j < dimension; ++j)
  {
    if (!(lo[j] <= hi[j]))
    {
      return result;
    }
  }
  // Random order (splitmix64-driven Fisher-Yates): the expected running time
  // is linear in the number of constraints for any input order.
  std::vector<LpHalfSpace> shuffled(constraints);
  std::uint64_t state = seed;
  for (std::size_t i = shuffled.size(); i > 1; --i)
  {
    state += 0x9e3779b97f4a7c15ULL;
    std::uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    std::swap(shuffled[i - 1], shuffled[z % i]);
  }
  ReducedConstraints reduced;
  result.Feasible =
    Solve(dimension, shuffled.data(), shuffled.size(), c.data(), lo.data(), hi.data(), result.X.data(), reduced);
  if (result.Feasible)
  {
    for (int j = 0; j < dimension; ++j)
    {
      result.Value += c[j] * result.X[j];
    }
  }
  return result;
}

} // namespace tpc
