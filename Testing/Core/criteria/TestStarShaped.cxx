// The star-shaped test accepts star-shaped configurations (a convex patch, a
// cap whose only witness is the sphere centre, the non-convex union of Fig.
// 3(a)) and rejects the paper's Fig. 2(e) (an overhang in the voxel) and
// Fig. 2(f) (a face cut in two pieces). Rejection must be sound: a witness is
// accepted only after interval verification.
#include "SceneBuilder.h"
#include "StarShapedCriterion.h"

#include <gtest/gtest.h>

using tpc::Box3;
using tpc::Vec3;
using tpctest::SceneBuilder;

TEST(StarShaped, AcceptsConvexPatch)
{
  SceneBuilder b;
  const auto e = b.Finish(b.Sphere({ 0, 0, 0 }, 1.0));
  const Box3 cell{ { 0.6, 0.6, 0.35 }, { 0.7, 0.7, 0.45 } };
  EXPECT_FALSE(e->IsInside(cell.Corner(7), b.Scene.Primitives));
  EXPECT_TRUE(e->IsInside(cell.Corner(0), b.Scene.Primitives));
  EXPECT_TRUE(tpc::IsStarShapedWithRespectToVoxel(e, b.Scene.Primitives, cell));
  for (int axis = 0; axis < 3; ++axis)
  {
    Box3 face = cell;
    face.hi[axis] = face.lo[axis];
    EXPECT_TRUE(tpc::IsStarShapedWithRespectToFace(e, b.Scene.Primitives, face, axis));
  }
}

TEST(StarShaped, AcceptsCapSeenOnlyFromTheCentre)
{
  // Most of a sphere inside the cell: its normals span more than a
  // hemisphere, so no direction works, but the centre does.
  SceneBuilder b;
  const Vec3 c{ 0.5, 0.5, 0.75 };
  const auto e = b.Finish(b.Sphere(c, 0.3));
  const Box3 cell{ { 0, 0, 0 }, { 1, 1, 1 } };
  EXPECT_TRUE(tpc::IsStarShapedWithRespectToVoxel(e, b.Scene.Primitives, cell));
  EXPECT_TRUE(tpc::VerifyStarWitness(*e, b.Scene.Primitives, cell, { c, 1.0 }, 4));
  EXPECT_FALSE(tpc::VerifyStarWitness(*e, b.Scene.Primitives, cell, { { 0, 0, -1 }, 0.0 }, 4));
}

TEST(StarShaped, AcceptsNonConvexUnionFig3a)
{
  // Fig. 3(a): star-shaped but not convex. Around the concave crease where two
  // overlapping spheres meet, the solid is seen whole from far along +y.
  SceneBuilder b;
  const auto e = b.Finish(
    SceneBuilder::Union({ b.Sphere({ -0.3, 0, 0 }, 0.5), b.Sphere({ 0.3, 0, 0 }, 0.5) }));
  const Box3 cell{ { -0.1, 0.3, -0.1 }, { 0.1, 0.5, 0.1 } };
  EXPECT_TRUE(e->IsInside({ 0.0, 0.3, 0.0 }, b.Scene.Primitives));
  EXPECT_FALSE(e->IsInside({ 0.0, 0.5, 0.0 }, b.Scene.Primitives));
  EXPECT_TRUE(tpc::IsStarShapedWithRespectToVoxel(e, b.Scene.Primitives, cell));
  EXPECT_TRUE(tpc::VerifyStarWitness(*e, b.Scene.Primitives, cell, { { 0, -1, 0 }, 0.0 }, 2));
}

TEST(StarShaped, RejectsOverhangFig2e)
{
  // A mushroom: slab, stem, and a cap overhanging the slab. A witness would
  // have to be below the slab top (to see it) and above the cap's underside
  // (to see that): none exists.
  SceneBuilder b;
  const auto e = b.Finish(SceneBuilder::Union({ b.Box({ -1, -1, -1 }, { 2, 2, 0.2 }),
    b.Cylinder({ 0.5, 0.5, 0 }, { 0, 0, 1 }, 0.08), b.Sphere({ 0.5, 0.5, 0.75 }, 0.25) }));
  const Box3 cell{ { 0, 0, 0 }, { 1, 1, 1 } };
  EXPECT_FALSE(tpc::IsStarShapedWithRespectToVoxel(e, b.Scene.Primitives, cell));
  // Soundness: no candidate on a grid of points and directions verifies.
  for (int i = 0; i <= 4; ++i)
  {
    for (int j = 0; j <= 4; ++j)
    {
      for (int k = 0; k <= 8; ++k)
      {
        const Vec3 p{ -0.5 + 0.5 * i, -0.5 + 0.5 * j, -1.0 + 0.375 * k };
        EXPECT_FALSE(tpc::VerifyStarWitness(*e, b.Scene.Primitives, cell, { p, 1.0 }, 4));
      }
    }
  }
  EXPECT_FALSE(tpc::VerifyStarWitness(*e, b.Scene.Primitives, cell, { { 0, 0, -1 }, 0.0 }, 4));
}

TEST(StarShaped, RejectsFaceCutInTwoFig2f)
{
  // Two pillars cross the face z = 0.5: its solid part is two discs.
  SceneBuilder b;
  const auto e = b.Finish(SceneBuilder::Union(
    { b.Cylinder({ 0.25, 0.5, 0 }, { 0, 0, 1 }, 0.1), b.Cylinder({ 0.75, 0.5, 0 }, { 0, 0, 1 }, 0.1) }));
  const Box3 face{ { 0, 0, 0.5 }, { 1, 1, 0.5 } };
  EXPECT_FALSE(tpc::IsStarShapedWithRespectToFace(e, b.Scene.Primitives, face, 2));
  // One pillar alone is star-shaped on the face.
  SceneBuilder one;
  const auto e1 = one.Finish(one.Cylinder({ 0.25, 0.5, 0 }, { 0, 0, 1 }, 0.1));
  EXPECT_TRUE(tpc::IsStarShapedWithRespectToFace(e1, one.Scene.Primitives, face, 2));
}

TEST(StarShaped, DifferenceUsesInvertedConstraints)
{
  // Box minus cylinder at the hole's rim: the hole wall faces the axis.
  SceneBuilder b;
  const auto e = b.Finish(SceneBuilder::Difference(
    { b.Box({ -1, -1, -0.3 }, { 1, 1, 0.3 }), b.Cylinder({ 0, 0, 0 }, { 0, 0, 1 }, 0.4) }));
  const Box3 rim{ { 0.35, -0.05, 0.25 }, { 0.45, 0.05, 0.35 } };
  EXPECT_TRUE(tpc::IsStarShapedWithRespectToVoxel(e, b.Scene.Primitives, rim));
}
