// Each loop's patch (LoopTriangulation.h): which of the three embedded
// triangulations is chosen, and where the apex of a fan goes.
#include "LoopTriangulation.h"
#include "SceneBuilder.h"

#include <gtest/gtest.h>

using tpc::Box3;
using tpc::LoopPatchKind;
using tpc::LoopPoint;
using tpc::Vec3;
using tpctest::SceneBuilder;

namespace
{
const Box3 Cell{ { 0, 0, 0 }, { 1, 1, 1 } };

/// Bit f of the cell faces (CubeTopology.h numbering) holding p.
unsigned FacesOf(const Vec3& p)
{
  unsigned faces = 0;
  for (int a = 0; a < 3; ++a)
  {
    faces |= (p[a] == 0.0 ? 1u : 0u) << (2 * a);
    faces |= (p[a] == 1.0 ? 1u : 0u) << (2 * a + 1);
  }
  return faces;
}

/// Loop points at `positions` with the normals of the solid `scene` there.
std::vector<LoopPoint> Loop(const tpc::ImplicitScene& scene, const std::vector<Vec3>& positions)
{
  std::vector<LoopPoint> loop;
  for (const Vec3& p : positions)
  {
    loop.push_back({ p, Normalized(scene.Expression->Gradient(p, scene.Primitives)), FacesOf(p) });
  }
  return loop;
}

/// Every fan triangle (p_k, p_k+1, apex) faces the way the surface does.
void ExpectFanFacesOutward(const std::vector<LoopPoint>& loop, const Vec3& apex)
{
  for (std::size_t k = 0; k < loop.size(); ++k)
  {
    const LoopPoint &a = loop[k], &b = loop[(k + 1) % loop.size()];
    EXPECT_GT(Dot(Cross(b.Position - a.Position, apex - a.Position), a.Normal + b.Normal), 0.0) << k;
  }
}
} // namespace

TEST(LoopTriangulation, ThreePointsNotOnOneFaceAreATriangle)
{
  SceneBuilder b;
  b.Finish(b.Sphere({ 0, 0, 0 }, 0.5));
  const auto loop = Loop(b.Scene, { { 0.5, 0, 0 }, { 0, 0.5, 0 }, { 0, 0, 0.5 } });
  EXPECT_EQ(tpc::TriangulateLoop(loop, tpc::ApexRoom{ Cell, {} }, false, *b.Scene.Expression, b.Scene.Primitives).Kind,
    LoopPatchKind::Triangle);
}

TEST(LoopTriangulation, SmoothLoopIsMarchingCubesFan)
{
  // A gently tilted plane through the four vertical edges: k - 2 triangles
  // from a loop point that shares no face with the non-adjacent points.
  SceneBuilder b;
  b.Finish(b.Add(tpc::Quadric::Plane({ 0.5, 0.5, 0.5 }, { 0.1, 0.2, 1.0 })));
  std::vector<Vec3> positions;
  for (const auto& xy : { std::pair<double, double>{ 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } })
  {
    const double z = 0.5 - (0.1 * (xy.first - 0.5) + 0.2 * (xy.second - 0.5));
    positions.push_back({ xy.first, xy.second, z });
  }
  const auto loop = Loop(b.Scene, positions);
  const tpc::LoopPatch patch = tpc::TriangulateLoop(loop, tpc::ApexRoom{ Cell, {} }, false, *b.Scene.Expression, b.Scene.Primitives);
  ASSERT_EQ(patch.Kind, LoopPatchKind::LoopFan);
  ASSERT_GE(patch.FanPoint, 0);
  const auto s = static_cast<std::size_t>(patch.FanPoint);
  EXPECT_EQ(loop[s].Faces & loop[(s + 2) % 4].Faces, 0u);
}

TEST(LoopTriangulation, CreaseApexIsTheFeaturePoint)
{
  // The edge x = y = 1/2 of the quarter space x, y < 1/2 crosses the cell:
  // the tangent planes at the four crossings meet on the crease, where the
  // fan's apex goes (as Extended Marching Cubes places it).
  SceneBuilder b;
  b.Finish(SceneBuilder::Intersection({ b.Add(tpc::Quadric::Plane({ 0.5, 0, 0 }, { 1, 0, 0 })),
    b.Add(tpc::Quadric::Plane({ 0, 0.5, 0 }, { 0, 1, 0 })) }));
  // (Loops run counter-clockwise seen from outside the solid.)
  const auto loop = Loop(b.Scene, { { 0.5, 0, 0 }, { 0, 0.5, 0 }, { 0, 0.5, 1 }, { 0.5, 0, 1 } });
  const tpc::LoopPatch patch = tpc::TriangulateLoop(loop, tpc::ApexRoom{ Cell, {} }, false, *b.Scene.Expression, b.Scene.Primitives);
  ASSERT_EQ(patch.Kind, LoopPatchKind::ApexFan);
  EXPECT_NEAR(patch.Apex[0], 0.5, 1e-12);
  EXPECT_NEAR(patch.Apex[1], 0.5, 1e-12);
  EXPECT_TRUE(tpc::StrictlyInside(patch.Apex, Cell));
  ExpectFanFacesOutward(loop, patch.Apex);
}

TEST(LoopTriangulation, CreaseFanRunsAlongTheCrease)
{
  // The same quarter space, its loop drawn through the crease's crossings
  // x1 = (1/2, 1/2, 0) and x2 = (1/2, 1/2, 1) (crease tiles,
  // CreaseCrossing.h). Fanned from x1 or x2 the diagonal x1 -> x2 is the
  // crease, and the other triangles lie in the two planes: four triangles,
  // where the apex fan takes six and draws the crease as two spokes.
  SceneBuilder b;
  b.Finish(SceneBuilder::Intersection({ b.Add(tpc::Quadric::Plane({ 0.5, 0, 0 }, { 1, 0, 0 })),
    b.Add(tpc::Quadric::Plane({ 0, 0.5, 0 }, { 0, 1, 0 })) }));
  auto loop =
    Loop(b.Scene, { { 0.5, 0, 0 }, { 0.5, 0.5, 0 }, { 0, 0.5, 0 }, { 0, 0.5, 1 }, { 0.5, 0.5, 1 }, { 0.5, 0, 1 } });
  for (const std::size_t x : { std::size_t(1), std::size_t(4) })
  {
    loop[x].OnMeshEdge = true;
    loop[x].Normal = Normalized(Vec3{ 1, 1, 0 });
  }
  EXPECT_EQ(tpc::LoopFanPoint(loop), -1); // not smooth along the loop
  const int s = tpc::MeshEdgeFanPoint(loop);
  ASSERT_TRUE(s == 1 || s == 4) << s;
  const auto k = static_cast<std::size_t>(s);
  const Vec3 x = loop[k].Position;
  for (std::size_t i = 1; i + 1 < loop.size(); ++i)
  {
    const Vec3& p = loop[(k + i) % loop.size()].Position;
    const Vec3& q = loop[(k + i + 1) % loop.size()].Position;
    // In the plane x = 1/2 or y = 1/2, facing out of the quarter space.
    const Vec3 n = Cross(p - x, q - x);
    const bool inX = p[0] == 0.5 && q[0] == 0.5, inY = p[1] == 0.5 && q[1] == 0.5;
    EXPECT_TRUE(inX || inY) << i;
    EXPECT_GT(Dot(n, inX ? Vec3{ 1, 0, 0 } : Vec3{ 0, 1, 0 }), 0.0) << i;
  }
  // Without its crease points, or with a crease point sharing its face with
  // a point other than its neighbours, there is no crease fan.
  auto plain = loop;
  plain[1].OnMeshEdge = plain[4].OnMeshEdge = false;
  EXPECT_EQ(tpc::MeshEdgeFanPoint(plain), -1);
  auto crowded = loop;
  crowded[4].OnMeshEdge = false;
  crowded[3].Faces |= crowded[1].Faces; // as if (0, 1/2, 1) lay on z = 0 too
  EXPECT_EQ(tpc::MeshEdgeFanPoint(crowded), -1);
}

TEST(LoopTriangulation, MeshEdgePointRoundedOntoASideIsNoFanEnd)
{
  // A mesh edge's point names one face (its lattice plane); computed
  // strictly inside that face it lies on it alone, rounded onto a side of
  // it the faces it lies on are unknown: all six.
  const unsigned x0 = 1u, y0 = 4u; // faces x = 0 and y = 0 (CubeTopology.h numbering)
  EXPECT_EQ(tpc::FacesAsPlaced(x0, true, { 0, 0.3, 0.5 }, Cell), x0);
  EXPECT_EQ(tpc::FacesAsPlaced(x0, true, { 0, 0.0, 0.5 }, Cell), 0x3Fu);
  EXPECT_EQ(tpc::FacesAsPlaced(x0, true, { 0, 0.3, 1.0 }, Cell), 0x3Fu);
  EXPECT_EQ(tpc::FacesAsPlaced(x0 | y0, false, { 0, 0.0, 0.5 }, Cell), x0 | y0); // (a sub-edge's crossing)
  // A loop through an exact neighbour's trace point q on the face x = 0
  // that rounded onto its side y = 0 (so it lies on y = 0 as well), then a on
  // x = 0 and z = 0, b on y = 0 and z = 0, c inside y = 0; the surface smooth
  // along it. Read as lying on x = 0 alone, q is the fan point with the
  // shortest diagonal, q -> b, which lies in the face y = 0 - on the cell's
  // boundary, where the output is not embedded. As placed, no fan has q (or
  // b, whose diagonal is the same) as its point.
  const Vec3 normal = Normalized(Vec3{ -0.5, 0.3, -0.8 });
  std::vector<LoopPoint> loop{ { { 0, 0, 0.2 }, normal, x0 }, { { 0, 0.9, 0 }, normal, x0 | 16u },
    { { 0.5, 0, 0 }, normal, y0 | 16u }, { { 0.05, 0, 0.15 }, normal, y0 } };
  LoopPoint& q = loop[0];
  q.OnMeshEdge = true;
  // (Its faces as its crossing names them.)
  EXPECT_EQ(tpc::LoopFanPoint(loop), 0);
  EXPECT_EQ(tpc::MeshEdgeFanPoint(loop), 0);
  q.Faces = tpc::FacesAsPlaced(x0, true, q.Position, Cell);
  const int s = tpc::LoopFanPoint(loop);
  EXPECT_TRUE(s == -1 || s == 1 || s == 3) << s; // none, or from a or c: diagonal a -> c
  EXPECT_EQ(tpc::MeshEdgeFanPoint(loop), -1);
}

TEST(LoopTriangulation, CapApexIsStrictlyInsideItsRegion)
{
  // A sphere bulging through the top face: its eight crossings all lie on
  // the face z = 1. The apex goes strictly inside the cell, 1/32 of it away
  // from every face (the patch must meet the cell boundary in its loop
  // only), where the fan faces the way the surface does.
  SceneBuilder b;
  const Vec3 c{ 0.5, 0.5, 1.3 };
  const double r = 0.75;
  b.Finish(b.Sphere(c, r));
  const double d = std::sqrt(r * r - 0.09 - 0.25); // where the circle meets each face edge
  const auto loop = Loop(b.Scene, { { 0, 0.5 - d, 1 }, { 0, 0.5 + d, 1 }, { 0.5 - d, 1, 1 }, { 0.5 + d, 1, 1 },
                                    { 1, 0.5 + d, 1 }, { 1, 0.5 - d, 1 }, { 0.5 + d, 0, 1 }, { 0.5 - d, 0, 1 } });
  const tpc::LoopPatch patch = tpc::TriangulateLoop(loop, tpc::ApexRoom{ Cell, {} }, false, *b.Scene.Expression, b.Scene.Primitives);
  ASSERT_EQ(patch.Kind, LoopPatchKind::ApexFan);
  EXPECT_TRUE(tpc::StrictlyInside(patch.Apex, Cell));
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_GE(patch.Apex[a], 1.0 / 32 - 1e-12);
    EXPECT_LE(patch.Apex[a], 1.0 - 1.0 / 32 + 1e-12);
  }
  ExpectFanFacesOutward(loop, patch.Apex);
}

