#include "AdaptiveOctree.h"

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
  }
  return "unknown";
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
  std::int64_t node = tree[0] + this->Grid.Dims[0] * (tree[1] + this->Grid.Dims[1] * tree[2]);
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
  std::uint32_t p[3];
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
    this->Expressions.capacity() * sizeof(CsgExpressionPtr) + this->Signs.MemoryBytes();
}

} // namespace tpc
