#include "PolyDataToMesh.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCleanPolyData.h"
#include "vtkFillHolesFilter.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cmath>

namespace tpc
{
namespace vtkadapter
{

namespace
{
/// `surface` with its holes closed: exactly coincident points merged (so
/// that triangles of a soup share edges), every boundary loop filled by a
/// polygon. The number of triangles this adds goes to `filled`.
vtkSmartPointer<vtkPolyData> FilledHoles(vtkPolyData* surface, std::size_t& filled)
{
  vtkNew<vtkCleanPolyData> merge;
  merge->SetInputData(surface);
  merge->SetTolerance(0.0);
  merge->ConvertLinesToPointsOff();
  merge->ConvertPolysToLinesOff();
  merge->ConvertStripsToPolysOff();
  vtkNew<vtkFillHolesFilter> fill;
  fill->SetInputConnection(merge->GetOutputPort());
  fill->SetHoleSize(VTK_DOUBLE_MAX); // (every hole, however large)
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputConnection(fill->GetOutputPort());
  triangulate->Update();
  // (The merge keeps triangles triangles: its conversions are off.)
  const vtkIdType added = triangulate->GetOutput()->GetNumberOfPolys() - merge->GetOutput()->GetNumberOfPolys();
  filled = static_cast<std::size_t>(std::max<vtkIdType>(0, added));
  return triangulate->GetOutput();
}
} // namespace

bool ConvertPolyData(vtkPolyData* input, MeshInput& mesh, std::string& error, bool fillHoles,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  mesh.IgnoredLines = input->GetLines() ? static_cast<std::size_t>(input->GetLines()->GetNumberOfCells()) : 0;
  mesh.IgnoredVertices = input->GetVerts() ? static_cast<std::size_t>(input->GetVerts()->GetNumberOfCells()) : 0;

  // Polygons and triangle strips become triangles.
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(input->GetPoints());
  surface->SetPolys(input->GetPolys());
  surface->SetStrips(input->GetStrips());
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(surface);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  vtkSmartPointer<vtkPolyData> triangles = triangulate->GetOutput();
  std::size_t filled = 0;
  if (fillHoles && triangles->GetNumberOfPolys() > 0)
  {
    triangles = FilledHoles(triangles, filled);
  }
  if (triangles->GetNumberOfPolys() == 0)
  {
    error = "it has no polygons or triangle strips";
    return false;
  }

  std::vector<Vec3> points(static_cast<std::size_t>(triangles->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < triangles->GetNumberOfPoints(); ++i)
  {
    double p[3];
    triangles->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      error = "point " + std::to_string(i) + " has a non-finite coordinate";
      return false;
    }
    points[static_cast<std::size_t>(i)] = { p[0], p[1], p[2] };
  }
  std::vector<std::array<std::uint32_t, 3>> faces;
  faces.reserve(static_cast<std::size_t>(triangles->GetNumberOfPolys()));
  auto it = vtk::TakeSmartPointer(triangles->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    if (n == 3)
    {
      faces.push_back({ static_cast<std::uint32_t>(ids[0]), static_cast<std::uint32_t>(ids[1]),
        static_cast<std::uint32_t>(ids[2]) });
    }
  }
  mesh.Repair = RepairMesh(points, faces, true, 100, parallelFor, progress);
  mesh.Repair.FilledHoleTriangles = filled;
  mesh.Solid = MeshSolid(std::move(points), std::move(faces));
  return true;
}

} // namespace vtkadapter
} // namespace tpc
