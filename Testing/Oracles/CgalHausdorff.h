// An oracle for the tests: the two-sided Hausdorff distance between two
// triangle meshes by CGAL's bounded-error method
// (CGAL::Polygon_mesh_processing::bounded_error_Hausdorff_distance, Tang et
// al.'s branch and bound: certified, not sampled). CGAL is GPL: it is linked
// into test programs only, never into the product.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace tpcoracle
{

struct TriangleSoup
{
  std::vector<std::array<double, 3>> Points;
  std::vector<std::array<std::uint32_t, 3>> Triangles;
};

/// The directed Hausdorff distance from `from` to `to` lies in [Lower, Upper]
/// (Upper - Lower = 2 errorBound at most).
struct HausdorffEstimate
{
  double Lower = 0.0;
  double Upper = 0.0;
};

/// CGAL's estimate, within `errorBound` of the true directed distance. The
/// meshes need not be closed or manifold: a polygon soup is enough.
HausdorffEstimate DirectedHausdorffWithCgal(const TriangleSoup& from, const TriangleSoup& to, double errorBound);

} // namespace tpcoracle
