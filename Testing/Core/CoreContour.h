// Runs a scene through the core's entry point, tpc::Contour, for the tests.
// Every run's embedding verdict is held against CGAL's independent
// self-intersection test; DistanceWithinBound holds a surface against the
// reported bound with CGAL's certified distance.
#pragma once

#include "CgalEmbedding.h"
#include "CgalHausdorff.h"
#include "Contour.h"
#include "SceneBuilder.h"

#include <algorithm>

#ifndef TPC_TESTS_WITHOUT_GTEST
#include <gtest/gtest.h>
#endif

namespace tpctest
{
struct ContourRun
{
  tpc::SubdivisionResult Subdivision;
  tpc::ExtractionResult Extraction;
  tpc::EmbeddingReport Embedding;
  tpc::TopologyReport Report; ///< of the surface as a mesh (an empty one: genus -1, not closed)
  /// Components and genus as the output's report gives them (ContourReport:
  /// 0 and 0 for an empty solid).
  long long ReportedComponents = 0, ReportedGenus = -1;
  double Tolerance = 0.0; ///< absolute
  double HausdorffBound = 0.0; ///< the report's proven two-sided bound
  bool Guaranteed = false;
  bool Contoured = false; ///< contoured, or the solid is empty (else Messages say why)
  bool Aborted = false;   ///< `progress` asked to stop
  int RepairRuns = 0;     ///< ContourResult::RepairRuns
  std::vector<tpc::ContourMessage> Messages;
};

/// Points and triangles as CGAL's oracles take them.
template <typename Points, typename Triangles>
tpcoracle::TriangleSoup SoupOf(const Points& points, const Triangles& triangles)
{
  tpcoracle::TriangleSoup soup;
  for (const tpc::Vec3& p : points)
  {
    soup.Points.push_back({ p[0], p[1], p[2] });
  }
  soup.Triangles.assign(triangles.begin(), triangles.end());
  return soup;
}

/// CGAL's certified two-sided distance between `a` and `b` within
/// `errorBound`: the larger directed estimate's lower and upper ends (the
/// distance is at least Lower, at most Upper).
inline tpcoracle::HausdorffEstimate TwoSidedDistanceWithCgal(
  const tpcoracle::TriangleSoup& a, const tpcoracle::TriangleSoup& b, double errorBound)
{
  const tpcoracle::HausdorffEstimate there = tpcoracle::DirectedHausdorffWithCgal(a, b, errorBound);
  const tpcoracle::HausdorffEstimate back = tpcoracle::DirectedHausdorffWithCgal(b, a, errorBound);
  return { std::max(there.Lower, back.Lower), std::max(there.Upper, back.Upper) };
}

/// Whether the run's surface and `exact` (another surface, as a triangle
/// soup) are within the run's reported HausdorffBound of each other, both
/// ways, by CGAL's certified distance (CgalHausdorff.h): the lower end of
/// its estimate - the distance is at least that - at most the bound (up to
/// a billionth of the tolerance: `exact`'s points are rounded). Two empty
/// surfaces are; one empty and one not are not.
inline bool DistanceWithinBound(const ContourRun& r, const tpcoracle::TriangleSoup& exact)
{
  const tpc::TriangleMesh& mesh = r.Extraction.Mesh;
  if (exact.Triangles.empty() || mesh.Triangles.empty())
  {
    return exact.Triangles.empty() == mesh.Triangles.empty();
  }
  const double lower = TwoSidedDistanceWithCgal(SoupOf(mesh.Points, mesh.Triangles), exact, 0.01 * r.Tolerance).Lower;
  return lower <= r.HausdorffBound + 1e-9 * r.Tolerance;
}

/// CGAL's verdict on a mesh, with the mesh's own vertex ids.
inline tpcoracle::EmbeddingVerdict CgalVerdict(const tpc::TriangleMesh& mesh)
{
  const tpcoracle::TriangleSoup soup = SoupOf(mesh.Points, mesh.Triangles);
  return tpcoracle::CheckEmbeddingWithCgal(soup.Points, soup.Triangles);
}

#ifndef TPC_TESTS_WITHOUT_GTEST
/// The core's exact embedding check says what CGAL says.
inline void ExpectEmbeddingCheckAgreesWithCgal(const tpc::EmbeddingReport& core, const tpc::TriangleMesh& mesh)
{
  const tpcoracle::EmbeddingVerdict cgal = CgalVerdict(mesh);
  if (!cgal.Checked)
  {
    return;
  }
  EXPECT_EQ(core.Embedded(), cgal.Embedded())
    << "core: " << core.ImproperPairs << " improper pairs, " << core.CoincidentVertices
    << " coincident vertices, " << core.DegenerateTriangles << " degenerate, " << core.TrianglesOutsideCells
    << " outside their cells, aborted " << core.Aborted << "; CGAL: " << cgal.SelfIntersectingPairs
    << " self-intersecting pairs, " << cgal.CoincidentVertices << " coincident vertices";
}
#endif

/// TopologyGuaranteed as the core decided it.
inline bool Guaranteed(const ContourRun& r) { return r.Guaranteed; }

/// `bounds` grown by 5 % of its diagonal on every side (the margin the core
/// gives the solid, so that the surface stays off the grid's outer boundary).
inline tpc::Box3 GrownDomain(const tpc::Box3& bounds) { return bounds.Grown(0.05); }

/// `scene` as the core's entry point takes it: one input, the test scene.
inline tpc::ContourScene ContourSceneOf(const Scene& scene)
{
  tpc::ContourScene input;
  input.Primitives = scene.Primitives;
  tpc::SceneInput solid;
  solid.Name = "The test scene";
  solid.Solid = scene.Solid;
  input.Inputs.push_back(std::move(solid));
  return input;
}

/// A whole run through the core's entry point (tpc::Contour) with
/// parameters `p`. The test scenes' meshes meet the paper's assumptions.
inline ContourRun Contour(const Scene& scene, const tpc::ContourParameters& p,
  const tpc::ProgressCallback& progress = nullptr)
{
  tpc::ContourResult result = tpc::Contour(ContourSceneOf(scene), p, tpc::SequentialFor, progress);
  ContourRun r;
  r.Messages = std::move(result.Messages);
  r.Subdivision = std::move(result.Placed.Result);
  r.Extraction = std::move(result.Extraction);
  r.Embedding = std::move(result.Embedding);
  r.Report = result.Topology;
  r.ReportedComponents = result.Report.Components;
  r.ReportedGenus = result.Report.Genus;
  r.Tolerance = result.Report.AbsoluteTolerance;
  r.HausdorffBound = result.Report.HausdorffBound;
  r.Guaranteed = result.Report.Guaranteed;
  r.RepairRuns = result.RepairRuns;
  r.Contoured = result.Status == tpc::ContourResult::Outcome::Contoured ||
    result.Status == tpc::ContourResult::Outcome::Empty;
  r.Aborted = result.Status == tpc::ContourResult::Outcome::Aborted;
  if (r.Aborted)
  {
    return r;
  }
#ifndef TPC_TESTS_WITHOUT_GTEST
  EXPECT_TRUE(r.Contoured) << (r.Messages.empty() ? std::string() : r.Messages.front().Text);
  ExpectEmbeddingCheckAgreesWithCgal(r.Embedding, r.Extraction.Mesh);
#endif
  return r;
}

/// The parameters of a test run: the lattice laid over `bounds` (Region:
/// grown by the usual margin, not clipped), the tolerance relative to its
/// diagonal, trying up to `placements` lattice placements, refining at most
/// to `maxDepth` (the product's default, the lattice's end), decimated if
/// asked (through the cells' bounds: the scene is one term).
inline tpc::ContourParameters ParametersFor(const tpc::Box3& bounds, double relativeTolerance,
  int maxDepth = tpc::DeepestMaximumDepth, int placements = tpc::LatticePlacements, std::size_t maxCells = 10000000,
  bool decimate = false)
{
  tpc::ContourParameters p;
  p.Decimate = decimate;
  p.Region = bounds;
  p.Tolerance = relativeTolerance;
  p.MaximumDepth = maxDepth;
  p.MaximumNumberOfCells = maxCells;
  p.LatticePlacements = placements;
  return p;
}

/// A whole run with the parameters of ParametersFor.
inline ContourRun Contour(const Scene& scene, const tpc::Box3& bounds, double relativeTolerance,
  int maxDepth = tpc::DeepestMaximumDepth, int placements = tpc::LatticePlacements, std::size_t maxCells = 10000000,
  const tpc::ProgressCallback& progress = nullptr, bool decimate = false)
{
  return Contour(scene, ParametersFor(bounds, relativeTolerance, maxDepth, placements, maxCells, decimate), progress);
}
} // namespace tpctest
