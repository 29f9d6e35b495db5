// Bad input gets a clear error (and empty outputs), never a crash; limits
// give a warning, marked cells and TopologyGuaranteed = 0; Bounds clip and
// cap unbounded solids.
#include "FilterTestHelpers.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkPoints.h"
#include "vtkBox.h"
#include "vtkCellData.h"
#include "vtkCubeSource.h"
#include "vtkCylinder.h"
#include "vtkImplicitBoolean.h"
#include "vtkPlane.h"
#include "vtkSphere.h"
#include "vtkSphereSource.h"
#include "vtkSuperquadric.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using tpctest::FilterResult;
using tpctest::MessageRecorder;

TEST(FilterErrors, NoSolidAtAll)
{
  vtkNew<vtkTopologyPreservingContour> f;
  MessageRecorder messages(f);
  f->Update();
  EXPECT_NE(messages.Errors.find("ImplicitFunction"), std::string::npos) << messages.Errors;
  EXPECT_EQ(f->GetSurfaceOutput()->GetNumberOfPoints(), 0);
}

TEST(FilterErrors, OpenMeshIsRefusedClearly)
{
  // A sphere with a cap cut off has no inside.
  vtkNew<vtkSphereSource> open;
  open->SetEndTheta(300.0);
  vtkNew<vtkTopologyPreservingContour> f;
  f->AddInputConnection(open->GetOutputPort());
  MessageRecorder messages(f);
  f->Update();
  EXPECT_NE(messages.Errors.find("not a closed surface"), std::string::npos) << messages.Errors;
  // Advice a ParaView user can follow: the filter's own option, or Clean.
  EXPECT_NE(messages.Errors.find("FillHoles"), std::string::npos) << messages.Errors;
  EXPECT_NE(messages.Errors.find("Clean"), std::string::npos) << messages.Errors;
  EXPECT_EQ(f->GetSurfaceOutput()->GetNumberOfPoints(), 0);
}

TEST(FilterErrors, FillHolesClosesAnOpenMeshAndSaysSo)
{
  // A sphere missing one triangle (its points stored once per triangle, as
  // in an STL file): with FillHoles the hole is closed and reported.
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(24);
  source->SetPhiResolution(16);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  triangles->Update();
  vtkPolyData* sphere = triangles->GetOutput();
  vtkNew<vtkPoints> soup;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 1; c < sphere->GetNumberOfCells(); ++c) // (all but the first)
  {
    sphere->GetCellPoints(c, ids);
    vtkIdType own[3];
    for (int k = 0; k < 3; ++k)
    {
      own[k] = soup->InsertNextPoint(sphere->GetPoint(ids->GetId(k)));
    }
    polys->InsertNextCell(3, own);
  }
  vtkNew<vtkPolyData> open;
  open->SetPoints(soup);
  open->SetPolys(polys);
  vtkNew<vtkTopologyPreservingContour> f;
  f->AddInputData(open);
  f->SetTolerance(0.03);
  f->FillHolesOn();
  MessageRecorder messages(f);
  const FilterResult r = tpctest::Run(f);
  EXPECT_TRUE(messages.Errors.empty()) << messages.Errors;
  EXPECT_NE(messages.Warnings.find("holes filled with 1 triangles"), std::string::npos) << messages.Warnings;
  EXPECT_EQ(r.Guaranteed, 1);
  EXPECT_EQ(r.Components, 1);
  EXPECT_EQ(r.Genus, 0);
}

TEST(FilterErrors, ExactDuplicatePointsAreMergedSilently)
{
  // ParaView's Box source stores each corner once per face: 24 points for 8
  // corners. That is a closed box, not a mesh needing repair.
  vtkNew<vtkCubeSource> box;
  box->SetBounds(-0.4, 0.5, -0.3, 0.2, -0.25, 0.35);
  vtkNew<vtkTopologyPreservingContour> f;
  f->AddInputConnection(box->GetOutputPort());
  f->SetTolerance(0.03);
  MessageRecorder messages(f);
  const FilterResult r = tpctest::Run(f);
  EXPECT_TRUE(messages.Warnings.empty()) << messages.Warnings;
  EXPECT_TRUE(messages.Errors.empty()) << messages.Errors;
  EXPECT_EQ(r.Guaranteed, 1);
  EXPECT_EQ(r.Genus, 0);
}

TEST(FilterErrors, ClosedMeshIsContoured)
{
  vtkNew<vtkSphereSource> mesh;
  mesh->SetThetaResolution(24);
  mesh->SetPhiResolution(16);
  vtkNew<vtkTopologyPreservingContour> f;
  f->AddInputConnection(mesh->GetOutputPort());
  MessageRecorder messages(f);
  const FilterResult r = tpctest::Run(f);
  EXPECT_TRUE(messages.Errors.empty()) << messages.Errors;
  EXPECT_EQ(r.Components, 1);
  EXPECT_EQ(r.Genus, 0);
  EXPECT_EQ(r.Guaranteed, 1);
}

TEST(FilterErrors, SelfIntersectingMeshIsComputedQuicklyWithoutGuarantee)
{
  // Two overlapping spheres in one mesh: its surface crosses itself, which
  // no refinement resolves. The filter says so, caps the depth (instead of
  // refining every crossing to MaximumDepth) and returns a closed manifold.
  vtkNew<vtkSphereSource> a, b;
  b->SetCenter(0.3, 0.1, 0.05);
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(a->GetOutputPort());
  both->AddInputConnection(b->GetOutputPort());
  vtkNew<vtkTopologyPreservingContour> f;
  f->AddInputConnection(both->GetOutputPort());
  f->SetTolerance(1.0 / 32);
  MessageRecorder messages(f);
  const FilterResult r = tpctest::Run(f);
  EXPECT_TRUE(messages.Errors.empty()) << messages.Errors;
  EXPECT_NE(messages.Warnings.find("self-intersecting"), std::string::npos) << messages.Warnings;
  EXPECT_NE(messages.Warnings.find("refinement stops at depth"), std::string::npos) << messages.Warnings;
  EXPECT_EQ(r.Guaranteed, 0);
  const tpctest::IndependentTopology t = tpctest::Measure(r.Surface);
  EXPECT_EQ(t.BoundaryEdges, 0);
  EXPECT_EQ(t.NonManifoldEdges, 0);
  int deepest = 0;
  vtkDataArray* depth = r.Grid->GetCellData()->GetArray("Depth");
  ASSERT_NE(depth, nullptr);
  for (vtkIdType i = 0; i < depth->GetNumberOfTuples(); ++i)
  {
    deepest = std::max(deepest, static_cast<int>(depth->GetTuple1(i)));
  }
  EXPECT_LT(deepest, f->GetMaximumDepth());
}

TEST(FilterErrors, InputsTouchingAlongAFaceStopEarlyWithoutGuarantee)
{
  // Two cubes sharing a face, united: their surfaces meet without crossing
  // over a whole square, a tangential contact over an area. Refining it to
  // MaximumDepth took more than ten minutes (millions of cells); the filter
  // now says so and stops three levels below the tolerance's cells.
  vtkNew<vtkCubeSource> a, b;
  b->SetCenter(1, 0, 0);
  vtkNew<vtkTriangleFilter> ta, tb;
  ta->SetInputConnection(a->GetOutputPort());
  tb->SetInputConnection(b->GetOutputPort());
  vtkNew<vtkTopologyPreservingContour> f;
  f->AddInputConnection(ta->GetOutputPort());
  f->AddInputConnection(tb->GetOutputPort());
  f->SetTolerance(0.05);
  MessageRecorder messages(f);
  const FilterResult r = tpctest::Run(f);
  EXPECT_NE(messages.Warnings.find("Input 0 and Input 1 touch along coincident faces"), std::string::npos)
    << messages.Warnings;
  EXPECT_NE(messages.Warnings.find("refinement stops at depth"), std::string::npos) << messages.Warnings;
  EXPECT_EQ(r.Guaranteed, 0);
  const tpctest::IndependentTopology t = tpctest::Measure(r.Surface);
  EXPECT_EQ(t.BoundaryEdges, 0);
  EXPECT_EQ(t.NonManifoldEdges, 0);
  EXPECT_LT(r.Grid->GetNumberOfCells(), 200000);

  // Apart by a visible gap, they are two guaranteed boxes.
  b->SetCenter(1.2, 0, 0);
  const FilterResult apart = tpctest::Run(f);
  EXPECT_EQ(apart.Guaranteed, 1);
  EXPECT_EQ(apart.Components, 2);

  // In a difference the subtracted solid is complemented: there a smaller
  // box flush with a face (a notch) is the contact, one touching from
  // outside removes nothing and is resolved.
  f->SetOperationToDifference();
  b->SetBounds(0.2, 0.5, -0.3, 0.3, -0.2, 0.2);
  MessageRecorder notch(f);
  const FilterResult flush = tpctest::Run(f);
  EXPECT_NE(notch.Warnings.find("coincident faces"), std::string::npos) << notch.Warnings;
  EXPECT_EQ(flush.Guaranteed, 0);
  EXPECT_EQ(tpctest::Measure(flush.Surface).BoundaryEdges, 0);
  b->SetBounds(0.5, 0.8, -0.3, 0.3, -0.2, 0.2);
  MessageRecorder outside(f);
  const FilterResult cut = tpctest::Run(f);
  EXPECT_EQ(outside.Warnings.find("coincident faces"), std::string::npos) << outside.Warnings;
  EXPECT_EQ(cut.Guaranteed, 1);
  EXPECT_EQ(cut.Components, 1);
}

TEST(FilterErrors, BoxFacesOnTheBoundsAreResolved)
{
  // Bounds through a box's faces put two primitives on the same planes
  // (x = 1 here): coincident surfaces, which once made every edge across
  // them undecidable and the filter run for hours.
  vtkNew<vtkBox> box;
  box->SetBounds(0, 1, 0, 1, 0, 1);
  vtkNew<vtkTopologyPreservingContour> f;
  f->SetImplicitFunction(box);
  f->SetBounds(-1, 1, -1, 1, -1, 1);
  f->SetTolerance(0.02);
  const FilterResult r = tpctest::Run(f);
  EXPECT_EQ(r.Guaranteed, 1);
  EXPECT_EQ(r.Components, 1);
  EXPECT_EQ(r.Genus, 0);
  double b[6];
  r.Surface->GetBounds(b);
  EXPECT_NEAR(b[0], 0.0, 1e-9);
  EXPECT_NEAR(b[1], 1.0, 1e-9);
}

TEST(FilterErrors, ProgressIsReportedAndAbortIsHonoured)
{
  vtkNew<vtkSphere> sphere;
  sphere->SetRadius(0.5);
  struct Watch
  {
    vtkTopologyPreservingContour* Filter = nullptr;
    std::vector<double> Progress;
    bool AbortAt30Percent = false;
  };
  auto onProgress = [](vtkObject*, unsigned long, void* clientData, void* callData) {
    auto* w = static_cast<Watch*>(clientData);
    w->Progress.push_back(*static_cast<double*>(callData));
    if (w->AbortAt30Percent && w->Progress.back() >= 0.3)
    {
      w->Filter->SetAbortExecute(1);
      w->AbortAt30Percent = false; // (once, as a user clicks)
    }
  };
  for (const bool abort : { false, true })
  {
    vtkNew<vtkTopologyPreservingContour> f;
    f->SetImplicitFunction(sphere);
    f->SetTolerance(0.005);
    Watch watch;
    watch.Filter = f;
    watch.AbortAt30Percent = abort;
    vtkNew<vtkCallbackCommand> cb;
    cb->SetCallback(onProgress);
    cb->SetClientData(&watch);
    f->AddObserver(vtkCommand::ProgressEvent, cb);
    MessageRecorder messages(f);
    f->Update();
    ASSERT_GT(watch.Progress.size(), 3u);
    EXPECT_TRUE(std::is_sorted(watch.Progress.begin(), watch.Progress.end()));
    if (abort)
    {
      // Stopped at the next level after the request: well before the end.
      EXPECT_NE(messages.Warnings.find("Aborted"), std::string::npos) << messages.Warnings;
      EXPECT_EQ(f->GetSurfaceOutput()->GetNumberOfPoints(), 0);
      // (VTK's executive reports 1.0 when RequestData returns.)
      double reached = 0.0;
      for (const double p : watch.Progress)
      {
        reached = p < 1.0 ? std::max(reached, p) : reached;
      }
      EXPECT_LT(reached, 0.85);
      // The aborted outputs are up to date (VTK 9.2 would run the filter again
      // at the next request, so ParaView's abort restarted the run): Update
      // does not run it, a change does.
      EXPECT_EQ(f->GetAbortExecute(), 0);
      const std::size_t reports = watch.Progress.size();
      f->Update();
      EXPECT_EQ(watch.Progress.size(), reports) << "an aborted filter ran again without a change";
      f->SetTolerance(0.01);
      f->Update();
      EXPECT_GT(f->GetSurfaceOutput()->GetNumberOfPolys(), 0) << "the filter ran again after a change";
    }
    else
    {
      EXPECT_GT(f->GetSurfaceOutput()->GetNumberOfPolys(), 0);
      EXPECT_EQ(watch.Progress.back(), 1.0);
    }
  }
}

TEST(FilterErrors, AbortIsHonouredAtEveryStage)
{
  // Progress: inputs [0, 0.08), the core's input checks and subdivision
  // [0.08, 0.845), extraction and embedding check [0.845, 0.952), topology
  // report and grid output [0.952, 1). An abort requested at a stage's
  // first report stops the filter at the first check that sees it: at most
  // one report follows besides the executive's final 1.0 (how long apart the
  // checks are is measured by the benchmark: run_benchmark.py --limits).
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(200);
  source->SetPhiResolution(200);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  triangles->Update();
  struct Watch
  {
    vtkTopologyPreservingContour* Filter = nullptr;
    double From = 0.0, To = 1.0;
    bool Requested = false;
    std::vector<double> Before, After;
  };
  auto onProgress = [](vtkObject*, unsigned long, void* clientData, void* callData) {
    auto* w = static_cast<Watch*>(clientData);
    const double f = *static_cast<double*>(callData);
    if (w->Requested)
    {
      w->After.push_back(f);
      return;
    }
    w->Before.push_back(f);
    if (f >= w->From && f < w->To)
    {
      w->Filter->SetAbortExecute(1);
      w->Requested = true;
    }
  };
  const std::pair<double, double> stages[] = { { 0.0, 0.08 }, { 0.08, 0.845 }, { 0.845, 0.952 }, { 0.952, 1.0 } };
  for (const auto& stage : stages)
  {
    vtkNew<vtkTopologyPreservingContour> f;
    f->SetInputData(triangles->GetOutput());
    f->SetTolerance(0.005);
    Watch watch;
    watch.Filter = f;
    watch.From = stage.first;
    watch.To = stage.second;
    vtkNew<vtkCallbackCommand> cb;
    cb->SetCallback(onProgress);
    cb->SetClientData(&watch);
    f->AddObserver(vtkCommand::ProgressEvent, cb);
    MessageRecorder messages(f);
    f->Update();
    SCOPED_TRACE("stage [" + std::to_string(stage.first) + ", " + std::to_string(stage.second) + ")");
    ASSERT_FALSE(watch.Before.empty());
    EXPECT_GE(watch.Before.back(), stage.first) << "the stage reported progress";
    EXPECT_LT(watch.Before.back(), stage.second);
    // (A request made at the executive's own 0.0 report is seen at the
    // filter's first check, which reports once.)
    EXPECT_LE(std::count_if(watch.After.begin(), watch.After.end(), [](double p) { return p < 1.0; }), 1)
      << watch.After.size() << " reports after the abort, the first " << watch.After.front();
    EXPECT_NE(messages.Warnings.find("Aborted"), std::string::npos) << messages.Warnings;
    EXPECT_EQ(f->GetSurfaceOutput()->GetNumberOfPoints(), 0);
    EXPECT_EQ(f->GetGridOutput()->GetNumberOfCells(), 0);
  }
}

TEST(FilterErrors, UnsupportedFunctionsAreRefused)
{
  vtkNew<vtkSuperquadric> superquadric;
  vtkNew<vtkTopologyPreservingContour> f;
  f->SetImplicitFunction(superquadric);
  MessageRecorder messages(f);
  f->Update();
  EXPECT_NE(messages.Errors.find("vtkSuperquadric"), std::string::npos) << messages.Errors;

  vtkNew<vtkImplicitBoolean> magnitudes;
  vtkNew<vtkSphere> s;
  magnitudes->AddFunction(s);
  magnitudes->SetOperationTypeToUnionOfMagnitudes();
  f->SetImplicitFunction(magnitudes);
  MessageRecorder more(f);
  f->Update();
  EXPECT_NE(more.Errors.find("UnionOfMagnitudes"), std::string::npos) << more.Errors;
}

TEST(FilterErrors, UnboundedSolidNeedsBoundsThenIsCapped)
{
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0, 0, 0.1);
  plane->SetNormal(0, 0, 1);
  vtkNew<vtkTopologyPreservingContour> f;
  f->SetImplicitFunction(plane);
  MessageRecorder messages(f);
  f->Update();
  EXPECT_NE(messages.Errors.find("Bounds"), std::string::npos) << messages.Errors;

  // With Bounds the half-space becomes a capped box: one closed sphere-like surface.
  f->SetBounds(-1, 1, -1, 1, -1, 1);
  const FilterResult r = tpctest::Run(f);
  EXPECT_EQ(r.Guaranteed, 1);
  EXPECT_EQ(r.Components, 1);
  EXPECT_EQ(r.Genus, 0);
  double b[6];
  r.Surface->GetBounds(b);
  EXPECT_NEAR(b[5], 0.1, r.Tolerance);
  EXPECT_NEAR(b[0], -1.0, r.Tolerance);

  // A cylinder clipped by Bounds is a closed rod.
  vtkNew<vtkCylinder> cylinder;
  cylinder->SetRadius(0.3);
  f->SetImplicitFunction(cylinder);
  const FilterResult rod = tpctest::Run(f);
  EXPECT_EQ(rod.Guaranteed, 1);
  EXPECT_EQ(rod.Components, 1);
  EXPECT_EQ(rod.Genus, 0);
}

TEST(FilterErrors, AnEmptySolidIsReportedAlikeWhicheverWayItIsFound)
{
  // Two spheres apart, intersected: empty. Where their boxes are apart too,
  // the bounds prove it before any cell; where the boxes overlap, the cells
  // find no surface. Either way: empty outputs, a warning saying so, and the
  // report of the empty surface - guaranteed, 0 components, genus 0.
  for (const double offset : { 3.0, 1.5 }) // (boxes apart; boxes overlapping, spheres apart)
  {
    SCOPED_TRACE("offset " + std::to_string(offset));
    vtkNew<vtkSphere> a, b;
    a->SetRadius(1.0);
    b->SetRadius(1.0);
    b->SetCenter(offset, offset, 0.0);
    vtkNew<vtkImplicitBoolean> both;
    both->SetOperationTypeToIntersection();
    both->AddFunction(a);
    both->AddFunction(b);
    vtkNew<vtkTopologyPreservingContour> f;
    f->SetImplicitFunction(both);
    f->SetTolerance(0.05);
    MessageRecorder messages(f);
    const FilterResult r = tpctest::Run(f);
    EXPECT_TRUE(messages.Errors.empty()) << messages.Errors;
    EXPECT_NE(messages.Warnings.find("The solid is empty"), std::string::npos) << messages.Warnings;
    EXPECT_EQ(r.Surface->GetNumberOfCells(), 0);
    EXPECT_EQ(r.Guaranteed, 1);
    EXPECT_EQ(r.Components, 0);
    EXPECT_EQ(r.Genus, 0);
    EXPECT_EQ(r.Embedded, 1);
    EXPECT_EQ(r.HausdorffBound, 0.0);
    EXPECT_EQ(tpctest::FieldValue(r.Surface, "Closed"), 1.0);
    EXPECT_EQ(tpctest::FieldValue(r.Surface, "Manifold"), 1.0);
    EXPECT_EQ(tpctest::FieldValue(r.Grid, "TopologyGuaranteed"), 1.0);
    // Which way it was found: by the bounds, before any cell (no grid, and no
    // domain to scale the relative tolerance by), or by the cells.
    const bool byBounds = offset > 2.0;
    EXPECT_EQ(r.Grid->GetNumberOfCells() == 0, byBounds);
    EXPECT_EQ(std::isnan(r.Tolerance), byBounds);
    // Bad parameters are refused all the same.
    f->SetTolerance(-1.0);
    MessageRecorder refused(f);
    f->Update();
    EXPECT_NE(refused.Errors.find("Tolerance must be positive"), std::string::npos) << refused.Errors;
    EXPECT_EQ(tpctest::FieldValue(f->GetOutputDataObject(0), "TopologyGuaranteed"), 0.0);
  }
}

TEST(FilterErrors, NonPositiveToleranceIsRefused)
{
  vtkNew<vtkSphere> sphere;
  vtkNew<vtkTopologyPreservingContour> f;
  f->SetImplicitFunction(sphere);
  f->SetTolerance(0.0);
  MessageRecorder messages(f);
  f->Update();
  EXPECT_NE(messages.Errors.find("Tolerance"), std::string::npos) << messages.Errors;
  EXPECT_EQ(f->GetSurfaceOutput()->GetNumberOfPoints(), 0);
}

namespace
{
/// Two unit spheres 0.001 apart along the diagonal: whatever the lattice
/// placement, separating them takes cells about the size of the gap.
vtkSmartPointer<vtkImplicitBoolean> SpheresAThousandthApart()
{
  const double c = 0.5005 / std::sqrt(3.0);
  vtkNew<vtkSphere> a, b;
  a->SetCenter(-c, -c, -c);
  a->SetRadius(0.5);
  b->SetCenter(c, c, c);
  b->SetRadius(0.5);
  auto u = vtkSmartPointer<vtkImplicitBoolean>::New();
  u->AddFunction(a);
  u->AddFunction(b);
  return u;
}

/// Two vtkBox solids, united.
vtkSmartPointer<vtkImplicitBoolean> TwoBoxes(const double a[6], const double b[6])
{
  vtkNew<vtkBox> first, second;
  first->SetBounds(a);
  second->SetBounds(b);
  auto u = vtkSmartPointer<vtkImplicitBoolean>::New();
  u->AddFunction(first);
  u->AddFunction(second);
  return u;
}

/// Number of grid cells in state 3 (unresolved); each must carry `reason`.
int CountMarkedCells(vtkHyperTreeGrid* grid, int reason)
{
  auto* state = vtkUnsignedCharArray::SafeDownCast(grid->GetCellData()->GetArray("CellState"));
  auto* split = vtkUnsignedCharArray::SafeDownCast(grid->GetCellData()->GetArray("SplitReason"));
  EXPECT_TRUE(state && split);
  int marked = 0;
  for (vtkIdType i = 0; state && split && i < state->GetNumberOfTuples(); ++i)
  {
    if (state->GetValue(i) == 3)
    {
      EXPECT_EQ(split->GetValue(i), reason);
      ++marked;
    }
  }
  return marked;
}

/// A run some cells of which were stopped: no guarantee, every stopped cell
/// marked with `reason`, and still a closed manifold surface.
void ExpectStoppedCellsMarkedAndClosed(const FilterResult& r, int reason)
{
  EXPECT_EQ(r.Guaranteed, 0);
  EXPECT_GT(r.Unresolved, 0);
  EXPECT_EQ(CountMarkedCells(r.Grid, reason), r.Unresolved);
  const tpctest::IndependentTopology t = tpctest::Measure(r.Surface);
  EXPECT_EQ(t.BoundaryEdges, 0);
  EXPECT_EQ(t.NonManifoldEdges, 0);
}

/// `f` run again with a deeper MaximumDepth resolves it: guaranteed, with
/// `components` components.
void ExpectResolvedWithMaximumDepth(vtkTopologyPreservingContour* f, int depth, int components)
{
  f->SetMaximumDepth(depth);
  const FilterResult full = tpctest::Run(f);
  EXPECT_EQ(full.Guaranteed, 1);
  EXPECT_EQ(full.Components, components);
}
} // namespace

TEST(FilterErrors, DepthLimitWarnsMarksCellsAndKeepsAClosedManifold)
{
  // MaximumDepth 5 stops the cells before they are as small as the tolerance
  // (1/200 of the diagonal) asks.
  vtkNew<vtkTopologyPreservingContour> f;
  f->SetImplicitFunction(SpheresAThousandthApart());
  f->SetTolerance(0.005);
  f->SetMaximumDepth(5);
  MessageRecorder messages(f);
  const FilterResult r = tpctest::Run(f);
  EXPECT_NE(messages.Warnings.find("guarantee does not hold"), std::string::npos) << messages.Warnings;
  EXPECT_NE(messages.Warnings.find("MaximumDepth (5)"), std::string::npos) << messages.Warnings;
  EXPECT_NE(messages.Warnings.find("3 lattice placements"), std::string::npos) << messages.Warnings;
  ExpectStoppedCellsMarkedAndClosed(r, vtkTopologyPreservingContour::LIMIT_REACHED);

  // Raising the limit resolves it.
  ExpectResolvedWithMaximumDepth(f, 16, 2);
}

TEST(FilterErrors, CellLimitWarnsMarksCellsAndKeepsAClosedManifold)
{
  // A sphere at 1/500 of the diagonal needs more than 2 000 cells, even with
  // its cells certified larger than the tolerance (QuadricCellError.h; more
  // than 20 000 when every surface cell had to be at most the tolerance): the
  // level that would pass the limit is not split, its cells are marked.
  vtkNew<vtkSphere> sphere;
  sphere->SetRadius(0.5);
  vtkNew<vtkTopologyPreservingContour> f;
  f->SetImplicitFunction(sphere);
  f->SetTolerance(0.002);
  f->SetMaximumNumberOfCells(2000);
  MessageRecorder messages(f);
  const FilterResult r = tpctest::Run(f);
  EXPECT_NE(messages.Warnings.find("by MaximumNumberOfCells (2000)"), std::string::npos) << messages.Warnings;
  EXPECT_EQ(messages.Warnings.find("lattice placements"), std::string::npos) << "no retry after the cell limit";
  ExpectStoppedCellsMarkedAndClosed(r, vtkTopologyPreservingContour::LIMIT_REACHED);
  EXPECT_LE(r.Grid->GetNumberOfCells(), 2000);
  EXPECT_EQ(r.Components, 1);
}

TEST(FilterErrors, SurfacesCloserThanTheFinestCellAreSeparatedAtTheToleranceSize)
{
  // Two boxes 0.005 apart: at MaximumDepth 6 the finest cell is ten times
  // wider than the gap. The faces' loops are located down to the lattice
  // (which does not depend on MaximumDepth) and separated by a plane in the
  // gap, so the cells pass: guaranteed, no warning, on one placement.
  const double a[6] = { 0, 1, 0, 0.2, 0, 0.2 }, b[6] = { 1.005, 2, 0, 0.2, 0, 0.2 };
  vtkNew<vtkTopologyPreservingContour> f;
  f->SetImplicitFunction(TwoBoxes(a, b));
  f->SetTolerance(0.05);
  MessageRecorder messages(f);
  ExpectResolvedWithMaximumDepth(f, 6, 2);
  EXPECT_EQ(messages.Warnings.find("guarantee does not hold"), std::string::npos) << messages.Warnings;
}

TEST(FilterErrors, BoxesSharingAFaceStopQuicklyWithoutGuarantee)
{
  // Two vtkBox solids touching along a face: refining the contact grows like
  // its area (half a minute at MaximumDepth 10, hours at 16 and beyond).
  const double a[6] = { 0, 1, 0, 1, 0, 1 }, b[6] = { 1, 2, 0, 1, 0, 1 };
  vtkNew<vtkTopologyPreservingContour> f;
  f->SetImplicitFunction(TwoBoxes(a, b));
  MessageRecorder messages(f);
  const FilterResult r = tpctest::Run(f);
  EXPECT_NE(messages.Warnings.find("solids touching along a face"), std::string::npos) << messages.Warnings;
  EXPECT_NE(messages.Warnings.find("closer than the finest cell"), std::string::npos) << messages.Warnings;
  EXPECT_EQ(messages.Warnings.find("lattice placements"), std::string::npos) << messages.Warnings;
  ExpectStoppedCellsMarkedAndClosed(r, vtkTopologyPreservingContour::SURFACES_TOO_CLOSE);
  EXPECT_LT(r.Grid->GetNumberOfCells(), 100000);
  // The union's topology, one box, with nothing invented at the contact.
  EXPECT_EQ(r.Components, 1);
}

TEST(FilterErrors, APieceWithoutAControllerReportsItselfOnly)
{
  // UpdatePiece without a global controller over the pieces: the piece is
  // computed on its own (one lattice placement, no reductions), warned
  // about, and never guaranteed - its report describes this piece only.
  vtkNew<vtkSphere> sphere;
  sphere->SetRadius(0.5);
  vtkNew<vtkTopologyPreservingContour> f;
  f->SetImplicitFunction(sphere);
  f->SetTolerance(0.05);
  MessageRecorder messages(f);
  f->UpdatePiece(0, 2, 0);
  EXPECT_NE(messages.Warnings.find("without a global controller"), std::string::npos) << messages.Warnings;
  vtkPolyData* piece = f->GetSurfaceOutput();
  EXPECT_GT(piece->GetNumberOfCells(), 0);
  EXPECT_EQ(tpctest::FieldValue(piece, "TopologyGuaranteed"), 0.0);
  EXPECT_EQ(tpctest::FieldValue(piece, "Closed"), 0.0) << "half a sphere is open along the seam";
}
