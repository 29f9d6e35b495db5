// Boolean operations on real meshes (and a mesh minus implicit spheres):
// the filter's result has the topology of the exact Boolean, as computed
// independently by CGAL's corefinement on an exact kernel and recorded in
// Data/CsgReference.csv (Testing/Reference/CsgReference.cxx made it).
#include "CgalTestMeshes.h"
#include "FilterTestHelpers.h"

#include "vtkImplicitBoolean.h"
#include "vtkSphere.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct CsgCase
{
  std::string Name, MeshA, B, Operation;
  double Translation[3] = { 0, 0, 0 };
  int Components = -1, Genus = -1;
  double Angle = 0.0; ///< smallest angle between crossing triangles of A and B, degrees (-1: no crossing)
  double Gap = -1.0;  ///< distance between A and B relative to the domain's diagonal (-1: they meet)
};

std::vector<CsgCase> ReadReference()
{
  std::vector<CsgCase> cases;
  std::ifstream in(TPC_CSG_REFERENCE);
  std::string line;
  while (std::getline(in, line))
  {
    if (line.empty() || line[0] == '#')
    {
      continue;
    }
    std::stringstream fields(line);
    std::vector<std::string> f;
    std::string field;
    while (std::getline(fields, field, ','))
    {
      f.push_back(field);
    }
    if (f.size() != 11)
    {
      continue;
    }
    CsgCase c;
    c.Name = f[0];
    c.MeshA = f[1];
    c.B = f[2];
    c.Operation = f[3];
    for (int a = 0; a < 3; ++a)
    {
      c.Translation[a] = std::stod(f[4 + a]);
    }
    c.Components = std::stoi(f[7]);
    c.Genus = std::stoi(f[8]);
    c.Angle = std::stod(f[9]);
    c.Gap = std::stod(f[10]);
    cases.push_back(c);
  }
  return cases;
}

const std::vector<CsgCase>& Cases()
{
  static const std::vector<CsgCase> cases = ReadReference();
  return cases;
}

class CgalCsg : public testing::TestWithParam<std::tuple<int, int>>
{
};
} // namespace

TEST(CgalCsgReference, CoversUnionIntersectionDifferenceAndImplicits)
{
  // The test instantiation below covers exactly the recorded cases.
  ASSERT_EQ(Cases().size(), 16u) << "read " << TPC_CSG_REFERENCE << "; update Range() below";
  int unions = 0, intersections = 0, differences = 0, implicits = 0;
  for (const CsgCase& c : Cases())
  {
    unions += c.Operation == "union";
    intersections += c.Operation == "intersection";
    differences += c.Operation == "difference" && c.B.rfind("spheres:", 0) != 0;
    implicits += c.B.rfind("spheres:", 0) == 0;
  }
  EXPECT_GE(unions, 1);
  EXPECT_GE(intersections, 1);
  EXPECT_GE(differences, 1);
  EXPECT_GE(implicits, 1);
  // At least half cross at shallow angles or pass within 1e-4 of the domain
  // without meeting (issue 16): thin wedges along the intersection curve and
  // near contacts, what the lattice tests long failed on. Both kinds occur.
  int shallow = 0, near = 0;
  for (const CsgCase& c : Cases())
  {
    shallow += c.Angle >= 0.0 && c.Angle < 10.0;
    near += c.Gap > 0.0 && c.Gap < 1e-4;
  }
  EXPECT_GE(2 * (shallow + near), static_cast<int>(Cases().size()));
  EXPECT_GE(shallow, 3);
  EXPECT_GE(near, 3);
}

TEST_P(CgalCsg, SameTopologyAsTheExactBoolean)
{
  TPC_SKIP_WITHOUT_CGAL_MESHES();
  ASSERT_LT(static_cast<std::size_t>(std::get<0>(GetParam())), Cases().size());
  const CsgCase& c = Cases()[std::get<0>(GetParam())];
  const int denominator = 32 << std::get<1>(GetParam());

  vtkNew<vtkTopologyPreservingContour> filter;
  filter->AddInputData(tpctest::ReadCgalMesh(c.MeshA));
  vtkNew<vtkImplicitBoolean> spheres;
  vtkNew<vtkTransformPolyDataFilter> moved;
  if (c.B.rfind("spheres:", 0) == 0)
  {
    spheres->SetOperationTypeToUnion();
    std::stringstream list(c.B.substr(8));
    std::string item;
    while (std::getline(list, item, ';'))
    {
      std::stringstream v(item);
      double x, y, z, r;
      v >> x >> y >> z >> r;
      vtkNew<vtkSphere> s;
      s->SetCenter(x, y, z);
      s->SetRadius(r);
      spheres->AddFunction(s);
    }
    filter->SetImplicitFunction(spheres);
  }
  else
  {
    vtkNew<vtkTransform> t;
    t->Translate(c.Translation);
    moved->SetInputData(tpctest::ReadCgalMesh(c.B));
    moved->SetTransform(t);
    moved->Update();
    filter->AddInputData(moved->GetOutput());
  }
  filter->SetOperation(c.Operation == "union"
      ? vtkTopologyPreservingContour::UNION
      : (c.Operation == "intersection" ? vtkTopologyPreservingContour::INTERSECTION
                                       : vtkTopologyPreservingContour::DIFFERENCE));
  filter->SetTolerance(1.0 / denominator);
  const tpctest::FilterResult r = tpctest::Run(filter);

  EXPECT_EQ(r.Guaranteed, 1) << c.Name;
  EXPECT_EQ(r.Components, c.Components) << c.Name;
  EXPECT_EQ(r.Genus, c.Genus) << c.Name;
  const tpctest::IndependentTopology t = tpctest::Measure(r.Surface);
  EXPECT_EQ(t.BoundaryEdges, 0) << c.Name;
  EXPECT_EQ(t.NonManifoldEdges, 0) << c.Name;
  EXPECT_EQ(t.Components, c.Components) << c.Name;
  EXPECT_EQ(t.Genus, c.Genus) << c.Name;
}

// Cases are read at run time; the range covers the recorded ones (checked above).
INSTANTIATE_TEST_SUITE_P(Recorded, CgalCsg, testing::Combine(testing::Range(0, 16), testing::Range(0, 3)),
  [](const testing::TestParamInfo<std::tuple<int, int>>& info) {
    const std::size_t i = static_cast<std::size_t>(std::get<0>(info.param));
    return (i < Cases().size() ? Cases()[i].Name : "case" + std::to_string(i)) + "_1_" +
      std::to_string(32 << std::get<1>(info.param));
  });
