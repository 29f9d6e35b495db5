#include "PolygonHausdorff.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <numeric>
#include <tuple>
#include <utility>

namespace tpc
{
namespace
{
/// Squared distance between two boxes (0 when they overlap).
double BoxDistance2(const Box3& a, const Box3& b)
{
  double sum = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double gap = std::max({ 0.0, a.lo[k] - b.hi[k], b.lo[k] - a.hi[k] });
    sum += gap * gap;
  }
  return sum;
}

/// A piece of a source triangle. Its candidates - the targets that may be
/// nearest to one of its points - are Count entries of the branch and
/// bound's candidate arena from First (one buffer for all pieces, reused
/// across calls: a vector per piece made allocation a tenth of the run).
struct Piece
{
  SourceTriangle Vertices;
  std::size_t First = 0;
  std::size_t Count = 0;
  double Upper = HUGE_VAL;    ///< of the offset distance on the piece: UpperOfG + Offset
  double UpperOfG = HUGE_VAL; ///< of g on the piece (header: Offsets)
  double Offset = 0.0;        ///< its source triangle's offset
  /// The target of the single-target bound (1), and that bound of g (in
  /// EvaluateInHierarchy: only where below bound (2) and the parent's,
  /// else +inf and None).
  std::uint32_t SingleTarget = SingleTargetWitness::None;
  double Single = HUGE_VAL;
  /// g at its vertices where known (+inf where not yet): each is the
  /// minimum over every target, whichever piece it was found in (Evaluate).
  std::array<double, 3> Nearest{ HUGE_VAL, HUGE_VAL, HUGE_VAL };
  /// The target each of those is attained at (None where not known).
  std::array<std::uint32_t, 3> NearestTarget{ SingleTargetWitness::None, SingleTargetWitness::None,
    SingleTargetWitness::None };
  bool operator<(const Piece& o) const { return this->Upper < o.Upper; }
};

} // namespace

void AppendAsSources(const Vec3* corners, std::size_t count, std::vector<SourceTriangle>& sources)
{
  for (std::size_t i = 1; i + 1 < count; ++i)
  {
    sources.push_back({ corners[0], corners[i], corners[i + 1] });
  }
  if (count == 1 || count == 2)
  {
    sources.push_back({ corners[0], corners[count - 1], corners[count - 1] });
  }
}

double CoveringRadius(const SourceTriangle& t)
{
  // Squared edge lengths, c the longest, opposite vertex C; a opposite A
  // (next after C), b opposite B.
  double e2[3];
  for (int i = 0; i < 3; ++i)
  {
    const Vec3 d = t[(i + 1) % 3] - t[(i + 2) % 3];
    e2[i] = Dot(d, d); // (the edge opposite vertex i)
  }
  const int C = e2[0] >= e2[1] && e2[0] >= e2[2] ? 0 : e2[1] >= e2[2] ? 1 : 2;
  const double c2 = e2[C], a2 = e2[(C + 1) % 3], b2 = e2[(C + 2) % 3];
  if (c2 == 0.0)
  {
    return 0.0;
  }
  const double c = std::sqrt(c2);
  double radius;
  if (c2 >= a2 + b2)
  {
    // Right or obtuse at C: the circumcentre is not inside, and the farthest
    // point from the vertices is where the perpendicular bisector of AC or
    // of BC meets AB. On AB at distance r from A, |x - C| = r gives
    // r = b^2 c / (b^2 + c^2 - a^2) (law of cosines; the denominator is at
    // least 2 b^2 since c is the longest), likewise from B.
    const double fromA = b2 == 0.0 ? 0.0 : b2 * c / (b2 + c2 - a2);
    const double fromB = a2 == 0.0 ? 0.0 : a2 * c / (a2 + c2 - b2);
    radius = std::max(fromA, fromB);
  }
  else
  {
    // Acute: the circumcentre is inside, equidistant from all three, and
    // nothing in the triangle is farther from its nearest vertex: the
    // circumradius abc / (4 area) = abc / (2 |AB x AC|).
    const Vec3 cross = Cross(t[1] - t[0], t[2] - t[0]);
    radius = std::sqrt(a2 * b2) * c / (2.0 * Norm(cross));
  }
  // (A few roundings, relative: far below the caller's slack; the factor
  // keeps the result an upper bound anyway.)
  return radius * (1.0 + 1e-12);
}

namespace
{
/// max_i sum_a mu_a distances[a][i] over `targets` rows, or +inf where the
/// weights `mu` are not >= 0 and summing to 1 within 1e-13 (a weight of zero
/// is left out: 0 x inf would be NaN). The check is what makes any weights
/// computed below safe to try: rounding leaves a sum a few ulps from 1, which
/// LeastMixedMaximum's factor covers, but an overflow could leave weights of
/// zero - a bound of 0.
double AtWeights(const std::array<std::array<double, 3>, 3>& distances, int targets, const std::array<double, 3>& mu)
{
  double total = 0.0;
  for (int a = 0; a < targets; ++a)
  {
    if (!(mu[a] >= 0.0))
    {
      return HUGE_VAL;
    }
    total += mu[a];
  }
  if (!(std::fabs(total - 1.0) <= 1e-13))
  {
    return HUGE_VAL;
  }
  double worst = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    double sum = 0.0;
    for (int a = 0; a < targets; ++a)
    {
      sum += mu[a] > 0.0 ? mu[a] * distances[a][i] : 0.0;
    }
    worst = std::max(worst, sum);
  }
  return worst;
}

/// The weights on rows a and b alone where corners i and j's sums are equal:
/// alpha D_ai + (1 - alpha) D_bi = alpha D_aj + (1 - alpha) D_bj (NaN weights
/// where both sides are infinite, which AtWeights refuses).
std::array<double, 3> TwoRowsEqualizing(
  const std::array<std::array<double, 3>, 3>& distances, int a, int b, int i, int j)
{
  const double slope = (distances[a][i] - distances[b][i]) - (distances[a][j] - distances[b][j]);
  const double alpha = (distances[b][j] - distances[b][i]) / slope;
  std::array<double, 3> mu{ 0.0, 0.0, 0.0 };
  mu[a] = alpha;
  mu[b] = 1.0 - alpha;
  return mu;
}

/// The weights on three rows where all three corners' sums are equal:
/// mu . (D_0 - D_1) = mu . (D_1 - D_2) = 0 over the columns D_i, and sum mu
/// = 1, so mu is the cross product of those differences scaled to sum 1.
/// (Infinite entries, a zero or an overflowing sum give weights AtWeights
/// refuses.)
std::array<double, 3> ThreeRowsEqualizing(const std::array<std::array<double, 3>, 3>& distances)
{
  const auto difference = [&](int i, int j) {
    return Vec3(distances[0][i] - distances[0][j], distances[1][i] - distances[1][j],
      distances[2][i] - distances[2][j]);
  };
  const Vec3 n = Cross(difference(0, 1), difference(1, 2));
  const double sum = n[0] + n[1] + n[2];
  return { n[0] / sum, n[1] / sum, n[2] / sum };
}
} // namespace

double LeastMixedMaximum(const std::array<std::array<double, 3>, 3>& distances, int targets)
{
  // The least over the weights' simplex of a maximum of three affine
  // functions (one per corner) is at a vertex of their arrangement: a pure
  // weight (bound (1) with that row), a point of an edge of the simplex
  // where two corners' sums are equal, or one inside where all three are;
  // each is tried. Weights that rounding leaves a little off still prove a
  // bound (the header's chain holds for any that are >= 0 and sum to 1:
  // AtWeights checks), and the factor at the end covers their sum's few
  // ulps and the sums' own roundings.
  double best = HUGE_VAL;
  for (int a = 0; a < targets; ++a)
  {
    best = std::min(best, std::max({ distances[a][0], distances[a][1], distances[a][2] }));
    for (int b = a + 1; b < targets; ++b)
    {
      for (int i = 0; i < 3; ++i)
      {
        for (int j = i + 1; j < 3; ++j)
        {
          best = std::min(best, AtWeights(distances, targets, TwoRowsEqualizing(distances, a, b, i, j)));
        }
      }
    }
  }
  if (targets == 3)
  {
    best = std::min(best, AtWeights(distances, targets, ThreeRowsEqualizing(distances)));
  }
  return best * (1.0 + 1e-12);
}

namespace
{
/// g at the corners of the sources evaluated so far in one branch and bound,
/// with the target attaining it: the sources share corners (S_C's triangles
/// a mesh vertex each with about six others, a fan its apex with all of its
/// triangles), and g is a property of the point (Evaluate), so a corner is
/// searched about once, and a source whose corners are all nearest to one
/// target is often settled without a search (Evaluate). Armadillo at 1/64:
/// 5.85 -> 5.66 G instructions, and the same surfaces and bounds on every
/// scene compared (`run_benchmark.py --compare`); searching every new corner
/// first, even against a fan's few triangles, cost more than it saved
/// (5.75 G). Open addressing on the coordinates' bits, sized for every corner
/// of every source, so never full; a corner whose slot another took first
/// (an equal corner of the same piece, or a collision) is only searched
/// again. NaN coordinates compare unequal to themselves: never found.
class CornerDistances
{
public:
  struct Slot
  {
    Vec3 Point;
    double G = HUGE_VAL;
    std::uint32_t Target = SingleTargetWitness::None;
    std::uint32_t Stamp = 0; ///< the call it was filled in (else free)
  };
  /// Empty, with room for `corners` at most half full: the slots of earlier
  /// calls are free by their stamp, not cleared (a call with few targets
  /// settles its sources so fast that clearing a large table would cost more
  /// than the searches it saves). The memory a large call took is given back
  /// once calls are much smaller, as PolygonSet::Recycle does.
  void Reset(std::size_t corners)
  {
    int bits = 4;
    while ((std::size_t{ 1 } << bits) < 2 * corners)
    {
      ++bits;
    }
    const std::size_t size = std::size_t{ 1 } << bits;
    if (this->Slots.capacity() > 16 * size + 4096)
    {
      std::vector<Slot>().swap(this->Slots);
    }
    if (this->Slots.size() < size)
    {
      this->Slots.resize(size);
    }
    this->Size = size;
    this->Shift = 64 - bits;
    if (++this->Current == 0) // (come round after 2^32 calls: cleared once)
    {
      for (Slot& slot : this->Slots)
      {
        slot.Stamp = 0;
      }
      this->Current = 1;
    }
  }
  /// Fills `slot` (found free by At) for `p`.
  void Fill(Slot& slot, const Vec3& p, double g, std::uint32_t target)
  {
    slot = { p, g, target, this->Current };
  }
  bool IsFree(const Slot& slot) const { return slot.Stamp != this->Current; }
  /// The slot of `p`: its entry, or the free slot it takes.
  Slot& At(const Vec3& p)
  {
    std::uint64_t h = 0;
    for (int a = 0; a < 3; ++a)
    {
      const double x = p[a];
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      h = (h ^ bits) * 0x9E3779B97F4A7C15ull;
    }
    // The top bits: a multiplication carries every bit of the key up to
    // them, while its low bits see only the keys' low bits - all zero for
    // coordinates from floats, integers or k / 2^j (a box, a lattice), which
    // would start every probe at a handful of slots.
    const std::size_t mask = this->Size - 1;
    for (std::size_t i = static_cast<std::size_t>(h >> this->Shift);; i = (i + 1) & mask)
    {
      Slot& slot = this->Slots[i];
      if (this->IsFree(slot) || (slot.Point[0] == p[0] && slot.Point[1] == p[1] && slot.Point[2] == p[2]))
      {
        return slot;
      }
    }
  }

private:
  std::vector<Slot> Slots; ///< the first Size in use
  std::size_t Size = 0;
  int Shift = 60;
  std::uint32_t Current = 0;
};

/// Whether sqrt(distance2) + offset < limit, i.e. distance2 < (limit -
/// offset)^2 with limit - offset > 0 (with a zero offset: distance2 <
/// limit^2 for limit > 0, the comparison without offsets).
bool CloserThan(double distance2, double offset, double limit)
{
  const double room = limit - offset;
  return room > 0.0 && distance2 < room * room;
}

/// Whether target t at offset distance d is nearer than `best`, attained at
/// `bestTarget`: among equally near targets the lowest-numbered wins, so
/// that the target a search names as a point's nearest does not depend on
/// the order it visits them in: bound (3) is built on the corners' nearest
/// targets, and a corner above an edge or a vertex of S_C is equally near to
/// the polygons sharing it. For that every search for a nearest target
/// measures each target that may be as near as the best (MayBeAsNear).
bool NearerThan(double d, std::uint32_t t, double best, std::uint32_t bestTarget)
{
  return d < best || (d == best && d < HUGE_VAL && t < bestTarget);
}

/// Whether sqrt(distance2) + offset <= limit, with room for rounding: the
/// searches of a nearest target must measure every target as near as the
/// best (NearerThan), and one whose box distance is its distance (a point
/// beyond an axis-aligned edge) ties it exactly, while the square of a
/// rounded square root falls below the square it was taken of about one
/// time in four. (Also where candidates are kept for a piece's children:
/// a superset by at most that rounding.)
bool MayBeAsNear(double distance2, double offset, double limit)
{
  const double room = (limit - offset) * (1.0 + 1e-12);
  return room >= 0.0 && distance2 <= room * room;
}

/// d(p, Q_t) + offset, or +inf where that is not a number (a NaN
/// coordinate): the maxima and minima below would pass over a NaN, and a
/// piece with a vertex so measured would be bounded by its other vertices.
double OffsetDistance(const PolygonSet& polygons, const Vec3& p, std::uint32_t t, double offset)
{
  const double d = polygons.Distance(p, t) + offset;
  return std::isnan(d) ? HUGE_VAL : d;
}

} // namespace

/// A bounding volume hierarchy over the targets' boxes, for branch and
/// bounds with many targets (a large cell's S_C against its fan: a hundred
/// polygons and more). The pieces of the fan's triangles are searched in it
/// instead of scanning candidate lists: each scan was linear in the targets,
/// and over a call the scans cost about a sixth of a microsecond per source
/// and target (armadillo at 1/64: a call's time grew with the product of
/// both, the fan's direction two thirds of the branch and bound's time).
/// Median splits along the longest axis of the boxes' centres, at most
/// LeafSize targets a leaf; each node keeps the least offset of its
/// targets, so that its box distance plus that offset is a lower bound of
/// every target's offset distance under it.
class TargetHierarchy
{
public:
  /// The hierarchy of targets with boxes `boxes` and offsets `offsets`
  /// (null for zeros).
  void Build(const std::vector<Box3>& boxes, const std::vector<double>* offsets)
  {
    this->Boxes = &boxes;
    this->Offsets = offsets;
    this->Order.resize(boxes.size());
    this->Centres.resize(boxes.size());
    for (std::uint32_t t = 0; t < boxes.size(); ++t)
    {
      this->Order[t] = t;
      this->Centres[t] = boxes[t].Center();
      for (int a = 0; a < 3; ++a)
      {
        // (A NaN would leave the splits' order undefined. Such a target is
        // still searched - a box distance passes over a NaN coordinate - and
        // measured +inf: OffsetDistance.)
        this->Centres[t][a] = std::isnan(this->Centres[t][a]) ? HUGE_VAL : this->Centres[t][a];
      }
    }
    this->Nodes.clear();
    this->Add(0, static_cast<std::uint32_t>(boxes.size()));
  }

  /// g(p), the least offset distance from `p` to a target, and a target
  /// attaining it: every target whose box distance plus offset is below the
  /// best found is measured, so the minimum is over all of them.
  std::pair<double, std::uint32_t> Nearest(const Vec3& p, const PolygonSet& polygons) const
  {
    double best = HUGE_VAL;
    std::uint32_t bestTarget = SingleTargetWitness::None;
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0)
    {
      const Node& node = this->Nodes[stack[--top]];
      if (!MayBeAsNear(node.Box.Distance2(p), node.MinOffset, best))
      {
        continue;
      }
      if (node.Count > 0)
      {
        for (std::uint32_t k = node.First; k < node.First + node.Count; ++k)
        {
          const std::uint32_t t = this->Order[k];
          const double offset = this->OffsetOf(t);
          if (MayBeAsNear((*this->Boxes)[t].Distance2(p), offset, best))
          {
            const double d = OffsetDistance(polygons, p, t, offset);
            if (NearerThan(d, t, best, bestTarget))
            {
              best = d;
              bestTarget = t;
            }
          }
        }
        continue;
      }
      // (The nearer child on top: its targets usually lower `best` enough
      // to rule the other out.)
      const bool secondNearer =
        this->Nodes[node.Second].Box.Distance2(p) < this->Nodes[node.First].Box.Distance2(p);
      stack[top++] = secondNearer ? node.First : node.Second;
      stack[top++] = secondNearer ? node.Second : node.First;
    }
    return { best, bestTarget };
  }

  /// The least over targets t of max_i (d(v_i, Q_t) + p_t) - the single-
  /// target bound (1) - where it is below `below`, and its target; else
  /// (+inf, None). The vertices' nearest targets `seeds` (None where not
  /// known) are tried first - the piece usually lies near them - then the
  /// nodes nearer the vertices before the farther; a node is passed over
  /// when one vertex's box distance plus its least offset rules it out, a
  /// target when one vertex's distance does. The search stops at the first
  /// bound found that, plus the piece's offset `offset`, is within `within`
  /// (header: Settled pieces): it is then returned whether or not it is the
  /// least.
  std::pair<double, std::uint32_t> BestSingle(const SourceTriangle& v, double below,
    const std::array<std::uint32_t, 3>& seeds, const PolygonSet& polygons, double within, double offset) const
  {
    double best = below;
    std::uint32_t bestTarget = SingleTargetWitness::None;
    const auto settled = [&] { return bestTarget != SingleTargetWitness::None && best + offset <= within; };
    const auto farthestBox2 = [&](const Box3& box) {
      return std::max({ box.Distance2(v[0]), box.Distance2(v[1]), box.Distance2(v[2]) });
    };
    const auto tryTarget = [&](std::uint32_t t) {
      const double offset = this->OffsetOf(t);
      const Box3& box = (*this->Boxes)[t];
      const double box2[3] = { box.Distance2(v[0]), box.Distance2(v[1]), box.Distance2(v[2]) };
      const int farthestVertex = box2[0] >= box2[1] && box2[0] >= box2[2] ? 0 : box2[1] >= box2[2] ? 1 : 2;
      if (!CloserThan(box2[farthestVertex], offset, best))
      {
        return;
      }
      // (The vertex farthest from the target's box first: the likeliest to
      // rule it out with one distance.)
      double farthest = 0.0;
      for (int k = 0; k < 3 && farthest < best; ++k)
      {
        const int i = (farthestVertex + k) % 3;
        farthest = std::max(farthest, OffsetDistance(polygons, v[i], t, offset));
      }
      if (farthest < best)
      {
        best = farthest;
        bestTarget = t;
      }
    };
    for (int i = 0; i < 3 && !settled(); ++i)
    {
      if (seeds[i] != SingleTargetWitness::None && (i == 0 || seeds[i] != seeds[0]) &&
        (i < 2 || seeds[2] != seeds[1]))
      {
        tryTarget(seeds[i]);
      }
    }
    // (Each entry with its node's farthest squared box distance; left
    // uninitialized - std::pair's constructor zeroed the whole stack on
    // every call, 1.5 % of this function's time.)
    struct Entry
    {
      double LowerBound2;
      std::uint32_t Node;
    };
    Entry stack[64];
    int top = 0;
    stack[top++] = { farthestBox2(this->Nodes[0].Box), 0 };
    while (top > 0 && !settled())
    {
      const auto [lowerBound2, n] = stack[--top];
      const Node& node = this->Nodes[n];
      if (!CloserThan(lowerBound2, node.MinOffset, best))
      {
        continue;
      }
      if (node.Count == 0)
      {
        const double first2 = farthestBox2(this->Nodes[node.First].Box);
        const double second2 = farthestBox2(this->Nodes[node.Second].Box);
        const bool firstNearer = first2 <= second2;
        stack[top++] = firstNearer ? Entry{ second2, node.Second } : Entry{ first2, node.First };
        stack[top++] = firstNearer ? Entry{ first2, node.First } : Entry{ second2, node.Second };
        continue;
      }
      for (std::uint32_t k = node.First; k < node.First + node.Count; ++k)
      {
        tryTarget(this->Order[k]);
      }
    }
    return bestTarget == SingleTargetWitness::None ? std::make_pair(HUGE_VAL, bestTarget)
                                                   : std::make_pair(best, bestTarget);
  }

private:
  /// A leaf (Count > 0) holds Order[First, First + Count); an inner node's
  /// children are First and Second.
  struct Node
  {
    Box3 Box;
    double MinOffset = 0.0;
    std::uint32_t First = 0;
    std::uint32_t Second = 0;
    std::uint32_t Count = 0;
  };

  double OffsetOf(std::uint32_t t) const { return this->Offsets ? (*this->Offsets)[t] : 0.0; }

  /// The node over Order[begin, end), and its subtree; its index.
  std::uint32_t Add(std::uint32_t begin, std::uint32_t end)
  {
    const std::uint32_t index = static_cast<std::uint32_t>(this->Nodes.size());
    this->Nodes.emplace_back();
    Box3 box = (*this->Boxes)[this->Order[begin]];
    Box3 centres{ this->Centres[this->Order[begin]], this->Centres[this->Order[begin]] };
    double minOffset = HUGE_VAL;
    for (std::uint32_t k = begin; k < end; ++k)
    {
      const Box3& b = (*this->Boxes)[this->Order[k]];
      const Vec3& c = this->Centres[this->Order[k]];
      for (int a = 0; a < 3; ++a)
      {
        box.lo[a] = std::min(box.lo[a], b.lo[a]);
        box.hi[a] = std::max(box.hi[a], b.hi[a]);
        centres.lo[a] = std::min(centres.lo[a], c[a]);
        centres.hi[a] = std::max(centres.hi[a], c[a]);
      }
      minOffset = std::min(minOffset, this->OffsetOf(this->Order[k]));
    }
    this->Nodes[index].Box = box;
    this->Nodes[index].MinOffset = minOffset;
    // (Depth at most log2 of the targets over the leaf size, well within
    // the searches' stacks of 64.)
    if (end - begin <= LeafSize)
    {
      this->Nodes[index].First = begin;
      this->Nodes[index].Count = end - begin;
      return index;
    }
    const int axis = centres.Width(0) >= centres.Width(1) && centres.Width(0) >= centres.Width(2) ? 0
      : centres.Width(1) >= centres.Width(2)                                                   ? 1
                                                                                               : 2;
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(this->Order.begin() + begin, this->Order.begin() + middle, this->Order.begin() + end,
      [&](std::uint32_t a, std::uint32_t b) {
        const double ca = this->Centres[a][axis], cb = this->Centres[b][axis];
        return ca != cb ? ca < cb : a < b;
      });
    const std::uint32_t first = this->Add(begin, middle);
    const std::uint32_t second = this->Add(middle, end);
    this->Nodes[index].First = first;
    this->Nodes[index].Second = second;
    return index;
  }

  /// (Armadillo at 1/64: 8 took 0.4 % fewer instructions in all than 4 or
  /// 16, 1.4 % fewer than 2.)
  static constexpr std::uint32_t LeafSize = 8;
  const std::vector<Box3>* Boxes = nullptr;
  const std::vector<double>* Offsets = nullptr;
  std::vector<Node> Nodes;
  std::vector<std::uint32_t> Order;
  std::vector<Vec3> Centres; ///< of the targets' boxes
};

namespace
{

/// What every piece of one branch and bound is evaluated against: the
/// targets, their boxes side by side (the first loop reads only those), and
/// the scratch reused across pieces.
struct Targets
{
  const PolygonSet& Polygons;
  const std::vector<Box3>& Boxes;
  /// A piece's candidates with their squared box distances.
  std::vector<std::pair<double, std::uint32_t>>& InReach;
  std::vector<std::uint32_t>& Arena;
  const std::vector<double>* Offsets; ///< per target; null for zeros
  /// Pieces may settle without a search (SettledByCommonNearest,
  /// SettledByKnownTarget): no witnesses asked for.
  bool SettlesWithoutSearch;
  /// Searched instead of the candidates (EvaluateInHierarchy); null where
  /// the targets are few.
  const TargetHierarchy* Hierarchy;
  /// The caller's anyBoundWithin (header: Settled pieces).
  double AnyBoundWithin;
  /// The bound (of the offset distance: g plus the piece's offset) within
  /// which a piece settles with the first single-target bound found (header:
  /// Settled pieces), `lower` the lower bound found so far; below 0 where
  /// witnesses are asked for (the least names the witness).
  double FirstBoundWithin(double settle, double lower) const
  {
    return this->SettlesWithoutSearch ? std::min(settle, std::max(lower, this->AnyBoundWithin)) : -1.0;
  }
  /// Target t's offset; the branch and bound without target offsets (the
  /// fan-to-surface direction, most of its work) is compiled with zeros.
  template <bool WithOffsets>
  double OffsetOf(std::uint32_t t) const
  {
    return WithOffsets ? (*this->Offsets)[t] : 0.0;
  }
  /// Target t's offset, where the targets may or may not have offsets.
  double OffsetOf(std::uint32_t t) const { return this->Offsets ? (*this->Offsets)[t] : 0.0; }
};

/// Settles `piece` with the single-target bound (1) `single` of g, attained
/// at target `target`: its bound, and no candidates kept (never split).
void SettleWith(Piece& piece, double single, std::uint32_t target, const Targets& targets)
{
  piece.UpperOfG = piece.Single = single;
  piece.Upper = single + piece.Offset;
  piece.SingleTarget = target;
  piece.First = targets.Arena.size();
  piece.Count = 0;
}

/// Every corner known and nearest to one target t: the single-target bound
/// (1) is then max_i g(v_i), attained at t, and nothing is below it (it is
/// at least each g(v_i)) - what the searches find, without them, where that
/// settles the piece (no candidates to keep): then sets the piece's bound,
/// raises `lower` and returns true. Not where witnesses are asked for: among
/// targets giving the same bound the search may name another.
bool SettledByCommonNearest(Piece& piece, double settle, const Targets& targets, double& lower)
{
  if (!targets.SettlesWithoutSearch)
  {
    return false;
  }
  const auto& near = piece.NearestTarget;
  const double vertexMax = std::max({ piece.Nearest[0], piece.Nearest[1], piece.Nearest[2] });
  if (near[0] == SingleTargetWitness::None || near[0] != near[1] || near[0] != near[2] ||
    !(vertexMax + piece.Offset <= settle))
  {
    return false;
  }
  SettleWith(piece, vertexMax, near[0], targets);
  lower = std::max(lower, vertexMax + piece.Offset);
  return true;
}

/// Bound (3) of the header for `piece` from the targets its corners are
/// nearest to (their distances known; the others measured), or +inf where
/// those are fewer than two (then (3) is (1) with that target, which the
/// search finds anyway) or a corner's nearest is not known.
double MixedTargetsBound(const Piece& piece, const Targets& targets)
{
  std::array<std::uint32_t, 3> rows;
  int count = 0;
  for (const std::uint32_t t : piece.NearestTarget)
  {
    if (t == SingleTargetWitness::None)
    {
      return HUGE_VAL;
    }
    if (std::find(rows.begin(), rows.begin() + count, t) == rows.begin() + count)
    {
      rows[count++] = t;
    }
  }
  if (count < 2)
  {
    return HUGE_VAL;
  }
  std::array<std::array<double, 3>, 3> distances;
  for (int a = 0; a < count; ++a)
  {
    for (int i = 0; i < 3; ++i)
    {
      distances[a][i] = piece.NearestTarget[i] == rows[a]
        ? piece.Nearest[i]
        : OffsetDistance(targets.Polygons, piece.Vertices[i], rows[a], targets.OffsetOf(rows[a]));
    }
  }
  return LeastMixedMaximum(distances, count);
}

/// A piece's bound of g from (1), (2) and its parent's (a child lies in its
/// parent), `upper`, lowered by (3) where it does not settle the piece: most
/// pieces settle by (1) or (2) at once, and (3)'s distances would be work
/// for nothing there. Over a valley or a ridge of S_C, where the nearest
/// target changes across a piece, (3) is about the distance's maximum while
/// (1) is a far corner's distance to the other side, and the piece settles
/// instead of splitting. Evaluate and EvaluateInHierarchy both end with it,
/// on the same `upper` in exact arithmetic (the hierarchy's search leaves
/// out only a (1) at least (2) or the parent's bound, which the minimum
/// takes instead), so their bounds stay the same. (Computing (3) before the
/// hierarchy's search for (1), to skip or narrow it, cost more than it
/// saved: armadillo at 1/128, 1 %.)
double WithMixedTargets(double upper, const Piece& piece, double settle, const Targets& targets)
{
  return upper + piece.Offset <= settle ? upper : std::min(upper, MixedTargetsBound(piece, targets));
}

/// A piece settled without a search (header: Known targets) by a target one
/// of its known corners is nearest to, or `guess` (the last source's single
/// target, or its parent's): where the single-target bound (1) of one of
/// them, max_i (d(v_i, Q_t) + p_t), plus the piece's offset is at most both
/// `settle` and `lower`, it is the piece's bound; then true. `lower` is the
/// largest offset distance found at a vertex so far - or, for a source, its
/// maximum with the caller's anyBoundWithin. Within the former the
/// result is the same in exact arithmetic: the piece is never split (at
/// most `settle`); its corners' g are at most its bound, hence at most
/// `lower`, so none raises the lower bound; and its bound, at most `lower`,
/// is at most the result, every remaining piece's bound being at least g at
/// its corners, one of which attains the final lower bound. (Computed, a
/// corner's g may differ by an ulp with the order of the searches, as in
/// Evaluate: the same bit for bit on the tests and scenes compared.) Most of
/// S_C's triangles against a fan settle so: a corner shared with the sources
/// before them gives their target, and the search over every target, with
/// the new corners' nearest, is saved.
bool SettledByKnownTarget(Piece& piece, std::uint32_t guess, double settle, const Targets& targets, double lower)
{
  const double limit = std::min(settle, lower);
  if (!targets.SettlesWithoutSearch || !(piece.Offset <= limit))
  {
    return false;
  }
  std::array<std::uint32_t, 4> tried{ piece.NearestTarget[0], piece.NearestTarget[1], piece.NearestTarget[2], guess };
  for (std::size_t k = 0; k < tried.size(); ++k)
  {
    const std::uint32_t t = tried[k];
    if (t == SingleTargetWitness::None || std::find(tried.begin(), tried.begin() + k, t) != tried.begin() + k)
    {
      continue;
    }
    const double offset = targets.OffsetOf(t);
    double worst = 0.0;
    for (int i = 0; i < 3 && worst + piece.Offset <= limit; ++i)
    {
      const bool known = piece.NearestTarget[i] == t;
      worst =
        std::max(worst, known ? piece.Nearest[i] : OffsetDistance(targets.Polygons, piece.Vertices[i], t, offset));
    }
    if (worst + piece.Offset <= limit)
    {
      SettleWith(piece, worst, t, targets);
      return true;
    }
  }
  return false;
}

/// The piece's bound ((1), (2) and (3) of the header, the parent's where
/// lower; its source's offset added)
/// from the targets among the candidates (`count` entries of the arena from
/// `first`) that may be nearest to one of its points (box distance plus
/// offset within the parent's bound of g, `parentUpperOfG`); raises `lower`
/// to its vertices' (offset) distances. The nearest box's target is visited
/// first, then the others in any order, and a distance is computed only where
/// it may lower a vertex's nearest distance or the single-target bound (box
/// distances are lower bounds of distances), so both stay exact whatever the
/// order. A vertex whose g is known (piece.Nearest: found as a vertex of the
/// parent, of a sibling, or of another source: CornerDistances) is not
/// searched again: g is a property of the point, the minimum over every
/// target - those left out of a piece's candidates are farther from all of
/// its points than its parent's bound of g, hence never the nearest - so in
/// exact arithmetic it is the value the search would find. (As computed, a
/// comparison of a squared distance with (limit - offset)^2 may keep or drop
/// a target an ulp from the limit depending on the order of the visits, so
/// the value may differ by such an ulp: it is a computed distance to a
/// target all the same, far inside the rounding slack - MeshCellError.h.)
/// A split searches 3 new points instead of 12 (armadillo at 1/64, one
/// thread: 5.92 -> 5.85 G instructions in all, the same surfaces and
/// bounds). (`WithOffsets`: the targets have offsets; without, every offset
/// is the constant 0.0, the same comparisons and sums bit for bit.) A piece
/// whose bound is at most `settle` keeps no candidates: it is never split.
template <bool WithOffsets>
void Evaluate(Piece& piece, std::size_t first, std::size_t count, double parentUpperOfG, double settle,
  Targets& targets, double& lower)
{
  if (SettledByCommonNearest(piece, settle, targets, lower))
  {
    return;
  }
  std::vector<std::pair<double, std::uint32_t>>& inReach = targets.InReach;
  std::vector<std::uint32_t>& arena = targets.Arena;
  // (Box distances are compared squared: no square root per target.)
  const Box3 box = BoundsOf(piece.Vertices.data(), 3);
  const double reach = parentUpperOfG; // (g on the piece is at most g on its parent)
  inReach.clear();
  for (std::size_t k = first; k < first + count; ++k)
  {
    const std::uint32_t t = arena[k];
    const double d2 = BoxDistance2(box, targets.Boxes[t]);
    if (MayBeAsNear(d2, targets.template OffsetOf<WithOffsets>(t), reach))
    {
      inReach.emplace_back(d2, t);
    }
  }
  double nearest[3] = { piece.Nearest[0], piece.Nearest[1], piece.Nearest[2] };
  const bool known[3] = { nearest[0] < HUGE_VAL, nearest[1] < HUGE_VAL, nearest[2] < HUGE_VAL };
  std::array<std::uint32_t, 3> nearestTarget = piece.NearestTarget;
  double single = HUGE_VAL;
  std::uint32_t singleTarget = SingleTargetWitness::None;
  const auto largest = [&] { return std::max({ single, nearest[0], nearest[1], nearest[2] }); };
  // (Once the single-target bound settles the piece, no smaller one is
  // sought: header, Settled pieces.)
  const double firstWithin = targets.FirstBoundWithin(settle, lower);
  // Whether target t may lower a vertex's nearest distance or the single-
  // target bound, and then its distances. (A vertex's distance to the
  // target's box is a lower bound of its distance to the target: one vertex
  // that far rules the target out of the single-target bound, which for a
  // piece much larger than the targets is most of them.)
  const auto visit = [&](std::uint32_t t) {
    const double offset = targets.template OffsetOf<WithOffsets>(t);
    double boxDistance2Of[3];
    double farthestBox2 = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      boxDistance2Of[i] = targets.Boxes[t].Distance2(piece.Vertices[i]);
      farthestBox2 = std::max(farthestBox2, boxDistance2Of[i]);
    }
    bool improvesSingle = !(single + piece.Offset <= firstWithin) && CloserThan(farthestBox2, offset, single);
    double farthest = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      const bool improvesNearest = !known[i] && MayBeAsNear(boxDistance2Of[i], offset, nearest[i]);
      if (!improvesNearest && !improvesSingle)
      {
        continue;
      }
      const double d = OffsetDistance(targets.Polygons, piece.Vertices[i], t, offset);
      if (!known[i] && NearerThan(d, t, nearest[i], nearestTarget[i]))
      {
        nearest[i] = d;
        nearestTarget[i] = t;
      }
      farthest = std::max(farthest, d);
      improvesSingle = improvesSingle && farthest < single;
    }
    if (improvesSingle)
    {
      single = farthest; // (all three computed, their maximum below the bound)
      singleTarget = t;
    }
  };
  // Nearest box first: its target usually bounds the piece well enough to
  // rule out most others by their box distance alone. Among boxes equally
  // near - a large piece's box meets many targets' boxes, all at distance
  // 0 - the one nearest the piece's centroid: its single-target bound is
  // about the piece's circumradius, which rules out more of the others than
  // a target near one corner would (couplingdown at 1/128: 13 % fewer
  // instructions measuring polygon distances, 1.2 % fewer in all; the order
  // changes no bound, each being a minimum over every target that can lower
  // it). The rest are taken as they come, each skipped where its box
  // distance already rules it out: most of those still in the running after
  // the first are visited anyway (armadillo at 1/128: 7.6 of 9.6), so
  // ordering them (a sort, earlier a heap) cost more than the distances it
  // saved.
  if (!inReach.empty())
  {
    const Vec3 centroid = (piece.Vertices[0] + piece.Vertices[1] + piece.Vertices[2]) * (1.0 / 3.0);
    auto nearestBox = inReach.begin();
    double best = HUGE_VAL;
    for (auto e = inReach.begin(); e != inReach.end(); ++e)
    {
      if (e->first <= nearestBox->first)
      {
        const double d2 = targets.Boxes[e->second].Distance2(centroid);
        if (e->first < nearestBox->first || d2 < best)
        {
          best = d2;
          nearestBox = e;
        }
      }
    }
    std::iter_swap(inReach.begin(), nearestBox);
    visit(inReach.front().second);
    for (auto e = inReach.begin() + 1; e != inReach.end(); ++e)
    {
      if (MayBeAsNear(e->first, targets.template OffsetOf<WithOffsets>(e->second), largest()))
      {
        visit(e->second);
      }
    }
  }
  double vertexMax = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    vertexMax = std::max(vertexMax, nearest[i]);
    piece.Nearest[i] = nearest[i];
  }
  piece.NearestTarget = nearestTarget;
  const double upper = WithMixedTargets( // (of g)
    std::min({ single, vertexMax + CoveringRadius(piece.Vertices), parentUpperOfG }), piece, settle, targets);
  piece.UpperOfG = upper;
  piece.Upper = upper + piece.Offset;
  piece.SingleTarget = singleTarget;
  piece.Single = single;
  lower = std::max(lower, vertexMax == HUGE_VAL ? 0.0 : vertexMax + piece.Offset);
  // (Appended after the parent's entries were read: the arena may move.)
  piece.First = arena.size();
  if (piece.Upper <= settle)
  {
    piece.Count = 0; // (settled: never split)
    return;
  }
  for (const auto& [boxDistance2, t] : inReach)
  {
    if (MayBeAsNear(boxDistance2, targets.template OffsetOf<WithOffsets>(t), upper))
    {
      arena.push_back(t);
    }
  }
  piece.Count = arena.size() - piece.First;
}

/// Evaluate's bound of the piece, searched in the targets' hierarchy
/// (Targets::Hierarchy) instead of its parent's candidates, which it keeps
/// none of. The same bound in exact arithmetic:
/// - g at a vertex not known yet is the least distance over every target
///   (TargetHierarchy::Nearest); Evaluate's search among the candidates
///   finds that minimum too (its comment: no target left out of them can be
///   nearest to a point of the piece);
/// - the single-target bound (1) is searched below (2) and below the
///   parent's bound of g `parentUpperOfG` only: the piece's bound is the
///   smallest of (1), (2) and the parent's (a child lies in its parent),
///   then (3) where that does not settle it (WithMixedTargets). Over every
///   target rather than the candidates - a target left out of them is
///   farther than the parent's bound from the piece, so its (1) is above
///   that bound too;
/// - the vertices' nearest targets, on which (3) is built, are named alike
///   (NearerThan).
/// A piece that settles settles with the first bound found within
/// FirstBoundWithin, (2) where that is within it (header: Settled pieces).
/// The shortcut and `lower` are Evaluate's; no candidates are kept, settled
/// or not (a split searches the hierarchy again). (`first` and `count`, the
/// candidates, are unused.)
void EvaluateInHierarchy(Piece& piece, std::size_t, std::size_t, double parentUpperOfG, double settle,
  Targets& targets, double& lower)
{
  if (SettledByCommonNearest(piece, settle, targets, lower))
  {
    return;
  }
  double vertexMax = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    if (!(piece.Nearest[i] < HUGE_VAL))
    {
      std::tie(piece.Nearest[i], piece.NearestTarget[i]) =
        targets.Hierarchy->Nearest(piece.Vertices[i], targets.Polygons);
    }
    vertexMax = std::max(vertexMax, piece.Nearest[i]);
  }
  const double viaCorners = vertexMax + CoveringRadius(piece.Vertices); // (2)
  const double firstWithin = targets.FirstBoundWithin(settle, lower);
  std::tie(piece.Single, piece.SingleTarget) = viaCorners + piece.Offset <= firstWithin
    ? std::make_pair(HUGE_VAL, SingleTargetWitness::None)
    : targets.Hierarchy->BestSingle(piece.Vertices, std::min(viaCorners, parentUpperOfG), piece.NearestTarget,
        targets.Polygons, firstWithin, piece.Offset);
  piece.UpperOfG = WithMixedTargets(std::min({ piece.Single, viaCorners, parentUpperOfG }), piece, settle, targets);
  piece.Upper = piece.UpperOfG + piece.Offset;
  lower = std::max(lower, vertexMax == HUGE_VAL ? 0.0 : vertexMax + piece.Offset);
  piece.First = targets.Arena.size();
  piece.Count = 0;
}
} // namespace

HausdorffTargets::HausdorffTargets() = default;
HausdorffTargets::~HausdorffTargets() = default;

void HausdorffTargets::Prepare(const PolygonSet& polygons, const std::vector<double>* offsets)
{
  this->Prepare(polygons, offsets, true);
}

void HausdorffTargets::Prepare(const PolygonSet& polygons, const std::vector<double>* offsets, bool hierarchy)
{
  this->Polygons = &polygons;
  this->Offsets = offsets;
  this->Boxes.resize(polygons.size());
  for (std::uint32_t t = 0; t < polygons.size(); ++t)
  {
    this->Boxes[t] = polygons.Bounds(t);
  }
  this->HierarchyBuilt = hierarchy && polygons.size() >= HausdorffTargets::HierarchyFrom;
  if (this->HierarchyBuilt)
  {
    if (!this->Hierarchy)
    {
      this->Hierarchy = std::make_unique<TargetHierarchy>();
    }
    this->Hierarchy->Build(this->Boxes, offsets);
  }
}

HausdorffEstimate OneSidedHausdorff(const std::vector<SourceTriangle>& sources,
  const PolygonSet& targets, double enough, double giveUp, std::size_t budget,
  const DistanceOffsets& offsets, std::vector<SingleTargetWitness>* witnesses, double anyBoundWithin)
{
  // (Prepared for this call alone, in memory kept across calls; the
  // hierarchy only where it is searched - not where witnesses are asked for.)
  if (sources.empty())
  {
    if (witnesses)
    {
      witnesses->clear();
    }
    return HausdorffEstimate();
  }
  thread_local HausdorffTargets prepared;
  prepared.Prepare(targets, offsets.Targets, witnesses == nullptr);
  return OneSidedHausdorff(sources, prepared, enough, giveUp, budget, offsets.Sources, witnesses, anyBoundWithin);
}

HausdorffEstimate OneSidedHausdorff(const std::vector<SourceTriangle>& sources,
  const HausdorffTargets& prepared, double enough, double giveUp, std::size_t budget,
  const std::vector<double>* sourceOffsets, std::vector<SingleTargetWitness>* witnesses, double anyBoundWithin)
{
  HausdorffEstimate estimate;
  if (witnesses)
  {
    witnesses->assign(sources.size(), SingleTargetWitness{});
  }
  if (sources.empty())
  {
    return estimate;
  }
  assert(prepared.Polygons && "HausdorffTargets::Prepare first");
  const PolygonSet& targets = *prepared.Polygons;
  const DistanceOffsets offsets{ sourceOffsets, prepared.Offsets };
  // (A witness is the target whose single-target bound (1) alone settles a
  // source; the hierarchy's search measures (1) only below (2): witnesses
  // are asked of the scan.)
  const bool searchHierarchy = prepared.HierarchyBuilt && !witnesses;
  // Scratch reused across calls (one per thread): the candidate arena, its
  // first entries every target where they are scanned (the hierarchy's
  // searches keep no candidates); a piece's candidates in reach (Evaluate).
  thread_local std::vector<std::uint32_t> arena;
  thread_local std::vector<std::pair<double, std::uint32_t>> inReach;
  arena.resize(searchHierarchy ? 0 : targets.size());
  std::iota(arena.begin(), arena.end(), 0u);
  Targets context{ targets, prepared.Boxes, inReach, arena, offsets.Targets, witnesses == nullptr,
    searchHierarchy ? prepared.Hierarchy.get() : nullptr, anyBoundWithin };
  thread_local CornerDistances corners;
  corners.Reset(3 * sources.size());
  const auto evaluate = searchHierarchy ? &EvaluateInHierarchy
    : offsets.Targets                    ? &Evaluate<true>
                                         : &Evaluate<false>;
  // Pieces at most `settle` are never split (the loop below stops before
  // the largest piece is one of them): they are kept out of the queue, their
  // largest bound in `settledUpper`, and their candidates are not kept
  // (Evaluate). Most pieces of S_C against a patch settle at once.
  const double settle = std::min(enough, giveUp);
  double settledUpper = 0.0;
  thread_local std::vector<Piece> queue; // (a heap: std::push_heap, std::pop_heap)
  queue.clear();
  const auto keep = [&](const Piece& piece) {
    if (piece.Upper <= settle)
    {
      settledUpper = std::max(settledUpper, piece.Upper);
      return;
    }
    queue.push_back(piece);
    std::push_heap(queue.begin(), queue.end());
  };
  // Each source evaluated in order, or settled by a target its corners or
  // the last source gave (SettledByKnownTarget) within the lower bound found
  // so far or `anyBoundWithin`; those settled above the former wait in
  // `deferred`: where no piece is left to split, their bounds count as they
  // are, else they are evaluated again before the splits, so that the lower
  // bound the splits stop at is the one found without `anyBoundWithin`.
  // (Pieces evaluated, those sources' again included, still stop searching
  // for a smaller single-target bound within it: their corners are searched
  // all the same, so the lower bound is the same.)
  std::uint32_t guess = SingleTargetWitness::None;
  thread_local std::vector<std::pair<std::size_t, double>> deferred; // (source, bound)
  deferred.clear();
  const auto evaluateSource = [&](std::size_t k, double attained) {
    Piece piece{ sources[k], 0, 0, HUGE_VAL, HUGE_VAL, offsets.Sources ? (*offsets.Sources)[k] : 0.0 };
    std::array<CornerDistances::Slot*, 3> slots;
    for (int i = 0; i < 3; ++i)
    {
      slots[i] = &corners.At(piece.Vertices[i]);
      const bool known = !corners.IsFree(*slots[i]);
      piece.Nearest[i] = known ? slots[i]->G : HUGE_VAL;
      piece.NearestTarget[i] = known ? slots[i]->Target : SingleTargetWitness::None;
    }
    if (SettledByKnownTarget(piece, guess, settle, context, std::max(estimate.Lower, attained)))
    {
      guess = piece.SingleTarget;
      if (piece.Upper > estimate.Lower)
      {
        deferred.emplace_back(k, piece.Upper);
        return;
      }
    }
    else
    {
      evaluate(piece, 0, targets.size(), HUGE_VAL, settle, context, estimate.Lower);
      guess = piece.SingleTarget != SingleTargetWitness::None ? piece.SingleTarget : guess;
    }
    for (int i = 0; i < 3; ++i)
    {
      // (Where two corners of the piece found the same free slot - equal, or
      // colliding - the first fills it and the second is searched again.)
      if (piece.Nearest[i] < HUGE_VAL && corners.IsFree(*slots[i]))
      {
        corners.Fill(*slots[i], piece.Vertices[i], piece.Nearest[i], piece.NearestTarget[i]);
      }
    }
    if (witnesses && piece.Single + piece.Offset <= settle)
    {
      (*witnesses)[k] = { piece.SingleTarget, piece.Single + piece.Offset };
    }
    keep(piece);
  };
  for (std::size_t k = 0; k < sources.size(); ++k)
  {
    evaluateSource(k, anyBoundWithin);
  }
  const bool splits = !queue.empty();
  for (std::size_t d = 0, count = deferred.size(); d < count; ++d)
  {
    if (splits)
    {
      evaluateSource(deferred[d].first, 0.0); // (never deferred again)
    }
    else
    {
      settledUpper = std::max(settledUpper, deferred[d].second);
    }
  }
  std::size_t evaluated = sources.size();
  while (!queue.empty() && evaluated < budget && estimate.Lower <= giveUp)
  {
    const double top = queue.front().Upper; // (> settle)
    // (Within 10 % of the lower bound is close enough only below giveUp: the
    // caller needs a proof under it.)
    if ((top <= 1.1 * estimate.Lower && top <= giveUp) || top == HUGE_VAL)
    {
      break;
    }
    std::pop_heap(queue.begin(), queue.end());
    const Piece parent = queue.back();
    queue.pop_back();
    const SourceTriangle& v = parent.Vertices;
    const Vec3 m01 = (v[0] + v[1]) * 0.5, m12 = (v[1] + v[2]) * 0.5, m20 = (v[2] + v[0]) * 0.5;
    // g at the six points (the parent's corners known, the midpoints found
    // by the first child holding each), and each child's corners among them.
    std::array<double, 6> g{ parent.Nearest[0], parent.Nearest[1], parent.Nearest[2], HUGE_VAL, HUGE_VAL, HUGE_VAL };
    std::array<std::uint32_t, 6> nearestTarget{ parent.NearestTarget[0], parent.NearestTarget[1],
      parent.NearestTarget[2], SingleTargetWitness::None, SingleTargetWitness::None, SingleTargetWitness::None };
    constexpr int C0 = 0, C1 = 1, C2 = 2, M01 = 3, M12 = 4, M20 = 5;
    static constexpr std::array<std::array<int, 3>, 4> Children{ { { C0, M01, M20 }, { M01, C1, M12 },
      { M20, M12, C2 }, { M01, M12, M20 } } };
    const std::array<Vec3, 6> point{ v[0], v[1], v[2], m01, m12, m20 };
    for (const std::array<int, 3>& child : Children)
    {
      Piece piece{ { point[child[0]], point[child[1]], point[child[2]] }, 0, 0, HUGE_VAL, HUGE_VAL,
        parent.Offset };
      piece.Nearest = { g[child[0]], g[child[1]], g[child[2]] };
      piece.NearestTarget = { nearestTarget[child[0]], nearestTarget[child[1]], nearestTarget[child[2]] };
      if (SettledByKnownTarget(piece, parent.SingleTarget, settle, context, estimate.Lower))
      {
        keep(piece);
        continue;
      }
      evaluate(piece, parent.First, parent.Count, parent.UpperOfG, settle, context, estimate.Lower);
      for (int i = 0; i < 3; ++i)
      {
        g[child[i]] = piece.Nearest[i];
        nearestTarget[child[i]] = piece.NearestTarget[i];
      }
      // (The child lies in its parent: Evaluate's bound takes the parent's
      // where lower, but not its shortcut, SettledByCommonNearest.)
      piece.UpperOfG = std::min(piece.UpperOfG, parent.UpperOfG);
      piece.Upper = std::min(piece.Upper, parent.Upper);
      keep(piece);
    }
    evaluated += 4;
  }
  estimate.Upper = queue.empty() ? settledUpper : std::max(queue.front().Upper, settledUpper);
  return estimate;
}

} // namespace tpc
