// Constructive solid geometry over the primitives (paper 5.1).
//
// A CsgTerm is what users build (union, intersection, difference, complement
// of primitives). It is normalized into a CsgExpression: complements pushed to
// the leaves (De Morgan), so every leaf is sigma * f_i with sigma = +-1 and the
// inner nodes are min (union) and max (intersection). This is the form the
// star-shaped test needs: "a difference inverts the subtracted one's
// constraints" is exactly sigma = -1 on its leaves.
//
// Primitives are quadrics (Quadric.h) or closed triangle meshes (MeshSolid.h).
//
// Sign convention, used everywhere: a point is inside the solid iff the
// combined value is < 0; a value of exactly 0 is outside. Equivalently we
// contour F + delta for an infinitesimal delta > 0, so a plane through lattice
// points never makes a lattice edge lie on the surface.
//
// Pruning: over a cell, a leaf that provably has one sign is either
// irrelevant or decides its parent; the pruned expression has the same sign
// as the full one at every point of the closed cell, so each cell works with
// the few primitives that matter there. A mesh leaf carries the list of its
// triangles meeting the cell (the paper's 6.4), narrowed for each child; an
// empty list means one sign on the cell.
#pragma once

#include "Interval.h"
#include "MeshSolid.h"
#include "Quadric.h"
#include "Vector3.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace tpc
{

enum class PrimitiveKind : std::uint8_t
{
  Quadric,
  Mesh
};

/// All primitives of a scene; CSG leaves index into one of the two lists.
struct PrimitiveSet
{
  std::vector<Quadric> Quadrics;
  std::vector<MeshSolid> Meshes;
};

/// A user-level CSG tree.
struct CsgTerm
{
  enum class Op
  {
    Primitive,
    Union,
    Intersection,
    Difference, ///< first operand minus all the others
    Complement
  };
  Op Operation = Op::Primitive;
  PrimitiveKind Kind = PrimitiveKind::Quadric; ///< for Op::Primitive
  int PrimitiveIndex = -1;
  std::vector<CsgTerm> Operands;
  /// Known bounds of this sub-solid (e.g. the corners of a rotated box),
  /// intersected with what the operands give.
  bool HasBoundsHint = false;
  SolidBounds BoundsHint;

  static CsgTerm Primitive(int quadricIndex);
  static CsgTerm Mesh(int meshIndex);
  static CsgTerm Combine(Op op, std::vector<CsgTerm> operands);

  /// Bounding box of the solid (infinite where it cannot be derived).
  SolidBounds Bounds(const PrimitiveSet& primitives) const;
};

/// A leaf of the normalized expression: sigma * f_primitive.
struct CsgLeaf
{
  std::uint32_t Primitive = 0;
  std::int8_t Sigma = 1;
  PrimitiveKind Kind = PrimitiveKind::Quadric;
  /// Mesh leaves: the triangles that may meet the region the expression was
  /// pruned to (null: all of them). Owned by the expression node.
  const TriangleList* Triangles = nullptr;

  bool operator==(const CsgLeaf& o) const
  {
    return Primitive == o.Primitive && Sigma == o.Sigma && Kind == o.Kind;
  }
};

/// Sign class of a region: definitely inside, definitely outside, or neither.
enum class RegionSign : std::uint8_t
{
  Inside,
  Outside,
  Mixed
};

/// Leaf-level operations, dispatched on the primitive kind.
bool LeafIsInside(const CsgLeaf& leaf, const PrimitiveSet& primitives, const Vec3& p);
double LeafValue(const CsgLeaf& leaf, const PrimitiveSet& primitives, const Vec3& p);
/// Outward normal direction (unnormalized) of the leaf near p.
Vec3 LeafGradient(const CsgLeaf& leaf, const PrimitiveSet& primitives, const Vec3& p);

class CsgExpression;
using CsgExpressionPtr = std::shared_ptr<const CsgExpression>;

class CsgExpression
{
public:
  struct Node
  {
    enum class Kind : std::uint8_t
    {
      Leaf,
      Union,
      Intersection
    };
    Kind NodeKind = Kind::Leaf;
    CsgLeaf LeafData;                              // Leaf only
    std::shared_ptr<const TriangleList> Triangles; // mesh leaves: owns LeafData.Triangles
    std::uint32_t FirstChild = 0;                  // index into Children
    std::uint32_t ChildCount = 0;
  };

  /// Normalizes a user tree. Returns nullptr for an empty tree.
  static CsgExpressionPtr FromTerm(const CsgTerm& term);

  /// The result of pruning over a region: a definite sign or an expression.
  struct Pruned
  {
    RegionSign Sign = RegionSign::Mixed;
    CsgExpressionPtr Expression; // set iff Sign == Mixed
  };
  /// Prunes `self` over a closed box. `self` is returned unchanged when no
  /// leaf could be removed or narrowed (no allocation).
  static Pruned Prune(const CsgExpressionPtr& self, const Box3& box, const PrimitiveSet& primitives);

  /// Exact inside test (value < 0), from exact leaf signs.
  bool IsInside(const Vec3& p, const PrimitiveSet& primitives) const;
  /// The same with each leaf's sign from `leafInside(nodeIndex, node)`
  /// (short-circuit: leaves that cannot change the answer are not asked).
  template <typename LeafInside>
  bool Evaluate(const LeafInside& leafInside) const
  {
    return this->EvaluateNode(this->RootIndex, leafInside);
  }
  /// Floating-point value of min/max of the leaves, and the leaf node that attains it.
  double Value(const Vec3& p, const PrimitiveSet& primitives, int* leafNode = nullptr) const;
  /// Gradient of the leaf attaining the value at p (outward normal direction).
  Vec3 Gradient(const Vec3& p, const PrimitiveSet& primitives) const;

  /// Distinct leaves (primitive, sigma, kind), with their triangle lists.
  std::vector<CsgLeaf> Leaves() const;
  bool HasMeshLeaves() const;
  std::size_t NodeCount() const { return this->Nodes.size(); }
  const Node& NodeAt(std::size_t i) const { return this->Nodes[i]; }
  std::uint32_t Root() const { return this->RootIndex; }
  std::uint32_t ChildIndex(std::uint32_t k) const { return this->Children[k]; }

private:
  template <typename LeafInside>
  bool EvaluateNode(std::uint32_t i, const LeafInside& leafInside) const
  {
    const Node& n = this->Nodes[i];
    if (n.NodeKind == Node::Kind::Leaf)
    {
      return leafInside(i, n);
    }
    const bool isUnion = n.NodeKind == Node::Kind::Union;
    for (std::uint32_t c = 0; c < n.ChildCount; ++c)
    {
      if (this->EvaluateNode(this->Children[n.FirstChild + c], leafInside) == isUnion)
      {
        return isUnion; // union: the first inside child decides; intersection: the first outside
      }
    }
    return !isUnion;
  }

  std::vector<Node> Nodes;
  std::vector<std::uint32_t> Children;
  std::uint32_t RootIndex = 0;

  friend struct CsgExpressionBuilder;
};

/// The solid to contour: primitives combined by a CSG expression.
struct ImplicitScene
{
  PrimitiveSet Primitives;
  CsgExpressionPtr Expression;
};

} // namespace tpc
