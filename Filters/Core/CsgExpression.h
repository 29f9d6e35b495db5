// Constructive solid geometry over the primitives (paper 5.1).
//
// A CsgTerm is what users build (union, intersection, difference, complement
// of primitives). It is normalized into a CsgExpression: complements pushed to
// the leaves (De Morgan), so every leaf is sigma * f_i with sigma = +-1 and the
// inner nodes are min (union) and max (intersection). This is the form the
// star-shaped test needs: "a difference inverts the subtracted one's
// constraints" is exactly sigma = -1 on its leaves.
//
// Sign convention, used everywhere: a point is inside the solid iff the
// combined value is < 0; a value of exactly 0 is outside. Equivalently we
// contour F + delta for an infinitesimal delta > 0, so a plane through lattice
// points never makes a lattice edge lie on the surface.
//
// Pruning (the implicit-primitive analogue of the paper's per-cell triangle
// lists, 6.4): over a cell, a leaf whose enclosure has a definite sign is
// either irrelevant or decides its parent; the pruned expression has the same
// sign as the full one at every point of the closed cell, so each cell works
// with the few primitives that matter there.
#pragma once

#include "Interval.h"
#include "Quadric.h"
#include "Vector3.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace tpc
{

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
  int PrimitiveIndex = -1;
  std::vector<CsgTerm> Operands;
  /// Known bounds of this sub-solid (e.g. the corners of a rotated box),
  /// intersected with what the operands give.
  bool HasBoundsHint = false;
  SolidBounds BoundsHint;

  static CsgTerm Primitive(int index);
  static CsgTerm Combine(Op op, std::vector<CsgTerm> operands);

  /// Bounding box of the solid (infinite where it cannot be derived).
  SolidBounds Bounds(const std::vector<Quadric>& primitives) const;
};

/// A leaf of the normalized expression: sigma * f_primitive.
struct CsgLeaf
{
  std::uint32_t Primitive = 0;
  std::int8_t Sigma = 1;
  bool operator==(const CsgLeaf& o) const { return Primitive == o.Primitive && Sigma == o.Sigma; }
};

/// Sign class of a region: definitely inside, definitely outside, or neither.
enum class RegionSign : std::uint8_t
{
  Inside,
  Outside,
  Mixed
};

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
    CsgLeaf LeafData;             // Leaf only
    std::uint32_t FirstChild = 0; // index into Children
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
  /// leaf could be removed (no allocation).
  static Pruned Prune(
    const CsgExpressionPtr& self, const Box3& box, const std::vector<Quadric>& primitives);

  /// Exact inside test (value < 0), from exact leaf signs.
  bool IsInside(const Vec3& p, const std::vector<Quadric>& primitives) const;
  /// Floating-point value of min/max of the leaves, and the leaf that attains it.
  double Value(const Vec3& p, const std::vector<Quadric>& primitives, int* leafNode = nullptr) const;
  /// Gradient of the leaf attaining the value at p (outward normal direction).
  Vec3 Gradient(const Vec3& p, const std::vector<Quadric>& primitives) const;
  /// Conservative enclosure of the combined value over a box.
  Interval Enclose(const Box3& box, const std::vector<Quadric>& primitives) const;

  /// Distinct leaves (primitive, sigma).
  std::vector<CsgLeaf> Leaves() const;
  std::size_t NodeCount() const { return this->Nodes.size(); }
  const Node& NodeAt(std::size_t i) const { return this->Nodes[i]; }
  std::uint32_t Root() const { return this->RootIndex; }
  std::uint32_t ChildIndex(std::uint32_t k) const { return this->Children[k]; }

private:
  std::vector<Node> Nodes;
  std::vector<std::uint32_t> Children;
  std::uint32_t RootIndex = 0;

  friend struct CsgExpressionBuilder;
};

} // namespace tpc
