// Face refinement (FaceRefinement.h) and the exact edge crossings the
// extraction places (EdgeCrossings.h).
#include "CellSignCache.h"
#include "ComplexCellCriterion.h"
#include "EdgeCrossings.h"
#include "ExactCellCriterion.h"
#include "FaceDecisionCache.h"
#include "FaceRefinement.h"
#include "MeshBooleanSurface.h"
#include "MeshBuilders.h"
#include "SceneBuilder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <thread>

using tpc::FaceTile;
using tpc::Vec3;
using tpctest::SceneBuilder;

namespace
{
/// A unit root cell with a lattice of 2^10 spacings.
tpc::RootGrid UnitGrid()
{
  return tpctest::SingleRoot({ 0, 0, 0 }, 1.0, 10);
}
constexpr std::uint32_t Side = 1024;

/// Tiles that cover [0, Side]^2 exactly: inside it, of total area Side^2, no
/// two overlapping.
void ExpectTiling(const std::vector<FaceTile>& tiles)
{
  std::uint64_t area = 0;
  for (std::size_t i = 0; i < tiles.size(); ++i)
  {
    const FaceTile& t = tiles[i];
    ASSERT_TRUE(t.U0 < t.U1 && t.V0 < t.V1 && t.U1 <= Side && t.V1 <= Side);
    area += std::uint64_t(t.U1 - t.U0) * (t.V1 - t.V0);
    for (std::size_t j = i + 1; j < tiles.size(); ++j)
    {
      const FaceTile& o = tiles[j];
      ASSERT_FALSE(t.U0 < o.U1 && o.U0 < t.U1 && t.V0 < o.V1 && o.V0 < t.V1) << i << " overlaps " << j;
    }
  }
  EXPECT_EQ(area, std::uint64_t(Side) * Side);
}

/// Three scenes of meshes in [-1, 1]^3, built in `scenes`: a tilted cube's
/// edges and corners, a torus, and a sphere's mesh minus the cube's; their
/// expressions.
std::vector<tpc::CsgExpressionPtr> MeshScenes(std::vector<SceneBuilder>& scenes)
{
  const tpc::MeshSolid cube = tpctest::TiltedMesh(tpctest::CubeMesh({ -0.5, -0.5, -0.5 }, { 0.5, 0.5, 0.5 }));
  std::vector<tpc::CsgExpressionPtr> expressions;
  expressions.push_back(scenes[0].Finish(scenes[0].Mesh(cube)));
  expressions.push_back(scenes[1].Finish(scenes[1].Mesh(tpctest::TorusMesh({ 0.05, 0.02, 0.01 }, 0.55, 0.2, 40, 16))));
  expressions.push_back(scenes[2].Finish(SceneBuilder::Difference(
    { scenes[2].Mesh(tpctest::SphereMesh({ 0.1, 0.05, 0 }, 0.7, 3)), scenes[2].Mesh(cube) })));
  return expressions;
}
} // namespace

TEST(FaceRefinement, TilesCoverTheFaceAndEachPassesTheFaceTests)
{
  // The sharp wedge of ComplexCell.SharpCreaseIsResolvedByRefiningFaces,
  // on the face z = 1/2: wherever its crease pierces the face, the face is
  // tiled so that every tile passes on its own corners.
  const tpc::RootGrid grid = UnitGrid();
  int refined = 0;
  for (int k = 0; k < 40; ++k)
  {
    SceneBuilder b;
    const Vec3 through{ 0.5 + 0.4 * std::sin(1.3 * k), 0.5 + 0.3 * std::cos(0.7 * k), 0.5 };
    const auto e = b.Finish(SceneBuilder::Union({ b.Add(tpc::Quadric::Plane(through, { 1.0, 0.3, 0.15 })),
      b.Add(tpc::Quadric::Plane(through, { -1.0, 0.35, 0.1 })) }));
    const auto& prims = b.Scene.Primitives;
    tpc::LatticeSignTable global;
    tpc::CellSignCache signs(global, grid, *e, prims);
    const tpc::FaceRefinementResult r =
      tpc::RefineFace(e, prims, grid, 2, Side / 2, { 0, 0, Side, Side }, 10, signs);
    ASSERT_EQ(r.Failure, tpc::SplitReason::None) << k;
    ExpectTiling(r.Tiles);
    refined += r.Tiles.size() > 1 ? 1 : 0;
    for (const FaceTile& t : r.Tiles)
    {
      tpc::Box3 face;
      face.lo = { grid.Coordinate(0, t.U0), grid.Coordinate(1, t.V0), 0.5 };
      face.hi = { grid.Coordinate(0, t.U1), grid.Coordinate(1, t.V1), 0.5 };
      const bool inside[4] = { e->IsInside({ face.lo[0], face.lo[1], 0.5 }, prims),
        e->IsInside({ face.hi[0], face.lo[1], 0.5 }, prims), e->IsInside({ face.hi[0], face.hi[1], 0.5 }, prims),
        e->IsInside({ face.lo[0], face.hi[1], 0.5 }, prims) };
      EXPECT_EQ(tpc::FaceCompatibilityTest(e, prims, face, 2, inside), tpc::SplitReason::None);
    }
    // Every tile corner was sampled, exactly, and is kept for the table.
    for (const FaceTile& t : r.Tiles)
    {
      for (int c = 0; c < 4; ++c)
      {
        const tpc::PointKey key = tpc::TileCorner(2, Side / 2, t, c);
        const auto it = std::find_if(signs.NewSigns().begin(), signs.NewSigns().end(),
          [key](const auto& sign) { return sign.first == key; });
        ASSERT_NE(it, signs.NewSigns().end());
        EXPECT_EQ(it->second, e->IsInside(grid.Point(key), prims));
      }
    }
  }
  EXPECT_GT(refined, 10);
}

TEST(FaceRefinement, GivesUpWithinItsLevelsOnATangency)
{
  // A sphere touching the face z = 1/2 from below at its centre: the face
  // meets the surface at a point without a sign change, at every level (a
  // complex face, then tiles whose edges end at the touching point).
  const tpc::RootGrid grid = UnitGrid();
  SceneBuilder b;
  const auto e = b.Finish(b.Sphere({ 0.5, 0.5, 0.3 }, 0.2));
  tpc::LatticeSignTable global;
  tpc::CellSignCache signs(global, grid, *e, b.Scene.Primitives);
  const tpc::FaceRefinementResult whole =
    tpc::RefineFace(e, b.Scene.Primitives, grid, 2, Side / 2, { 0, 0, Side, Side }, 0, signs);
  EXPECT_TRUE(whole.Tiles.empty());
  EXPECT_EQ(whole.Failure, tpc::SplitReason::ComplexFace);
  const tpc::FaceRefinementResult refined =
    tpc::RefineFace(e, b.Scene.Primitives, grid, 2, Side / 2, { 0, 0, Side, Side }, 3, signs);
  EXPECT_TRUE(refined.Tiles.empty());
  EXPECT_TRUE(refined.Failure == tpc::SplitReason::ComplexFace || refined.Failure == tpc::SplitReason::ComplexEdge)
    << tpc::SplitReasonName(refined.Failure);
  // The circle where the sphere crosses z = 1/4 lies inside that face, away
  // from its corners: refining the face resolves it.
  const tpc::FaceRefinementResult circle =
    tpc::RefineFace(e, b.Scene.Primitives, grid, 2, Side / 4, { 0, 0, Side, Side }, 3, signs);
  EXPECT_EQ(circle.Failure, tpc::SplitReason::None);
  EXPECT_GT(circle.Tiles.size(), 1u);
  ExpectTiling(circle.Tiles);
}

TEST(EdgeCrossings, FoundOnTheExactSurfaceInsideTheSegment)
{
  // A sphere, a CSG union (regula falsi on the field), a difference, and a
  // mesh (exact bisection, or the crossed triangle's plane).
  SceneBuilder b;
  const auto sphere = b.Finish(b.Sphere({ 0.3, 0.2, 0.1 }, 0.45));
  const Vec3 a{ 0.3, 0.2, 0.1 }, z{ 0.3, 0.2, 1.0 };
  const Vec3 p = tpc::FindEdgeCrossing(*sphere, b.Scene.Primitives, a, z, true);
  EXPECT_NEAR(p[2], 0.55, 1e-13);
  EXPECT_EQ(p[0], 0.3);
  EXPECT_EQ(p[1], 0.2);

  SceneBuilder u;
  const auto both = u.Finish(SceneBuilder::Difference({ SceneBuilder::Union({ u.Sphere({ 0, 0, 0 }, 0.5),
    u.Sphere({ 0.6, 0, 0 }, 0.4) }), u.Sphere({ 0.9, 0, 0 }, 0.05) }));
  // Inside the union at 0.5, in the subtracted sphere (outside) at 0.9: its
  // wall at 0.85 is the one crossing.
  const Vec3 q = tpc::FindEdgeCrossing(*both, u.Scene.Primitives, { 0.5, 0, 0 }, { 0.9, 0, 0 }, true);
  EXPECT_NEAR(q[0], 0.85, 1e-12);

  SceneBuilder m;
  const auto cube = m.Finish(m.Mesh(tpctest::CubeMesh({ 0, 0, 0 }, { 1, 1, 1 })));
  const Vec3 s = tpc::FindEdgeCrossing(*cube, m.Scene.Primitives, { 0.25, 0.5, 0.5 }, { 0.25, 0.5, 1.5 }, true);
  EXPECT_NEAR(s[2], 1.0, 1e-12);
  EXPECT_EQ(s[0], 0.25);
}

TEST(EdgeCrossings, WhereMeshesMeetTheCrossingBracketsAChangeOfTheExactSign)
{
  // A sphere's mesh and a tilted cube's in each operation, pruned to boxes
  // as cells' expressions are (every leaf a mesh with its box's triangles:
  // the leaves' own crossings, checked against the exact signs), and
  // lattice-like segments along each axis whose ends differ: the point found
  // must lie within a few units in the last place (of the ends' coordinate)
  // of an exact change of the expression's sign - where two meshes cross
  // near the segment too.
  const tpc::MeshSolid ball = tpctest::SphereMesh({ 0.1, 0.05, 0 }, 0.5, 2);
  const tpc::MeshSolid box = tpctest::TiltedMesh(tpctest::CubeMesh({ -0.35, -0.35, -0.35 }, { 0.35, 0.35, 0.35 }));
  std::uint64_t state = 12345;
  const auto uniform = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  int checked = 0, bothMeshesCrossed = 0;
  for (const auto op : { tpc::CsgTerm::Op::Union, tpc::CsgTerm::Op::Intersection, tpc::CsgTerm::Op::Difference })
  {
    SceneBuilder b;
    const auto expression = b.Finish(tpc::CsgTerm::Combine(op, { b.Mesh(ball), b.Mesh(box) }));
    const tpc::PrimitiveSet& prims = b.Scene.Primitives;
    for (int cell = 0; cell < 60; ++cell)
    {
      const Vec3 lo{ -0.6 + 1.1 * uniform(), -0.6 + 1.1 * uniform(), -0.6 + 1.1 * uniform() };
      const double width = 0.1;
      const tpc::Box3 region{ lo, lo + Vec3(width, width, width) };
      const auto pruned = tpc::CsgExpression::Prune(expression, region, prims);
      if (pruned.Sign != tpc::RegionSign::Mixed || !tpc::IsMeshBoolean(*pruned.Expression))
      {
        continue;
      }
      for (int segment = 0; segment < 20; ++segment)
      {
        const int axis = segment % 3;
        Vec3 a{ lo[0] + width * uniform(), lo[1] + width * uniform(), lo[2] + width * uniform() };
        a[axis] = lo[axis];
        Vec3 z = a;
        z[axis] = lo[axis] + width;
        const bool insideA = pruned.Expression->IsInside(a, prims);
        if (insideA == pruned.Expression->IsInside(z, prims))
        {
          continue;
        }
        const Vec3 p = tpc::FindEdgeCrossing(*pruned.Expression, prims, a, z, insideA);
        // (Units of the larger end's coordinate: the scale a point of the
        // segment is rounded on.)
        const double scale = std::max(std::fabs(a[axis]), std::fabs(z[axis]));
        const double ulp = std::nextafter(scale, HUGE_VAL) - scale;
        Vec3 before = p, after = p;
        before[axis] -= 4.0 * ulp;
        after[axis] += 4.0 * ulp;
        for (int k = 0; k < 3; ++k)
        {
          if (k != axis)
          {
            ASSERT_EQ(p[k], a[k]);
          }
        }
        ASSERT_TRUE(p[axis] >= a[axis] && p[axis] <= z[axis]);
        EXPECT_EQ(pruned.Expression->IsInside(before, prims), insideA) << "segment " << checked;
        EXPECT_NE(pruned.Expression->IsInside(after, prims), insideA) << "segment " << checked;
        ++checked;
        int crossed = 0;
        for (const tpc::MeshSolid* m : { &prims.Meshes[0], &prims.Meshes[1] })
        {
          crossed += (m->IsInside(a) != m->IsInside(z)) ? 1 : 0;
        }
        bothMeshesCrossed += crossed == 2 ? 1 : 0;
      }
    }
  }
  EXPECT_GT(checked, 200);
  EXPECT_GT(bothMeshesCrossed, 10);
}

TEST(FaceRefinement, TilesOfMeshesPassWithTheWholeMeshListed)
{
  // Each tile is tested with the expression pruned to it (its mesh leaves
  // listing only the triangles that may meet it: FaceRefinement.cxx), its
  // children with theirs. A tile so passed must pass with every triangle of
  // the scene listed too: a tilted cube's edges and corners, a torus, and a
  // sphere's mesh minus the cube's, cut by faces of the unit lattice at many
  // heights.
  const tpc::RootGrid grid = tpctest::SingleRoot({ -1, -1, -1 }, 2.0, 10);
  std::vector<SceneBuilder> scenes(3);
  const std::vector<tpc::CsgExpressionPtr> expressions = MeshScenes(scenes);
  int refined = 0, tiles = 0;
  for (std::size_t s = 0; s < scenes.size(); ++s)
  {
    const tpc::PrimitiveSet& prims = scenes[s].Scene.Primitives;
    const tpc::CsgExpressionPtr& e = expressions[s];
    tpc::LatticeSignTable global;
    tpc::CellSignCache signs(global, grid, *e, prims);
    for (int axis = 0; axis < 3; ++axis)
    {
      for (tpc::LatticeIndex plane = 64; plane < Side; plane += 96)
      {
        const tpc::FaceRefinementResult r =
          tpc::RefineFace(e, prims, grid, axis, plane, { 0, 0, Side, Side }, 8, signs);
        if (r.Failure != tpc::SplitReason::None)
        {
          continue;
        }
        ExpectTiling(r.Tiles);
        refined += r.Tiles.size() > 1 ? 1 : 0;
        for (const FaceTile& t : r.Tiles)
        {
          // (Corners in the test's cyclic order; TileCorner's bit 0 is U1,
          // bit 1 V1.)
          const tpc::Box3 face{ grid.Point(tpc::TileCorner(axis, plane, t, 0)),
            grid.Point(tpc::TileCorner(axis, plane, t, 3)) };
          bool inside[4];
          for (int c = 0; c < 4; ++c)
          {
            inside[c] = e->IsInside(grid.Point(tpc::TileCorner(axis, plane, t, c == 2 ? 3 : c == 3 ? 2 : c)), prims);
          }
          EXPECT_EQ(tpc::FaceCompatibilityTest(e, prims, face, axis, inside), tpc::SplitReason::None)
            << "scene " << s << ", axis " << axis << ", plane " << plane << ", tile " << t.U0 << " " << t.V0 << " "
            << t.U1 << " " << t.V1;
          ++tiles;
        }
      }
    }
  }
  EXPECT_GT(refined, 10);
  EXPECT_GT(tiles, 500);
}

TEST(FaceRefinement, TilingsOfOneMeshAreSharedByTheCellsOnBothSides)
{
  // The two cells of one level sharing a face tile it alike where each one's
  // surface is one mesh (FaceDecisionCache.h): a tilted cube, a torus, and a
  // sphere's mesh minus the cube's (where one mesh only meets a cell), faces
  // of 128 lattice spacings, each refined with the scene pruned to the cell
  // below it and to the cell above. Then asked of a FaceDecisionCache (the
  // second asker takes the tiling out, learning the signs at its tiles'
  // corners): the cell below first, then the cell above, which samples no
  // point itself; the cell below with 7 levels, the cell above with 1 (another
  // tiling: not shared); and from two threads at once. Every answer is the
  // asker's own tiling, with every corner's exact sign. (Fails where a tiling
  // depends on the cell's list, with a key without the plane or the levels,
  // where the second asker tiles again, or is not given the corners' signs.)
  const tpc::RootGrid grid = tpctest::SingleRoot({ -1, -1, -1 }, 2.0, 10);
  std::vector<SceneBuilder> scenes(3);
  const std::vector<tpc::CsgExpressionPtr> expressions = MeshScenes(scenes);
  constexpr tpc::LatticeIndex Cell = 128;
  constexpr int Levels = 7, FewerLevels = 1;
  const auto same = [](const tpc::FaceRefinementResult& a, const tpc::FaceRefinementResult& b) {
    return a.Failure == b.Failure && a.Tiles == b.Tiles;
  };
  int shared = 0, refined = 0, sampledBeyondCorners = 0, otherWithFewerLevels = 0;
  for (std::size_t s = 0; s < scenes.size(); ++s)
  {
    const tpc::PrimitiveSet& prims = scenes[s].Scene.Primitives;
    struct Asked
    {
      int Axis;
      tpc::LatticeIndex Plane;
      FaceTile Face;
      std::array<tpc::CsgExpressionPtr, 2> Cells; ///< pruned to the cells below and above the face
      std::array<tpc::FaceRefinementResult, 2> Own;
      tpc::FaceRefinementResult AboveWithFewerLevels;
    };
    const auto own = [&](const Asked& a, int side, int levels) {
      tpc::LatticeSignTable global;
      tpc::CellSignCache signs(global, grid, *a.Cells[side], prims);
      return tpc::RefineFace(a.Cells[side], prims, grid, a.Axis, a.Plane, a.Face, levels, signs);
    };
    std::vector<Asked> asked;
    for (int axis = 0; axis < 3; ++axis)
    {
      for (tpc::LatticeIndex plane = Cell; plane < Side; plane += Cell)
      {
        for (tpc::LatticeIndex u = 0; u < Side; u += Cell)
        {
          for (tpc::LatticeIndex v = 0; v < Side; v += Cell)
          {
            Asked a{ axis, plane, { u, v, u + Cell, v + Cell }, {}, {}, {} };
            bool oneMesh = true;
            for (int side = 0; side < 2; ++side)
            {
              tpc::LatticeIndex lo[3], hi[3];
              lo[axis] = plane - (side ? 0 : Cell);
              hi[axis] = lo[axis] + Cell;
              lo[(axis + 1) % 3] = u;
              hi[(axis + 1) % 3] = u + Cell;
              lo[(axis + 2) % 3] = v;
              hi[(axis + 2) % 3] = v + Cell;
              const tpc::Box3 box{ grid.Point(tpc::MakePointKey(lo[0], lo[1], lo[2])),
                grid.Point(tpc::MakePointKey(hi[0], hi[1], hi[2])) };
              a.Cells[side] = tpc::CsgExpression::Prune(expressions[s], box, prims).Expression;
              oneMesh = oneMesh && a.Cells[side] && tpc::LoneMeshLeaf(*a.Cells[side]);
            }
            if (!oneMesh)
            {
              continue;
            }
            a.Own = { own(a, 0, Levels), own(a, 1, Levels) };
            ASSERT_TRUE(same(a.Own[0], a.Own[1])) << "scene " << s << ", axis " << axis << ", plane " << plane
                                                  << ", face " << u << " " << v;
            a.AboveWithFewerLevels = own(a, 1, FewerLevels);
            refined += a.Own[0].Tiles.size() > 1 ? 1 : 0;
            otherWithFewerLevels += same(a.AboveWithFewerLevels, a.Own[1]) ? 0 : 1;
            asked.push_back(std::move(a));
          }
        }
      }
    }
    shared += static_cast<int>(asked.size());
    tpc::FaceDecisionCache cache;
    // Whether the answer is the asker's own tiling (`levels`), with every
    // corner's exact sign among the signs the asker holds; in `beyond`,
    // whether it holds others too (points it sampled while tiling).
    const auto ask = [&](std::size_t i, int side, int levels, bool& beyond) {
      const Asked& a = asked[i];
      tpc::LatticeSignTable global;
      tpc::CellSignCache signs(global, grid, *a.Cells[side], prims);
      const tpc::FaceRefinementResult r =
        tpc::TileFace(&cache, a.Cells[side], prims, grid, a.Axis, a.Plane, a.Face, levels, signs);
      const auto& held = signs.NewSigns();
      std::size_t corners = 0;
      bool exact = true;
      for (const FaceTile& t : r.Tiles)
      {
        for (int c = 0; c < 4; ++c)
        {
          const tpc::PointKey key = tpc::TileCorner(a.Axis, a.Plane, t, c);
          const auto found = std::find_if(held.begin(), held.end(), [&](const auto& p) { return p.first == key; });
          exact = exact && found != held.end() && found->second == expressions[s]->IsInside(grid.Point(key), prims);
          corners += std::count_if(held.begin(), found, [&](const auto& p) { return p.first == key; }) == 0 ? 1 : 0;
        }
      }
      beyond = held.size() > corners; // (corners: the distinct ones)
      return exact && same(r, levels == Levels ? a.Own[side] : a.AboveWithFewerLevels);
    };
    bool beyond = false;
    for (std::size_t i = 0; i < asked.size(); ++i)
    {
      EXPECT_TRUE(ask(i, 0, Levels, beyond)) << "scene " << s << ", face " << i << ", cell below";
      sampledBeyondCorners += beyond ? 1 : 0;
    }
    for (std::size_t i = 0; i < asked.size(); ++i)
    {
      EXPECT_TRUE(ask(i, 1, Levels, beyond) && !beyond) << "scene " << s << ", face " << i << ", cell above";
    }
    for (std::size_t i = 0; i < asked.size(); ++i)
    {
      EXPECT_TRUE(ask(i, 0, Levels, beyond) && ask(i, 1, FewerLevels, beyond))
        << "scene " << s << ", face " << i << ", fewer levels";
    }
    cache.Clear();
    std::vector<char> first(asked.size()), second(asked.size());
    const auto askAll = [&](int side, std::vector<char>& answers) {
      bool sampled = false;
      for (std::size_t i = 0; i < asked.size(); ++i)
      {
        answers[i] = ask(i, side, Levels, sampled);
      }
    };
    std::thread other(askAll, 1, std::ref(second));
    askAll(0, first);
    other.join();
    EXPECT_EQ(std::count(first.begin(), first.end(), 1) + std::count(second.begin(), second.end(), 1),
      static_cast<std::ptrdiff_t>(2 * asked.size()))
      << "scene " << s;
  }
  EXPECT_GT(shared, 400);
  EXPECT_GE(refined, 8);
  EXPECT_GE(sampledBeyondCorners, 8); // (a second asker tiling again would hold such points)
  EXPECT_GE(otherWithFewerLevels, 1); // (a key without the levels would give those the deeper tiling)
}
