#include "CrackPatching.h"

#include "CreaseCrossing.h"
#include "CrossingVertices.h"
#include "CsgCreaseCrossing.h"

#include "ExactCell.h"

namespace tpc
{
namespace
{
/// Gathers the final samples on the boundary of one leaf (CrackPatching.h).
class CellBoundaryBuilder
{
public:
  CellBoundaryBuilder(const AdaptiveOctree& tree, std::size_t cell)
    : Tree(tree)
    , Cell(cell)
    , Node(tree.Nodes[cell])
  {
  }

  CellBoundary Build()
  {
    CellBoundary b;
    const int depth = this->Tree.Grid.MaxDepth;
    const int shift = depth - this->Node.Level;
    b.Size = LatticeIndex(1) << shift;
    for (int a = 0; a < 3; ++a)
    {
      b.Base[a] = this->Node.Ijk[a] << shift;
    }
    for (int c = 0; c < 8; ++c)
    {
      this->AddLeafCorner(b, this->Cell, c);
    }
    for (int f = 0; f < 6; ++f)
    {
      this->FaceTiles(b, f);
    }
    this->EdgeNeighborPoints(b);
    // Face-refinement points on every tile edge (T-junctions from refined
    // faces anywhere around this cell).
    std::vector<PointKey> extra;
    for (int f = 0; f < 6; ++f)
    {
      const int axis = f / 2;
      const int U = (axis + 1) % 3, V = (axis + 2) % 3;
      const LatticeIndex plane = b.Base[axis] + (f % 2 ? b.Size : 0);
      for (const FaceTile& t : b.Tiles[f])
      {
        // Bottom and top edges run along U, left and right along V.
        const LatticeIndex starts[4][2] = { { t.U0, t.V0 }, { t.U0, t.V1 }, { t.U0, t.V0 },
          { t.U1, t.V0 } };
        for (int k = 0; k < 4; ++k)
        {
          LatticeIndex p[3];
          p[axis] = plane;
          p[U] = starts[k][0];
          p[V] = starts[k][1];
          const int along = k < 2 ? U : V;
          this->Tree.RefinementPointsOn(p, along, k < 2 ? t.U1 : t.V1, extra);
        }
      }
    }
    for (const PointKey k : extra)
    {
      b.Points.emplace_back(k, this->Tree.Signs.Find(k) == 1);
    }
    return b;
  }

private:
  void AddLeafCorner(CellBoundary& b, std::size_t leaf, int corner) const
  {
    LatticeIndex p[3];
    CornerLattice(this->Tree.Grid, this->Tree.Nodes[leaf], corner, p);
    const PointKey key = MakePointKey(p[0], p[1], p[2]);
    b.Points.emplace_back(key, this->Tree.PointInside(leaf, key));
  }

  void AddTileCorners(CellBoundary& b, int axis, LatticeIndex plane, const FaceTile& t) const
  {
    for (int c = 0; c < 4; ++c)
    {
      const PointKey key = TileCorner(axis, plane, t, c);
      b.Points.emplace_back(key, this->Tree.Signs.Find(key) == 1);
    }
  }

  void CollectAdjacentLeaves(std::size_t node, int axisU, int bitU, int axisV, int bitV,
    std::vector<std::size_t>& out) const
  {
    const OctreeNode& n = this->Tree.Nodes[node];
    if (n.IsLeaf())
    {
      out.push_back(node);
      return;
    }
    for (int c = 0; c < 8; ++c)
    {
      if (((c >> axisU) & 1) == bitU && (axisV < 0 || ((c >> axisV) & 1) == bitV))
      {
        this->CollectAdjacentLeaves(static_cast<std::size_t>(n.FirstChild + c), axisU, bitU, axisV, bitV, out);
      }
    }
  }

  /// The neighbour displaced by `offset` at this cell's level, if it exists
  /// there and is refined (only then does it bring finer samples).
  std::int64_t RefinedNeighbor(const int offset[3]) const
  {
    const std::int64_t n = this->Neighbor(offset);
    if (n < 0)
    {
      return -1;
    }
    const OctreeNode& nn = this->Tree.Nodes[static_cast<std::size_t>(n)];
    return (nn.Level == this->Node.Level && !nn.IsLeaf()) ? n : -1;
  }

  /// The node displaced by `offset` at this cell's level, or the leaf
  /// holding that position; -1 outside the grid.
  std::int64_t Neighbor(const int offset[3]) const
  {
    std::int64_t ijk[3];
    for (int a = 0; a < 3; ++a)
    {
      ijk[a] = static_cast<std::int64_t>(this->Node.Ijk[a]) + offset[a];
    }
    return this->Tree.Find(this->Node.Level, ijk);
  }

  /// Tiles of the face of `leaf` on face f's side, refined if it was, with
  /// the leaf `across` them.
  void AddFaceOfLeaf(CellBoundary& b, int f, std::size_t leaf, int leafFace, std::int64_t across) const
  {
    const int axis = f / 2;
    const LatticeIndex plane = b.Base[axis] + (f % 2 ? b.Size : 0);
    const OctreeNode& q = this->Tree.Nodes[leaf];
    const auto it = this->Tree.FaceRefinements.find(FaceOf(this->Tree.Grid, q, leafFace));
    if (it != this->Tree.FaceRefinements.end())
    {
      for (const FaceTile& t : it->second)
      {
        b.Tiles[f].push_back(t);
        b.Across[f].push_back(across);
        this->AddTileCorners(b, axis, plane, t);
      }
      return;
    }
    const int shift = this->Tree.Grid.MaxDepth - q.Level;
    const LatticeIndex u0 = q.Ijk[(axis + 1) % 3] << shift, v0 = q.Ijk[(axis + 2) % 3] << shift;
    const FaceTile t{ u0, v0, u0 + (LatticeIndex(1) << shift), v0 + (LatticeIndex(1) << shift) };
    b.Tiles[f].push_back(t);
    b.Across[f].push_back(across);
    for (int c = 0; c < 8; ++c)
    {
      if (((c >> axis) & 1) == leafFace % 2)
      {
        this->AddLeafCorner(b, leaf, c);
      }
    }
  }

  void FaceTiles(CellBoundary& b, int f) const
  {
    const int axis = f / 2, side = f % 2;
    int offset[3] = { 0, 0, 0 };
    offset[axis] = side ? 1 : -1;
    const std::int64_t n = this->RefinedNeighbor(offset);
    if (n < 0)
    {
      this->AddFaceOfLeaf(b, f, this->Cell, f, this->Neighbor(offset));
      return;
    }
    std::vector<std::size_t> leaves;
    this->CollectAdjacentLeaves(static_cast<std::size_t>(n), axis, side ? 0 : 1, -1, 0, leaves);
    for (const std::size_t leaf : leaves)
    {
      this->AddFaceOfLeaf(b, f, leaf, 2 * axis + (side ? 0 : 1), static_cast<std::int64_t>(leaf));
    }
  }

  /// Corners of the finer leaves of the diagonal neighbours on this cell's edges.
  void EdgeNeighborPoints(CellBoundary& b) const
  {
    for (int e = 0; e < 12; ++e)
    {
      const int axis = e / 4, r = e % 4;
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const int du = r & 1, dv = (r >> 1) & 1;
      int offset[3] = { 0, 0, 0 };
      offset[u] = du ? 1 : -1;
      offset[v] = dv ? 1 : -1;
      const std::int64_t n = this->RefinedNeighbor(offset);
      if (n < 0)
      {
        continue;
      }
      std::vector<std::size_t> leaves;
      this->CollectAdjacentLeaves(static_cast<std::size_t>(n), u, du ? 0 : 1, v, dv ? 0 : 1, leaves);
      for (const std::size_t leaf : leaves)
      {
        for (int end = 0; end < 2; ++end)
        {
          this->AddLeafCorner(b, leaf, ((du ? 0 : 1) << u) | ((dv ? 0 : 1) << v) | (end << axis));
        }
      }
    }
  }

  const AdaptiveOctree& Tree;
  std::size_t Cell;
  const OctreeNode& Node;
};
} // namespace

CellBoundary GatherCellBoundary(const AdaptiveOctree& tree, std::size_t cell)
{
  return CellBoundaryBuilder(tree, cell).Build();
}

BoundaryLoopSet CellLoops(
  const AdaptiveOctree& tree, std::uint32_t cell, const PrimitiveSet& prims, FaceDecisionCache* faceDecisions)
{
  const CsgLeaf* own = tree.Nodes[cell].State == CellState::Exact ? LoneMeshLeaf(*tree.Expressions[cell]) : nullptr;
  if (own)
  {
    ExactPolygons polygons = ClipToExactCell(GatherCellBoundary(tree, cell), *own, prims, tree.Grid);
    BoundaryLoopSet set;
    set.Crossings = std::move(polygons.Vertices);
    set.LoopSizes = std::move(polygons.Sizes);
    return set;
  }
  CellBoundary boundary = MarkedCellBoundary(tree, cell, prims, faceDecisions);
  return TraceBoundaryLoops(boundary);
}

CellBoundary MarkedCellBoundary(
  const AdaptiveOctree& tree, std::uint32_t cell, const PrimitiveSet& prims, FaceDecisionCache* faceDecisions)
{
  CellBoundary boundary = GatherCellBoundary(tree, cell);
  // Tiles shared with an exact cell carry the mesh's exact trace.
  std::vector<ExactTile> exact;
  for (int f = 0; f < 6; ++f)
  {
    for (std::size_t k = 0; k < boundary.Tiles[f].size(); ++k)
    {
      const std::int64_t across = boundary.Across[f][k];
      const CsgLeaf* leaf = across >= 0 && tree.Nodes[static_cast<std::size_t>(across)].State == CellState::Exact
        ? LoneMeshLeaf(*tree.Expressions[static_cast<std::size_t>(across)])
        : nullptr;
      if (leaf)
      {
        exact.push_back({ f, k, leaf });
      }
    }
  }
  AddExactTileSegments(boundary, exact, prims, tree.Grid);
  // Crease tiles between two cells of the same lone mesh leaf, neither exact
  // (CreaseCrossing.h): both sides decide alike.
  if (const CsgLeaf* mine = LoneMeshLeaf(*tree.Expressions[cell]))
  {
    MarkCreaseTiles(boundary, *mine, prims, tree.Grid, [&](int f, std::size_t k) {
      const std::int64_t across = boundary.Across[f][k];
      if (across < 0 || (k < boundary.ExactTile[f].size() && boundary.ExactTile[f][k]))
      {
        return false;
      }
      const std::size_t other = static_cast<std::size_t>(across);
      const CsgLeaf* theirs = tree.Nodes[other].State != CellState::Exact && tree.Expressions[other]
        ? LoneMeshLeaf(*tree.Expressions[other])
        : nullptr;
      return theirs && theirs->Primitive == mine->Primitive;
    }, faceDecisions);
  }
  else
  {
    // CSG crease tiles (CsgCreaseCrossing.h): both cells sharing a tile decide
    // with the expression of a crease-fan cell if one of them is one (its
    // own loop was drawn so when it was accepted, QuadricCellError.h), else
    // of the one first in node order (the one placing x), except where an
    // exact cell draws the tile.
    MarkCsgCreaseTiles(boundary, prims, tree.Grid, [&](int f, std::size_t k) -> const CsgExpressionPtr* {
      if (k < boundary.ExactTile[f].size() && boundary.ExactTile[f][k])
      {
        return nullptr;
      }
      const std::int64_t across = boundary.Across[f][k];
      if (across < 0)
      {
        return &tree.Expressions[cell];
      }
      const std::size_t other = static_cast<std::size_t>(across);
      const bool mine = DecidesBefore(tree.Nodes[cell].CreaseFan, cell, tree.Nodes[other].CreaseFan, other);
      return &tree.Expressions[mine ? cell : other];
    });
  }
  return boundary;
}

} // namespace tpc
