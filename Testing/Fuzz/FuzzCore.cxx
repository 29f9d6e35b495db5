// libFuzzer target over the VTK-free core (issue 6). Each input is decoded
// into one of four kinds of scene:
//   0. a random CSG of 1-5 quadric primitives (spheres, ellipsoids, boxes,
//      cylinders, planes; union, intersection, difference; any overlap,
//      tangency or coincidence the bytes produce), clipped to a box;
//   1. a scene whose topology is known by construction: disjoint spheres and
//      ellipsoids (k components, genus 0), or a box minus parallel cylinders
//      through it (1 component, genus m);
//   2. a mesh from the bytes: a valid mesh (icosphere, torus, cube) randomly
//      perturbed, with triangles dropped, duplicated or flipped and vertices
//      moved or merged - or plain random triangles - in a shuffled order
//      where their number is odd (the 320-triangle icosphere's then reordered
//      along a Morton curve, MeshOrder.h; the smaller ones still count as in
//      a local order);
//   3. a valid mesh combined with primitives.
// About half the inputs are decimated (Decimate: CertifiedDecimation.h),
// with the same properties required of the decimated surface.
// Properties, on every input: no crash and no sanitizer report; bounded time
// (small depth and cell limits); a closed, manifold, oriented output with a
// consistent extraction even where limits stopped refinement; the core's exact
// embedding check agreeing with CGAL's self-intersection test, and an
// embedded output wherever every cell passed the tests (the sampled patches
// are embedded by construction, LoopTriangulation.h); and where the
// guarantee holds (no unresolved cell) on a scene of known topology - kind 1,
// and meshes meeting the paper's assumptions, whose own topology is the
// reference (the surface of a closed, manifold, self-intersection-free mesh
// is the solid's boundary) - the same components and genus.
#include "CoreContour.h"
#include "FuzzChecks.h"
#include "MeshBuilders.h"
#include "MeshRepair.h"
#include "SceneBuilder.h"

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>

using tpc::Vec3;
using tpcfuzz::Direction;
using tpcfuzz::Number;
using tpcfuzz::Point;
using tpcfuzz::Require;
using tpctest::SceneBuilder;

namespace
{
/// What the campaign exercised, printed at exit (to document coverage).
struct Tally
{
  long Scenes[4] = { 0, 0, 0, 0 };
  long TopologyChecked = 0, MeshesRefused = 0, TightLimits = 0;
  tpcfuzz::RunTally Runs;
  ~Tally()
  {
    std::fprintf(stderr,
      "FuzzCore: %ld random CSG, %ld known topology, %ld meshes, %ld meshes with primitives; "
      "%ld contoured (%ld non-empty, %ld guaranteed, %ld not embedded where a limit stopped cells, %ld with "
      "exact cells), %ld topologies checked against the reference, %ld broken meshes refused; %ld inputs with "
      "tight limits; %ld stopped after %d s; %ld decimated\n",
      Scenes[0], Scenes[1], Scenes[2], Scenes[3], Runs.Contoured, Runs.NonEmpty, Runs.Guaranteed, Runs.NotEmbedded,
      Runs.WithExactCells, TopologyChecked, MeshesRefused, TightLimits, Runs.OverTime, tpcfuzz::SceneSeconds,
      Runs.Decimated);
  }
} tally;

/// Depth and cell limits low enough to stop refinement on most scenes: the
/// output must still be closed and manifold (set per input).
bool tightLimits = false;

tpctest::ContourRun RunAndCheck(FuzzedDataProvider& in, const tpctest::Scene& scene, const tpc::Box3& bounds)
{
  return tpcfuzz::RunAndCheck(in, scene, bounds, tightLimits, tally.Runs);
}


tpc::CsgTerm RandomPrimitive(FuzzedDataProvider& in, SceneBuilder& b)
{
  const Vec3 c = Point(in, 1.0);
  switch (in.ConsumeIntegralInRange<int>(0, 4))
  {
    case 0:
      return b.Sphere(c, Number(in, 0.02, 1.0));
    case 1:
      return b.Ellipsoid(c, { Number(in, 0.02, 1.0), Number(in, 0.02, 1.0), Number(in, 0.02, 1.0) });
    case 2:
    {
      const Vec3 d{ Number(in, 0.01, 1.0), Number(in, 0.01, 1.0), Number(in, 0.01, 1.0) };
      return b.Box(c - d, c + d);
    }
    case 3:
      return b.Cylinder(c, Direction(in), Number(in, 0.02, 0.8));
    default:
      return b.Add(tpc::Quadric::Plane(c, Direction(in)));
  }
}

tpc::CsgTerm::Op RandomOperation(FuzzedDataProvider& in)
{
  const tpc::CsgTerm::Op ops[] = { tpc::CsgTerm::Op::Union, tpc::CsgTerm::Op::Intersection,
    tpc::CsgTerm::Op::Difference };
  return ops[in.ConsumeIntegralInRange<int>(0, 2)];
}

/// `t` combined with `more` random primitives by random operations, clipped
/// to a box (as the filter clips to its Bounds), contoured and checked.
void CombineClipAndRun(FuzzedDataProvider& in, SceneBuilder& b, tpc::CsgTerm t, int more)
{
  for (int k = 0; k < more; ++k)
  {
    t = tpc::CsgTerm::Combine(RandomOperation(in), { t, RandomPrimitive(in, b) });
  }
  const tpc::Box3 clip{ { -1.2, -1.2, -1.2 }, { 1.2, 1.2, 1.2 } };
  b.Finish(SceneBuilder::Intersection({ t, b.Box(clip.lo, clip.hi) }));
  RunAndCheck(in, b.Scene, clip);
}

void RandomCsg(FuzzedDataProvider& in)
{
  SceneBuilder b;
  const tpc::CsgTerm first = RandomPrimitive(in, b);
  CombineClipAndRun(in, b, first, in.ConsumeIntegralInRange<int>(0, 4));
}

void KnownTopology(FuzzedDataProvider& in)
{
  SceneBuilder b;
  long long components = 1, genus = 0;
  tpc::Box3 bounds;
  if (in.ConsumeBool())
  {
    // Disjoint blobs on a line, each in its own slot of width 1 with a
    // margin of at least 0.15 to the next.
    const int k = in.ConsumeIntegralInRange<int>(1, 4);
    std::vector<tpc::CsgTerm> blobs;
    for (int i = 0; i < k; ++i)
    {
      const Vec3 c{ static_cast<double>(i) + Number(in, -0.05, 0.05), Number(in, -0.1, 0.1), Number(in, -0.1, 0.1) };
      blobs.push_back(in.ConsumeBool()
          ? b.Sphere(c, Number(in, 0.15, 0.35))
          : b.Ellipsoid(c, { Number(in, 0.1, 0.35), Number(in, 0.1, 0.6), Number(in, 0.1, 0.6) }));
    }
    b.Finish(SceneBuilder::Union(blobs));
    components = k;
    bounds = { { -0.5, -0.75, -0.75 }, { k - 0.5, 0.75, 0.75 } };
  }
  else
  {
    // A slab minus m vertical cylinders, each in its own slot of width 0.5.
    const int m = in.ConsumeIntegralInRange<int>(1, 4);
    std::vector<tpc::CsgTerm> parts = { b.Box({ -0.25, -0.3, -0.2 }, { 0.5 * m - 0.25, 0.3, 0.2 }) };
    for (int i = 0; i < m; ++i)
    {
      const Vec3 c{ 0.5 * i + Number(in, -0.03, 0.03), Number(in, -0.05, 0.05), 0.0 };
      const Vec3 axis{ Number(in, -0.2, 0.2), Number(in, -0.2, 0.2), 1.0 };
      parts.push_back(b.Cylinder(c, axis, Number(in, 0.05, 0.12)));
    }
    b.Finish(SceneBuilder::Difference(parts));
    genus = m;
    bounds = { { -0.25, -0.3, -0.2 }, { 0.5 * m - 0.25, 0.3, 0.2 } };
  }
  const tpctest::ContourRun r = RunAndCheck(in, b.Scene, bounds);
  if (tpctest::Guaranteed(r))
  {
    ++tally.TopologyChecked;
    Require(r.Report.Components == components, "components of a scene of known topology");
    Require(r.Report.Genus == genus, "genus of a scene of known topology");
  }
}

/// A mesh from the bytes, repaired; true when it meets the paper's
/// assumptions (then `solid` is set and `components`/`genus` are its own).
bool MeshFromBytes(FuzzedDataProvider& in, tpc::MeshSolid& solid, tpc::MeshRepairReport& report)
{
  std::vector<Vec3> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  const int kind = in.ConsumeIntegralInRange<int>(0, 3);
  if (kind == 3)
  {
    const int n = in.ConsumeIntegralInRange<int>(3, 24);
    for (int i = 0; i < n; ++i)
    {
      points.push_back(Point(in, 1.0));
    }
    const int t = in.ConsumeIntegralInRange<int>(1, 48);
    for (int i = 0; i < t; ++i)
    {
      triangles.push_back({ in.ConsumeIntegralInRange<std::uint32_t>(0, n - 1),
        in.ConsumeIntegralInRange<std::uint32_t>(0, n - 1), in.ConsumeIntegralInRange<std::uint32_t>(0, n - 1) });
    }
  }
  else
  {
    const tpc::MeshSolid base = kind == 0 ? tpctest::SphereMesh({ 0, 0, 0 }, 0.8, in.ConsumeIntegralInRange<int>(0, 2))
      : kind == 1 ? tpctest::TorusMesh({ 0, 0, 0 }, 0.7, Number(in, 0.1, 0.4), 12, 8)
                  : tpctest::CubeMesh({ -0.7, -0.6, -0.5 }, { 0.6, 0.7, 0.5 });
    points = base.Points();
    triangles = base.Triangles();
    const int edits = in.ConsumeIntegralInRange<int>(0, 6);
    for (int e = 0; e < edits && !triangles.empty(); ++e)
    {
      const std::size_t t = in.ConsumeIntegralInRange<std::size_t>(0, triangles.size() - 1);
      const std::size_t v = in.ConsumeIntegralInRange<std::size_t>(0, points.size() - 1);
      switch (in.ConsumeIntegralInRange<int>(0, 4))
      {
        case 0:
          triangles.erase(triangles.begin() + static_cast<std::ptrdiff_t>(t));
          break;
        case 1:
          triangles.push_back(triangles[t]);
          break;
        case 2:
          std::swap(triangles[t][0], triangles[t][1]);
          break;
        case 3:
          points[v] = points[v] + Point(in, 0.3);
          break;
        default:
          points[v] = points[in.ConsumeIntegralInRange<std::size_t>(0, points.size() - 1)];
          break;
      }
    }
  }
  // The meshes of an odd number of triangles shuffled - decided by their
  // size, which reads no byte, so that the inputs kept for regressions read
  // as before - and repaired as the filter repairs them, which reorders those
  // then in no local order (MeshOrder.h).
  if (triangles.size() % 2 == 1)
  {
    std::mt19937 random(static_cast<std::uint32_t>(triangles.size()));
    std::shuffle(triangles.begin(), triangles.end(), random);
  }
  solid = tpc::RepairIntoSolid(std::move(points), std::move(triangles), report);
  return report.MeetsAssumptions() && !solid.Triangles().empty();
}

void MeshScene(FuzzedDataProvider& in, bool withPrimitives)
{
  tpc::MeshSolid mesh;
  tpc::MeshRepairReport report;
  if (!MeshFromBytes(in, mesh, report))
  {
    ++tally.MeshesRefused;
    return; // refused, as the filter refuses it (repair must not crash)
  }
  SceneBuilder b;
  const tpc::Box3 bounds = mesh.Bounds();
  tpc::CsgTerm t = b.Mesh(std::move(mesh));
  if (withPrimitives)
  {
    CombineClipAndRun(in, b, t, in.ConsumeIntegralInRange<int>(1, 3));
    return;
  }
  b.Finish(t);
  const tpctest::ContourRun r = RunAndCheck(in, b.Scene, bounds);
  if (tpctest::Guaranteed(r))
  {
    ++tally.TopologyChecked;
    Require(r.Report.Components == static_cast<std::int64_t>(report.Components), "components of the input mesh");
    Require(r.Report.Genus == report.Genus, "genus of the input mesh");
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  FuzzedDataProvider in(data, size);
  const int choice = in.ConsumeIntegralInRange<int>(0, 7);
  const int kind = choice % 4;
  tightLimits = choice >= 4;
  ++tally.Scenes[kind];
  tally.TightLimits += tightLimits ? 1 : 0;
  switch (kind)
  {
    case 0:
      RandomCsg(in);
      break;
    case 1:
      KnownTopology(in);
      break;
    case 2:
      MeshScene(in, false);
      break;
    default:
      MeshScene(in, true);
      break;
  }
  return 0;
}
