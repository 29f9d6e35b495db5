#include "CsgExpression.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace tpc
{

CsgTerm CsgTerm::Primitive(int index)
{
  CsgTerm t;
  t.Operation = Op::Primitive;
  t.PrimitiveIndex = index;
  return t;
}

CsgTerm CsgTerm::Mesh(int index)
{
  CsgTerm t = CsgTerm::Primitive(index);
  t.Kind = PrimitiveKind::Mesh;
  return t;
}

CsgTerm CsgTerm::Combine(Op op, std::vector<CsgTerm> operands)
{
  CsgTerm t;
  t.Operation = op;
  t.Operands = std::move(operands);
  return t;
}

SolidBounds CsgTerm::Bounds(const PrimitiveSet& primitives) const
{
  SolidBounds b;
  switch (this->Operation)
  {
    case Op::Primitive:
      if (this->PrimitiveIndex < 0)
      {
        b = SolidBounds::Nothing();
      }
      else if (this->Kind == PrimitiveKind::Quadric)
      {
        b = primitives.Quadrics[static_cast<std::size_t>(this->PrimitiveIndex)].Bounds();
      }
      else
      {
        const MeshSolid& m = primitives.Meshes[static_cast<std::size_t>(this->PrimitiveIndex)];
        b = m.TriangleCount() == 0 ? SolidBounds::Nothing() : SolidBounds{ false, m.Bounds() };
      }
      break;
    case Op::Complement:
      b = SolidBounds::Everything();
      break;
    case Op::Difference:
      b = this->Operands.empty() ? SolidBounds::Nothing() : this->Operands[0].Bounds(primitives);
      break;
    case Op::Union:
      b = SolidBounds::Nothing();
      for (const CsgTerm& t : this->Operands)
      {
        b = SolidBounds::Hull(b, t.Bounds(primitives));
      }
      break;
    case Op::Intersection:
      b = this->Operands.empty() ? SolidBounds::Nothing() : SolidBounds::Everything();
      for (const CsgTerm& t : this->Operands)
      {
        b = SolidBounds::Overlap(b, t.Bounds(primitives));
      }
      break;
  }
  return this->HasBoundsHint ? SolidBounds::Overlap(b, this->BoundsHint) : b;
}

// ---------------------------------------------------------------------------
struct CsgExpressionBuilder
{
  CsgExpression Out;

  std::size_t NodeCount() const { return Out.Nodes.size(); }
  std::pair<std::size_t, std::size_t> Mark() const { return { Out.Nodes.size(), Out.Children.size() }; }
  void Rewind(const std::pair<std::size_t, std::size_t>& mark)
  {
    Out.Nodes.resize(mark.first);
    Out.Children.resize(mark.second);
  }

  std::uint32_t AddLeaf(CsgLeaf leaf, std::shared_ptr<const TriangleList> triangles = nullptr)
  {
    CsgExpression::Node n;
    n.NodeKind = CsgExpression::Node::Kind::Leaf;
    n.LeafData = leaf;
    n.LeafData.Triangles = triangles.get();
    n.Triangles = std::move(triangles);
    Out.Nodes.push_back(std::move(n));
    return static_cast<std::uint32_t>(Out.Nodes.size() - 1);
  }

  std::uint32_t AddInner(CsgExpression::Node::Kind kind, const std::vector<std::uint32_t>& kids)
  {
    CsgExpression::Node n;
    n.NodeKind = kind;
    n.FirstChild = static_cast<std::uint32_t>(Out.Children.size());
    n.ChildCount = static_cast<std::uint32_t>(kids.size());
    Out.Children.insert(Out.Children.end(), kids.begin(), kids.end());
    Out.Nodes.push_back(n);
    return static_cast<std::uint32_t>(Out.Nodes.size() - 1);
  }

  // Builds the normalized form of `t` (complemented if `neg`); -1 if empty.
  long Build(const CsgTerm& t, bool neg)
  {
    using Op = CsgTerm::Op;
    using Kind = CsgExpression::Node::Kind;
    switch (t.Operation)
    {
      case Op::Primitive:
      {
        if (t.PrimitiveIndex < 0)
        {
          return -1;
        }
        CsgLeaf leaf;
        leaf.Primitive = static_cast<std::uint32_t>(t.PrimitiveIndex);
        leaf.Sigma = static_cast<std::int8_t>(neg ? -1 : 1);
        leaf.Kind = t.Kind;
        return static_cast<long>(this->AddLeaf(leaf));
      }
      case Op::Complement:
        return t.Operands.empty() ? -1 : this->Build(t.Operands[0], !neg);
      default:
        break;
    }
    if (t.Operands.empty())
    {
      return -1;
    }
    // De Morgan: complement swaps union and intersection. A difference
    // A - B - C is A & ~B & ~C.
    Kind kind;
    if (t.Operation == Op::Union)
    {
      kind = neg ? Kind::Intersection : Kind::Union;
    }
    else
    {
      kind = neg ? Kind::Union : Kind::Intersection;
    }
    std::vector<std::uint32_t> kids;
    for (std::size_t i = 0; i < t.Operands.size(); ++i)
    {
      const bool operandNeg = (t.Operation == Op::Difference && i > 0) ? !neg : neg;
      const long k = this->Build(t.Operands[i], operandNeg);
      if (k < 0)
      {
        if (t.Operation == Op::Difference && i == 0)
        {
          return -1; // nothing minus anything is nothing
        }
        continue;
      }
      const auto& child = Out.Nodes[static_cast<std::size_t>(k)];
      if (child.NodeKind == kind)
      {
        // Flatten nested nodes of the same kind.
        for (std::uint32_t c = 0; c < child.ChildCount; ++c)
        {
          kids.push_back(Out.Children[child.FirstChild + c]);
        }
      }
      else
      {
        kids.push_back(static_cast<std::uint32_t>(k));
      }
    }
    if (kids.empty())
    {
      return -1;
    }
    if (kids.size() == 1)
    {
      return kids[0];
    }
    return this->AddInner(kind, kids);
  }
};

CsgExpressionPtr CsgExpression::FromTerm(const CsgTerm& term)
{
  CsgExpressionBuilder b;
  const long root = b.Build(term, false);
  if (root < 0)
  {
    return nullptr;
  }
  b.Out.RootIndex = static_cast<std::uint32_t>(root);
  return std::make_shared<CsgExpression>(std::move(b.Out));
}

// ---------------------------------------------------------------------------
bool LeafIsInside(const CsgLeaf& leaf, const PrimitiveSet& prims, const Vec3& p)
{
  if (leaf.Kind == PrimitiveKind::Quadric)
  {
    return prims.Quadrics[leaf.Primitive].ExactSign(p) * leaf.Sigma < 0;
  }
  return prims.Meshes[leaf.Primitive].IsInside(p) == (leaf.Sigma > 0);
}

double LeafValue(const CsgLeaf& leaf, const PrimitiveSet& prims, const Vec3& p)
{
  if (leaf.Kind == PrimitiveKind::Quadric)
  {
    return leaf.Sigma * prims.Quadrics[leaf.Primitive].Value(p);
  }
  const MeshSolid& m = prims.Meshes[leaf.Primitive];
  if (!leaf.Triangles)
  {
    return leaf.Sigma * (m.IsInside(p) ? -1.0 : 1.0) * HUGE_VAL;
  }
  return leaf.Sigma * m.ApproximateSignedDistance(p, *leaf.Triangles);
}

Vec3 LeafGradient(const CsgLeaf& leaf, const PrimitiveSet& prims, const Vec3& p)
{
  if (leaf.Kind == PrimitiveKind::Quadric)
  {
    return prims.Quadrics[leaf.Primitive].Gradient(p) * static_cast<double>(leaf.Sigma);
  }
  const MeshSolid& m = prims.Meshes[leaf.Primitive];
  if (!leaf.Triangles || leaf.Triangles->empty())
  {
    return Vec3();
  }
  std::uint32_t nearest = 0;
  m.ApproximateSignedDistance(p, *leaf.Triangles, &nearest);
  return m.Normal(nearest) * static_cast<double>(leaf.Sigma);
}

namespace
{
/// Sign of a leaf over a closed box; for a mesh leaf that stays mixed, the
/// triangles meeting the box.
RegionSign LeafOverBox(const CsgLeaf& leaf, const Box3& box, const PrimitiveSet& prims,
  std::shared_ptr<const TriangleList>& narrowed)
{
  if (leaf.Kind == PrimitiveKind::Quadric)
  {
    Interval v = prims.Quadrics[leaf.Primitive].EncloseForSign(box);
    if (leaf.Sigma < 0)
    {
      v = -v;
    }
    return v.hi < 0.0 ? RegionSign::Inside : (v.lo >= 0.0 ? RegionSign::Outside : RegionSign::Mixed);
  }
  const MeshSolid& m = prims.Meshes[leaf.Primitive];
  auto list = std::make_shared<TriangleList>();
  if (leaf.Triangles)
  {
    m.Overlapping(box, *leaf.Triangles, *list);
  }
  else
  {
    *list = m.Overlapping(box);
  }
  if (list->empty())
  {
    // No triangle meets the closed box: one sign on all of it.
    return LeafIsInside(leaf, prims, box.Center()) ? RegionSign::Inside : RegionSign::Outside;
  }
  narrowed = std::move(list);
  return RegionSign::Mixed;
}

struct Pruner
{
  const CsgExpression& Src;
  const Box3& Box;
  const PrimitiveSet& Prims;
  CsgExpressionBuilder Dst;
  bool Narrowed = false;

  std::pair<RegionSign, std::uint32_t> Run(std::uint32_t i)
  {
    using Kind = CsgExpression::Node::Kind;
    const auto& n = Src.NodeAt(i);
    if (n.NodeKind == Kind::Leaf)
    {
      std::shared_ptr<const TriangleList> narrowed;
      const RegionSign s = LeafOverBox(n.LeafData, Box, Prims, narrowed);
      if (s != RegionSign::Mixed)
      {
        return { s, 0 };
      }
      if (narrowed && (!n.Triangles || narrowed->size() < n.Triangles->size()))
      {
        this->Narrowed = true;
        return { RegionSign::Mixed, Dst.AddLeaf(n.LeafData, std::move(narrowed)) };
      }
      return { RegionSign::Mixed, Dst.AddLeaf(n.LeafData, n.Triangles) };
    }    // Union: any inside child makes it inside, outside children drop out.
    // Intersection: the dual.
    const RegionSign absorbing = n.NodeKind == Kind::Union ? RegionSign::Inside : RegionSign::Outside;
    const RegionSign neutral = n.NodeKind == Kind::Union ? RegionSign::Outside : RegionSign::Inside;
    const auto mark = Dst.Mark();
    std::vector<std::uint32_t> kept;
    for (std::uint32_t c = 0; c < n.ChildCount; ++c)
    {
      const auto r = this->Run(Src.ChildIndex(n.FirstChild + c));
      if (r.first == absorbing)
      {
        Dst.Rewind(mark);
        return { absorbing, 0 };
      }
      if (r.first == RegionSign::Mixed)
      {
        kept.push_back(r.second);
      }
    }
    if (kept.empty())
    {
      return { neutral, 0 };
    }
    if (kept.size() == 1)
    {
      return { RegionSign::Mixed, kept[0] };
    }
    return { RegionSign::Mixed, Dst.AddInner(n.NodeKind, kept) };
  }
};
} // namespace

CsgExpression::Pruned CsgExpression::Prune(
  const CsgExpressionPtr& self, const Box3& box, const PrimitiveSet& primitives)
{
  Pruner p{ *self, box, primitives, {}, false };
  const auto r = p.Run(self->RootIndex);
  Pruned result;
  result.Sign = r.first;
  if (r.first != RegionSign::Mixed)
  {
    return result;
  }
  if (p.Dst.Out.Nodes.size() == self->Nodes.size() && !p.Narrowed)
  {
    result.Expression = self; // nothing removed or narrowed
    return result;
  }
  p.Dst.Out.RootIndex = r.second;
  result.Expression = std::make_shared<CsgExpression>(std::move(p.Dst.Out));
  return result;
}

// ---------------------------------------------------------------------------
bool CsgExpression::IsInside(const Vec3& p, const PrimitiveSet& prims) const
{
  return this->Evaluate([&](std::uint32_t, const Node& n) { return LeafIsInside(n.LeafData, prims, p); });
}

double CsgExpression::Value(const Vec3& p, const PrimitiveSet& prims, int* leafNode) const
{
  struct Eval
  {
    const CsgExpression& E;
    const Vec3& P;
    const PrimitiveSet& Prims;
    double Run(std::uint32_t i, std::uint32_t& leaf) const
    {
      const auto& n = E.NodeAt(i);
      if (n.NodeKind == Node::Kind::Leaf)
      {
        leaf = i;
        return LeafValue(n.LeafData, Prims, P);
      }
      double best = this->Run(E.ChildIndex(n.FirstChild), leaf);
      for (std::uint32_t c = 1; c < n.ChildCount; ++c)
      {
        std::uint32_t l = 0;
        const double v = this->Run(E.ChildIndex(n.FirstChild + c), l);
        if (n.NodeKind == Node::Kind::Union ? v < best : v > best)
        {
          best = v;
          leaf = l;
        }
      }
      return best;
    }
  };
  std::uint32_t leaf = 0;
  const double v = Eval{ *this, p, prims }.Run(this->RootIndex, leaf);
  if (leafNode)
  {
    *leafNode = static_cast<int>(leaf);
  }
  return v;
}

Vec3 CsgExpression::Gradient(const Vec3& p, const PrimitiveSet& prims) const
{
  // (A lone leaf is the one whose value wins: not evaluated for nothing - a
  // mesh leaf's value is a search of its triangles, as its gradient is; for
  // the output vertices' normals of a mesh scene, 1.1 % of the turbine's
  // instructions at 1/64.)
  const Node& root = this->NodeAt(this->RootIndex);
  if (root.NodeKind == Node::Kind::Leaf)
  {
    return LeafGradient(root.LeafData, prims, p);
  }
  int leaf = 0;
  this->Value(p, prims, &leaf);
  return LeafGradient(this->Nodes[static_cast<std::size_t>(leaf)].LeafData, prims, p);
}

std::vector<CsgLeaf> CsgExpression::Leaves() const
{
  std::vector<CsgLeaf> leaves;
  for (const Node& n : this->Nodes)
  {
    if (n.NodeKind == Node::Kind::Leaf &&
      std::find(leaves.begin(), leaves.end(), n.LeafData) == leaves.end())
    {
      leaves.push_back(n.LeafData);
    }
  }
  return leaves;
}

bool CsgExpression::HasMeshLeaves() const
{
  for (const Node& n : this->Nodes)
  {
    if (n.NodeKind == Node::Kind::Leaf && n.LeafData.Kind == PrimitiveKind::Mesh)
    {
      return true;
    }
  }
  return false;
}

} // namespace tpc
