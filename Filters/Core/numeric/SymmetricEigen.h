// Eigen-decomposition of a symmetric 3x3 matrix and the truncated
// pseudo-inverse solve built on it (vertex placement, witness candidates).
// Hand-written: a 3x3 cyclic Jacobi is a few lines, Eigen would be a large
// dependency for it.
#pragma once

#include <algorithm>
#include <cmath>

namespace tpc
{

/// Eigen-decomposition of a symmetric 3x3 matrix (cyclic Jacobi).
inline void SymmetricEigen(double a[3][3], double vectors[3][3], double values[3])
{
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      vectors[i][j] = i == j ? 1.0 : 0.0;
    }
  }
  for (int sweep = 0; sweep < 20; ++sweep)
  {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    if (off < 1e-30)
    {
      break;
    }
    for (int p = 0; p < 2; ++p)
    {
      for (int q = p + 1; q < 3; ++q)
      {
        if (std::fabs(a[p][q]) < 1e-300)
        {
          continue;
        }
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 3; ++k)
        {
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k)
        {
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k)
        {
          const double vkp = vectors[k][p], vkq = vectors[k][q];
          vectors[k][p] = c * vkp - s * vkq;
          vectors[k][q] = s * vkp + c * vkq;
        }
      }
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    values[i] = a[i][i];
  }
}

/// x minimizing |A x - b| with eigenvalues below `relative` * largest treated
/// as zero (the minimum-norm solution along flat directions).
inline void SolveTruncated(const double a[3][3], const double b[3], double relative, double x[3])
{
  double m[3][3], vec[3][3], val[3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      m[i][j] = a[i][j];
    }
    x[i] = 0.0;
  }
  SymmetricEigen(m, vec, val);
  const double largest = std::max({ std::fabs(val[0]), std::fabs(val[1]), std::fabs(val[2]) });
  for (int k = 0; k < 3; ++k)
  {
    if (largest <= 0.0 || std::fabs(val[k]) < relative * largest)
    {
      continue;
    }
    double proj = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      proj += vec[i][k] * b[i];
    }
    for (int i = 0; i < 3; ++i)
    {
      x[i] += vec[i][k] * proj / val[k];
    }
  }
}

} // namespace tpc
