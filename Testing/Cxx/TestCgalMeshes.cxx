// Remeshing real closed meshes of known topology (CGAL's demo data, Debian
// package libcgal-demo) at three tolerances: the output has the input's
// components and genus (both measured with VTK's own filters), is closed and
// manifold, carries the guarantee, and lies within the tolerance of the
// input both ways (vtkHausdorffDistancePointSetFilter on densified samples).
#include "CgalTestMeshes.h"
#include "FilterTestHelpers.h"

#include "CgalPolygonTriangulation.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkHausdorffDistancePointSetFilter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyDataPointSampler.h"

#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <tuple>

namespace
{
using tpctest::CgalMeshes;
using tpctest::KnownMesh;
using tpctest::ReadCgalMesh;

const int Denominators[] = { 32, 64, 128 };

/// `surface` with its polygons as triangles, triangulated by CGAL in their
/// planes (the oracle's: VTK's triangles of a nearly planar non-convex face
/// can lie outside it, and the point sampler's own points of such a polygon
/// do).
vtkSmartPointer<vtkPolyData> Triangulated(vtkPolyData* surface)
{
  std::vector<std::array<double, 3>> points(static_cast<std::size_t>(surface->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    surface->GetPoint(i, points[static_cast<std::size_t>(i)].data());
  }
  std::vector<std::vector<std::uint32_t>> polygons;
  auto cells = vtk::TakeSmartPointer(surface->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    cells->GetCurrentCell(n, ids);
    polygons.emplace_back(ids, ids + n);
  }
  vtkNew<vtkCellArray> triangles;
  for (const auto& t : tpcoracle::TriangulateFacesWithCgal(points, polygons))
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    triangles->InsertNextCell(3, ids);
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->SetPoints(surface->GetPoints());
  result->SetPolys(triangles);
  return result;
}

/// The surface's triangles with extra points on them every `spacing`
/// (unreferenced by the triangles): its points sample the whole surface and
/// its cells are the surface itself.
vtkSmartPointer<vtkPolyData> Densified(vtkPolyData* surface, double spacing)
{
  vtkNew<vtkPolyDataPointSampler> sampler;
  sampler->SetInputData(surface);
  sampler->SetDistance(spacing);
  sampler->GenerateVertexPointsOn();
  sampler->GenerateEdgePointsOn();
  sampler->GenerateInteriorPointsOn();
  sampler->Update();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(surface->GetPoints());
  vtkPoints* samples = sampler->GetOutput()->GetPoints();
  for (vtkIdType i = 0; samples && i < samples->GetNumberOfPoints(); ++i)
  {
    points->InsertNextPoint(samples->GetPoint(i));
  }
  auto dense = vtkSmartPointer<vtkPolyData>::New();
  dense->SetPoints(points);
  dense->SetPolys(surface->GetPolys());
  return dense;
}

/// `surface`, its polygons triangulated by CGAL if it has any.
vtkSmartPointer<vtkPolyData> AsTriangles(vtkPolyData* surface)
{
  return surface->GetPolys()->IsHomogeneous() == 3 ? vtkSmartPointer<vtkPolyData>(surface) : Triangulated(surface);
}

/// Largest distance from a sample of `from` to the triangles of `to`.
double DirectedHausdorff(vtkPolyData* from, vtkPolyData* to, double spacing)
{
  vtkNew<vtkHausdorffDistancePointSetFilter> h;
  h->SetInputData(0, Densified(AsTriangles(from), spacing));
  h->SetInputData(1, AsTriangles(to));
  h->SetTargetDistanceMethod(vtkHausdorffDistancePointSetFilter::POINT_TO_CELL);
  h->Update();
  return h->GetRelativeDistance()[0];
}

class CgalRemeshing : public testing::TestWithParam<std::tuple<int, int>>
{
};
} // namespace

TEST(CgalMeshInputs, AreClosedManifoldWithThePublishedTopology)
{
  TPC_SKIP_WITHOUT_CGAL_MESHES();
  for (const KnownMesh& m : CgalMeshes)
  {
    vtkSmartPointer<vtkPolyData> input = ReadCgalMesh(m.Name);
    ASSERT_GT(input->GetNumberOfPolys(), 0) << m.Name;
    vtkNew<vtkCleanPolyData> clean; // merge the duplicate vertices some files have
    clean->SetInputData(input);
    clean->Update();
    const tpctest::IndependentTopology t = tpctest::Measure(clean->GetOutput());
    EXPECT_EQ(t.BoundaryEdges, 0) << m.Name;
    EXPECT_EQ(t.NonManifoldEdges, 0) << m.Name;
    EXPECT_EQ(t.Components, m.Components) << m.Name;
    EXPECT_EQ(t.Genus, m.Genus) << m.Name;
  }
}

TEST_P(CgalRemeshing, SameTopologyClosedManifoldGuaranteedWithinTolerance)
{
  TPC_SKIP_WITHOUT_CGAL_MESHES();
  const KnownMesh& m = CgalMeshes[std::get<0>(GetParam())];
  const int denominator = Denominators[std::get<1>(GetParam())];
  vtkSmartPointer<vtkPolyData> input = ReadCgalMesh(m.Name);

  vtkNew<vtkTopologyPreservingContour> filter;
  filter->SetInputData(input);
  filter->SetTolerance(1.0 / denominator);
  const tpctest::FilterResult r = tpctest::Run(filter);

  EXPECT_EQ(r.Guaranteed, 1);
  EXPECT_EQ(r.Unresolved, 0);
  EXPECT_EQ(r.Components, m.Components);
  EXPECT_EQ(r.Genus, m.Genus);
  const tpctest::IndependentTopology t = tpctest::Measure(r.Surface);
  EXPECT_EQ(t.BoundaryEdges, 0);
  EXPECT_EQ(t.NonManifoldEdges, 0);
  EXPECT_EQ(t.Components, m.Components);
  EXPECT_EQ(t.Genus, m.Genus);

  // Two-sided Hausdorff distance, sampled at half the tolerance (the
  // measured distances are an order of magnitude below it).
  ASSERT_GT(r.Tolerance, 0.0);
  EXPECT_LE(r.HausdorffBound, r.Tolerance * (1 + 1e-9));
  const double toOutput = DirectedHausdorff(input, r.Surface, r.Tolerance / 2);
  const double toInput = DirectedHausdorff(r.Surface, input, r.Tolerance / 2);
  EXPECT_LE(toOutput, r.Tolerance);
  EXPECT_LE(toInput, r.Tolerance);
  std::cout << m.Name << " at 1/" << denominator << ": " << input->GetNumberOfPolys() << " -> "
            << r.Surface->GetNumberOfPolys() << " triangles, Hausdorff " << toOutput << " / "
            << toInput << " <= " << r.Tolerance << std::endl;
}

// The paper's remeshing/simplification use (6.2, 6.3): at a coarse tolerance
// dense inputs come out with fewer triangles and the same topology.
TEST(CgalRemeshing, CoarseToleranceReducesTriangleCountKeepingTopology)
{
  TPC_SKIP_WITHOUT_CGAL_MESHES();
  for (const char* name : { "turbine", "knot2", "knot1" })
  {
    const KnownMesh* m = nullptr;
    for (const KnownMesh& k : CgalMeshes)
    {
      m = std::string(k.Name) == name ? &k : m;
    }
    ASSERT_NE(m, nullptr);
    vtkSmartPointer<vtkPolyData> input = ReadCgalMesh(name);
    vtkNew<vtkTopologyPreservingContour> filter;
    filter->SetInputData(input);
    filter->SetTolerance(1.0 / 16);
    const tpctest::FilterResult r = tpctest::Run(filter);
    const tpctest::IndependentTopology t = tpctest::Measure(r.Surface);
    EXPECT_EQ(r.Guaranteed, 1) << name;
    EXPECT_EQ(t.Components, m->Components) << name;
    EXPECT_EQ(t.Genus, m->Genus) << name;
    EXPECT_EQ(t.BoundaryEdges + t.NonManifoldEdges, 0) << name;
    const vtkIdType in = input->GetNumberOfPolys(), out = r.Surface->GetNumberOfPolys();
    EXPECT_LT(out, in) << name;
    EXPECT_LE(DirectedHausdorff(input, r.Surface, r.Tolerance / 2), r.Tolerance) << name;
    EXPECT_LE(DirectedHausdorff(r.Surface, input, r.Tolerance / 2), r.Tolerance) << name;
    std::cout << name << " remeshed at 1/16: " << in << " -> " << out << " triangles ("
              << 100.0 * out / in << " %)" << std::endl;
    RecordProperty(std::string(name) + "_triangles_out_of_" + std::to_string(in), static_cast<int>(out));
  }
}

INSTANTIATE_TEST_SUITE_P(AllMeshes, CgalRemeshing,
  testing::Combine(testing::Range(0, static_cast<int>(std::size(CgalMeshes))), testing::Range(0, 3)),
  [](const testing::TestParamInfo<std::tuple<int, int>>& info) {
    return tpctest::TestName(CgalMeshes[std::get<0>(info.param)]) + "_1_" +
      std::to_string(Denominators[std::get<1>(info.param)]);
  });
