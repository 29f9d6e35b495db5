// Helpers for the filter tests: run the filter, read its report, and measure
// the output's topology independently with VTK filters (connectivity,
// feature edges, edge extraction) rather than with the core's own report.
// Every run's "Embedded" field is held against CGAL's self-intersection test.
#pragma once

#include "CgalEmbedding.h"
#include "vtkTopologyPreservingContour.h"

#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkPoints.h"

#include <gtest/gtest.h>

#include "vtkCallbackCommand.h"
#include "vtkCleanPolyData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExtractEdges.h"
#include "vtkFeatureEdges.h"
#include "vtkFieldData.h"
#include "vtkHyperTreeGrid.h"
#include "vtkImplicitFunction.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataConnectivityFilter.h"
#include "vtkSmartPointer.h"

#include <string>

namespace tpctest
{

inline double FieldValue(vtkDataObject* d, const char* name)
{
  vtkDataArray* a = vtkDataArray::SafeDownCast(d->GetFieldData()->GetAbstractArray(name));
  return a && a->GetNumberOfTuples() > 0 ? a->GetTuple1(0) : -999.0;
}

struct FilterResult
{
  vtkSmartPointer<vtkPolyData> Surface;
  vtkSmartPointer<vtkHyperTreeGrid> Grid;
  int Components = -1;
  int Genus = -1;
  int Euler = 0;
  int Guaranteed = -1;
  int Unresolved = -1;
  int Embedded = -1;
  int Outward = -1;
  double HausdorffBound = 0.0;
  double Tolerance = 0.0;
};

/// CGAL's verdict on a triangle surface, with its own point ids.
inline tpcoracle::EmbeddingVerdict CgalVerdict(vtkPolyData* surface)
{
  std::vector<std::array<double, 3>> points(static_cast<std::size_t>(surface->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    surface->GetPoint(i, points[static_cast<std::size_t>(i)].data());
  }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
  {
    surface->GetCellPoints(c, ids);
    triangles.push_back({ static_cast<std::uint32_t>(ids->GetId(0)), static_cast<std::uint32_t>(ids->GetId(1)),
      static_cast<std::uint32_t>(ids->GetId(2)) });
  }
  return tpcoracle::CheckEmbeddingWithCgal(points, triangles);
}

inline FilterResult Run(vtkTopologyPreservingContour* filter)
{
  filter->Update();
  FilterResult r;
  r.Surface = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0));
  r.Grid = vtkHyperTreeGrid::SafeDownCast(filter->GetOutputDataObject(1));
  r.Components = static_cast<int>(FieldValue(r.Surface, "Components"));
  r.Genus = static_cast<int>(FieldValue(r.Surface, "Genus"));
  r.Euler = static_cast<int>(FieldValue(r.Surface, "EulerCharacteristic"));
  r.Guaranteed = static_cast<int>(FieldValue(r.Surface, "TopologyGuaranteed"));
  r.Unresolved = static_cast<int>(FieldValue(r.Surface, "UnresolvedCells"));
  r.Embedded = static_cast<int>(FieldValue(r.Surface, "Embedded"));
  r.Outward = static_cast<int>(FieldValue(r.Surface, "Outward"));
  if (r.Surface->GetNumberOfCells() > 0)
  {
    const tpcoracle::EmbeddingVerdict cgal = CgalVerdict(r.Surface);
    EXPECT_TRUE(!cgal.Checked || (r.Embedded == 1) == cgal.Embedded())
      << "CGAL: " << cgal.SelfIntersectingPairs << " self-intersecting pairs, " << cgal.CoincidentVertices
      << " coincident vertices";
    // (Every component pointing out of the solid, against CGAL's verdict on
    // the same surface.)
    EXPECT_TRUE(!cgal.Checked || !cgal.VolumeChecked || (r.Outward == 1) == cgal.Outward)
      << "Outward " << r.Outward << ", CGAL " << cgal.Outward;
  }
  r.HausdorffBound = FieldValue(r.Surface, "HausdorffBound");
  r.Tolerance = FieldValue(r.Surface, "AbsoluteTolerance");
  return r;
}

inline FilterResult Contour(vtkImplicitFunction* f, double tolerance, int maximumDepth = 16)
{
  vtkNew<vtkTopologyPreservingContour> filter;
  filter->SetImplicitFunction(f);
  filter->SetTolerance(tolerance);
  filter->SetMaximumDepth(maximumDepth);
  return Run(filter);
}

/// Topology measured with VTK's own filters.
struct IndependentTopology
{
  vtkIdType Components = 0;
  vtkIdType BoundaryEdges = 0;
  vtkIdType NonManifoldEdges = 0;
  vtkIdType Euler = 0;
  vtkIdType Genus = -1;
};

inline IndependentTopology Measure(vtkPolyData* surface)
{
  IndependentTopology t;
  vtkNew<vtkPolyDataConnectivityFilter> conn;
  conn->SetInputData(surface);
  conn->SetExtractionModeToAllRegions();
  conn->Update();
  t.Components = conn->GetNumberOfExtractedRegions();

  vtkNew<vtkFeatureEdges> fe;
  fe->SetInputData(surface);
  fe->BoundaryEdgesOn();
  fe->NonManifoldEdgesOff();
  fe->FeatureEdgesOff();
  fe->ManifoldEdgesOff();
  fe->Update();
  t.BoundaryEdges = fe->GetOutput()->GetNumberOfCells();
  fe->BoundaryEdgesOff();
  fe->NonManifoldEdgesOn();
  fe->Update();
  t.NonManifoldEdges = fe->GetOutput()->GetNumberOfCells();

  vtkNew<vtkExtractEdges> edges;
  edges->SetInputData(surface);
  edges->UseAllPointsOn();
  edges->Update();
  t.Euler = surface->GetNumberOfPoints() - edges->GetOutput()->GetNumberOfLines() +
    surface->GetNumberOfPolys();
  if ((2 * t.Components - t.Euler) % 2 == 0)
  {
    t.Genus = (2 * t.Components - t.Euler) / 2;
  }
  return t;
}

/// Records errors and warnings emitted by an algorithm.
class MessageRecorder
{
public:
  explicit MessageRecorder(vtkObject* watched)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback(&MessageRecorder::OnEvent);
    watched->AddObserver(vtkCommand::ErrorEvent, this->Callback);
    watched->AddObserver(vtkCommand::WarningEvent, this->Callback);
  }
  std::string Errors;
  std::string Warnings;

private:
  static void OnEvent(vtkObject*, unsigned long event, void* clientData, void* callData)
  {
    auto* self = static_cast<MessageRecorder*>(clientData);
    const char* text = static_cast<const char*>(callData);
    (event == vtkCommand::ErrorEvent ? self->Errors : self->Warnings) += text ? text : "";
  }
  vtkNew<vtkCallbackCommand> Callback;
};

} // namespace tpctest
