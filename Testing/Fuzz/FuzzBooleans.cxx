// libFuzzer target over the core's mesh Booleans (issue 17: everything the
// guarantee says stays true, creases where two meshes meet included). Each
// input is decoded into two valid closed meshes - icospheres, tori, cubes,
// prisms - each scaled along its axes, rotated and moved, and one of union,
// intersection and difference of their solids. The properties every
// contoured scene must have are FuzzChecks.h's (closed, manifold, oriented,
// embedded where every cell passed, the exact embedding check agreeing with
// CGAL's, the bound within the tolerance); and wherever the guarantee holds,
// the components and genus must be those of the exact Boolean, computed
// independently by CGAL's corefinement on an exact kernel, and the two-sided
// distance to it within the reported bound (CGAL's certified estimate: its
// lower end at most the bound; CgalBoolean.h, CgalHausdorff.h). Where the
// Boolean's boundary is not an embedded 2-manifold - the solids touch -
// there is no reference, and none is asked for.
#include "CgalBoolean.h"
#include "FuzzChecks.h"
#include "MeshBuilders.h"
#include "MeshRepair.h"
#include "SceneBuilder.h"

#include <cmath>

using tpc::Vec3;

namespace
{
/// What the campaign exercised, printed at exit (to document coverage).
struct Tally
{
  long Operations[3] = { 0, 0, 0 };
  long Compared = 0, Crossing = 0, LargerCellsWhereTheyMeet = 0, NoReference = 0, TightLimits = 0;
  tpcfuzz::RunTally Runs;
  ~Tally()
  {
    std::fprintf(stderr,
      "FuzzBooleans: %ld unions, %ld intersections, %ld differences of two meshes; %ld contoured (%ld non-empty, "
      "%ld guaranteed, %ld not embedded where a limit stopped cells, %ld with exact cells), %ld topologies equal "
      "to CGAL's exact Boolean and within the reported bound of it (%ld where the surfaces meet, %ld with cells "
      "where they meet larger than the tolerance), %ld "
      "guaranteed without a reference (the solids touch); %ld inputs with tight limits; %ld stopped after %d s; "
      "%ld decimated\n",
      Operations[0], Operations[1], Operations[2], Runs.Contoured, Runs.NonEmpty, Runs.Guaranteed, Runs.NotEmbedded,
      Runs.WithExactCells, Compared, Crossing, LargerCellsWhereTheyMeet, NoReference, TightLimits, Runs.OverTime, tpcfuzz::SceneSeconds,
      Runs.Decimated);
  }
} tally;

/// The regular polygon of `n` corners on the circle of radius `r` (a
/// prism's section: CAD-like sharp edges, flat faces split by diagonals).
std::vector<std::array<double, 2>> RegularPolygon(int n, double r)
{
  std::vector<std::array<double, 2>> corners;
  for (int k = 0; k < n; ++k)
  {
    corners.push_back({ r * std::cos(2 * M_PI * k / n), r * std::sin(2 * M_PI * k / n) });
  }
  return corners;
}

/// A valid closed mesh from the bytes: an icosphere (20 to 320 triangles), a
/// torus, a cube or a prism over a regular polygon, scaled along its axes, rotated and moved - an affine map
/// of a valid mesh, so still closed, manifold and free of
/// self-intersections (checked: RepairMesh, as the filter checks its
/// inputs).
bool SolidMeshFromBytes(FuzzedDataProvider& in, tpc::MeshSolid& solid)
{
  const int kind = in.ConsumeIntegralInRange<int>(0, 3);
  const tpc::MeshSolid base = kind == 0 ? tpctest::SphereMesh({ 0, 0, 0 }, 0.5, in.ConsumeIntegralInRange<int>(0, 2))
    : kind == 1 ? tpctest::TorusMesh({ 0, 0, 0 }, 0.45, tpcfuzz::Number(in, 0.08, 0.3), 12, 8)
    : kind == 2 ? tpctest::CubeMesh({ -0.5, -0.5, -0.5 }, { 0.5, 0.5, 0.5 })
                : tpctest::PrismMesh(RegularPolygon(in.ConsumeIntegralInRange<int>(3, 12), 0.5), -0.5, 0.5);
  const Vec3 scale{ tpcfuzz::Number(in, 0.3, 1.2), tpcfuzz::Number(in, 0.3, 1.2), tpcfuzz::Number(in, 0.3, 1.2) };
  const Vec3 axis = tpc::Normalized(tpcfuzz::Direction(in));
  const double angle = tpcfuzz::Number(in, 0.0, 3.14159);
  const Vec3 shift = tpcfuzz::Point(in, 0.6);
  const tpc::MeshSolid moved = tpctest::AffineMesh(base, scale, axis, angle, shift);
  std::vector<Vec3> points = moved.Points();
  std::vector<std::array<std::uint32_t, 3>> triangles = moved.Triangles();
  if (!tpc::RepairMesh(points, triangles).MeetsAssumptions())
  {
    return false;
  }
  solid = tpc::MeshSolid(std::move(points), std::move(triangles));
  return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  FuzzedDataProvider in(data, size);
  const int choice = in.ConsumeIntegralInRange<int>(0, 8);
  const int operation = choice % 3;
  const bool tightLimits = choice >= 6;
  tpc::MeshSolid a, b;
  if (!SolidMeshFromBytes(in, a) || !SolidMeshFromBytes(in, b))
  {
    return 0;
  }
  ++tally.Operations[operation];
  tally.TightLimits += tightLimits ? 1 : 0;
  const tpcoracle::TriangleSoup soupA = tpctest::SoupOf(a.Points(), a.Triangles());
  const tpcoracle::TriangleSoup soupB = tpctest::SoupOf(b.Points(), b.Triangles());
  const tpc::Box3 bounds = tpctest::BoundsOfBoth(a, b);
  const tpc::CsgTerm::Op ops[] = { tpc::CsgTerm::Op::Union, tpc::CsgTerm::Op::Intersection,
    tpc::CsgTerm::Op::Difference };
  tpctest::SceneBuilder builder;
  const tpc::CsgTerm termA = builder.Mesh(std::move(a));
  const tpc::CsgTerm termB = builder.Mesh(std::move(b));
  builder.Finish(tpc::CsgTerm::Combine(ops[operation], { termA, termB }));
  const tpctest::ContourRun r = tpcfuzz::RunAndCheck(in, builder.Scene, bounds, tightLimits, tally.Runs);
  if (!tpctest::Guaranteed(r))
  {
    return 0;
  }
  const tpcoracle::BooleanOperation exactOps[] = { tpcoracle::BooleanOperation::Union,
    tpcoracle::BooleanOperation::Intersection, tpcoracle::BooleanOperation::Difference };
  const tpcoracle::BooleanTopology exact =
    tpcoracle::ExactBooleanTopology(soupA, soupB, exactOps[operation]);
  if (!exact.Checked)
  {
    return 0;
  }
  if (!exact.Valid)
  {
    ++tally.NoReference;
    return 0;
  }
  if (std::getenv("TPC_FUZZ_VERBOSE"))
  {
    std::fprintf(stderr, "filter: %lld components, genus %lld; CGAL: %lld, %lld\n",
      r.ReportedComponents, r.ReportedGenus, exact.Components, exact.Genus);
  }
  // (The output's report, as the user reads it: an empty solid has 0
  // components and genus 0 there.)
  tpcfuzz::Require(r.ReportedComponents == exact.Components, "components of the exact Boolean (CGAL)");
  tpcfuzz::Require(r.ReportedGenus == exact.Genus, "genus of the exact Boolean (CGAL)");
  tpcfuzz::Require(
    tpctest::DistanceWithinBound(r, exact.Surface), "the exact Boolean within the reported bound (CGAL)");
  ++tally.Compared;
  tally.Crossing += exact.SurfacesMeet ? 1 : 0;
  // (Cells where both meshes meet accepted larger than the tolerance,
  // MeshBooleanCellError.h: their final patches were certified above.)
  tally.LargerCellsWhereTheyMeet += r.Subdivision.Octree.BooleanFanApexes.empty() ? 0 : 1;
  return 0;
}
