#include "QuadricCellError.h"

#include "CreasePoint.h"
#include "Interval.h"

#include <algorithm>
#include <cmath>

namespace tpc
{
namespace
{
/// Distances and squared lengths are computed in floating point; this
/// relative allowance covers their few ulps of rounding many times over.
constexpr double RoundingAllowance = 1.0 + 1e-12;

/// The leaf's quadric with its sign: sigma * f.
Quadric SignedQuadric(const Quadric& q, int sigma)
{
  if (sigma > 0)
  {
    return q;
  }
  std::array<double, 10> a = q.Coefficients();
  for (double& v : a)
  {
    v = -v;
  }
  return Quadric(a);
}

/// A proven lower bound of grad f . d over the box (Quadric::
/// EncloseDirectionalDerivative: affine, its natural extension is exact up
/// to rounding). A flat box (a face) is a rectangle.
double MinimumRise(const Quadric& q, const Box3& box, const Vec3& d)
{
  return q.EncloseDirectionalDerivative(box, d).lo;
}

/// An upper bound of the spectral norm of A (half the Hessian): the smaller
/// of the largest absolute row sum (the spectral norm of a symmetric matrix is
/// at most its infinity norm) and the Frobenius norm, rounded up.
double CurvatureBound(const Quadric& q)
{
  const auto& c = q.Coefficients();
  // A = [[c0, c3/2, c5/2], [c3/2, c1, c4/2], [c5/2, c4/2, c2]] (halving is exact).
  const double a[3][3] = { { c[0], 0.5 * c[3], 0.5 * c[5] }, { 0.5 * c[3], c[1], 0.5 * c[4] },
    { 0.5 * c[5], 0.5 * c[4], c[2] } };
  double rows = 0.0, frobenius = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    double row = 0.0;
    for (int j = 0; j < 3; ++j)
    {
      row += std::fabs(a[i][j]);
      frobenius += a[i][j] * a[i][j];
    }
    rows = std::max(rows, row);
  }
  return std::min(rows, std::sqrt(frobenius)) * RoundingAllowance;
}

double SquaredNorm(const Vec3& v)
{
  return Dot(v, v);
}

/// Squared radius of the smallest ball holding the triangle: half its longest
/// side where the triangle is right or obtuse (or degenerate), else its
/// circumradius.
double SmallestBallRadiusSquared(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const double ab = SquaredNorm(b - a), bc = SquaredNorm(c - b), ca = SquaredNorm(a - c);
  const double longest = std::max({ ab, bc, ca });
  if (2.0 * longest >= ab + bc + ca) // (longest^2 >= sum of the others': not acute)
  {
    return 0.25 * longest;
  }
  const double twiceArea2 = SquaredNorm(Cross(b - a, c - a));
  if (!(twiceArea2 > 0.0))
  {
    return 0.25 * longest;
  }
  // R = |ab| |bc| |ca| / (4 area) = |ab| |bc| |ca| / (2 |(b-a) x (c-a)|).
  return std::min(ab * bc * ca / (4.0 * twiceArea2), 0.25 * (ab + bc + ca));
}

/// The leaves of `expression` when it is one quadric leaf, or one union or
/// intersection (nested nodes of the same kind flattened) of at most
/// MaximumFields quadric leaves, in a fixed order; false otherwise.
bool FlatQuadricLeaves(const CsgExpression& expression, std::vector<CsgLeaf>& leaves, bool& isUnion)
{
  using Kind = CsgExpression::Node::Kind;
  leaves.clear();
  const CsgExpression::Node& root = expression.NodeAt(expression.Root());
  isUnion = root.NodeKind == Kind::Union;
  std::vector<std::uint32_t> pending{ expression.Root() };
  while (!pending.empty())
  {
    const CsgExpression::Node& node = expression.NodeAt(pending.back());
    pending.pop_back();
    if (node.NodeKind == Kind::Leaf)
    {
      if (std::find(leaves.begin(), leaves.end(), node.LeafData) != leaves.end())
      {
        continue; // (a leaf met twice is one field: max(f, f) = f)
      }
      if (node.LeafData.Kind != PrimitiveKind::Quadric || leaves.size() == QuadricCellError::MaximumFields)
      {
        return false;
      }
      leaves.push_back(node.LeafData);
      continue;
    }
    if (node.NodeKind != root.NodeKind)
    {
      return false;
    }
    for (std::uint32_t c = 0; c < node.ChildCount; ++c)
    {
      pending.push_back(expression.ChildIndex(node.FirstChild + c));
    }
  }
  return !leaves.empty();
}

/// The bit of `leaf` among `leaves` (bit i: leaves[i]); all of them when it
/// is not there.
unsigned FieldBit(const std::vector<CsgLeaf>& leaves, const CsgLeaf& leaf)
{
  const auto at = std::find(leaves.begin(), leaves.end(), leaf);
  return at == leaves.end() ? (1u << leaves.size()) - 1 : 1u << (at - leaves.begin());
}

/// An enclosure of F over a triangle or segment with vertices `v` (count 2
/// or 3) in the smallest ball of squared radius `radius2`, from the leaves
/// in `fields` (header: the interpolation error); its magnitude bounds |F|.
double CombinedMagnitude(const QuadricCellError& bound, unsigned fields, const Vec3* v, int count, double radius2)
{
  const double spread = bound.Curvature * radius2 * RoundingAllowance;
  Interval combined;
  bool first = true;
  for (std::size_t i = 0; i < bound.Fields.size(); ++i)
  {
    if (!(fields & (1u << i)))
    {
      continue;
    }
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int k = 0; k < count; ++k)
    {
      const Interval at = bound.Fields[i].Enclose(Box3{ v[k], v[k] });
      lo = std::min(lo, at.lo);
      hi = std::max(hi, at.hi);
    }
    const Interval leaf(lo - spread, hi + spread);
    combined = first ? leaf : bound.Union ? Min(combined, leaf) : Max(combined, leaf);
    first = false;
  }
  return first ? HUGE_VAL : combined.Magnitude() * RoundingAllowance;
}

/// The sum of unit vectors along the leaves' gradients (for a face: with the
/// face's normal part removed) at p, normalized; zero when they cancel.
Vec3 BisectingDirection(const QuadricCellError& bound, unsigned fields, const Vec3& p, int dropAxis)
{
  Vec3 sum;
  for (std::size_t i = 0; i < bound.Fields.size(); ++i)
  {
    if (fields & (1u << i))
    {
      Vec3 g = bound.Fields[i].Gradient(p);
      if (dropAxis >= 0)
      {
        g[dropAxis] = 0.0;
      }
      const double length = Norm(g);
      sum += length > 0.0 ? g * (1.0 / length) : Vec3();
    }
  }
  const double length = Norm(sum);
  return length > 0.0 ? sum * (1.0 / length) : Vec3();
}

/// min over the leaves in `fields` of MinimumRise along d over the box.
double MinimumRiseOfAll(const QuadricCellError& bound, unsigned fields, const Box3& box, const Vec3& d)
{
  double lowest = HUGE_VAL;
  for (std::size_t i = 0; i < bound.Fields.size(); ++i)
  {
    if (fields & (1u << i))
    {
      lowest = std::min(lowest, MinimumRise(bound.Fields[i], box, d));
    }
  }
  return lowest;
}

/// Whether no two of `fields` vanish at a common point of the box: proven by
/// enclosures, the box halved along every axis up to `depth` times where two
/// enclosures still hold zero.
bool NoCommonZero(const std::vector<Quadric>& fields, const Box3& box, int depth)
{
  int holdingZero = 0;
  for (const Quadric& f : fields)
  {
    holdingZero += f.EncloseForSign(box).ContainsZero() ? 1 : 0;
  }
  if (holdingZero <= 1)
  {
    return true;
  }
  if (depth == 0)
  {
    return false;
  }
  const Vec3 mid = box.Center();
  for (int octant = 0; octant < 8; ++octant)
  {
    Box3 part = box;
    for (int a = 0; a < 3; ++a)
    {
      (octant & (1 << a) ? part.lo : part.hi)[a] = mid[a];
    }
    if (!NoCommonZero(fields, part, depth - 1))
    {
      return false;
    }
  }
  return true;
}

/// Halvings NoCommonZero may try on a cell with several leaves.
constexpr int CreaseSearchDepth = 3;

/// The face's rectangle (flat box) of the cell.
Box3 FaceBox(const Box3& cell, int face)
{
  Box3 f = cell;
  const int axis = face / 2;
  (face % 2 ? f.lo : f.hi)[axis] = (face % 2 ? cell.hi : cell.lo)[axis];
  return f;
}

/// Every leaf of the bound (bit i: Fields[i]).
unsigned AllFields(const QuadricCellError& bound)
{
  return (1u << bound.Fields.size()) - 1;
}

/// Both ends lie exactly on the plane of the cell's face `face`.
bool OnFacePlane(const Box3& cell, int face, const Vec3& a, const Vec3& b)
{
  const double plane = (face % 2 ? cell.hi : cell.lo)[face / 2];
  return a[face / 2] == plane && b[face / 2] == plane;
}

/// `box` grown by `reach` on every side (rounded outward), within `limit`.
Box3 GrownWithin(const Box3& box, double reach, const Box3& limit)
{
  Box3 grown = GrownByMargin(box, reach);
  for (int a = 0; a < 3; ++a)
  {
    grown.lo[a] = std::max(grown.lo[a], limit.lo[a]);
    grown.hi[a] = std::min(grown.hi[a], limit.hi[a]);
  }
  return grown;
}

/// The bounding box of `count` points.
Box3 BoxAround(const Vec3* points, int count)
{
  Box3 box{ points[0], points[0] };
  for (int k = 1; k < count; ++k)
  {
    for (int a = 0; a < 3; ++a)
    {
      box.lo[a] = std::min(box.lo[a], points[k][a]);
      box.hi[a] = std::max(box.hi[a], points[k][a]);
    }
  }
  return box;
}

/// The term F / g_T of a patch triangle with |F| <= `magnitude` on it, or of
/// the triangles refining one, lying in `around` (header: Local rises).
double LocalTriangleTerm(const QuadricCellError& bound, double magnitude, const Box3& around)
{
  const double reach = magnitude / bound.Rise;
  if (!(reach <= bound.Margin))
  {
    return reach; // (beyond the margin, failed: no local rise outside C+)
  }
  const unsigned all = AllFields(bound);
  const Box3 region = GrownWithin(around, reach, GrownByMargin(bound.Cell, bound.Margin));
  return magnitude / std::max(bound.Rise, MinimumRiseOfAll(bound, all, region, bound.Direction));
}

/// Whether face `face` carries chords: F rises along m_phi on it (FaceRise
/// is 0 where it does not, +inf where the face misses S).
bool FaceRises(const QuadricCellError& bound, int face)
{
  return bound.FaceRise[face] > 0.0 && bound.FaceRise[face] != HUGE_VAL;
}

/// The stretch of face `face` between a chord with |F| <= `magnitude` on it,
/// lying in `around`, and its arc: within F / g_phi of the chord, in the face
/// (header: Local rises). The face must rise (FaceRises).
Box3 ChordStretch(const QuadricCellError& bound, int face, double magnitude, const Box3& around)
{
  return GrownWithin(around, magnitude / bound.FaceRise[face], FaceBox(bound.Cell, face));
}

/// g_phi over a chord's `stretch` (ChordStretch), at least the face's.
double LocalFaceRise(const QuadricCellError& bound, int face, const Box3& stretch)
{
  return std::max(
    bound.FaceRise[face], MinimumRiseOfAll(bound, bound.FaceFields[face], stretch, bound.FaceDirection[face]));
}

/// The term F (1/g + 1/g_phi) of a chord on face `face` with |F| <=
/// `magnitude` on it, or of the sub-chords refining one, lying in `around`
/// (header: Local rises). The face must rise (FaceRises).
double LocalChordTerm(const QuadricCellError& bound, int face, double magnitude, const Box3& around)
{
  const Box3 stretch = ChordStretch(bound, face, magnitude, around);
  const Box3 inward = GrownWithin(stretch, magnitude / bound.Rise, bound.Cell);
  const double normalRise = std::max(bound.Rise, MinimumRiseOfAll(bound, AllFields(bound), inward, bound.Direction));
  return magnitude * (1.0 / normalRise + 1.0 / LocalFaceRise(bound, face, stretch));
}
} // namespace

Box3 GrownByMargin(const Box3& cell, double margin)
{
  Box3 grown = cell;
  for (int a = 0; a < 3; ++a)
  {
    grown.lo[a] = std::nextafter(cell.lo[a] - margin, -HUGE_VAL);
    grown.hi[a] = std::nextafter(cell.hi[a] + margin, HUGE_VAL);
  }
  return grown;
}

std::optional<QuadricCellError> BoundQuadricCell(const CsgExpressionPtr& cellExpression,
  const CsgExpressionPtr& nearExpression, const PrimitiveSet& primitives, const Box3& cell, double margin,
  bool creases)
{
  if (!cellExpression || !nearExpression || !(margin > 0.0))
  {
    return std::nullopt;
  }
  std::vector<CsgLeaf> own, leaves;
  bool isUnion = false, crease = false;
  if (!FlatQuadricLeaves(*cellExpression, own, isUnion))
  {
    return std::nullopt; // (cheap exit: the expression pruned to C already has more)
  }
  // Several leaves only for a cell larger than the tolerance (the margin): a
  // smaller one is bounded by its size anyway, and the bound with several
  // leaves costs their rises and a pruning per face (and NoCommonZero up to
  // 512 enclosures per leaf).
  const bool oversized = cell.Diagonal() > margin * (1.0 + 1e-9);
  if (own.size() > 1)
  {
    // Several leaves in C itself: only where no crease crosses C (header).
    if (!oversized)
    {
      return std::nullopt;
    }
    std::vector<Quadric> fields;
    for (const CsgLeaf& leaf : own)
    {
      fields.push_back(primitives.Quadrics[leaf.Primitive]);
    }
    crease = !NoCommonZero(fields, cell, CreaseSearchDepth);
    if (crease && !(creases && own.size() == 2))
    {
      return std::nullopt;
    }
  }
  QuadricCellError bound;
  bound.Crease = crease;
  if (crease)
  {
    bound.CreaseLeaves[0] = own[0];
    bound.CreaseLeaves[1] = own[1];
  }
  bound.Cell = cell;
  bound.Margin = margin;
  const Box3 grown = GrownByMargin(cell, margin);
  const CsgExpression::Pruned there = CsgExpression::Prune(nearExpression, grown, primitives);
  if (there.Sign != RegionSign::Mixed || !FlatQuadricLeaves(*there.Expression, leaves, isUnion) ||
    (leaves.size() > 1 && !oversized))
  {
    return std::nullopt; // another kind of primitive, or another combination, within the margin
  }
  bound.Union = isUnion;
  for (const CsgLeaf& leaf : leaves)
  {
    bound.Fields.push_back(SignedQuadric(primitives.Quadrics[leaf.Primitive], leaf.Sigma));
    bound.Curvature = std::max(bound.Curvature, CurvatureBound(bound.Fields.back()));
  }
  const unsigned all = AllFields(bound);
  // n: the normal of one of the cell's own leaves, the bisector of its own
  // leaves' (a crease in it) or of all the leaves' (a crease within the
  // margin), whichever rises fastest.
  std::vector<unsigned> candidates;
  unsigned ownFields = 0;
  for (const CsgLeaf& leaf : own)
  {
    candidates.push_back(FieldBit(leaves, leaf));
    ownFields |= candidates.back();
  }
  if (own.size() > 1 && ownFields != all)
  {
    candidates.push_back(ownFields); // (the crease's own bisector, a third primitive near)
  }
  candidates.push_back(all);
  for (const unsigned from : candidates)
  {
    const Vec3 n = BisectingDirection(bound, from, cell.Center(), -1);
    const double rise = MinimumRiseOfAll(bound, all, grown, n);
    if (rise > bound.Rise)
    {
      bound.Direction = n;
      bound.Rise = rise;
    }
  }
  if (!(bound.Rise > 0.0))
  {
    return std::nullopt;
  }
  for (int face = 0; face < 6; ++face)
  {
    const Box3 rectangle = FaceBox(cell, face);
    unsigned onFace = all;
    if (bound.Fields.size() == 1)
    {
      onFace = bound.Fields[0].EncloseForSign(rectangle).ContainsZero() ? 1u : 0u;
    }
    else
    {
      // The leaves that decide F's sign on the face.
      const CsgExpression::Pruned face = CsgExpression::Prune(there.Expression, rectangle, primitives);
      std::vector<CsgLeaf> faceLeaves;
      bool faceUnion = false;
      onFace = 0;
      if (face.Sign == RegionSign::Mixed)
      {
        if (!FlatQuadricLeaves(*face.Expression, faceLeaves, faceUnion))
        {
          return std::nullopt;
        }
        for (const CsgLeaf& l : faceLeaves)
        {
          onFace |= FieldBit(leaves, l);
        }
      }
    }
    bound.FaceFields[face] = onFace;
    if (!onFace)
    {
      bound.FaceRise[face] = HUGE_VAL; // carries no chord
      continue;
    }
    bound.FaceDirection[face] = BisectingDirection(bound, onFace, rectangle.Center(), face / 2);
    bound.FaceRise[face] = Norm(bound.FaceDirection[face]) > 0.0
      ? std::max(0.0, MinimumRiseOfAll(bound, onFace, rectangle, bound.FaceDirection[face]))
      : 0.0;
  }
  return bound;
}

double PredictedCellError(const QuadricCellError& bound)
{
  const Vec3 w = bound.Cell.hi - bound.Cell.lo;
  const double diagonal2 = SquaredNorm(w) * RoundingAllowance;
  double error = bound.Curvature * 0.25 * diagonal2 / bound.Rise;
  for (int face = 0; face < 6; ++face)
  {
    if (bound.FaceRise[face] == HUGE_VAL)
    {
      continue;
    }
    if (!(bound.FaceRise[face] > 0.0))
    {
      return HUGE_VAL;
    }
    const int axis = face / 2;
    const double faceDiagonal2 = (diagonal2 - w[axis] * w[axis]) * RoundingAllowance;
    error = std::max(
      error, bound.Curvature * 0.25 * faceDiagonal2 * (1.0 / bound.Rise + 1.0 / bound.FaceRise[face]));
  }
  return error * RoundingAllowance;
}

std::vector<PredictedChordTerms> PredictFanTerms(
  const QuadricCellError& bound, const std::vector<Vec3>& loop, const Vec3& apex)
{
  const unsigned all = AllFields(bound);
  // The final loop's points are crossings placed as the own loop's are: |F|
  // there is about as small; the largest of the own loop's stands for theirs.
  double pointTerm = 0.0;
  for (const Vec3& p : loop)
  {
    pointTerm = std::max(pointTerm, CombinedMagnitude(bound, all, &p, 1, 0.0));
  }
  std::vector<PredictedChordTerms> terms;
  const std::size_t m = loop.size();
  for (std::size_t k = 0; k < m; ++k)
  {
    const Vec3 &a = loop[k], &b = loop[(k + 1) % m];
    int face = 0;
    while (face < 6 && !OnFacePlane(bound.Cell, face, a, b))
    {
      ++face;
    }
    if (face == 6 || !FaceRises(bound, face))
    {
      terms.push_back({ HUGE_VAL, HUGE_VAL });
      continue;
    }
    const Vec3 ends[2] = { a, b };
    const double chord2 = SquaredNorm(b - a);
    const double onChord = CombinedMagnitude(bound, bound.FaceFields[face], ends, 2, 0.25 * chord2);
    const Box3 chordBox = BoxAround(ends, 2);
    // delta_ab (header: Predicted on the cell's own loop; Local rises).
    const double arc =
      onChord / LocalFaceRise(bound, face, ChordStretch(bound, face, onChord, chordBox)) * RoundingAllowance;
    const double ball = std::sqrt(SmallestBallRadiusSquared(a, b, apex)) + arc;
    const double halfChord = 0.5 * std::sqrt(chord2) + arc;
    const Vec3 v[3] = { a, b, apex };
    const double onTriangles = CombinedMagnitude(bound, all, v, 3, ball * ball) + pointTerm;
    const double onSubChords = CombinedMagnitude(bound, bound.FaceFields[face], ends, 2, halfChord * halfChord) + pointTerm;
    terms.push_back({ LocalTriangleTerm(bound, onTriangles, GrownByMargin(BoxAround(v, 3), arc)) * RoundingAllowance,
      LocalChordTerm(bound, face, onSubChords, GrownByMargin(chordBox, arc)) * RoundingAllowance });
  }
  return terms;
}

double PredictedFanError(const QuadricCellError& bound, const std::vector<Vec3>& loop, const Vec3& apex)
{
  double error = 0.0;
  for (const PredictedChordTerms& t : PredictFanTerms(bound, loop, apex))
  {
    error = std::max({ error, t.Triangles, t.Chords });
  }
  return error;
}

double TriangleError(const QuadricCellError& bound, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 v[3] = { a, b, c };
  const unsigned all = AllFields(bound);
  const double magnitude = CombinedMagnitude(bound, all, v, 3, SmallestBallRadiusSquared(a, b, c));
  return LocalTriangleTerm(bound, magnitude, BoxAround(v, 3)) * RoundingAllowance;
}

double ChordError(const QuadricCellError& bound, int face, const Vec3& a, const Vec3& b)
{
  if (!FaceRises(bound, face)) // (no chord was expected on a face missing S)
  {
    return HUGE_VAL;
  }
  const Vec3 v[2] = { a, b };
  const double ends = CombinedMagnitude(bound, bound.FaceFields[face], v, 2, 0.25 * SquaredNorm(b - a));
  return LocalChordTerm(bound, face, ends, BoxAround(v, 2)) * RoundingAllowance;
}

int ExactSign(const QuadricCellError& bound, const Vec3& p)
{
  int sign = bound.Union ? 1 : -1;
  for (const Quadric& f : bound.Fields)
  {
    const int s = f.ExactSign(p);
    sign = bound.Union ? std::min(sign, s) : std::max(sign, s);
  }
  return sign;
}

std::optional<Vec3> CreaseApex(const QuadricCellError& bound, const PrimitiveSet& primitives)
{
  const Box3& cell = bound.Cell;
  const std::optional<Vec3> x =
    OntoCrease(bound.CreaseLeaves[0], bound.CreaseLeaves[1], primitives, cell.Center(), cell.Diagonal());
  if (!x)
  {
    return std::nullopt;
  }
  const Box3 inner = cell.Shrunk(1.0 / 32.0);
  for (int a = 0; a < 3; ++a)
  {
    if (!((*x)[a] > inner.lo[a] && (*x)[a] < inner.hi[a]))
    {
      return std::nullopt;
    }
  }
  return x;
}

double EdgeChordError(const QuadricCellError& bound, const Vec3& a, const Vec3& b)
{
  double error = 0.0;
  for (int face = 0; face < 6; ++face)
  {
    if (OnFacePlane(bound.Cell, face, a, b))
    {
      error = std::max(error, ChordError(bound, face, a, b));
    }
  }
  return error;
}

double FanError(const QuadricCellError& bound, const std::vector<Vec3>& loop, const Vec3& apex)
{
  double error = 0.0;
  const std::size_t m = loop.size();
  for (std::size_t k = 0; k < m; ++k)
  {
    const Vec3 &a = loop[k], &b = loop[(k + 1) % m];
    error = std::max({ error, TriangleError(bound, a, b, apex), EdgeChordError(bound, a, b) });
  }
  return error <= bound.Margin ? error : HUGE_VAL;
}

std::optional<Vec3> SurfacePointAlongDirection(const QuadricCellError& bound, const Vec3& p, const Box3& region)
{
  // The stretch of the line p + t n inside the region.
  double t0 = -HUGE_VAL, t1 = HUGE_VAL;
  for (int a = 0; a < 3; ++a)
  {
    const double d = bound.Direction[a];
    if (d == 0.0)
    {
      if (p[a] <= region.lo[a] || p[a] >= region.hi[a])
      {
        return std::nullopt;
      }
      continue;
    }
    const double s0 = (region.lo[a] - p[a]) / d, s1 = (region.hi[a] - p[a]) / d;
    t0 = std::max(t0, std::min(s0, s1));
    t1 = std::min(t1, std::max(s0, s1));
  }
  if (!(t0 < t1))
  {
    return std::nullopt;
  }
  // F increases along n: the root, if any, is where the exact sign changes.
  double lo = t0, hi = t1;
  if (ExactSign(bound, p + bound.Direction * lo) >= 0 || ExactSign(bound, p + bound.Direction * hi) <= 0)
  {
    return std::nullopt;
  }
  for (int i = 0; i < 80 && hi - lo > 0.0; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi)
    {
      break;
    }
    (ExactSign(bound, p + bound.Direction * mid) < 0 ? lo : hi) = mid;
  }
  return p + bound.Direction * (0.5 * (lo + hi));
}

} // namespace tpc
