// Sign robustness of the core's inside test (MeshSolid::IsInside: exact ray
// parity with one symbolic perturbation) on every CGAL test mesh: at the
// points of a grid over the mesh's box that are not within a hair of the
// surface, it agrees with an independent classification, the generalized
// winding number (sum of the triangles' solid angles / 4 pi), whose floating
// point error is far below 1/2 away from the surface. The meshes are read
// with VTK, repaired by the core as the filter does, and classified by the
// core directly.
#include "CgalTestMeshes.h"

#include "MeshRepair.h"
#include "MeshSolid.h"
#include "PolygonTriangulation.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
/// Winding number of the closed triangle surface around p (Van Oosterom and
/// Strackee's solid angle formula).
double WindingNumber(const tpc::MeshSolid& mesh, const tpc::Vec3& p)
{
  double sum = 0.0;
  for (const auto& t : mesh.Triangles())
  {
    const tpc::Vec3 a = mesh.Points()[t[0]] - p, b = mesh.Points()[t[1]] - p, c = mesh.Points()[t[2]] - p;
    const double la = tpc::Norm(a), lb = tpc::Norm(b), lc = tpc::Norm(c);
    const double numerator = tpc::Dot(a, tpc::Cross(b, c));
    const double denominator = la * lb * lc + tpc::Dot(a, b) * lc + tpc::Dot(b, c) * la + tpc::Dot(c, a) * lb;
    sum += 2.0 * std::atan2(numerator, denominator);
  }
  return sum / (4.0 * M_PI);
}

class CgalMeshSigns : public testing::TestWithParam<int>
{
};
} // namespace

TEST_P(CgalMeshSigns, InsideTestAgreesWithWindingNumberAwayFromTheSurface)
{
  TPC_SKIP_WITHOUT_CGAL_MESHES();
  const tpctest::KnownMesh& known = tpctest::CgalMeshes[GetParam()];
  vtkSmartPointer<vtkPolyData> input = tpctest::ReadCgalMesh(known.Name);
  std::vector<tpc::Vec3> points;
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    const double* x = input->GetPoint(i);
    points.emplace_back(x[0], x[1], x[2]);
  }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint32_t> corners;
  auto cells = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    cells->GetCurrentCell(n, ids);
    corners.assign(ids, ids + n); // (polygons as the filter triangulates them)
    tpc::TriangulatePolygon(points, corners.data(), corners.size(), triangles);
  }
  const tpc::MeshRepairReport repair = tpc::RepairMesh(points, triangles);
  ASSERT_TRUE(repair.Closed());
  ASSERT_EQ(repair.SelfIntersections, 0u);
  const tpc::MeshSolid mesh(points, triangles);

  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(input);
  locator->BuildLocator();
  const tpc::Box3 box = mesh.Bounds();
  const double hair = 1e-6 * box.Diagonal();
  constexpr int N = 24; // points per axis, on a generic grid slightly larger than the box
  int tested = 0, inside = 0, disagreements = 0;
  for (int i = 0; i < N; ++i)
  {
    for (int j = 0; j < N; ++j)
    {
      for (int k = 0; k < N; ++k)
      {
        const int ijk[3] = { i, j, k };
        tpc::Vec3 p;
        for (int a = 0; a < 3; ++a)
        {
          const double f = (ijk[a] + 0.5 + 0.1234 * (a + 1)) / (N + 1);
          p[a] = box.lo[a] - 0.02 * box.Width(a) + f * 1.04 * box.Width(a);
        }
        double x[3] = { p[0], p[1], p[2] }, closest[3], d2;
        vtkIdType cell;
        int sub;
        locator->FindClosestPoint(x, closest, cell, sub, d2);
        if (std::sqrt(d2) < hair)
        {
          continue;
        }
        const double w = WindingNumber(mesh, p);
        ASSERT_LT(std::fabs(w - std::round(w)), 0.25) << "winding number not near an integer";
        const bool expected = std::lround(w) % 2 != 0;
        const bool got = mesh.IsInside(p);
        disagreements += expected != got ? 1 : 0;
        inside += got ? 1 : 0;
        ++tested;
      }
    }
  }
  EXPECT_EQ(disagreements, 0) << known.Name;
  EXPECT_GT(tested, N * N * N * 9 / 10);
  EXPECT_GT(inside, 0); // the grid does see the solid
}

INSTANTIATE_TEST_SUITE_P(AllMeshes, CgalMeshSigns,
  testing::Range(0, static_cast<int>(std::size(tpctest::CgalMeshes))),
  [](const testing::TestParamInfo<int>& info) { return tpctest::TestName(tpctest::CgalMeshes[info.param]); });
