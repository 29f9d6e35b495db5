// Runs the whole core pipeline (subdivision, extraction, embedding check,
// report) on a scene, for the tests. Every run's embedding verdict is held
// against CGAL's independent self-intersection test.
#pragma once

#include "CgalEmbedding.h"
#include "ExactCell.h"
#include "SurfaceEmbedding.h"
#include "SurfaceExtraction.h"
#include "TopologyPreservingSubdivision.h"
#include "TopologyReport.h"

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
  tpc::TopologyReport Report;
  double Tolerance = 0.0; ///< absolute
};

/// CGAL's verdict on a mesh, with the mesh's own vertex ids.
inline tpcoracle::EmbeddingVerdict CgalVerdict(const tpc::TriangleMesh& mesh)
{
  std::vector<std::array<double, 3>> points;
  for (const tpc::Vec3& p : mesh.Points)
  {
    points.push_back({ p[0], p[1], p[2] });
  }
  return tpcoracle::CheckEmbeddingWithCgal(points, mesh.Triangles);
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
    << " coincident vertices, " << core.DegenerateTriangles << " degenerate; CGAL: " << cgal.SelfIntersectingPairs
    << " self-intersecting pairs, " << cgal.CoincidentVertices << " coincident vertices";
}
#endif

/// What the filter calls TopologyGuaranteed, from a core run.
inline bool Guaranteed(const ContourRun& r)
{
  const bool empty = r.Report.Faces == 0;
  return r.Subdivision.UnresolvedCells == 0 && r.Extraction.InconsistentCells == 0 && r.Embedding.Embedded() &&
    (empty || (r.Report.Closed && r.Report.Manifold && r.Report.Oriented));
}

/// `bounds` grown by 5 % of its diagonal on every side (as the filter does,
/// so that the surface stays off the grid's outer boundary).
inline tpc::Box3 GrownDomain(const tpc::Box3& bounds)
{
  tpc::Box3 domain = bounds;
  const double d = bounds.Diagonal();
  for (int a = 0; a < 3; ++a)
  {
    domain.lo[a] -= 0.05 * d;
    domain.hi[a] += 0.05 * d;
  }
  return domain;
}

/// Contours `scene` over `bounds` grown by 5 % of its diagonal, with the
/// tolerance relative to the diagonal of `bounds`, trying up to
/// `placements` lattice placements.
inline ContourRun Contour(const tpc::ImplicitScene& scene, const tpc::Box3& bounds,
  double relativeTolerance, int maxDepth = 16, int placements = tpc::LatticePlacements)
{
  ContourRun r;
  const tpc::Box3 domain = GrownDomain(bounds);
  const double d = bounds.Diagonal();
  tpc::SubdivisionParameters p;
  p.HausdorffTolerance = relativeTolerance * d;
  p.MaximumDepth = maxDepth;
  // As the filter does for one closed mesh (the test meshes meet the paper's
  // assumptions): exact cells where the tests cannot resolve one.
  p.ExactCells = tpc::IsOneMesh(*scene.Expression);
  r.Tolerance = p.HausdorffTolerance;
  tpc::PlacedSubdivision placed = tpc::RunOnBestLatticePlacement(scene, domain, p, placements);
  r.Subdivision = std::move(placed.Result);
  r.Extraction = tpc::ExtractSurface(r.Subdivision.Octree, scene);
  r.Embedding = tpc::CheckEmbedding(r.Subdivision.Octree, r.Extraction.Mesh);
  r.Report = tpc::ComputeTopologyReport(r.Extraction.Mesh);
#ifndef TPC_TESTS_WITHOUT_GTEST
  ExpectEmbeddingCheckAgreesWithCgal(r.Embedding, r.Extraction.Mesh);
#endif
  return r;
}
} // namespace tpctest
