#include "FaceRefinement.h"

#include "ComplexCellCriterion.h"

#include <cmath>
#include <limits>

namespace tpc
{

namespace
{
struct FaceRefiner
{
  const PrimitiveSet& Primitives;
  const RootGrid& Grid;
  int Axis;
  LatticeIndex Plane;
  CellSignCache& Signs;
  FaceRefinementResult Result;

  bool Inside(LatticeIndex u, LatticeIndex v)
  {
    return this->Signs.Inside(TileCorner(this->Axis, this->Plane, { u, v, u, v }, 0));
  }

  /// Where to split a failing tile. A midpoint split meets a thin wedge tip
  /// at every level with the same odds (it slips between the corners again);
  /// splitting at a sample of the opposite sign puts a corner inside the
  /// wedge, which settles it at once.
  void SplitPoint(const FaceTile& t, const Box3& face, const CsgExpressionPtr& expression, SplitReason why,
    int edge, double opposite, const bool inside[4], LatticeIndex& us, LatticeIndex& vs)
  {
    us = t.U0 + (t.U1 - t.U0) / 2;
    vs = t.V0 + (t.V1 - t.V0) / 2;
    if (why == SplitReason::ComplexEdge && edge >= 0 && inside[edge] == inside[(edge + 1) % 4] &&
      this->LatticePointOfOppositeSign(t, edge, opposite, inside[edge], us, vs))
    {
      return;
    }
    constexpr int Samples = 8;
    if (why == SplitReason::ComplexFace)
    {
      // Corners agree: look for an interior sample that does not.
      for (int i = 1; i < Samples; ++i)
      {
        for (int j = 1; j < Samples; ++j)
        {
          const LatticeIndex u = t.U0 + static_cast<LatticeIndex>((std::uint64_t(t.U1 - t.U0) * i) / Samples);
          const LatticeIndex v = t.V0 + static_cast<LatticeIndex>((std::uint64_t(t.V1 - t.V0) * j) / Samples);
          if (u > t.U0 && u < t.U1 && v > t.V0 && v < t.V1 && this->Inside(u, v) != inside[0])
          {
            us = u;
            vs = v;
            return;
          }
        }
      }
      // None: a gap or wedge too thin for the samples may still cross an
      // edge twice, where the crossing count finds a point inside it (a few
      // pieces per level suffice for that; a surface lying along the edge,
      // as where two solids touch, would take thousands).
      for (int k = 0; k < 4; ++k)
      {
        double point = std::numeric_limits<double>::quiet_NaN();
        EdgeCrossedOnce(expression, this->Primitives, face, this->Axis, inside, k, &point, 128);
        if (this->LatticePointOfOppositeSign(t, k, point, inside[k], us, vs))
        {
          return;
        }
      }
    }
    else if (why == SplitReason::ComplexEdge && edge >= 0 && inside[edge] == inside[(edge + 1) % 4])
    {
      // An edge crossed twice with equal end signs: split it between the crossings.
      const bool alongU = edge == 0 || edge == 2;
      const LatticeIndex fixed = edge == 0 ? t.V0 : edge == 1 ? t.U1 : edge == 2 ? t.V1 : t.U0;
      const LatticeIndex a = alongU ? t.U0 : t.V0, b = alongU ? t.U1 : t.V1;
      for (int i = 1; i < 4 * Samples; ++i)
      {
        const LatticeIndex x = a + static_cast<LatticeIndex>((std::uint64_t(b - a) * i) / (4 * Samples));
        if (x <= a || x >= b)
        {
          continue;
        }
        if ((alongU ? this->Inside(x, fixed) : this->Inside(fixed, x)) != inside[edge])
        {
          (alongU ? us : vs) = x;
          return;
        }
      }
    }
  }

  /// The crossing count of a twice-crossed edge met a point of the other
  /// sign (`opposite`, a world coordinate along the edge; NaN if none):
  /// a lattice point beside it has that sign too unless the gap or wedge is
  /// thinner than the lattice there. Splitting there puts a tile corner in
  /// it whatever its width; then in the child holding a wedge's apex both
  /// sides leave through different edges with odds 1/2 per level, so the
  /// face ends in a few levels where fixed samples would need ~1/angle.
  bool LatticePointOfOppositeSign(const FaceTile& t, int edge, double opposite, bool endsInside,
    LatticeIndex& us, LatticeIndex& vs)
  {
    if (std::isnan(opposite))
    {
      return false;
    }
    const bool alongU = edge == 0 || edge == 2;
    const int axis = (this->Axis + (alongU ? 1 : 2)) % 3;
    const LatticeIndex fixed = edge == 0 ? t.V0 : edge == 1 ? t.U1 : edge == 2 ? t.V1 : t.U0;
    const LatticeIndex a = alongU ? t.U0 : t.V0, b = alongU ? t.U1 : t.V1;
    const double spacing = std::ldexp(this->Grid.RootSize, -this->Grid.MaxDepth);
    const double index = std::floor((opposite - this->Grid.Origin[axis]) / spacing);
    for (const double candidate : { index, index + 1.0, index - 1.0, index + 2.0 })
    {
      if (!(candidate > static_cast<double>(a) && candidate < static_cast<double>(b)))
      {
        continue;
      }
      const LatticeIndex x = static_cast<LatticeIndex>(candidate);
      if ((alongU ? this->Inside(x, fixed) : this->Inside(fixed, x)) != endsInside)
      {
        (alongU ? us : vs) = x;
        return true;
      }
    }
    return false;
  }

  /// Refines tile `t`, whose parent's (or face's) expression is `outer`.
  bool Refine(const FaceTile& t, int levels, const CsgExpressionPtr& outer)
  {
    const bool inside[4] = { this->Inside(t.U0, t.V0), this->Inside(t.U1, t.V0),
      this->Inside(t.U1, t.V1), this->Inside(t.U0, t.V1) };
    const Box3 face = TileBox(this->Grid, this->Axis, this->Plane, t);
    // The tile's tests, and its children's, see the expression pruned to the
    // closed tile: its mesh leaves list only the triangles that may meet it
    // (in the same order), so the edges' crossing counts, the star-shaped
    // test and the constant-sign proofs decide as they did with the cell's
    // lists, scanning far shorter ones (with the cell's whole lists, the face
    // tests were 9 % of the turbine's instructions at 1/64, 3.8 % after).
    // (Where meshes meet, a crossing count bisects an edge where its pieces
    // are not proven of one sign; the triangle filter is conservative, and a
    // shorter list keeps fewer triangles that miss the piece, so it may prove
    // other pieces, meet another point of the other sign first, and the tile
    // split there: as valid, not the same.) Pruned to one sign, the surface
    // misses the tile: the test's own proof for tiles whose corners agree
    // (ProveConstantSign prunes to the tile first).
    const CsgExpression::Pruned pruned = CsgExpression::Prune(outer, face, this->Primitives);
    const bool constant = pruned.Sign != RegionSign::Mixed;
    const bool sameCorners = inside[0] == inside[1] && inside[1] == inside[2] && inside[2] == inside[3];
    if (constant && sameCorners)
    {
      this->Result.Tiles.push_back(t);
      return true;
    }
    // (Corners that differ over a tile of one proven sign cannot happen with
    // exact signs; the outer expression is then kept, as before.)
    const CsgExpressionPtr& expression = constant ? outer : pruned.Expression;
    int edge = -1;
    double opposite = std::numeric_limits<double>::quiet_NaN();
    const SplitReason r = FaceCompatibilityTest(
      expression, this->Primitives, face, this->Axis, inside, &edge, &opposite, !constant);
    if (r == SplitReason::None)
    {
      this->Result.Tiles.push_back(t);
      return true;
    }
    if (levels == 0 || t.U1 - t.U0 < 2 || t.V1 - t.V0 < 2)
    {
      this->Result.Failure = r;
      return false;
    }
    LatticeIndex us, vs;
    this->SplitPoint(t, face, expression, r, edge, opposite, inside, us, vs);
    return this->Refine({ t.U0, t.V0, us, vs }, levels - 1, expression) &&
      this->Refine({ us, t.V0, t.U1, vs }, levels - 1, expression) &&
      this->Refine({ t.U0, vs, us, t.V1 }, levels - 1, expression) &&
      this->Refine({ us, vs, t.U1, t.V1 }, levels - 1, expression);
  }
};
} // namespace

FaceRefinementResult RefineFace(const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const RootGrid& grid, int axis, LatticeIndex plane,
  const FaceTile& face, int maxLevels, CellSignCache& signs)
{
  FaceRefiner r{ primitives, grid, axis, plane, signs, {} };
  if (!r.Refine(face, maxLevels, expression))
  {
    r.Result.Tiles.clear();
  }
  return std::move(r.Result);
}

} // namespace tpc
