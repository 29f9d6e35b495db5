// Interval arithmetic and exact signs: every enclosure contains the exact
// result (checked in 113-bit __float128, exact for the sampled operations),
// and exact results stay exact.
#include "ExactSum.h"
#include "Interval.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using tpc::Interval;

namespace
{
using Quad = __float128;

bool Contains(const Interval& i, Quad v)
{
  return static_cast<Quad>(i.lo) <= v && v <= static_cast<Quad>(i.hi);
}

Interval RandomInterval(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> mag(-8.0, 8.0);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double a = unit(rng) * std::pow(10.0, mag(rng));
  const double b = a + std::fabs(unit(rng)) * std::pow(10.0, mag(rng));
  return { a, b };
}

double Sample(const Interval& i, std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> t(0.0, 1.0);
  const double v = i.lo + t(rng) * (i.hi - i.lo);
  return std::min(std::max(v, i.lo), i.hi);
}
} // namespace

TEST(Interval, EnclosuresContainExactResultsOfSampledOperands)
{
  std::mt19937_64 rng(7);
  int checked = 0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    const Interval a = RandomInterval(rng), b = RandomInterval(rng);
    const Interval sum = a + b, diff = a - b, prod = a * b, sq = tpc::Square(a);
    for (int s = 0; s < 4; ++s)
    {
      const double x = Sample(a, rng), y = Sample(b, rng);
      const Quad qx = x, qy = y;
      ASSERT_TRUE(Contains(sum, qx + qy));
      ASSERT_TRUE(Contains(diff, qx - qy));
      ASSERT_TRUE(Contains(prod, qx * qy));
      ASSERT_TRUE(Contains(sq, qx * qx));
      ++checked;
    }
  }
  EXPECT_EQ(checked, 80000);
}

TEST(Interval, RoundingMovesBoundsOnlyWhenInexact)
{
  // 0.1 + 0.2 is inexact: the enclosure must be a genuine interval around it.
  const Interval s = Interval(0.1) + Interval(0.2);
  EXPECT_LT(s.lo, s.hi);
  EXPECT_TRUE(Contains(s, static_cast<Quad>(0.1) + static_cast<Quad>(0.2)));
  // Exact operations stay points: a plane through lattice points gives [0, 0].
  const Interval z = Interval(0.5) * Interval(2.0) - Interval(1.0);
  EXPECT_EQ(z.lo, 0.0);
  EXPECT_EQ(z.hi, 0.0);
  const Interval p = Interval(0.0) * Interval(-3.0, 5.0);
  EXPECT_EQ(p.lo, 0.0);
  EXPECT_EQ(p.hi, 0.0);
}

TEST(Interval, SquareOfStraddlingIntervalStartsAtZero)
{
  const Interval s = tpc::Square(Interval(-2.0, 3.0));
  EXPECT_EQ(s.lo, 0.0);
  EXPECT_GE(s.hi, 9.0);
  const Interval naive = Interval(-2.0, 3.0) * Interval(-2.0, 3.0);
  EXPECT_LT(naive.lo, 0.0); // the dependency problem Square avoids
}

TEST(ExactSum, SignOfCancellingSums)
{
  tpc::ExactSum s;
  s.Add(1e16);
  s.Add(1.0);
  s.Add(-1e16);
  EXPECT_EQ(s.Sign(), 1);

  tpc::ExactSum zero;
  zero.AddProduct(0.1, 0.1, 3.0);
  zero.AddProduct(-0.1, 0.1, 3.0);
  EXPECT_EQ(zero.Sign(), 0);

  // (1 + 2^-52)^2 - 1 - 2^-51 = 2^-104: invisible in double arithmetic.
  const double e = std::ldexp(1.0, -52);
  tpc::ExactSum tiny;
  tiny.AddProduct(1.0 + e, 1.0 + e);
  tiny.Add(-1.0);
  tiny.Add(-2.0 * e);
  EXPECT_EQ(tiny.Sign(), 1);
  EXPECT_EQ((1.0 + e) * (1.0 + e) - 1.0 - 2.0 * e, 0.0);
}

TEST(ExactSum, AgreesWithQuadPrecisionOnRandomProducts)
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20000; ++trial)
  {
    // Sums of two-factor products are exact in __float128 when the terms are
    // within 2^9 of each other in magnitude.
    tpc::ExactSum s;
    Quad q = 0;
    const int terms = 1 + trial % 6;
    for (int k = 0; k < terms; ++k)
    {
      const double a = u(rng), b = u(rng);
      s.AddProduct(a, b);
      q += static_cast<Quad>(a) * static_cast<Quad>(b);
    }
    const int expected = q > 0 ? 1 : (q < 0 ? -1 : 0);
    ASSERT_EQ(s.Sign(), expected);
  }
}
