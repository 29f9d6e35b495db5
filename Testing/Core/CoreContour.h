// Runs the whole core pipeline (subdivision, extraction, report) on a scene,
// for the tests.
#pragma once

#include "SurfaceExtraction.h"
#include "TopologyPreservingSubdivision.h"
#include "TopologyReport.h"

namespace tpctest
{
struct ContourRun
{
  tpc::SubdivisionResult Subdivision;
  tpc::ExtractionResult Extraction;
  tpc::TopologyReport Report;
  double Tolerance = 0.0; ///< absolute
};

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
  r.Tolerance = p.HausdorffTolerance;
  tpc::PlacedSubdivision placed = tpc::RunOnBestLatticePlacement(scene, domain, p, placements);
  r.Subdivision = std::move(placed.Result);
  r.Extraction = tpc::ExtractSurface(r.Subdivision.Octree, scene);
  r.Report = tpc::ComputeTopologyReport(r.Extraction.Mesh);
  return r;
}
} // namespace tpctest
