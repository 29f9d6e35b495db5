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

CsgTerm CsgTerm::Combine(Op op, std::vector<CsgTerm> operands)
{
  CsgTerm t;
  t.Operation = op;
  t.Operands = std::move(operands);
  return t;
}

SolidBounds CsgTerm::Bounds(const std::vector<Quadric>& primitives) const
{
  SolidBounds b;
  switch (this->Operation)
  {
    case Op::Primitive:
      b = this->PrimitiveIndex >= 0 ? primitives[static_cast<std::size_t>(this->PrimitiveIndex)].Bounds()
                                    : SolidBounds::Nothing();
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

  std::uint32_t AddLeaf(CsgLeaf leaf)
  {
    CsgExpression::Node n;
    n.NodeKind = CsgExpression::Node::Kind::Leaf;
    n.LeafData = leaf;
    Out.Nodes.push_back(n);
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
        return t.PrimitiveIndex < 0
          ? -1
          : static_cast<long>(this->AddLeaf(
              { static_cast<std::uint32_t>(t.PrimitiveIndex), static_cast<std::int8_t>(neg ? -1 : 1) }));
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
namespace
{
Interval LeafEnclosure(const CsgLeaf& leaf, const Box3& box, const std::vector<Quadric>& prims)
{
  const Interval v = prims[leaf.Primitive].Enclose(box);
  return leaf.Sigma > 0 ? v : -v;
}

struct Pruner
{
  const CsgExpression& Src;
  const Box3& Box;
  const std::vector<Quadric>& Prims;
  CsgExpressionBuilder Dst;

  std::pair<RegionSign, std::uint32_t> Run(std::uint32_t i)
  {
    using Kind = CsgExpression::Node::Kind;
    const auto& n = Src.NodeAt(i);
    if (n.NodeKind == Kind::Leaf)
    {
      const Interval v = LeafEnclosure(n.LeafData, Box, Prims);
      if (v.hi < 0.0)
      {
        return { RegionSign::Inside, 0 };
      }
      if (v.lo >= 0.0)
      {
        return { RegionSign::Outside, 0 };
      }
      return { RegionSign::Mixed, Dst.AddLeaf(n.LeafData) };
    }
    // Union: any inside child makes it inside, outside children drop out.
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
  const CsgExpressionPtr& self, const Box3& box, const std::vector<Quadric>& primitives)
{
  Pruner p{ *self, box, primitives, {} };
  const auto r = p.Run(self->RootIndex);
  Pruned result;
  result.Sign = r.first;
  if (r.first != RegionSign::Mixed)
  {
    return result;
  }
  if (p.Dst.Out.Nodes.size() == self->Nodes.size())
  {
    result.Expression = self; // nothing removed
    return result;
  }
  p.Dst.Out.RootIndex = r.second;
  result.Expression = std::make_shared<CsgExpression>(std::move(p.Dst.Out));
  return result;
}

// ---------------------------------------------------------------------------
bool CsgExpression::IsInside(const Vec3& p, const std::vector<Quadric>& prims) const
{
  // Recursive with short-circuit: exact leaf signs are the costly part.
  struct Eval
  {
    const CsgExpression& E;
    const Vec3& P;
    const std::vector<Quadric>& Prims;
    bool Run(std::uint32_t i) const
    {
      const auto& n = E.NodeAt(i);
      if (n.NodeKind == Node::Kind::Leaf)
      {
        return Prims[n.LeafData.Primitive].ExactSign(P) * n.LeafData.Sigma < 0;
      }
      const bool isUnion = n.NodeKind == Node::Kind::Union;
      for (std::uint32_t c = 0; c < n.ChildCount; ++c)
      {
        const bool in = this->Run(E.ChildIndex(n.FirstChild + c));
        if (in == isUnion)
        {
          return in; // union: first inside child decides; intersection: first outside
        }
      }
      return !isUnion;
    }
  };
  return Eval{ *this, p, prims }.Run(this->RootIndex);
}

double CsgExpression::Value(const Vec3& p, const std::vector<Quadric>& prims, int* leafNode) const
{
  struct Eval
  {
    const CsgExpression& E;
    const Vec3& P;
    const std::vector<Quadric>& Prims;
    double Run(std::uint32_t i, std::uint32_t& leaf) const
    {
      const auto& n = E.NodeAt(i);
      if (n.NodeKind == Node::Kind::Leaf)
      {
        leaf = i;
        return n.LeafData.Sigma * Prims[n.LeafData.Primitive].Value(P);
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

Vec3 CsgExpression::Gradient(const Vec3& p, const std::vector<Quadric>& prims) const
{
  int leaf = 0;
  this->Value(p, prims, &leaf);
  const CsgLeaf& l = this->Nodes[static_cast<std::size_t>(leaf)].LeafData;
  return prims[l.Primitive].Gradient(p) * static_cast<double>(l.Sigma);
}

Interval CsgExpression::Enclose(const Box3& box, const std::vector<Quadric>& prims) const
{
  struct Eval
  {
    const CsgExpression& E;
    const Box3& B;
    const std::vector<Quadric>& Prims;
    Interval Run(std::uint32_t i) const
    {
      const auto& n = E.NodeAt(i);
      if (n.NodeKind == Node::Kind::Leaf)
      {
        return LeafEnclosure(n.LeafData, B, Prims);
      }
      Interval acc = this->Run(E.ChildIndex(n.FirstChild));
      for (std::uint32_t c = 1; c < n.ChildCount; ++c)
      {
        const Interval v = this->Run(E.ChildIndex(n.FirstChild + c));
        acc = n.NodeKind == Node::Kind::Union ? Min(acc, v) : Max(acc, v);
      }
      return acc;
    }
  };
  return Eval{ *this, box, prims }.Run(this->RootIndex);
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

} // namespace tpc
