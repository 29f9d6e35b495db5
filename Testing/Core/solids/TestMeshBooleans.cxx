// Booleans of two meshes through the core's entry point against the exact
// Boolean's topology, computed independently by CGAL's corefinement
// (Testing/Oracles/CgalBoolean.h), and its distance to the exact surface
// against the reported bound (CgalHausdorff.h) - the oracles that the fuzz target
// FuzzBooleans asks on random pairs, first checked here on Booleans whose
// topology is known by construction.
#include "CgalBoolean.h"
#include "CoreContour.h"
#include "MeshBuilders.h"
#include "SceneBuilder.h"

#include <gtest/gtest.h>

#include <string>

using tpc::CsgTerm;
using tpc::MeshSolid;
using tpc::Vec3;
using tpcoracle::BooleanOperation;

namespace
{
tpcoracle::BooleanTopology Exact(const MeshSolid& a, const MeshSolid& b, BooleanOperation operation)
{
  return tpcoracle::ExactBooleanTopology(
    tpctest::SoupOf(a.Points(), a.Triangles()), tpctest::SoupOf(b.Points(), b.Triangles()), operation);
}

/// Expects the oracle's answer `components`, `genus` (or no reference).
void ExpectExact(const MeshSolid& a, const MeshSolid& b, BooleanOperation operation, bool valid,
  long long components = 0, long long genus = 0)
{
  const tpcoracle::BooleanTopology exact = Exact(a, b, operation);
  if (!exact.Checked)
  {
    GTEST_SKIP() << "TPC_SKIP_CGAL_ORACLE is set";
  }
  ASSERT_EQ(exact.Valid, valid);
  if (valid)
  {
    EXPECT_EQ(exact.Components, components);
    EXPECT_EQ(exact.Genus, genus);
  }
}

tpctest::ContourRun ContourBoolean(const MeshSolid& a, const MeshSolid& b, CsgTerm::Op op, double tolerance)
{
  tpctest::SceneBuilder builder;
  const CsgTerm ta = builder.Mesh(a), tb = builder.Mesh(b);
  builder.Finish(CsgTerm::Combine(op, { ta, tb }));
  return tpctest::Contour(builder.Scene, tpctest::BoundsOfBoth(a, b), tolerance);
}
} // namespace

TEST(MeshBooleans, TheOracleGivesTheTopologyOfBooleansKnownByConstruction)
{
  const MeshSolid cube = tpctest::CubeMesh({ -0.5, -0.5, -0.5 }, { 0.5, 0.5, 0.5 });
  const MeshSolid overlapping = tpctest::CubeMesh({ -0.2, -0.3, -0.4 }, { 0.8, 0.7, 0.6 });
  const MeshSolid far = tpctest::CubeMesh({ 2, 2, 2 }, { 3, 3, 3 });
  ExpectExact(cube, overlapping, BooleanOperation::Union, true, 1, 0);
  ExpectExact(cube, overlapping, BooleanOperation::Intersection, true, 1, 0);
  ExpectExact(cube, far, BooleanOperation::Union, true, 2, 0);
  ExpectExact(cube, far, BooleanOperation::Intersection, true, 0, 0); // (empty)
  ExpectExact(cube, far, BooleanOperation::Difference, true, 1, 0);
  // A box minus a torus inside it: the box's boundary and the void's, a torus.
  const MeshSolid box = tpctest::CubeMesh({ -1, -1, -0.5 }, { 1, 1, 0.5 });
  const MeshSolid ring = tpctest::TorusMesh({ 0, 0, 0 }, 0.6, 0.2, 16, 8);
  ExpectExact(box, ring, BooleanOperation::Difference, true, 2, 1);
  // A standing ring through a slab: its arcs above and below the slab are
  // two handles of the union.
  const MeshSolid slab = tpctest::CubeMesh({ -1, -1, -0.1 }, { 1, 1, 0.1 });
  const MeshSolid standing = tpctest::AffineMesh(ring, { 1, 1, 1 }, { 1, 0, 0 }, 1.5707963267948966, { 0, 0, 0 });
  ExpectExact(slab, standing, BooleanOperation::Union, true, 1, 2);
  // Two boxes sharing only an edge: the union's boundary is pinched there;
  // only a corner: corefinement makes no intersection line and leaves the
  // two touching there, which the oracle refuses too.
  const MeshSolid edgeNeighbour = tpctest::CubeMesh({ 0.5, 0.5, -0.5 }, { 1.5, 1.5, 0.5 });
  ExpectExact(cube, edgeNeighbour, BooleanOperation::Union, false);
  const MeshSolid cornerNeighbour = tpctest::CubeMesh({ 0.5, 0.5, 0.5 }, { 1.5, 1.5, 1.5 });
  ExpectExact(cube, cornerNeighbour, BooleanOperation::Union, false);
}

TEST(MeshBooleans, GuaranteedBooleansOfTurnedSolidsHaveTheExactTopologyWithinTheBound)
{
  // Tilted pairs whose surfaces cross: an icosphere through a torus's ring,
  // a box through a torus, two linked tori whose tubes overlap (each core
  // circle passes through the other's centre; the circles come within 0.45
  // of each other, less than the two tubes' radii of 0.26).
  const MeshSolid sphere = tpctest::SphereMesh({ 0, 0, 0 }, 0.5, 2);
  const MeshSolid torus = tpctest::TorusMesh({ 0, 0, 0 }, 0.45, 0.18, 16, 10);
  const MeshSolid thick = tpctest::TorusMesh({ 0, 0, 0 }, 0.45, 0.26, 16, 10);
  const MeshSolid cube = tpctest::CubeMesh({ -0.5, -0.5, -0.5 }, { 0.5, 0.5, 0.5 });
  const Vec3 tilt = tpc::Normalized(Vec3(0.3, 1.0, 0.2));
  struct Case
  {
    MeshSolid A, B;
  };
  const std::vector<Case> cases = {
    { tpctest::AffineMesh(torus, { 1, 1, 1 }, tilt, 0.4, { 0, 0, 0 }),
      tpctest::AffineMesh(sphere, { 0.4, 0.4, 1.0 }, tilt, 1.1, { 0.45, 0.05, 0.02 }) },
    { tpctest::AffineMesh(cube, { 0.3, 0.3, 1.2 }, tilt, 0.7, { 0.43, 0.02, 0.01 }),
      tpctest::AffineMesh(torus, { 1, 1, 1 }, tilt, 0.2, { 0, 0, 0 }) },
    { tpctest::AffineMesh(thick, { 1, 1, 1 }, { 1, 0, 0 }, 1.5707963, { 0.45, 0.01, 0.02 }),
      tpctest::AffineMesh(thick, { 1, 1, 1 }, tilt, 0.05, { 0, 0, 0 }) },
  };
  const std::pair<CsgTerm::Op, BooleanOperation> ops[] = { { CsgTerm::Op::Union, BooleanOperation::Union },
    { CsgTerm::Op::Intersection, BooleanOperation::Intersection },
    { CsgTerm::Op::Difference, BooleanOperation::Difference } };
  for (std::size_t k = 0; k < cases.size(); ++k)
  {
    for (const auto& [op, exactOp] : ops)
    {
      const tpcoracle::BooleanTopology exact = Exact(cases[k].A, cases[k].B, exactOp);
      if (!exact.Checked)
      {
        GTEST_SKIP() << "TPC_SKIP_CGAL_ORACLE is set";
      }
      ASSERT_TRUE(exact.Valid) << "case " << k;
      ASSERT_TRUE(exact.SurfacesMeet) << "case " << k;
      const tpctest::ContourRun r = ContourBoolean(cases[k].A, cases[k].B, op, 1.0 / 32.0);
      const std::string which = "case " + std::to_string(k) + ", operation " + std::to_string(static_cast<int>(op));
      ASSERT_TRUE(r.Guaranteed) << which;
      EXPECT_EQ(r.ReportedComponents, exact.Components) << which;
      EXPECT_EQ(r.ReportedGenus, exact.Genus) << which;
      EXPECT_TRUE(tpctest::DistanceWithinBound(r, exact.Surface)) << which << ": bound " << r.HausdorffBound;
    }
  }
}
