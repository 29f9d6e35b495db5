// The adaptive octree forest produced by the topology preserving subdivision
// (paper 5.3): nodes with their level, lattice position, split reason and
// state, the exact corner signs, and for each leaf meeting the surface the
// CSG expression pruned to it (what the extraction evaluates).
#pragma once

#include "CsgExpression.h"
#include "FaceTile.h"
#include "ForestPartition.h"
#include "LatticeSignTable.h"
#include "RootGrid.h"
#include "SplitReason.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace tpc
{

struct OctreeNode
{
  LatticeIndex Ijk[3] = { 0, 0, 0 }; ///< integer position at this node's level
  std::uint8_t Level = 0;
  SplitReason Reason = SplitReason::None;
  CellState State = CellState::Outside;
  /// For Unresolved leaves: the criterion that still failed.
  SplitReason FailedTest = SplitReason::None;
  /// A Surface leaf kept larger than the tolerance because the surface in it
  /// is a union of plane sections (PlanarCell.h): its patches must stay in
  /// their planes.
  bool PlaneSection = false;
  /// A Surface leaf where one quadric or one mesh is the surface and its
  /// error is certified on its patch (QuadricCellError.h, MeshCellError.h);
  /// it may be larger than the tolerance.
  bool ErrorBounded = false;
  /// An ErrorBounded leaf larger than the tolerance that a crease of two
  /// quadrics crosses (QuadricCellError.h): its patch is the fan around its
  /// crease apex, and the tiles of its faces decide CSG crease crossings with
  /// its expression (CrackPatching.h).
  bool CreaseFan = false;
  /// Children are FirstChild + c, c = x + 2y + 4z (VTK's HyperTree order); -1 for leaves.
  std::int32_t FirstChild = -1;

  bool IsLeaf() const { return FirstChild < 0; }
};

/// Corner c of a cell is at offset (c&1, (c>>1)&1, (c>>2)&1).
inline void CornerLattice(const RootGrid& grid, const OctreeNode& n, int c, LatticeIndex p[3])
{
  const int shift = grid.MaxDepth - n.Level;
  for (int a = 0; a < 3; ++a)
  {
    p[a] = (n.Ijk[a] + ((c >> a) & 1)) << shift;
  }
}

/// A face of a cell: its low corner (lattice), normal axis and cell level.
struct FaceKey
{
  PointKey Low = 0;
  std::uint8_t Axis = 0;
  std::uint8_t Level = 0;
  bool operator==(const FaceKey& o) const { return Low == o.Low && Axis == o.Axis && Level == o.Level; }
};

struct FaceKeyHash
{
  std::size_t operator()(const FaceKey& k) const
  {
    return HashKey(k.Low ^ (static_cast<LatticeKey>(k.Axis * 64u + k.Level) << 126));
  }
};

/// Face f (see CubeTopology.h) of node n.
FaceKey FaceOf(const RootGrid& grid, const OctreeNode& n, int f);

class AdaptiveOctree
{
public:
  RootGrid Grid;
  /// The tolerance the cells were accepted with (the margin of the certified
  /// cells' bounds, QuadricCellError.h).
  double HausdorffTolerance = 0.0;
  /// The scene's whole expression, for what looks beyond a cell (the grown
  /// cell of QuadricCellError.h).
  CsgExpressionPtr SceneExpression;
  /// Role of each tree in a run split into pieces (ForestPartition.h);
  /// empty: one piece, every tree its own.
  std::vector<TreeRole> Roles;
  TreeRole RoleOf(const OctreeNode& n) const
  {
    return this->Roles.empty() ? TreeRole::Own
                               : this->Roles[static_cast<std::size_t>(TreeOf(this->Grid, n.Level, n.Ijk))];
  }
  /// Roots first: node t is the root of tree t (t = i + Dims0 * (j + Dims1 * k)).
  std::vector<OctreeNode> Nodes;
  /// Pruned expression of each node that meets the surface (null elsewhere).
  std::vector<CsgExpressionPtr> Expressions;
  /// For each node whose own expression has no mesh leaf: the scene's
  /// expression pruned to its cell grown by the tolerance (GrownByMargin,
  /// QuadricCellError.h), from its parent's where that has one (a child's
  /// grown cell lies in its parent's), else from the scene's; null for nodes
  /// holding a mesh, whose bounds look no further than the cell's own
  /// expression. It equals the scene's on the grown cell, but may hold fewer
  /// leaves than pruning the scene there directly: an enclosure on a
  /// parent's box may prove a sign that one on the child's does not.
  std::vector<CsgExpressionPtr> NearExpressions;
  /// An expression equal to the scene's on node n's cell grown by `margin`:
  /// its NearExpressions entry for a margin up to the tolerance, else the
  /// scene's whole expression.
  const CsgExpressionPtr& NearExpression(std::size_t n, double margin) const
  {
    return margin <= this->HausdorffTolerance && n < this->NearExpressions.size() && this->NearExpressions[n]
      ? this->NearExpressions[n]
      : this->SceneExpression;
  }
  /// Exact inside/outside at lattice corners of cells that met the surface.
  LatticeSignTable Signs;

  /// The subdivision's certified prediction for each error-bounded leaf
  /// larger than the tolerance where one mesh is the surface
  /// (MeshCellError.h): Bound bounds the error of the fan the extraction
  /// builds there when its final loop holds the cell's own loop's points in
  /// order (crack patching only refines the cell's own loop) and is fanned
  /// around the same apex; a cell of several loops (MeshCellError.h:
  /// Several loops) has one apex per loop, and Bound holds where each final
  /// loop refines its own around its apex.
  struct MeshCellPrediction
  {
    double Bound = HUGE_VAL;
    /// The points of the cell's own loops, loop by loop.
    std::vector<std::vector<Vec3>> Loops;
    /// Each loop's apex (MeshCellApex; with several loops, each in its
    /// loop's room, ApexRooms.h; or points of creases, MeshCellError.h:
    /// Crease apexes): the extraction's apex fans are around them
    /// (a fan from a loop point, if drawn instead, is certified on its own).
    std::vector<Vec3> Apexes;
    /// The largest distance between the fans over Loops and the mesh that
    /// the prediction came upon.
    double Attained = 0.0;
    /// The fans over Loops' certified error alone (Bound without the chords'
    /// deviation): the final patch's where the final loops are the own loops
    /// themselves;
    /// +inf where the cell was accepted on the per-chord bound (a bound of
    /// the fan's error too, but far above it: not kept as one,
    /// MeshCellError.h).
    double OwnFanError = HUGE_VAL;
    /// Set where the prediction failed at a probe, before its branch and
    /// bound (MeshCellError.h: Probes; such cells split).
    bool ProbeStrayed = false;
    /// What the prediction found of the cell's creases before its branch
    /// and bound (MeshCellError.h: Creases first), where it looked.
    enum class CreaseFans : std::uint8_t
    {
      NotAsked,
      ApexFanFollows,  ///< the fan over Loops around Apexes follows them
      OtherFanFollows, ///< it does not, a fan around crease points does
      NoneFollows      ///< no fan over the loops does: the cell splits
    };
    /// (Set to ApexFanFollows too where PredictCreaseApex chose Apexes.)
    CreaseFans Creases = CreaseFans::NotAsked;
    /// The chords' largest deviation from the trace, delta, with the
    /// rounding slack (+inf until computed).
    double Delta = HUGE_VAL;
  };
  std::unordered_map<std::uint32_t, MeshCellPrediction> MeshCellPredictions;

  /// The apex of each error-bounded leaf larger than the tolerance accepted
  /// on the fan over its own loop where a quadric is the surface
  /// (QuadricCellError.h: Predicted on the cell's own loop). The extraction
  /// draws that fan where its usual patch is not certified within the
  /// tolerance.
  std::unordered_map<std::uint32_t, Vec3> QuadricFanApexes;
  /// The apexes of each error-bounded leaf larger than the tolerance where
  /// meshes meet, one per loop (MeshBooleanCellError.h): the extraction
  /// draws the fans around them over the final loops and certifies them.
  std::unordered_map<std::uint32_t, std::vector<Vec3>> BooleanFanApexes;

  /// Tiles of faces that were refined (FaceRefinement.h), for leaves that
  /// passed the tests; faces not listed are a single tile.
  std::unordered_map<FaceKey, std::vector<FaceTile>, FaceKeyHash> FaceRefinements;
  /// Positions of face-refinement sample points on each lattice line (see
  /// LineKey), sorted: the points every cell touching the line must use.
  std::unordered_map<LatticeKey, std::vector<LatticeIndex>, LatticeKeyHash> RefinementLines;

  /// Fills RefinementLines from FaceRefinements.
  void IndexRefinementPoints();
  /// Refinement points strictly inside the lattice segment from `p` along
  /// `axis` to coordinate `end`.
  void RefinementPointsOn(const LatticeIndex p[3], int axis, LatticeIndex end,
    std::vector<PointKey>& out) const;

  /// Index of the node at (level, ijk) if it exists, otherwise of the deepest
  /// existing ancestor (a leaf containing that position), or -1 outside the grid.
  std::int64_t Find(int level, const std::int64_t ijk[3]) const;

  /// Inside/outside at a corner of node `n` (constant leaves know their sign
  /// without a table entry).
  bool CornerInside(std::size_t n, int corner) const;
  bool PointInside(std::size_t leafContainingPoint, PointKey key) const;

  std::size_t MemoryBytes() const;
};

} // namespace tpc
