// CSG crease tiles (CsgCreaseCrossing.h): the crossing of two primitives'
// crease with a face tile is found where it is, named by its tile and placed
// where it was found, and refused where the tile holds no crease of two
// leaves, the crossing lies past a side, or (mesh leaves) the traces cross
// twice in it or a mesh vertex lies on its plane; with quadric leaves, and
// with mesh leaves (a Boolean of meshes, or of a mesh and a quadric).
#include "CsgCreaseCrossing.h"
#include "MeshBuilders.h"
#include "SceneBuilder.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
using tpc::FaceTile;
using tpc::LatticeIndex;
using tpctest::SceneBuilder;
using tpctest::Vec3;

/// A wedge: the intersection of two half-spaces whose planes meet along a
/// line oblique to every axis.
struct Wedge
{
  SceneBuilder B;
  tpc::RootGrid Grid = tpctest::SingleRoot({ -1, -1, -1 }, 2.0, 10);
  Vec3 N1{ 1.0, 0.0, 0.3 }, N2{ 0.0, 1.0, -0.2 };
  Wedge()
  {
    B.Finish(SceneBuilder::Intersection(
      { B.Add(tpc::Quadric::Plane({ 0.1, 0.0, 0.0 }, N1)), B.Add(tpc::Quadric::Plane({ 0.0, -0.05, 0.0 }, N2)) }));
  }
  /// Where the crease meets the plane z = z: n1.(p - (0.1, 0, 0)) = 0 and
  /// n2.(p - (0, -0.05, 0)) = 0.
  Vec3 CreaseAt(double z) const { return { 0.1 - 0.3 * z, -0.05 + 0.2 * z, z }; }
};

FaceTile TileAround(const tpc::RootGrid& grid, const Vec3& p, LatticeIndex size)
{
  const auto lattice = [&](int a) {
    return static_cast<LatticeIndex>(std::floor((p[a] - grid.Origin[a]) / grid.Spacing())) / size * size;
  };
  FaceTile t;
  t.U0 = lattice(0);
  t.V0 = lattice(1);
  t.U1 = t.U0 + size;
  t.V1 = t.V0 + size;
  return t;
}

/// In a sweep across the wedge's crease, every tile of a face between two
/// cells of level 6 is a crease tile for the scene pruned to either cell's
/// box or for neither, at the same point; the number of crease tiles.
int CreaseTilesDecidedAlike(const tpc::ImplicitScene& scene, const tpc::RootGrid& grid)
{
  int creaseTiles = 0;
  for (LatticeIndex plane = 400; plane < 700; plane += 16)
  {
    for (LatticeIndex i = 0; i < 1024; i += 16)
    {
      for (LatticeIndex j = 0; j < 1024; j += 16)
      {
        const FaceTile tile{ i, j, i + 16, j + 16 };
        const LatticeIndex above[3] = { i / 16, j / 16, plane / 16 }, below[3] = { i / 16, j / 16, plane / 16 - 1 };
        const auto upper = tpc::CsgExpression::Prune(scene.Expression, grid.CellBox(6, above), scene.Primitives);
        const auto lower = tpc::CsgExpression::Prune(scene.Expression, grid.CellBox(6, below), scene.Primitives);
        if (upper.Sign != tpc::RegionSign::Mixed || lower.Sign != tpc::RegionSign::Mixed)
        {
          continue;
        }
        const auto a = tpc::CsgCreaseOnTile(upper.Expression, scene.Primitives, grid, 2, plane, tile);
        const auto b = tpc::CsgCreaseOnTile(lower.Expression, scene.Primitives, grid, 2, plane, tile);
        EXPECT_EQ(a.has_value(), b.has_value()) << plane << " " << i << " " << j;
        if (a && b)
        {
          ++creaseTiles;
          EXPECT_EQ((*a)[0], (*b)[0]);
          EXPECT_EQ((*a)[1], (*b)[1]);
        }
      }
    }
  }
  return creaseTiles;
}
} // namespace

TEST(CsgCreaseCrossing, TwoPlanesCreaseIsFoundWhereItCrossesTheTile)
{
  const Wedge w;
  const LatticeIndex plane = 600; // z = -1 + 2 * 600 / 1024
  const double z = w.Grid.Coordinate(2, plane);
  const Vec3 expected = w.CreaseAt(z);
  const FaceTile tile = TileAround(w.Grid, expected, 16);
  const auto x = tpc::CsgCreaseOnTile(w.B.Scene.Expression, w.B.Scene.Primitives, w.Grid, 2, plane, tile);
  ASSERT_TRUE(x.has_value());
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_NEAR((*x)[a], expected[a], 1e-14);
  }
  // Named by its tile; placed by recomputing it, with the normal halfway
  // between the two planes'.
  const tpc::Crossing c = tpc::CsgCreaseCrossing(2, plane, tile);
  EXPECT_EQ(c.Kind, tpc::CrossingKind::CsgCrease);
  const auto vertex = tpc::CsgCreaseVertex(c, w.B.Scene.Expression, w.B.Scene.Primitives, w.Grid);
  ASSERT_TRUE(vertex.has_value());
  EXPECT_EQ(vertex->first[0], (*x)[0]);
  EXPECT_EQ(vertex->first[1], (*x)[1]);
  const Vec3 bisector = tpc::Normalized(tpc::Normalized(w.N1) + tpc::Normalized(w.N2));
  EXPECT_NEAR(tpc::Dot(vertex->second, bisector), 1.0, 1e-12);
  // The crossing lies on the tile's face of a cell above and of one below.
  LatticeIndex base[3] = { tile.U0, tile.V0, plane };
  EXPECT_EQ(tpc::CrossingFaces(c, base, 16), 1u << 4);
  base[2] = plane - 16;
  EXPECT_EQ(tpc::CrossingFaces(c, base, 16), 1u << 5);
}

TEST(CsgCreaseCrossing, BothCellsSharingATileDecideAlike)
{
  // The decision depends on the tile and the two leaves left there: with the
  // scene pruned to either cell's box, every tile of a face between two
  // cells, in a sweep across the crease, is a crease tile for both or for
  // neither, at the same point. (The extraction does not rely on the two
  // prunings agreeing - an enclosure deciding a leaf over one box need not
  // decide it over the tile - and decides with the first cell's expression.)
  const Wedge w;
  const int creaseTiles = CreaseTilesDecidedAlike(w.B.Scene, w.Grid);
  EXPECT_GT(creaseTiles, 10);
}

TEST(CsgCreaseCrossing, TilesWithoutACreaseOfTwoLeavesAreRefused)
{
  const Wedge w;
  const LatticeIndex plane = 600;
  const Vec3 expected = w.CreaseAt(w.Grid.Coordinate(2, plane));
  const FaceTile tile = TileAround(w.Grid, expected, 16);
  auto onTile = [&](const tpc::ImplicitScene& s, const FaceTile& t) {
    return tpc::CsgCreaseOnTile(s.Expression, s.Primitives, w.Grid, 2, plane, t).has_value();
  };
  // A tile beside the crease's: it crosses another.
  FaceTile beside = tile;
  beside.U0 += 32;
  beside.U1 += 32;
  EXPECT_FALSE(onTile(w.B.Scene, beside));
  // The crossing 0.5 % of the tile's width from a side is found (the margin
  // is a millionth: a crease cell needs its crease's crossings in tiles a
  // finer neighbour may have cut anywhere); one just past the side is not.
  const double spacing = w.Grid.Spacing();
  FaceTile edge;
  edge.U0 = static_cast<LatticeIndex>(std::floor((expected[0] - w.Grid.Origin[0]) / spacing - 0.005 * 512));
  edge.U1 = edge.U0 + 512;
  edge.V0 = tile.V0;
  edge.V1 = tile.V1;
  EXPECT_TRUE(onTile(w.B.Scene, edge));
  FaceTile past = edge;
  past.U0 = static_cast<LatticeIndex>(std::floor((expected[0] - w.Grid.Origin[0]) / spacing)) + 1;
  past.U1 = past.U0 + 512;
  EXPECT_FALSE(onTile(w.B.Scene, past));
  // One leaf (a sphere); no surface at all (just above a box's corner).
  SceneBuilder sphere;
  sphere.Finish(sphere.Sphere({ 0, 0, 0 }, 0.5));
  EXPECT_FALSE(onTile(sphere.Scene, TileAround(w.Grid, { 0.3, 0.3, 0.0 }, 64)));
  SceneBuilder corner;
  corner.Finish(corner.Box({ -0.5, -0.5, -0.5 }, { 0.2, 0.2, 0.2 }));
  FaceTile atCorner = TileAround(w.Grid, { 0.2, 0.2, 0.2 }, 64);
  EXPECT_FALSE(tpc::CsgCreaseOnTile(corner.Scene.Expression, corner.Scene.Primitives, w.Grid, 2,
    static_cast<LatticeIndex>((0.2 + 1.0) / spacing) + 3, atCorner)
                 .has_value());
  // The same tile just below the box's top face (z = 0.2): two side planes
  // (x = 0.2, y = 0.2) cross on it, the top is pruned away.
  EXPECT_TRUE(tpc::CsgCreaseOnTile(corner.Scene.Expression, corner.Scene.Primitives, w.Grid, 2,
    static_cast<LatticeIndex>((0.2 + 1.0) / spacing) - 40, atCorner)
                .has_value());
}

namespace
{
/// The half-space n.(p - centre) <= 0 near `centre` (n a unit normal) as a
/// closed mesh: a hexagon of side 6 on the plane, fanned from `centre`, and
/// an apex 5 below it, each face oriented away from a point inside.
tpc::MeshSolid FannedHalfSpace(const Vec3& centre, const Vec3& n)
{
  const Vec3 u = tpc::Normalized(tpc::Cross(n, std::fabs(n[0]) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
  const Vec3 v = tpc::Cross(n, u);
  std::vector<Vec3> p = { centre };
  for (int k = 0; k < 6; ++k)
  {
    p.push_back(centre + (u * std::cos(k * M_PI / 3.0) + v * std::sin(k * M_PI / 3.0)) * 6.0);
  }
  p.push_back(centre - n * 5.0);
  const Vec3 inside = centre - n * 1.0;
  tpctest::Triangles t;
  for (std::uint32_t k = 0; k < 6; ++k)
  {
    t.push_back({ 0, 1 + k, 1 + (k + 1) % 6 });
    t.push_back({ 7, 1 + (k + 1) % 6, 1 + k });
  }
  for (auto& f : t)
  {
    const Vec3 normal = tpc::Cross(p[f[1]] - p[f[0]], p[f[2]] - p[f[0]]);
    if (tpc::Dot(normal, p[f[0]] - inside) < 0.0)
    {
      std::swap(f[1], f[2]);
    }
  }
  return tpc::MeshSolid(p, t);
}
} // namespace

TEST(CsgCreaseCrossing, AMeshVertexOnTheTilesPlaneLeavesItStraight)
{
  // The wedge's first half-space as a mesh whose face on the plane is a fan
  // around a vertex in the tile, near the crease. With that vertex exactly on
  // the tile's plane the trace is not made of segments crossing it (the
  // triangles around it touch the plane there): refused, the tile drawn
  // straight (CsgCreaseCrossing.cxx, MeshTrace); a hair off the plane, the
  // crossing is found where the crease is.
  const Wedge w;
  const LatticeIndex plane = 600;
  const double z = w.Grid.Coordinate(2, plane);
  const Vec3 expected = w.CreaseAt(z);
  const FaceTile tile = TileAround(w.Grid, expected, 16);
  const Vec3 n1 = tpc::Normalized(w.N1);
  for (const double off : { 0.0, 1e-9 })
  {
    // On the first plane: x = 0.1 - 0.3 z' at height z'.
    const double height = z + off;
    const Vec3 centre{ 0.1 - 0.3 * height, expected[1] + 0.005, height };
    SceneBuilder b;
    const auto first = b.Mesh(FannedHalfSpace(centre, n1));
    const auto second = b.Mesh(FannedHalfSpace({ 0.0, -0.05, 0.0 }, tpc::Normalized(w.N2)));
    b.Finish(SceneBuilder::Intersection({ first, second }));
    const auto x = tpc::CsgCreaseOnTile(b.Scene.Expression, b.Scene.Primitives, w.Grid, 2, plane, tile);
    if (off == 0.0)
    {
      EXPECT_FALSE(x.has_value());
      continue;
    }
    ASSERT_TRUE(x.has_value());
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_NEAR((*x)[a], expected[a], 1e-8);
    }
  }
}

TEST(CsgCreaseCrossing, MeshLeavesCreaseIsFoundWhereItCrossesTheTile)
{
  // The wedge again, each half-space a mesh with a face on its plane (two
  // meshes), or one of them the plane (a mesh and a quadric): the crease is where the
  // two leaves' traces on the tile cross (CsgCreaseCrossing.cxx,
  // CrossingOfTraces), at the same point; a tile beside it is refused, and
  // the cells on both sides of a tile decide alike.
  const Wedge w;
  const Vec3 p1{ 0.1, 0.0, 0.0 }, p2{ 0.0, -0.05, 0.0 };
  for (const bool secondIsMesh : { true, false })
  {
    SceneBuilder b;
    const auto first = b.Mesh(FannedHalfSpace(p1, tpc::Normalized(w.N1)));
    const auto second =
      secondIsMesh ? b.Mesh(FannedHalfSpace(p2, tpc::Normalized(w.N2))) : b.Add(tpc::Quadric::Plane(p2, w.N2));
    b.Finish(SceneBuilder::Intersection({ first, second }));
    const LatticeIndex plane = 600;
    const Vec3 expected = w.CreaseAt(w.Grid.Coordinate(2, plane));
    const FaceTile tile = TileAround(w.Grid, expected, 16);
    const auto x = tpc::CsgCreaseOnTile(b.Scene.Expression, b.Scene.Primitives, w.Grid, 2, plane, tile);
    ASSERT_TRUE(x.has_value()) << secondIsMesh;
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_NEAR((*x)[a], expected[a], 1e-13) << secondIsMesh;
    }
    const tpc::Crossing c = tpc::CsgCreaseCrossing(2, plane, tile);
    const auto vertex = tpc::CsgCreaseVertex(c, b.Scene.Expression, b.Scene.Primitives, w.Grid);
    ASSERT_TRUE(vertex.has_value());
    EXPECT_EQ(vertex->first[0], (*x)[0]);
    EXPECT_EQ(vertex->first[1], (*x)[1]);
    const Vec3 bisector = tpc::Normalized(tpc::Normalized(w.N1) + tpc::Normalized(w.N2));
    EXPECT_NEAR(tpc::Dot(vertex->second, bisector), 1.0, 1e-12) << secondIsMesh;
    FaceTile beside = tile;
    beside.U0 += 32;
    beside.U1 += 32;
    EXPECT_FALSE(tpc::CsgCreaseOnTile(b.Scene.Expression, b.Scene.Primitives, w.Grid, 2, plane, beside));
    // Both cells sharing a tile decide alike, in a sweep across the crease.
    const int creaseTiles = CreaseTilesDecidedAlike(b.Scene, w.Grid);
    EXPECT_GT(creaseTiles, 10) << secondIsMesh;
  }
}

TEST(CsgCreaseCrossing, AMeshAndASphereCrossWhereTheirTracesDo)
{
  // A mesh's face on the wedge's first plane and a sphere of radius
  // 0.5 about the origin: on the plane z = c their traces, the line
  // x = 0.1 - 0.3 c and a circle, cross twice, at y = +-sqrt(0.25 - x^2 -
  // c^2) - a curved quadric, so the crossing is a root of a true quadratic
  // along the mesh's segment (CrossingsWithQuadric). A small tile around one
  // crossing finds it; a tile holding both is refused.
  const Wedge w;
  SceneBuilder b;
  const auto mesh = b.Mesh(FannedHalfSpace({ 0.1, 0.0, 0.0 }, tpc::Normalized(w.N1)));
  b.Finish(SceneBuilder::Intersection({ mesh, b.Sphere({ 0, 0, 0 }, 0.5) }));
  const LatticeIndex plane = 600;
  const double z = w.Grid.Coordinate(2, plane), x = 0.1 - 0.3 * z;
  const Vec3 expected{ x, std::sqrt(0.25 - x * x - z * z), z };
  const FaceTile tile = TileAround(w.Grid, expected, 16);
  const auto found = tpc::CsgCreaseOnTile(b.Scene.Expression, b.Scene.Primitives, w.Grid, 2, plane, tile);
  ASSERT_TRUE(found.has_value());
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_NEAR((*found)[a], expected[a], 1e-13);
  }
  const FaceTile both{ 512, 0, 1024, 1024 }; // x in [0, 1], y in [-1, 1]
  EXPECT_FALSE(tpc::CsgCreaseOnTile(b.Scene.Expression, b.Scene.Primitives, w.Grid, 2, plane, both).has_value());
  // The other crossing alone (y < 0) is found too.
  const FaceTile lower = TileAround(w.Grid, { expected[0], -expected[1], z }, 16);
  const auto other = tpc::CsgCreaseOnTile(b.Scene.Expression, b.Scene.Primitives, w.Grid, 2, plane, lower);
  ASSERT_TRUE(other.has_value());
  EXPECT_NEAR((*other)[1], -expected[1], 1e-13);
}
