#include "PolyDataToMesh.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include <cmath>

namespace tpc
{
namespace vtkadapter
{

bool ConvertPolyData(vtkPolyData* input, MeshInput& mesh, std::string& error, const ParallelFor& parallelFor,
  const ProgressCallback& progress)
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
  vtkPolyData* triangles = triangulate->GetOutput();
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
  mesh.Solid = MeshSolid(std::move(points), std::move(faces));
  return true;
}

} // namespace vtkadapter
} // namespace tpc
