// Seidel's small-dimension LP against GLPK's simplex (an independent solver)
// on thousands of random instances: same feasibility, same optimal value, and
// the returned point satisfies every constraint.
#include "SmallDimensionLp.h"

#include <glpk.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace tpc;

namespace
{
struct Oracle
{
  bool Feasible = false;
  double Value = 0.0;
};

Oracle SolveWithGlpk(int d, const std::vector<LpHalfSpace>& cons, const LpVector& c,
  const LpVector& lo, const LpVector& hi)
{
  glp_prob* lp = glp_create_prob();
  glp_set_obj_dir(lp, GLP_MAX);
  glp_add_cols(lp, d);
  for (int j = 0; j < d; ++j)
  {
    glp_set_col_bnds(lp, j + 1, GLP_DB, lo[j], hi[j]);
    glp_set_obj_coef(lp, j + 1, c[j]);
  }
  if (!cons.empty())
  {
    glp_add_rows(lp, static_cast<int>(cons.size()));
  }
  std::vector<int> ind(d + 1);
  std::vector<double> val(d + 1);
  for (std::size_t i = 0; i < cons.size(); ++i)
  {
    const int row = static_cast<int>(i) + 1;
    glp_set_row_bnds(lp, row, GLP_UP, 0.0, cons[i].B);
    for (int j = 0; j < d; ++j)
    {
      ind[j + 1] = j + 1;
      val[j + 1] = cons[i].A[j];
    }
    glp_set_mat_row(lp, row, d, ind.data(), val.data());
  }
  glp_smcp params;
  glp_init_smcp(&params);
  params.msg_lev = GLP_MSG_OFF;
  params.presolve = GLP_OFF;
  Oracle result;
  if (glp_simplex(lp, &params) == 0)
  {
    const int status = glp_get_status(lp);
    result.Feasible = status == GLP_OPT;
    result.Value = glp_get_obj_val(lp);
  }
  glp_delete_prob(lp);
  return result;
}

/// Random instance: constraints tangent to a random ball (always feasible)
/// or crossing each other around it (often infeasible), plus a random
/// objective and box.
void RandomInstance(std::mt19937_64& rng, int d, std::vector<LpHalfSpace>& cons, LpVector& c,
  LpVector& lo, LpVector& hi)
{
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const int n = std::uniform_int_distribution<int>(0, 40)(rng);
  const bool tight = std::uniform_int_distribution<int>(0, 1)(rng) == 1;
  LpVector center{};
  for (int j = 0; j < d; ++j)
  {
    center[j] = uniform(rng);
    lo[j] = -4.0 + 2.0 * uniform(rng);
    hi[j] = 4.0 + 2.0 * uniform(rng);
    c[j] = normal(rng);
  }
  cons.clear();
  for (int i = 0; i < n; ++i)
  {
    LpHalfSpace h;
    double norm = 0.0;
    for (int j = 0; j < d; ++j)
    {
      h.A[j] = normal(rng);
      norm += h.A[j] * h.A[j];
    }
    norm = std::sqrt(norm);
    double ac = 0.0;
    for (int j = 0; j < d; ++j)
    {
      ac += h.A[j] * center[j];
    }
    // Half-spaces at signed distance r from the centre: r > 0 keeps the
    // centre inside, r < 0 (tight instances) cuts it off.
    const double r = tight ? uniform(rng) * 0.6 - 0.1 : 0.2 + std::fabs(uniform(rng));
    h.B = ac + r * norm;
    cons.push_back(h);
  }
}
} // namespace

TEST(SmallDimensionLp, AgreesWithGlpkOnRandomInstances)
{
  std::mt19937_64 rng(20261122);
  int feasible = 0, infeasible = 0;
  for (int instance = 0; instance < 6000; ++instance)
  {
    const int d = 1 + instance % MaxLpDimension;
    std::vector<LpHalfSpace> cons;
    LpVector c{}, lo{}, hi{};
    RandomInstance(rng, d, cons, c, lo, hi);
    const LpSolution mine = SolveSmallDimensionLp(d, cons, c, lo, hi, instance + 1);
    const Oracle oracle = SolveWithGlpk(d, cons, c, lo, hi);
    ASSERT_EQ(mine.Feasible, oracle.Feasible) << "instance " << instance << " d " << d;
    if (!mine.Feasible)
    {
      ++infeasible;
      continue;
    }
    ++feasible;
    EXPECT_NEAR(mine.Value, oracle.Value, 1e-7 * (1.0 + std::fabs(oracle.Value)))
      << "instance " << instance << " d " << d;
    for (const LpHalfSpace& h : cons)
    {
      double ax = 0.0, scale = std::fabs(h.B);
      for (int j = 0; j < d; ++j)
      {
        ax += h.A[j] * mine.X[j];
        scale += std::fabs(h.A[j] * mine.X[j]);
      }
      EXPECT_LE(ax, h.B + 1e-9 * scale) << "instance " << instance;
    }
    for (int j = 0; j < d; ++j)
    {
      EXPECT_GE(mine.X[j], lo[j] - 1e-9);
      EXPECT_LE(mine.X[j], hi[j] + 1e-9);
    }
  }
  // Both outcomes are exercised in quantity.
  EXPECT_GT(feasible, 1500);
  EXPECT_GT(infeasible, 500);
}

TEST(SmallDimensionLp, DegenerateAndParallelConstraints)
{
  // x + y <= 1 twice, -x - y <= -1: the feasible set is a segment; maximize x.
  std::vector<LpHalfSpace> cons(3);
  cons[0].A = { 1, 1, 0, 0 };
  cons[0].B = 1;
  cons[1] = cons[0];
  cons[2].A = { -1, -1, 0, 0 };
  cons[2].B = -1;
  const LpSolution s = SolveSmallDimensionLp(2, cons, { 1, 0, 0, 0 }, { -5, -5, 0, 0 }, { 5, 5, 0, 0 });
  ASSERT_TRUE(s.Feasible);
  EXPECT_NEAR(s.X[0], 5.0, 1e-12);
  EXPECT_NEAR(s.X[1], -4.0, 1e-12);
  // 0 . x <= -1 is infeasible whatever x.
  LpHalfSpace impossible;
  impossible.B = -1;
  EXPECT_FALSE(SolveSmallDimensionLp(3, { impossible }, { 1, 1, 1, 0 }, { 0, 0, 0, 0 }, { 1, 1, 1, 0 }).Feasible);
  // Zero objective: any feasible point will do.
  const LpSolution any = SolveSmallDimensionLp(2, cons, { 0, 0, 0, 0 }, { -5, -5, 0, 0 }, { 5, 5, 0, 0 });
  ASSERT_TRUE(any.Feasible);
  EXPECT_NEAR(any.X[0] + any.X[1], 1.0, 1e-12);
}
