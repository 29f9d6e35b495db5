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

/// Seidel's recursion: keep the optimum of the constraints seen so far; when
/// a new constraint is violated, the new optimum lies on its boundary (even
/// when optima are not unique, by convexity), so solve the problem restricted
/// to that hyperplane, one dimension lower.
bool Solve(int d, const LpHalfSpace* cons, std::size_t n, const double* c, const double* lo,
  const double* hi, double* x)
{
  if (d == 1)
  {
    return SolveOneDimension(cons, n, c[0], lo[0], hi[0], x[0]);
  }
  for (int j = 0; j < d; ++j)
  {
    x[j] = c[j] > 0.0 ? hi[j] : c[j] < 0.0 ? lo[j] : 0.5 * (lo[j] + hi[j]);
  }
  std::vector<LpHalfSpace> sub;
  for (std::size_t i = 0; i < n; ++i)
  {
    const LpHalfSpace& h = cons[i];
    if (Dot(h, x, d) <= h.B + Slack(h, x, d))
    {
      continue;
    }
    int k = 0;
    for (int j = 1; j < d; ++j)
    {
      if (std::fabs(h.A[j]) > std::fabs(h.A[k]))
      {
        k = j;
      }
    }
    if (h.A[k] == 0.0)
    {
      return false; // 0 <= B < 0
    }
    // On the hyperplane, x_k = beta - sum_j gamma_j x_j.
    double gamma[MaxLpDimension] = {};
    for (int j = 0; j < d; ++j)
    {
      gamma[j] = j == k ? 0.0 : h.A[j] / h.A[k];
    }
    const double beta = h.B / h.A[k];
    auto reduce = [&](const double* a, double b, LpHalfSpace& out) {
      int m = 0;
      for (int j = 0; j < d; ++j)
      {
        if (j != k)
        {
          out.A[m++] = a[j] - a[k] * gamma[j];
        }
      }
      out.B = b - a[k] * beta;
    };
    sub.clear();
    sub.reserve(i + 2);
    LpHalfSpace r;
    double unit[MaxLpDimension] = {};
    unit[k] = 1.0;
    reduce(unit, hi[k], r); // x_k <= hi_k
    sub.push_back(r);
    unit[k] = -1.0;
    reduce(unit, -lo[k], r); // -x_k <= -lo_k
    sub.push_back(r);
    for (std::size_t g = 0; g < i; ++g)
    {
      reduce(cons[g].A.data(), cons[g].B, r);
      sub.push_back(r);
    }
    double subC[MaxLpDimension] = {}, subLo[MaxLpDimension] = {}, subHi[MaxLpDimension] = {};
    int m = 0;
    for (int j = 0; j < d; ++j)
    {
      if (j != k)
      {
        subC[m] = c[j] - c[k] * gamma[j];
        subLo[m] = lo[j];
        subHi[m] = hi[j];
        ++m;
      }
    }
    double y[MaxLpDimension] = {};
    if (!Solve(d - 1, sub.data(), sub.size(), subC, subLo, subHi, y))
    {
      return false;
    }
    double xk = beta;
    m = 0;
    for (int j = 0; j < d; ++j)
    {
      if (j != k)
      {
        x[j] = y[m++];
        xk -= gamma[j] * x[j];
      }
    }
    x[k] = xk;
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
  result.Feasible =
    Solve(dimension, shuffled.data(), shuffled.size(), c.data(), lo.data(), hi.data(), result.X.data());
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
