// MC-compatibility of one cell (paper 4.2, Definition 1), as decided during
// the subdivision: the complex-cell test, the star-shaped test and the
// Hausdorff size, with faces refined where a face test fails.
#pragma once

#include "AdaptiveOctree.h"

#include <utility>
#include <vector>

namespace tpc
{

/// Outcome of the tests for one cell.
enum class McVerdict : std::uint8_t
{
  Pass,
  Constant, // proven free of the surface after local refinement
  Split
};

struct McCompatibility
{
  McVerdict Kind = McVerdict::Pass;
  SplitReason Reason = SplitReason::None;
  RegionSign Sign = RegionSign::Mixed;
  /// Faces this cell refined (only kept if it passes).
  std::vector<std::pair<FaceKey, std::vector<FaceTile>>> Refinements;
  /// Signs evaluated during the tests, for the global table.
  std::vector<std::pair<PointKey, bool>> NewSigns;
};

/// Face refinement levels allowed below a cell (bounded by the lattice).
constexpr int FaceRefinementLevels = 10;

/// The tests of paper 5.3 on one cell, with faces refined where a face test
/// fails (FaceRefinement.h). A cell passes when
/// - it is no larger than the tolerance (Hausdorff, 5.3.4);
/// - each face can be tiled by MC-compatible tiles (complex face and edge,
///   face ambiguity, star-shaped w.r.t. the face; Lemma 1 per tile);
/// - the surface draws exactly one loop on the cell boundary: none while the
///   voxel is not proven empty is a complex voxel, two or more is the voxel
///   ambiguity of Fig. 2(d) (or two sheets);
/// - the solid in the voxel is star-shaped (verified witness). With the ray
///   argument of Lemma 2 this makes the surface in the cell a single disk
///   (Lemma 3) bounded by that loop.
McCompatibility TestMcCompatibility(const AdaptiveOctree& tree, std::uint32_t n,
  const PrimitiveSet& primitives, double tolerance);

} // namespace tpc
