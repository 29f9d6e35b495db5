#include "PolyDataToMesh.h"

#include "PolygonTriangulation.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCleanPolyData.h"
#include "vtkFillHolesFilter.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>

namespace tpc
{
namespace vtkadapter
{

namespace
{
/// The input's points, or false (with `error` set) at a non-finite one.
bool ReadPoints(vtkPoints* input, std::vector<Vec3>& points, std::string& error)
{
  const vtkIdType n = input ? input->GetNumberOfPoints() : 0;
  points.resize(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      error = "point " + std::to_string(i) + " has a non-finite coordinate";
      return false;
    }
    points[static_cast<std::size_t>(i)] = { p[0], p[1], p[2] };
  }
  return true;
}

/// Polygons as triangles, exactly (PolygonTriangulation.h: no polygon loses
/// a triangle, as vtkTriangleFilter's tolerance-based triangulation did on
/// nearly planar non-convex faces); the polygons that had to be fanned are
/// counted in `fanned`.
void AppendPolygons(vtkCellArray* polys, const std::vector<Vec3>& points, std::vector<Triangle>& faces,
  std::size_t& fanned)
{
  std::vector<std::uint32_t> corners;
  // (Room for every triangle at once - n - 2 per polygon of n corners:
  // grown as it came, the list was copied a dozen times into fresh pages.)
  const vtkIdType triangles = polys->GetNumberOfConnectivityIds() - 2 * polys->GetNumberOfCells();
  faces.reserve(faces.size() + static_cast<std::size_t>(std::max<vtkIdType>(triangles, 0)));
  auto it = vtk::TakeSmartPointer(polys->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    if (n < 3)
    {
      continue;
    }
    corners.assign(ids, ids + n);
    if (TriangulatePolygon(points, corners.data(), corners.size(), faces) == PolygonTriangulation::Fan)
    {
      ++fanned;
    }
  }
}

/// Triangle strips as triangles, each oriented as the strip's first
/// (vtkTriangleStrip's convention: every other triangle is turned).
void AppendStrips(vtkCellArray* strips, std::vector<Triangle>& faces)
{
  auto it = vtk::TakeSmartPointer(strips->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    for (vtkIdType i = 0; i + 2 < n; ++i)
    {
      const auto a = static_cast<std::uint32_t>(ids[i + (i % 2)]);
      const auto b = static_cast<std::uint32_t>(ids[i + 1 - (i % 2)]);
      faces.push_back({ a, b, static_cast<std::uint32_t>(ids[i + 2]) });
    }
  }
}

/// The mesh with its holes closed: exactly coincident points merged (so
/// that triangles of a soup share edges), every boundary loop filled by a
/// polygon (vtkFillHolesFilter), triangulated as the input's polygons are.
/// The triangles this adds go to `filled`.
void FillHoles(std::vector<Vec3>& points, std::vector<Triangle>& faces, std::size_t& filled, std::size_t& fanned)
{
  vtkNew<vtkPoints> inputPoints;
  inputPoints->SetDataTypeToDouble();
  for (const Vec3& p : points)
  {
    inputPoints->InsertNextPoint(p[0], p[1], p[2]);
  }
  vtkNew<vtkCellArray> triangles;
  for (const Triangle& t : faces)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    triangles->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(inputPoints);
  mesh->SetPolys(triangles);
  vtkNew<vtkCleanPolyData> merge;
  merge->SetInputData(mesh);
  merge->SetTolerance(0.0);
  merge->ConvertLinesToPointsOff();
  merge->ConvertPolysToLinesOff();
  merge->ConvertStripsToPolysOff();
  vtkNew<vtkFillHolesFilter> fill;
  fill->SetInputConnection(merge->GetOutputPort());
  fill->SetHoleSize(VTK_DOUBLE_MAX); // (every hole, however large)
  fill->Update();
  std::string unused; // (the points were finite already)
  ReadPoints(fill->GetOutput()->GetPoints(), points, unused);
  const std::size_t before = faces.size();
  faces.clear();
  AppendPolygons(fill->GetOutput()->GetPolys(), points, faces, fanned);
  filled = faces.size() > before ? faces.size() - before : 0;
}
} // namespace

bool ConvertPolyData(vtkPolyData* input, MeshInput& mesh, std::string& error, bool fillHoles,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  mesh.IgnoredLines = input->GetLines() ? static_cast<std::size_t>(input->GetLines()->GetNumberOfCells()) : 0;
  mesh.IgnoredVertices = input->GetVerts() ? static_cast<std::size_t>(input->GetVerts()->GetNumberOfCells()) : 0;
  std::vector<Vec3> points;
  if (!ReadPoints(input->GetPoints(), points, error))
  {
    return false;
  }
  std::vector<Triangle> faces;
  std::size_t fanned = 0, filled = 0;
  if (input->GetPolys())
  {
    AppendPolygons(input->GetPolys(), points, faces, fanned);
  }
  if (input->GetStrips())
  {
    AppendStrips(input->GetStrips(), faces);
  }
  if (fillHoles && !faces.empty())
  {
    FillHoles(points, faces, filled, fanned);
  }
  if (faces.empty())
  {
    error = "it has no polygons or triangle strips";
    return false;
  }
  mesh.Solid = RepairIntoSolid(std::move(points), std::move(faces), mesh.Repair, 100, parallelFor, progress);
  mesh.Repair.FilledHoleTriangles = filled;
  mesh.Repair.FannedPolygons = fanned;
  return true;
}

} // namespace vtkadapter
} // namespace tpc
