// The slab bound of a mesh cell's error (SlabBound.h): where the surface in
// the cell and the fan both face one way, sqrt(t^2 + delta^2) bounds their
// two-sided distance measured by dense sampling - on bumpy height fields
// under fans over loops of few and many chords, where the chords' deviation
// from the trace is a large part of it - and it refuses where a triangle of
// either faces the other way.
#include "ConvexPolygons.h"
#include "MeshCellError.h"
#include "PolygonHausdorff.h"
#include "SampledDistance.h"
#include "SlabBound.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <vector>

using tpc::Box3;
using tpc::SourceTriangle;
using tpc::Vec3;

namespace
{
/// A height field over the unit square on an n x n grid, as a mesh of
/// triangles facing +z (a soup of its own triangles: S_C of the cell
/// [0, 1]^2 x [-1, 1], whose trace is the field's boundary polyline).
struct HeightField
{
  int N = 0;
  std::vector<Vec3> Points;
  std::vector<std::array<std::uint32_t, 3>> Faces;

  template <typename Height>
  HeightField(int n, const Height& height)
    : N(n)
  {
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        const double x = double(i) / n, y = double(j) / n;
        this->Points.emplace_back(x, y, height(x, y));
      }
    }
    const auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        this->Faces.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
        this->Faces.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
      }
    }
  }
  const Vec3& At(int i, int j) const { return this->Points[static_cast<std::size_t>(j * (this->N + 1) + i)]; }

  /// The boundary's grid points every `step` (corners always), counter-
  /// clockwise seen from +z: a loop whose chords each lie on one face.
  std::vector<Vec3> Loop(int step) const
  {
    std::vector<Vec3> loop;
    const int n = this->N;
    const auto side = [&](auto point) {
      for (int k = 0; k < n; ++k)
      {
        if (k % step == 0)
        {
          loop.push_back(point(k));
        }
      }
    };
    side([&](int k) { return this->At(k, 0); });
    side([&](int k) { return this->At(n, k); });
    side([&](int k) { return this->At(n - k, n); });
    side([&](int k) { return this->At(0, n - k); });
    return loop;
  }
};

std::vector<SourceTriangle> Triangles(const HeightField& field)
{
  std::vector<SourceTriangle> triangles;
  for (const auto& f : field.Faces)
  {
    triangles.push_back({ field.Points[f[0]], field.Points[f[1]], field.Points[f[2]] });
  }
  return triangles;
}

/// The two-sided distance between `a` and `b`, sampled (12 steps a side).
double Sampled(const std::vector<SourceTriangle>& a, const std::vector<SourceTriangle>& b)
{
  return std::max(tpctest::SampledHausdorff(a, b, 12), tpctest::SampledHausdorff(b, a, 12));
}

/// The face tile of the unit cell between loop points `a` and `b` (on one
/// side of the square), spanning the cell's height.
Box3 TileBetween(const Vec3& a, const Vec3& b)
{
  return { { std::min(a[0], b[0]), std::min(a[1], b[1]), -1.0 },
    { std::max(a[0], b[0]), std::max(a[1], b[1]), 1.0 } };
}

struct SlabCase
{
  tpc::MeshSolid Mesh;
  tpc::TriangleList Listed;
  tpc::PolygonSet Surface;
  std::vector<SourceTriangle> Fan;
  double Delta = 0.0; ///< the largest chord deviation
  std::vector<std::vector<Vec3>> Loops; ///< the fan's loop
  std::vector<double> Deltas;           ///< each chord's deviation
};

/// The cell of the height fields.
const Box3 UnitCell{ { 0, 0, -1 }, { 1, 1, 1 } };

/// The field's S_C, and the fan over its loop every `step` around S_C's
/// apex, with its chords' deviations from the trace.
SlabCase FanOverField(const HeightField& field, int step)
{
  SlabCase c{ tpc::MeshSolid(field.Points, field.Faces), {}, {}, {}, 0.0, {}, {} };
  for (std::uint32_t t = 0; t < field.Faces.size(); ++t)
  {
    c.Listed.push_back(t);
    c.Surface.Add({ c.Mesh.Vertex(t, 0), c.Mesh.Vertex(t, 1), c.Mesh.Vertex(t, 2) });
  }
  const std::vector<Vec3> loop = field.Loop(step);
  c.Fan = tpc::ApexFan(loop, tpc::MeshCellApex(c.Surface, UnitCell));
  for (std::size_t k = 0; k < loop.size(); ++k)
  {
    const Vec3& a = loop[k];
    const Vec3& b = loop[(k + 1) % loop.size()];
    c.Deltas.push_back(tpc::ChordDeviation(c.Surface, TileBetween(a, b), a, b));
    c.Delta = std::max(c.Delta, c.Deltas.back());
  }
  c.Loops = { loop };
  return c;
}
} // namespace

TEST(SlabBound, BoundsTheSampledDistanceWhereBothFaceOneWay)
{
  // Random gentle bumps and tilts, fanned over loops of one chord a side up
  // to one per grid edge: the bound is at least the two-sided distance
  // measured (its largest over 91 samples a triangle each way).
  std::mt19937 random(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double tightest = HUGE_VAL, widest = 0.0, chordShare = 0.0;
  for (int trial = 0; trial < 24; ++trial)
  {
    const double amplitude = 0.01 + 0.05 * unit(random), fx = 2 + 5 * unit(random), fy = 2 + 5 * unit(random),
                 phase = 6 * unit(random), tilt = 0.3 * unit(random);
    const HeightField field(8, [&](double x, double y) {
      return tilt * (x - 0.5) + amplitude * std::sin(fx * x + phase) * std::cos(fy * y);
    });
    const int step = 1 + trial % 8;
    const SlabCase c = FanOverField(field, step);
    const double bound = tpc::SlabPatchError(c.Mesh, c.Listed, c.Surface, c.Fan, c.Delta, 0.0);
    ASSERT_LT(bound, HUGE_VAL) << "trial " << trial;
    const std::vector<SourceTriangle> surface = Triangles(field);
    const double measured = Sampled(c.Fan, surface);
    EXPECT_LE(measured, bound) << "trial " << trial;
    tightest = std::min(tightest, bound / measured);
    widest = std::max(widest, bound / measured);
    chordShare = std::max(chordShare, c.Delta / bound);
  }
  // Not vacuous: within a few times of the distance, and within 1.7 times
  // of it somewhere (measured 1.48 .. 6.5; 2 - 3 times mostly, where bumps
  // rise and fall within the fan's triangles: t is their whole range).
  EXPECT_LT(tightest, 1.7);
  EXPECT_LT(widest, 8.0);
  EXPECT_GT(chordShare, 0.5); // some loops' chords cut their trace by most of the bound
  std::cout << "bound / measured: " << tightest << " .. " << widest << "; largest delta / bound " << chordShare
            << "\n";
}

TEST(SlabBound, ChordsFarFromTheTraceAreInTheBound)
{
  // A gently tilted sheet with a bump across it leaves the cell [0, 1]^2 x
  // [-1, 0.1] through its top face along a curved level line, x = 0.5 -+
  // 0.15 sin(pi y); the loop's chord there runs straight from (0.5, 0) to
  // (0.5, 1). The sheet is thin along its normal (t about 0.03), but the fan
  // overhangs it (the line bends in) or the sheet reaches beyond the fan's
  // shadow (it bends out) by about the chord's deviation, 0.15, near the top
  // face: the slab alone would not bound that, the bound with delta does.
  for (const double bend : { 1.0, -1.0 })
  {
    const auto height = [bend](double x, double y) {
      return 0.2 * x + bend * 0.03 * std::sin(3.141592653589793 * y);
    };
    const HeightField field(32, height);
    const Box3 cell{ { 0, 0, -1 }, { 1, 1, 0.1 } };
    SlabCase c{ tpc::MeshSolid(field.Points, field.Faces), {}, {}, {}, 0.0, {}, {} };
    std::vector<SourceTriangle> surface;
    for (std::uint32_t t = 0; t < field.Faces.size(); ++t)
    {
      tpc::ClippedCorners corners;
      for (int k = 0; k < 3; ++k)
      {
        corners.push_back(c.Mesh.Vertex(t, k));
      }
      tpc::ClipToBox(corners, cell);
      if (!corners.empty())
      {
        c.Listed.push_back(t);
        c.Surface.Add(corners.begin(), corners.size());
        tpc::AppendAsSources(corners.begin(), corners.size(), surface);
      }
    }
    // The loop: the sheet's corners on x = 0, and where its sides y = 0, 1
    // meet the top face (h = 0.1 at x = 0.5 there).
    const std::vector<Vec3> loop{ field.At(0, 0), { 0.5, 0, 0.1 }, { 0.5, 1, 0.1 }, field.At(0, 32) };
    c.Fan = tpc::ApexFan(loop, tpc::MeshCellApex(c.Surface, cell));
    const Box3 tiles[4] = { { { 0, 0, -1 }, { 1, 0, 0.1 } }, { { 0, 0, 0.1 }, { 1, 1, 0.1 } },
      { { 0, 1, -1 }, { 1, 1, 0.1 } }, { { 0, 0, -1 }, { 0, 1, 0.1 } } };
    for (std::size_t k = 0; k < 4; ++k)
    {
      c.Deltas.push_back(tpc::ChordDeviation(c.Surface, tiles[k], loop[k], loop[(k + 1) % 4]));
      c.Delta = std::max(c.Delta, c.Deltas.back());
    }
    EXPECT_NEAR(c.Delta, 0.15, 0.002) << bend; // (the top face's chord; the level line is piecewise linear)
    const double bound = tpc::SlabPatchError(c.Mesh, c.Listed, c.Surface, c.Fan, c.Delta, 0.0);
    const double slabAlone = tpc::SlabPatchError(c.Mesh, c.Listed, c.Surface, c.Fan, 0.0, 0.0);
    // The local heights over the same chords (asked for below any value:
    // the smaller of both is returned).
    c.Loops = { loop };
    const tpc::OwnChords own{ &c.Loops, &c.Deltas, HUGE_VAL, false, cell };
    const double local = tpc::SlabPatchError(c.Mesh, c.Listed, c.Surface, c.Fan, c.Delta, 0.0, own, 0.0);
    const double measured = Sampled(c.Fan, surface);
    EXPECT_LE(measured, bound) << bend;
    EXPECT_LE(measured, local) << bend;
    EXPECT_LT(slabAlone, 0.05) << bend;
    EXPECT_GT(measured, 2 * slabAlone) << bend;
    std::cout << "bend " << bend << ": measured " << measured << ", bound " << bound << ", local " << local
              << ", slab alone " << slabAlone << "\n";
  }
}

TEST(SlabBound, RefusesWhereATriangleFacesTheOtherWay)
{
  const HeightField field(8, [](double x, double y) { return 0.05 * std::sin(5 * x) * std::cos(3 * y); });
  const SlabCase c = FanOverField(field, 2);
  ASSERT_LT(tpc::SlabPatchError(c.Mesh, c.Listed, c.Surface, c.Fan, c.Delta, 0.0), HUGE_VAL);
  // A fold: one triangle of the surface turned over.
  HeightField folded = field;
  std::swap(folded.Faces[20][1], folded.Faces[20][2]);
  const SlabCase f = FanOverField(folded, 2);
  EXPECT_EQ(tpc::SlabPatchError(f.Mesh, f.Listed, f.Surface, c.Fan, c.Delta, 0.0), HUGE_VAL);
  // A fan whose apex lies outside its loop's shadow: a triangle faces down.
  std::vector<SourceTriangle> outside = c.Fan;
  for (SourceTriangle& t : outside)
  {
    t[2] = Vec3(1.5, 0.5, 0.0);
  }
  EXPECT_EQ(tpc::SlabPatchError(c.Mesh, c.Listed, c.Surface, outside, c.Delta, 0.0), HUGE_VAL);
  // The lists disagree: no bound.
  tpc::TriangleList shorter(c.Listed.begin(), c.Listed.end() - 1);
  EXPECT_EQ(tpc::SlabPatchError(c.Mesh, shorter, c.Surface, c.Fan, c.Delta, 0.0), HUGE_VAL);
}

TEST(SlabBound, LocalHeightsBoundTheSampledDistanceOverCurvedSheets)
{
  // Bumps several times the chords' deviations, fanned over loops of one
  // chord a side up to one per grid edge: the slab's thickness is their
  // whole range, the local heights follow the fan's triangles (LocalHeights.h).
  // Each bound is at least the two-sided distance measured.
  std::mt19937 random(29);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double tightest = HUGE_VAL;
  int tighterThanTheSlab = 0;
  const int trials = 32;
  for (int trial = 0; trial < trials; ++trial)
  {
    const double amplitude = 0.03 + 0.1 * unit(random), fx = 1 + 4 * unit(random), fy = 1 + 4 * unit(random),
                 phase = 6 * unit(random), tilt = 0.6 * unit(random);
    const HeightField field(8, [&](double x, double y) {
      return tilt * (y - 0.5) + amplitude * std::sin(fx * x + phase) * std::cos(fy * y);
    });
    const SlabCase c = FanOverField(field, 1 + trial % 8);
    const double slab = tpc::SlabPatchError(c.Mesh, c.Listed, c.Surface, c.Fan, c.Delta, 0.0);
    const tpc::OwnChords own{ &c.Loops, &c.Deltas, HUGE_VAL, false, UnitCell };
    const double bound = tpc::SlabPatchError(c.Mesh, c.Listed, c.Surface, c.Fan, c.Delta, 0.0, own, 0.0);
    ASSERT_LT(bound, HUGE_VAL) << "trial " << trial;
    const double measured = Sampled(c.Fan, Triangles(field));
    EXPECT_LE(measured, bound) << "trial " << trial;
    tightest = std::min(tightest, bound / measured);
    tighterThanTheSlab += bound < 0.8 * slab ? 1 : 0;
  }
  // Not vacuous: the local heights beat the slab by a fifth in most trials,
  // and come within 1.3 times of the distance somewhere.
  EXPECT_GT(tighterThanTheSlab, trials / 2);
  EXPECT_LT(tightest, 1.3);
  std::cout << "local heights below 0.8 of the slab in " << tighterThanTheSlab << " of " << trials
            << " trials; tightest bound / measured " << tightest << "\n";
}

TEST(SlabBound, LocalHeightsOverLoopsRefiningTheOwn)
{
  // The extraction's final loops refine the cell's own (crack patching put
  // trace points between its loop points): the fan over the fine loop
  // around the same apex, bounded over the own chords with Refined (their
  // polylines are within delta_c of them, header).
  std::mt19937 random(31);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int tighterThanTheSlab = 0;
  for (int trial = 0; trial < 16; ++trial)
  {
    const double amplitude = 0.03 + 0.1 * unit(random), fx = 1 + 4 * unit(random), fy = 1 + 4 * unit(random),
                 tilt = 0.6 * unit(random);
    const HeightField field(8, [&](double x, double y) {
      return tilt * (x - 0.5) + amplitude * std::cos(fx * x) * std::sin(fy * y + 1);
    });
    const SlabCase own = FanOverField(field, 8);  // one chord a side
    const SlabCase fine = FanOverField(field, 2); // its points and the trace's between
    const Vec3 apex = tpc::MeshCellApex(own.Surface, UnitCell);
    const std::vector<SourceTriangle> patch = tpc::ApexFan(fine.Loops[0], apex);
    const double slab = tpc::SlabPatchError(own.Mesh, own.Listed, own.Surface, patch, 2 * own.Delta, 0.0);
    const tpc::OwnChords chords{ &own.Loops, &own.Deltas, HUGE_VAL, true, UnitCell };
    const double bound =
      tpc::SlabPatchError(own.Mesh, own.Listed, own.Surface, patch, 2 * own.Delta, 0.0, chords, 0.0);
    ASSERT_LT(bound, HUGE_VAL) << "trial " << trial;
    EXPECT_LE(Sampled(patch, Triangles(field)), bound) << "trial " << trial;
    tighterThanTheSlab += bound < slab ? 1 : 0;
  }
  EXPECT_GT(tighterThanTheSlab, 8);
}

TEST(SlabBound, SheetBySheetBoundsTwoSheetsFacingOppositeWays)
{
  // Two bumpy sheets across the cell [0, 1]^2 x [-1, 1], one near z = 0.4
  // facing up and one near z = -0.4 facing down (a thin part's two faces, as
  // one mesh), each with its own loop on the cell's sides and its own fan: no
  // direction passes the facing test for both, so the slab bound alone
  // refuses; bounded sheet by sheet (MeshCellError.h: Several sheets), the
  // result is at least the two-sided distance measured between the unions.
  std::mt19937 random(37);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double tightest = HUGE_VAL;
  for (int trial = 0; trial < 12; ++trial)
  {
    const double amplitude = 0.02 + 0.1 * unit(random), fx = 1 + 4 * unit(random), fy = 1 + 4 * unit(random);
    const HeightField top(8, [&](double x, double y) { return 0.4 + amplitude * std::sin(fx * x) * std::cos(fy * y); });
    const HeightField bottom(8, [&](double x, double y) { return -0.4 + amplitude * std::cos(fy * x + fx * y); });
    std::vector<Vec3> points = top.Points;
    std::vector<std::array<std::uint32_t, 3>> faces = top.Faces;
    const std::uint32_t base = static_cast<std::uint32_t>(points.size());
    points.insert(points.end(), bottom.Points.begin(), bottom.Points.end());
    for (const auto& f : bottom.Faces)
    {
      faces.push_back({ base + f[0], base + f[2], base + f[1] }); // (facing down)
    }
    const tpc::MeshSolid mesh(points, faces);
    tpc::TriangleList listed;
    tpc::PolygonSet surface, upper, lower;
    for (std::uint32_t t = 0; t < faces.size(); ++t)
    {
      listed.push_back(t);
      surface.Add({ mesh.Vertex(t, 0), mesh.Vertex(t, 1), mesh.Vertex(t, 2) });
      (t < top.Faces.size() ? upper : lower)
        .Add({ mesh.Vertex(t, 0), mesh.Vertex(t, 1), mesh.Vertex(t, 2) });
    }
    const int step = 1 + trial % 4;
    std::vector<Vec3> down = bottom.Loop(step);
    std::reverse(down.begin(), down.end());
    const std::vector<std::vector<Vec3>> loops{ top.Loop(step), down };
    const std::vector<std::vector<SourceTriangle>> fans{ tpc::ApexFan(loops[0], tpc::MeshCellApex(upper, UnitCell)),
      tpc::ApexFan(loops[1], tpc::MeshCellApex(lower, UnitCell)) };
    // Each chord against its own sheet's trace (the tile of its half of the
    // side: the sheets' traces lie apart on it).
    std::vector<double> deltas;
    double delta = 0.0;
    for (std::size_t l = 0; l < 2; ++l)
    {
      for (std::size_t k = 0; k < loops[l].size(); ++k)
      {
        const Vec3& a = loops[l][k];
        const Vec3& b = loops[l][(k + 1) % loops[l].size()];
        Box3 tile = TileBetween(a, b);
        (l == 0 ? tile.lo : tile.hi)[2] = 0.0;
        deltas.push_back(tpc::ChordDeviation(surface, tile, a, b));
        delta = std::max(delta, deltas.back());
      }
    }
    std::vector<SourceTriangle> patch = fans[0];
    patch.insert(patch.end(), fans[1].begin(), fans[1].end());
    ASSERT_EQ(tpc::SlabPatchError(mesh, listed, surface, patch, delta, 0.0), HUGE_VAL) << "trial " << trial;
    const tpc::OwnChords chords{ nullptr, &deltas, HUGE_VAL, false, UnitCell };
    const double slack = 1e-12; // (each loop's sheet is the one within it of its points)
    const double bound =
      tpc::SheetwiseSlabError(mesh, listed, surface, UnitCell, loops, chords, fans, delta, slack, 0.0, HUGE_VAL);
    ASSERT_LT(bound, HUGE_VAL) << "trial " << trial;
    std::vector<SourceTriangle> sheets = Triangles(top);
    for (const auto& f : bottom.Faces)
    {
      sheets.push_back({ bottom.Points[f[0]], bottom.Points[f[2]], bottom.Points[f[1]] });
    }
    const double measured = Sampled(patch, sheets);
    EXPECT_LE(measured, bound) << "trial " << trial;
    tightest = std::min(tightest, bound / measured);
    // A loop on no sheet of its own (both loops on the top sheet) proves nothing.
    const std::vector<std::vector<Vec3>> same{ loops[0], loops[0] };
    std::vector<double> twice = deltas;
    std::copy(deltas.begin(), deltas.begin() + static_cast<std::ptrdiff_t>(loops[0].size()), twice.begin());
    twice.resize(2 * loops[0].size());
    std::copy(deltas.begin(), deltas.begin() + static_cast<std::ptrdiff_t>(loops[0].size()),
      twice.begin() + static_cast<std::ptrdiff_t>(loops[0].size()));
    const tpc::OwnChords both{ nullptr, &twice, HUGE_VAL, false, UnitCell };
    EXPECT_EQ(tpc::SheetwiseSlabError(mesh, listed, surface, UnitCell, same, both, { fans[0], fans[0] }, delta,
                slack, 0.0, HUGE_VAL),
      HUGE_VAL)
      << "trial " << trial;
  }
  EXPECT_LT(tightest, 1.5); // not vacuous
  std::cout << "sheet by sheet: tightest bound / measured " << tightest << "\n";
}
