// The certified error of a cell's final patch (issue 17): the bound of
// QuadricCellError.h evaluated on the triangles and loop chords the cell
// actually drew, after crack patching and apex placement; or, where one mesh
// is the surface, MeshCellError.h's distance between those triangles and the
// mesh in the cell; where meshes meet, the same against the surface's two
// sides (MeshBooleanSurface.h).
#pragma once

#include "AdaptiveOctree.h"
#include "CellPatches.h"
#include "MeshBooleanSurface.h"
#include "MeshCellError.h"
#include "QuadricCellError.h"
#include "SlabBound.h"
#include "TriangleMesh.h"

namespace tpc
{

/// The cell's triangles with their vertices' positions.
std::vector<SourceTriangle> PatchTriangles(const CellPatches& patches, const TriangleMesh& mesh);

/// E_C of the cell's `patches` (crossing vertices in `mesh`, apexes local):
/// the largest triangle term over its triangles and the largest chord term
/// over the triangle edges lying in one face of the cell (the loop's chords:
/// an apex is strictly inside the cell, and Marching Cubes' fan diagonals
/// join points on no common face, LoopTriangulation.h). +inf when a chord
/// lies on a face without a monotone direction, or when E_C exceeds the
/// margin (the argument's segments must stay in the grown cell).
double CertifiedPatchError(const QuadricCellError& bound, const CellPatches& patches, const TriangleMesh& mesh);

/// S in a surface leaf whose patch is certified against it: where one mesh
/// is the surface S_C (MeshCellError.h), where meshes meet S from both
/// sides (MeshBooleanSurface.h), with the creases where they cross when
/// asked; the memory reused from cell to cell (ScratchPool.h).
struct CellSurface
{
  PolygonSet Mesh;
  TriangleList MeshTriangles;         ///< where one mesh is the surface: each polygon's triangle
  const MeshSolid* Solid = nullptr;   ///< that mesh
  MeshBooleanSurface Boolean;
  std::vector<CreaseSegment> Creases;
  bool OneMesh = true;
  /// The scene is one mesh (IsOneMesh): nothing reads the cells' errors
  /// tighter than they are asked for (CertifiedCellError).
  bool SceneOfOneMesh = true;
  double Slack = 0.0;

  const PolygonSet& OnSurface() const { return this->OneMesh ? this->Mesh : this->Boolean.OnSurface; }
  const PolygonSet& Covering() const { return this->OneMesh ? this->Mesh : this->Boolean.Covering; }
};

/// S in leaf `n`, where one mesh is the surface or meshes meet
/// (IsCertifiableMeshBoolean), in `surface` - with the creases where meshes
/// cross if `creases` (MeshBooleanSurfaceInCell); false where it is
/// neither.
bool SurfaceOfCell(
  const AdaptiveOctree& tree, std::uint32_t n, const PrimitiveSet& prims, bool creases, CellSurface& surface);

/// E(P) of the cell's `patches` against `surface` (MeshCellError.h,
/// CertifiedSurfacePatchError); Lower kept only where it is a distance the
/// patch attains (one mesh), else 0. In a scene of one mesh, pieces settle
/// with the first bound found within `enough` (PolygonHausdorff.h: Settled
/// pieces): the first certificates aim there, RefineMeshCertificates refines
/// those above 1.1 times the largest Lower (max(enough, Lower) is what it
/// would be without it, so that threshold is at most lower, the bound
/// reported within it all the same), and the errors are read only as proven
/// bounds (the decimation measures against the mesh itself there). In other
/// scenes the decimation takes each cell's error as its triangles' spent
/// room (TriangleErrorBounds.h, ErrorCertificates' ThroughBounds): they are
/// bounded as tightly as their branch and bounds find.
HausdorffEstimate CertifiedCellError(const CellSurface& surface, const CellPatches& patches, const TriangleMesh& mesh,
  double enough, double giveUp, std::size_t budget);

/// E(P) of the cell's `patches` by the slab bound (SlabBound.h) where one
/// mesh is the surface, in a scene of one closed manifold mesh (elsewhere
/// the decimation reads the cells' errors as spent room: CertifiedCellError
/// keeps them tight): every chord of the patch's loops within
/// `chordReach` of the trace as that bound needs it (SlabBound.h: Loops
/// refining the cell's own); where that is above `enough`, the local
/// heights' bound over the cell's own chords `own` is tried too
/// (LocalHeights.h), up to `giveUp`. +inf where neither applies.
double SlabCellError(const CellSurface& surface, const CellPatches& patches, const TriangleMesh& mesh,
  double chordReach, const OwnChords& own = {}, double enough = HUGE_VAL, double giveUp = HUGE_VAL);

/// E(P) of the cell's apex fans over final loops that refine its own
/// (`same`: are them) where S_C is several sheets: the slab bound sheet by
/// sheet (SheetwiseSlabError, MeshCellError.h), each fan grouped with the own
/// loop whose apex (`prediction`'s) it is drawn around, `enough` and `giveUp`
/// as for SlabCellError; +inf where SlabCellError would not apply, a
/// triangle is around no own apex, or a sheet's bound is above `giveUp`.
double SheetwiseCellError(const CellSurface& surface, const CellPatches& patches, const TriangleMesh& mesh,
  const AdaptiveOctree::MeshCellPrediction& prediction, bool same, const Box3& cell, double enough, double giveUp);

/// E(P) of the cell's fans over its final loops (`loops`, their points
/// `finals`: FinalLoopPoints), whether or not those refine its own: each
/// final chord's delta measured on the cell's final boundary (`boundary`,
/// MarkedCellBoundary: the tiles the final chords cross, from whichever side
/// of each face is finer - tiles that passed the face tests there, one arc
/// of the trace each - and the crease tiles' halves) as the prediction
/// measures its own chords (MeshCellError.h: MeasureChords), plus the slack;
/// then the slab bound with the largest of them as the chords' reach and the
/// final chords as the own (SlabBound.h: the final chords are the patch's,
/// each within its delta of its arc; LocalHeights.h), sheet by sheet where
/// there are several loops (MeshCellError.h: Several sheets; each loop's fan
/// the triangles around its apex). Where a finer neighbour retiled a crease
/// tile, the final loops no longer hold the own loops' points and the
/// prediction's bound no longer holds (FinalLoopsRefine); this does. +inf
/// where SlabCellError would not apply, a chord has no tile, or the fans
/// are not one per loop around its own apex.
double FinalChordsCellError(const CellSurface& surface, const CellPatches& patches, const TriangleMesh& mesh,
  const RootGrid& grid, const CellBoundary& boundary, const BoundaryLoopSet& loops,
  const std::vector<std::vector<Vec3>>& finals, const Box3& cell, double enough, double giveUp);

} // namespace tpc
