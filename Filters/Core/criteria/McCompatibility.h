// MC-compatibility of one cell (paper 4.2, Definition 1), as decided during
// the subdivision: the complex-cell test, the star-shaped test and the
// Hausdorff size, with faces refined where a face test fails.
#pragma once

#include "AdaptiveOctree.h"
#include "BoundaryLoops.h"
#include "ConvexPolygons.h"

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace tpc
{

class FaceDecisionCache; // (FaceDecisionCache.h)

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
  /// Passed while larger than the tolerance: the surface in it is a plane
  /// section (PlanarCell.h), so its patch is exact whatever its size.
  bool Planar = false;
  /// One quadric is the surface in the cell and the certified error of any
  /// patch of it, or of the fan over its own loop (QuadricCellError.h), or
  /// one mesh and the certified error of its final fan (MeshCellError.h),
  /// PredictedError, is within the tolerance: the cell may pass at any size,
  /// and its error is certified on its final patch (CellPatches.h).
  bool ErrorBounded = false;
  double PredictedError = HUGE_VAL;
  /// ErrorBounded where one mesh is the surface in a cell larger than the
  /// tolerance (MeshCellError.h): the prediction holds for the fans around
  /// its apexes (MeshCellApex, or one per loop) over the final loops. (Cells
  /// of one mesh, or where meshes
  /// meet - MeshBooleanSurface.h - within the tolerance are ErrorBounded
  /// too, predicted by their diagonal, with their own patch.)
  bool MeshSurface = false;
  /// For MeshSurface: the prediction (its Bound is PredictedError), kept
  /// for the extraction.
  AdaptiveOctree::MeshCellPrediction MeshPrediction;
  /// ErrorBounded where a crease of two quadrics crosses a cell larger than
  /// the tolerance (QuadricCellError.h): its patch is the fan around its
  /// crease apex, over a loop drawn through the crease on its tiles (bounded
  /// for any patch, or predicted over that loop).
  bool CreaseFan = false;
  /// Set where one quadric (or several, no crease) is the surface in a cell
  /// larger than the tolerance whose bound for any patch failed, but whose
  /// fan around this apex over its own loop, refined as crack patching
  /// refines it, is within the tolerance (QuadricCellError.h: Predicted on
  /// the cell's own loop): ErrorBounded then, the apex kept for the
  /// extraction.
  std::optional<Vec3> QuadricFanApex;
  /// Set where meshes meet in a cell larger than the tolerance whose fans
  /// around these apexes (one per loop) over its own loops are predicted
  /// within the tolerance (MeshBooleanCellError.h): ErrorBounded and
  /// CreaseFan then, the apexes kept for the extraction, which certifies the
  /// final patch.
  std::vector<Vec3> BooleanFanApexes;
  /// Larger than the tolerance (the Hausdorff size test's own comparison).
  bool Oversized = false;
  /// Split for its size before the other tests: a spoke of every fan its
  /// prediction could be made with strays beyond the tolerance
  /// (MeshCellError.h: Spokes).
  bool SplitBySpoke = false;
  /// Split for its size because its prediction's fan has a point too far
  /// from the mesh (MeshCellError.h: Probes).
  bool SplitByProbe = false;
  /// Split because no fan its prediction could draw follows its creases,
  /// found before the branch and bound (MeshCellError.h: Creases first).
  bool SplitByCreases = false;
  /// Passed on a prediction made over finer chords (MeshCellError.h: Chords
  /// refined).
  bool ChordsRefined = false;
  /// Faces this cell refined (only kept if it passes).
  std::vector<std::pair<FaceKey, std::vector<FaceTile>>> Refinements;
  /// Signs evaluated during the tests, for the global table.
  std::vector<std::pair<PointKey, bool>> NewSigns;
};

/// Face refinement levels allowed below a cell (bounded by the lattice).
constexpr int FaceRefinementLevels = 10;

/// The tests of paper 5.3 on one cell, with faces refined where a face test
/// fails (FaceRefinement.h). A cell passes when
/// - it is no larger than the tolerance (Hausdorff, 5.3.4), or the surface in
///   it is a plane section (PlanarCell.h: the patch is then exact), or one
///   quadric or one mesh whose certified error is within the tolerance
///   (QuadricCellError.h, MeshCellError.h: for a mesh, and for a quadric
///   whose bound for any patch fails, decided last, on the loop the other
///   tests traced);
/// - each face can be tiled by MC-compatible tiles (complex face and edge,
///   face ambiguity, star-shaped w.r.t. the face; Lemma 1 per tile);
/// - the surface draws at least one loop on the cell boundary (none while the
///   voxel is not proven empty is a complex voxel), and if several, they are
///   proven to bound different pieces of the surface (ComplexCellCriterion.h);
///   otherwise it is the voxel ambiguity of Fig. 2(d) - two corners joined by
///   a tube, or not;
/// - the solid in the voxel is star-shaped (verified witness). With the ray
///   argument of Lemma 2 this makes each piece of the surface in the cell a
///   disk (Lemma 3) bounded by its own loop.
/// `faceRefinementLevels` below the cell at most (FaceRefinementLevels; fewer
/// where a failing cell keeps its mesh anyway, ExactCell.h). With
/// `provenFailuresFirst`, a cell larger than the tolerance whose surface is
/// one mesh is first checked for a spoke that rules out every fan, and its
/// prediction probes its fan before the branch and bound (MeshCellError.h:
/// Spokes, Probes; SubdivisionParameters::ProvenFailuresFirst), and every
/// cell's error tests run before its star-shaped test (a cell failing both
/// reports its error's reason).
/// `surfaceScratch`: where S_C is built (a buffer reused across cells,
/// ScratchPool.h); null for one of its own. With `refineChords`, a mesh
/// cell's failed prediction is made again over finer chords where they
/// strayed (MeshCellError.h: Chords refined). `faceDecisions` (if given): the
/// crease tiles and face tilings decided for the cells tested with it
/// (FaceDecisionCache.h).
McCompatibility TestMcCompatibility(const AdaptiveOctree& tree, std::uint32_t n,
  const PrimitiveSet& primitives, double tolerance, int faceRefinementLevels = FaceRefinementLevels,
  bool provenFailuresFirst = true, PolygonSet* surfaceScratch = nullptr, bool refineChords = true,
  FaceDecisionCache* faceDecisions = nullptr);

} // namespace tpc
