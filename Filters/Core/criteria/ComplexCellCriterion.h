// The complex-cell test (paper 4.2 and 5.3.1): each face's tests (on every
// tile of a refined face, FaceRefinement.h), then the voxel's.
//
// A face is complex if the surface meets it but its corners show no sign
// change, if an edge is crossed more than once, or if its corner signs
// alternate (face ambiguity). For polyhedra the paper answers "does the
// surface meet this face/voxel" with max-norm distances; for our implicit
// primitives it is answered conservatively by interval enclosures of the
// pruned CSG expression: a box is free of the surface only if a single sign is
// proven on it. Overestimation can only cause extra refinement, never a missed
// intersection. The voxel's conditions (complex voxel, voxel ambiguity) are
// decided from the loops the surface draws on the cell boundary
// (BoundaryLoops.h), once its faces pass.
#pragma once

#include "BoundaryLoops.h"
#include "CsgExpression.h"
#include "RootGrid.h"
#include "SplitReason.h"

namespace tpc
{

/// Sign of the field on a closed box. Where the enclosure is not conclusive
/// the box is split (along its non-degenerate axes) up to `depth` times,
/// visiting at most `budget` pieces: near a CSG crease each primitive alone
/// straddles zero although their union or intersection does not, and only
/// smaller pieces separate them.
RegionSign ProveConstantSign(const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const Box3& box, int depth, int budget = 1 << 30);

/// Depth and budget used for "does the surface meet this voxel/face" proofs.
constexpr int ConstantProofDepth = 6;
constexpr int ConstantProofBudget = 64;

/// Box of face f of a cell box.
Box3 FaceBox(const Box3& cell, int face);

/// The complex-cell and ambiguity tests of one (sub)face of a cell
/// (paper 5.3.1, Lemma 1): returns ComplexFace (no sign change at its corners
/// but the surface may meet it), FaceAmbiguity (alternating corners),
/// ComplexEdge (an edge crossed more than once or not provably once),
/// NotStarShapedFace (no verified 2-D witness), or None. `inside` gives the
/// corner signs in the cyclic order (u0,v0), (u1,v0), (u1,v1), (u0,v1) with
/// u = axis + 1, v = axis + 2 (mod 3). The expression must be valid on the face.
/// For ComplexEdge, `failingEdge` (if given) receives k: the edge from corner
/// k to corner k + 1 in that order, and `opposite` (if given) the coordinate
/// along it of a point strictly inside it whose sign differs from its ends',
/// when the crossing count met one (else it is left unchanged): a point in
/// the gap or wedge between two crossings. `prunedToFace`: the expression is
/// already pruned to the face, to a mixed sign (face refinement prunes each
/// tile's: FaceRefinement.cxx), and neither the constant-sign proof nor the
/// star-shaped test prunes it again.
SplitReason FaceCompatibilityTest(const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const Box3& face, int axis, const bool inside[4],
  int* failingEdge = nullptr, double* opposite = nullptr, bool prunedToFace = false);

/// Edge k of a face (corners as for FaceCompatibilityTest) is crossed at
/// most once, proven. `opposite` as above, asked only when its ends agree;
/// `maxPieces` as for CountEdgeCrossings.
bool EdgeCrossedOnce(const CsgExpressionPtr& expression, const PrimitiveSet& primitives, const Box3& face,
  int axis, const bool inside[4], int k, double* opposite, int maxPieces = 4096);

/// Several loops on a cell boundary bound either several disks or pieces
/// joined inside the cell (a tube: the voxel ambiguity). They bound different
/// pieces if every two of them lie on opposite sides of a plane whose section
/// of the cell the surface provably misses: no piece can cross it. Near a
/// shallow crease, where a cell often holds a bit of each wall but not the
/// crease itself, this avoids refining what is already two simple disks.
/// The planes are placed between the loops' extents, located first to a
/// sixteenth of the cell, then (if that does not separate them) to the
/// lattice: surfaces passing closer than the cell - a near contact - are
/// separated at any gap wider than a few lattice spacings, without refining
/// down to the gap. Where no axis-aligned plane lies between two loops - the
/// two sheets beside a thin wedge's edge, in a generic orientation - an
/// oblique one between their crossings (SeparatingPlane.h) is tried, proven
/// missed leaf by leaf (planes and mesh triangles exactly, up to rounding
/// slack; curved quadrics by pieces of the cell). `regions`, when separated:
/// per loop, the cell cut by the axis-aligned planes separating it from the
/// others, on its side - a box that holds that loop and no other, and whose
/// cut sides the surface misses; the cell alone when an oblique plane was
/// needed (its sides are no box: the star-shaped test is then asked of the
/// whole cell, which implies it on either side).
bool LoopsSeparated(const BoundaryLoopSet& loops, const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const RootGrid& grid, const Box3& cell, std::vector<Box3>* regions = nullptr);

/// The voxel part of the complex-cell test, from the loops the surface draws
/// on the boundary of a cell (not proven free of the surface): ComplexVoxel
/// when there is none (the surface may meet the voxel but shows no sign
/// change on its boundary) or they do not close, VoxelAmbiguity when
/// several are not proven to bound different pieces (Fig. 2(d): two corners
/// joined by a tube, or not), else None. `loopRegions` receives the boxes in
/// which the star-shaped test must hold, one per loop (LoopsSeparated), or
/// the cell alone.
SplitReason VoxelCompatibilityTest(const BoundaryLoopSet& loops, const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const RootGrid& grid, const Box3& cell, std::vector<Box3>* loopRegions = nullptr);

} // namespace tpc
