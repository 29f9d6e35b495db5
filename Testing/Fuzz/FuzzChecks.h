// What the libFuzzer targets over the core (FuzzCore.cxx, FuzzBooleans.cxx)
// check on every scene they contour, and the decoding helpers they share.
#pragma once

#include "CoreContour.h"

#include <fuzzer/FuzzedDataProvider.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace tpcfuzz
{
/// Wall-clock seconds one scene may take (libFuzzer's -timeout is 60).
constexpr int SceneSeconds = 10;

/// What the runs of a campaign gave, printed by each target at exit.
struct RunTally
{
  long Contoured = 0, NonEmpty = 0, Guaranteed = 0, NotEmbedded = 0, WithExactCells = 0, OverTime = 0,
       Decimated = 0;
};

inline void Require(bool ok, const char* property)
{
  if (!ok)
  {
    std::fprintf(stderr, "property violated: %s\n", property);
    std::abort();
  }
}

inline double Number(FuzzedDataProvider& in, double lo, double hi)
{
  return in.ConsumeFloatingPointInRange<double>(lo, hi);
}

inline tpc::Vec3 Point(FuzzedDataProvider& in, double extent)
{
  return { Number(in, -extent, extent), Number(in, -extent, extent), Number(in, -extent, extent) };
}

inline tpc::Vec3 Direction(FuzzedDataProvider& in)
{
  tpc::Vec3 d = Point(in, 1.0);
  return tpc::Norm(d) > 1e-3 ? d : tpc::Vec3(0, 0, 1);
}

/// The scene and parameters, for reproducing a failing input:
/// TPC_FUZZ_VERBOSE=1 FuzzCore <file> (or FuzzBooleans).
inline void Describe(
  const tpc::ImplicitScene& scene, double tolerance, int depth, std::size_t cells, const tpc::Box3& domain)
{
  std::fprintf(stderr, "tolerance %.17g, depth %d, cells %zu, domain [%g %g %g]-[%g %g %g]\n", tolerance, depth,
    cells, domain.lo[0], domain.lo[1], domain.lo[2], domain.hi[0], domain.hi[1],
    domain.hi[2]);
  for (const tpc::Quadric& q : scene.Primitives.Quadrics)
  {
    std::fprintf(stderr, "quadric");
    for (const double c : q.Coefficients())
    {
      std::fprintf(stderr, " %.17g", c);
    }
    std::fprintf(stderr, "\n");
  }
  for (const tpc::MeshSolid& m : scene.Primitives.Meshes)
  {
    std::fprintf(stderr, "mesh of %zu triangles\n", m.TriangleCount());
  }
}

/// Runs the core's entry point with small limits (`tightLimits`: low enough
/// to stop refinement on most scenes, the output still closed and manifold)
/// and checks the properties that hold for every input, counting in `tally`.
/// Returns the run for further checks.
inline tpctest::ContourRun RunAndCheck(FuzzedDataProvider& in, const tpctest::Scene& scene, const tpc::Box3& bounds,
  bool tightLimits, RunTally& tally)
{
  tpctest::ContourRun r;
  if (!scene.Expression)
  {
    return r;
  }
  // (An exhausted input gives the coarsest tolerance and the deepest limit.)
  const double tolerance = 0.3 - Number(in, 0.0, 0.26);
  const int depth = tightLimits ? 2 + in.ConsumeIntegralInRange<int>(0, 3) : 9 - in.ConsumeIntegralInRange<int>(0, 5);
  const std::size_t cells = tightLimits ? 3000 : 300000;
  // (From the depth's parity, not a byte of its own: the regression inputs
  // in Data/ must decode to the scenes they were saved for.)
  const bool decimate = depth % 2 == 1;
  if (std::getenv("TPC_FUZZ_VERBOSE"))
  {
    Describe(scene, tolerance * bounds.Diagonal(), depth, cells, tpctest::GrownDomain(bounds));
  }
  // A scene the filter cannot settle within SceneSeconds is stopped and
  // dropped: the campaign checks properties of results, and one slow scene
  // would end it as a timeout. (Known: two quadrics meeting at a grazing
  // angle fail the face tests in every tile at every level; see the note on
  // issue 17. The count is printed at exit.)
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(SceneSeconds);
  r = tpctest::Contour(
    scene, bounds, tolerance, depth, 1, cells,
    [deadline](double) { return std::chrono::steady_clock::now() > deadline; }, decimate);
  if (r.Aborted)
  {
    ++tally.OverTime;
    return r;
  }
  if (std::getenv("TPC_FUZZ_VERBOSE"))
  {
    std::size_t tiles = 0;
    for (const auto& f : r.Subdivision.Octree.FaceRefinements)
    {
      tiles += f.second.size();
    }
    std::printf("octree: %zu nodes, %zu refined faces with %zu tiles, %zu bytes (nodes, expressions, signs)\n",
      r.Subdivision.Octree.Nodes.size(), r.Subdivision.Octree.FaceRefinements.size(), tiles,
      r.Subdivision.Octree.MemoryBytes());
  }
  Require(r.Contoured, "every scene with a solid is contoured");
  ++tally.Contoured;
  tally.Decimated += decimate ? 1 : 0;
  tally.NonEmpty += r.Extraction.Mesh.Triangles.empty() ? 0 : 1;
  tally.Guaranteed += tpctest::Guaranteed(r) ? 1 : 0;
  tally.NotEmbedded += r.Embedding.Embedded() ? 0 : 1;
  tally.WithExactCells += r.Subdivision.ExactCells > 0 ? 1 : 0;
  Require(r.Extraction.InconsistentCells == 0, "every cell's crossings close into loops");
  Require(r.Embedding.Embedded() == tpctest::CgalVerdict(r.Extraction.Mesh).Embedded(),
    "the exact embedding check agrees with CGAL's self-intersection test");
  // (Exact cells are embedded as their input is, down to rounding: a mesh
  // with sheets closer than that is flagged by the check, not a violation.)
  Require(r.Embedding.Embedded() || r.Subdivision.UnresolvedCells > 0 || r.Subdivision.ExactCells > 0,
    "embedded wherever every cell passed the tests");
  if (!r.Extraction.Mesh.Triangles.empty())
  {
    Require(r.Report.Closed, "closed output");
    Require(r.Report.Manifold, "manifold output");
    Require(r.Report.Oriented, "oriented output");
  }
  Require(r.Subdivision.HausdorffBound <= r.Tolerance * (1 + 1e-9) || r.Subdivision.UnresolvedCells > 0 ||
      r.Extraction.Mesh.Triangles.empty(),
    "Hausdorff bound within the tolerance when every cell passed");
  Require(!r.Guaranteed || r.HausdorffBound <= r.Tolerance * (1 + 1e-9),
    "the reported bound (of the decimated surface too) within the tolerance where guaranteed");
  return r;
}

} // namespace tpcfuzz
