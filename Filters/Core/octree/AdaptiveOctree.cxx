#include "AdaptiveOctree.h"

#include <algorithm>

namespace tpc
{

const char* SplitReasonName(SplitReason r)
{
  switch (r)
  {
    case SplitReason::None:
      return "none";
    case SplitReason::ComplexVoxel:
      return "complex voxel";
    case SplitReason::ComplexFace:
      return "complex face";
    case SplitReason::ComplexEdge:
      return "complex edge";
    case SplitReason::FaceAmbiguity:
      return "face ambiguity";
    case SplitReason::VoxelAmbiguity:
      return "voxel ambiguity";
    case SplitReason::NotStarShapedVoxel:
      return "not star-shaped w.r.t. voxel";
    case SplitReason::NotStarShapedFace:
      return "not star-shaped w.r.t. a face";
    case SplitReason::HausdorffSize:
      return "Hausdorff size";
    case SplitReason::LimitReached:
      return "limit reached";
    case SplitReason::SurfacesTooClose:
      return "surfaces too close";
    case SplitReason::PatchNotEmbedded:
      return "patch not embedded";
    case SplitReason::CreaseNotFollowed:
      return "crease not followed";
    case SplitReason::PatchNotCertified:
      return "patch not certified";
  }
  return "unknown";
}

const char* CellStateName(CellState s)
{
  switch (s)
  {
    case CellState::Inside:
      return "inside";
    case CellState::Outside:
      return "outside";
    case CellState::Surface:
      return "surface";
    case CellState::Unresolved:
      return "unresolved";
    case CellState::Refined:
      return "refined";
    case CellState::Exact:
      return "exact input";
  }
  return "unknown";
}

FaceKey FaceOf(const RootGrid& grid, const OctreeNode& n, int f)
{
  const int axis = f / 2, side = f % 2;
  const int shift = grid.MaxDepth - n.Level;
  LatticeIndex p[3];
  for (int a = 0; a < 3; ++a)
  {
    p[a] = (n.Ijk[a] + (a == axis ? static_cast<LatticeIndex>(side) : LatticeIndex(0))) << shift;
  }
  return { MakePointKey(p[0], p[1], p[2]), static_cast<std::uint8_t>(axis), n.Level };
}

void AdaptiveOctree::IndexRefinementPoints()
{
  this->RefinementLines.clear();
  for (const auto& entry : this->FaceRefinements)
  {
    LatticeIndex low[3];
    SplitPointKey(entry.first.Low, low);
    const int axis = entry.first.Axis;
    for (const FaceTile& t : entry.second)
    {
      for (int c = 0; c < 4; ++c)
      {
        LatticeIndex p[3];
        SplitPointKey(TileCorner(axis, low[axis], t, c), p);
        for (int a = 0; a < 3; ++a)
        {
          this->RefinementLines[LineKey(p, a)].push_back(p[a]);
        }
      }
    }
  }
  for (auto& line : this->RefinementLines)
  {
    std::sort(line.second.begin(), line.second.end());
    line.second.erase(std::unique(line.second.begin(), line.second.end()), line.second.end());
  }
}

void AdaptiveOctree::RefinementPointsOn(
  const LatticeIndex p[3], int axis, LatticeIndex end, std::vector<PointKey>& out) const
{
  const auto it = this->RefinementLines.find(LineKey(p, axis));
  if (it == this->RefinementLines.end())
  {
    return;
  }
  const LatticeIndex lo = std::min(p[axis], end), hi = std::max(p[axis], end);
  auto first = std::upper_bound(it->second.begin(), it->second.end(), lo);
  for (; first != it->second.end() && *first < hi; ++first)
  {
    LatticeIndex q[3] = { p[0], p[1], p[2] };
    q[axis] = *first;
    out.push_back(MakePointKey(q[0], q[1], q[2]));
  }
}

std::int64_t AdaptiveOctree::Find(int level, const std::int64_t ijk[3]) const
{
  std::int64_t tree[3];
  for (int a = 0; a < 3; ++a)
  {
    if (ijk[a] < 0)
    {
      return -1;
    }
    tree[a] = ijk[a] >> level;
    if (tree[a] >= this->Grid.Dims[a])
    {
      return -1;
    }
  }
  std::int64_t node = this->Grid.TreeIndex(static_cast<int>(tree[0]), static_cast<int>(tree[1]), static_cast<int>(tree[2]));
  for (int l = 1; l <= level; ++l)
  {
    const OctreeNode& n = this->Nodes[static_cast<std::size_t>(node)];
    if (n.IsLeaf())
    {
      return node;
    }
    const int shift = level - l;
    const int child = static_cast<int>(((ijk[0] >> shift) & 1) | (((ijk[1] >> shift) & 1) << 1) |
      (((ijk[2] >> shift) & 1) << 2));
    node = n.FirstChild + child;
  }
  return node;
}

bool AdaptiveOctree::CornerInside(std::size_t n, int corner) const
{
  const OctreeNode& node = this->Nodes[n];
  if (node.State == CellState::Inside || node.State == CellState::Outside)
  {
    return node.State == CellState::Inside;
  }
  LatticeIndex p[3];
  CornerLattice(this->Grid, node, corner, p);
  return this->Signs.Find(MakePointKey(p[0], p[1], p[2])) == 1;
}

bool AdaptiveOctree::PointInside(std::size_t leaf, PointKey key) const
{
  const OctreeNode& node = this->Nodes[leaf];
  if (node.State == CellState::Inside || node.State == CellState::Outside)
  {
    return node.State == CellState::Inside;
  }
  return this->Signs.Find(key) == 1;
}

std::size_t AdaptiveOctree::MemoryBytes() const
{
  return this->Nodes.capacity() * sizeof(OctreeNode) +
    (this->Expressions.capacity() + this->NearExpressions.capacity()) * sizeof(CsgExpressionPtr) +
    this->Signs.MemoryBytes();
}

} // namespace tpc
