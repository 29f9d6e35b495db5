// A certified upper bound of the one-sided Hausdorff distance between two
// sets of convex planar polygons (issue 17: the certified error of cells
// where a mesh is the surface, MeshCellError.h).
//
// h(A, B) = max over a in A of d(a, B), B = union of convex polygons Q_j.
// Branch and bound over A's triangles (sources), which rests on three facts:
// - d(., Q) is convex for one convex Q, so over a triangle T its maximum is at
//   T's vertices: max over T of d(., B) <= min_j max_i d(v_i, Q_j). (1)
//   (d(., B) itself is a minimum of convex functions and is not convex: the
//   bound must pick one Q_j for the whole piece.)
// - d(., B) is 1-Lipschitz, and every x of T is within R of a vertex, R =
//   max over T of min_i |x - v_i| (CoveringRadius: the circumradius of an
//   acute T, else the distance to its end of the longest edge's point that
//   is as far from the obtuse vertex; a midpoint split keeps the pieces'
//   shape, so a thin piece is bounded by about half its length, not by the
//   two thirds the centroid's farthest vertex would give):
//   max over T of d(., B) <= max_i d(v_i, B) + R. (2)
// - Where the nearest Q_j changes across T (T over a valley or a ridge of B),
//   (1) with any one Q_j is far above the distance, and (2) is the piece's
//   size: a mixture of targets does better. For targets Q_a (those nearest
//   to T's vertices) and weights mu_a >= 0 summing to 1, at x of T with
//   barycentric coordinates lambda_i(x),
//     d(x, B) <= min_a d(x, Q_a) <= sum_a mu_a d(x, Q_a)
//             <= sum_a mu_a sum_i lambda_i(x) d(v_i, Q_a)   (each convex)
//             <= max_i sum_a mu_a d(v_i, Q_a),                          (3)
//   a bound for any weights (pure weights give (1) with one Q_a); the least
//   over them is the value of the matrix game D_ai = d(v_i, Q_a)
//   (LeastMixedMaximum), which is the exact maximum of the distance where it
//   is affine on T in each Q_a and no other target is nearer (T over the
//   planes of two or three polygons): a piece straddling a valley of B
//   settles without being split.
// A piece's upper bound is the smallest of (1), (2), its parent's and, where
// those do not settle it, (3) (PolygonHausdorff.cxx, WithMixedTargets; the
// corners' nearest targets are named alike by every search: NearerThan).
// The exact distances at its vertices, max_i d(v_i, B), are lower bounds of
// h. The largest upper bound is split into four (edge midpoints) until it is
// within `enough` (and `giveUp`), or within 10 % of the best lower bound and
// `giveUp`, or the lower bound exceeds `giveUp`, or the budget of pieces is
// spent; the largest remaining upper bound is returned (always an upper
// bound of h, however the loop ended). A polygon Q_j whose
// box is farther from a piece's box than the piece's upper bound cannot be the
// nearest to any of its points and is dropped for the piece's sub-pieces.
//
// Offsets (the per-chord composition of MeshCellError.h). With an offset o_s
// per source triangle and p_t per target, what is bounded is
//   max over sources s, x in s of  o_s + g(x),  g(x) = min_t ( d(x, Q_t) + p_t ).
// The facts survive: each d(., Q_t) + p_t is convex, so over a piece g <=
// min_t max_i ( d(v_i, Q_t) + p_t ) (1), and (3) holds with d(., Q_a) + p_a
// for d(., Q_a); g is a minimum of 1-Lipschitz functions, hence 1-Lipschitz,
// so g <= max_i g(v_i) + R (2). A target whose
// box distance plus p_t exceeds a piece's bound of g cannot be the minimum at
// any of its points and is dropped as before. Lower is then attained by
// o_s + g, not by the distance itself. With no offsets (zeros) every
// comparison and sum is the one without them, bit for bit.
//
// Many targets (from 32: a large cell's S_C against its fan). A piece's
// candidates were scanned, which cost as much as sources times targets; the
// pieces are then searched in a hierarchy of the targets' boxes instead:
// g at a vertex as the least distance over every target, the single-target
// bound (1) only below (2) and the parent's bound. The same bound in exact arithmetic - a target
// outside a piece's candidates is farther from it than its parent's bound,
// which both take where lower - and, computed, bit for bit on the tests
// and scenes compared (PolygonHausdorff.cxx, EvaluateInHierarchy). Where
// witnesses are asked for, the candidates are scanned as before.
//
// Known targets. A piece whose single-target bound (1) with a target known
// to be near it - the nearest of one of its corners already searched, its
// parent's single target, or the last source's - is at most the lower bound
// found so far (and the settling bound) is settled with it, without the
// search for its new corners' nearest: neither bound returned changes, since
// its corners are no farther than the lower bound, and every piece left has
// a bound at least g at its corners, one of which attains the final lower
// bound (PolygonHausdorff.cxx, SettledByKnownTarget; witnesses turn it off):
// the same in exact arithmetic and, computed, bit for bit on the tests and
// scenes compared (a corner's g may differ by an ulp with the order of the
// searches, as the hierarchy's may).
//
// Settled pieces. A piece is settled (never split) once a bound of it is
// within `enough` (and `giveUp`); which bound does not matter to the search:
// the pieces split, their bounds and the lower bound are the same whatever a
// settled piece's bound is. So a piece stops searching for a smaller one -
// the least single-target bound over the targets, (1) where (2) already
// settles it - once it has one within the lower bound found so far: that
// changes neither bound returned, as above. A caller that needs no tighter
// result below a value - it takes the maximum with a value attained elsewhere
// (the other direction's Lower: CertifiedSurfacePatchError), or compares the
// result with nothing below it (MeshCellError.h: Prediction precision) - may
// pass it (anyBoundWithin): pieces then settle with the first bound found
// within it too, and sources by a known target within it, without the search
// for their new corners; where pieces are left to split, those sources
// settled above the lower bound are searched before the splits, which stop at
// the lower bound found without it. (Where witnesses are asked for, the
// least single-target bound names the witness: none of this applies.) Most
// of S_C's triangles settle so against a fan within the other direction's
// Lower (stop 58, armadillo at 1/64, one thread: 5.01 -> 4.75 G instructions,
// the same surfaces, grids and bounds).
//
// Distances are computed in floating point; the caller adds the rounding
// slack (MeshCellError.h).
#pragma once

#include "ConvexPolygons.h"
#include "Vector3.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace tpc
{

/// max over the triangle of the distance to its nearest vertex (rounded up).
double CoveringRadius(const std::array<Vec3, 3>& triangle);

/// Bound (3) of the header for `targets` (1 to 3) rows of `distances`, row
/// a holding d(v_i, Q_a) (offsets included; >= 0 or +inf, never NaN:
/// OffsetDistance) at the piece's vertices i: the
/// least over weights mu (>= 0, summing to 1) of max_i sum_a mu_a
/// distances[a][i] - the value of that matrix game, attained at a vertex of
/// the weights' arrangement, which are all tried - rounded up. An upper bound
/// of min_a sum_i lambda_i distances[a][i] for every lambda of the simplex,
/// and at most min_a max_i distances[a][i] (bound (1) over those rows)
/// times 1 + 1e-12.
double LeastMixedMaximum(const std::array<std::array<double, 3>, 3>& distances, int targets);

using SourceTriangle = std::array<Vec3, 3>;

struct HausdorffEstimate
{
  double Upper = 0.0; ///< proven: h(sources, targets) <= Upper
  double Lower = 0.0; ///< attained at a point of the sources (with offsets: by the offset distance)
};

/// Appends the convex polygon with corners `corners` (in order) as source
/// triangles: a fan from its first corner; a point or a segment (what a
/// clipping may leave) as one degenerate triangle, which the bounds measure
/// all the same.
void AppendAsSources(const Vec3* corners, std::size_t count, std::vector<SourceTriangle>& sources);

/// Offsets added to the distances (header: Offsets): one per source
/// triangle, one per target, each >= 0; null for zeros.
struct DistanceOffsets
{
  const std::vector<double>* Sources = nullptr;
  const std::vector<double>* Targets = nullptr;
};

/// A source triangle settled whole by the single-target bound (1): every
/// point of it within Bound of target Target alone (offsets included).
struct SingleTargetWitness
{
  static constexpr std::uint32_t None = ~std::uint32_t{ 0 };
  std::uint32_t Target = None; ///< None: not settled so (split, or by (2), (3) or the parent's)
  double Bound = 0.0;
};

class TargetHierarchy; // (PolygonHausdorff.cxx)

/// The targets of branch and bounds, prepared: their boxes and, from
/// HierarchyFrom targets, the hierarchy they are searched in.
/// OneSidedHausdorff prepares its targets for each call; a caller bounding
/// many sources one call at a time against the same targets prepares them
/// once (the decimation's made triangles against the input mesh,
/// ErrorCertificates.cxx: a hierarchy built for each collapse was half of
/// armadillo's decimation at 1/64). Refers to the polygons and offsets
/// prepared, which must stay as they are while it is used; once prepared,
/// any number of threads may search it at once (the searches only read it);
/// Prepare keeps the memory of the last. Neither copied nor moved: its
/// hierarchy points at its boxes.
class HausdorffTargets
{
public:
  HausdorffTargets();
  ~HausdorffTargets();
  HausdorffTargets(const HausdorffTargets&) = delete;
  HausdorffTargets& operator=(const HausdorffTargets&) = delete;

  /// The least number of targets searched in a hierarchy (fewer are
  /// scanned; from 16 to 64, armadillo's instructions at 1/64 within 0.6 %).
  static constexpr std::size_t HierarchyFrom = 32;

  /// Prepares `polygons`, with offsets `offsets` (header: Offsets; null for
  /// zeros).
  void Prepare(const PolygonSet& polygons, const std::vector<double>* offsets = nullptr);

private:
  friend HausdorffEstimate OneSidedHausdorff(const std::vector<SourceTriangle>&, const PolygonSet&, double,
    double, std::size_t, const DistanceOffsets&, std::vector<SingleTargetWitness>*, double);
  friend HausdorffEstimate OneSidedHausdorff(const std::vector<SourceTriangle>&, const HausdorffTargets&, double,
    double, std::size_t, const std::vector<double>*, std::vector<SingleTargetWitness>*, double);
  /// `hierarchy`: build it where the targets are many (not where the calls
  /// ask for witnesses: those scan).
  void Prepare(const PolygonSet& polygons, const std::vector<double>* offsets, bool hierarchy);

  const PolygonSet* Polygons = nullptr;
  const std::vector<double>* Offsets = nullptr;
  std::vector<Box3> Boxes;
  std::unique_ptr<TargetHierarchy> Hierarchy;
  bool HierarchyBuilt = false;
};

/// Bounds h(sources, targets) as above (with `offsets`, the offset distance);
/// Upper is +inf when there are sources but no targets. `witnesses`, when
/// given, receives one entry per source: the target that settled it at its
/// first evaluation by (1) alone, within min(enough, giveUp) - a certificate
/// that stays true as long as that target does (CertifiedDecimation.h keeps
/// them between collapses).
/// `anyBoundWithin`: a value below which the caller needs no tighter result
/// (header: Settled pieces): pieces with a bound within it settle with the
/// first found, so Upper and Lower may differ where they are below it:
/// max(anyBoundWithin, Upper) and max(anyBoundWithin, Lower) are those
/// without it, and Upper is an upper bound all the same. Ignored where
/// `witnesses` are asked for.
HausdorffEstimate OneSidedHausdorff(const std::vector<SourceTriangle>& sources,
  const PolygonSet& targets, double enough, double giveUp, std::size_t budget = 4096,
  const DistanceOffsets& offsets = {}, std::vector<SingleTargetWitness>* witnesses = nullptr,
  double anyBoundWithin = 0.0);

/// The same against prepared targets (their offsets as prepared), with
/// `sourceOffsets` (null for zeros): the same bound, bit for bit.
HausdorffEstimate OneSidedHausdorff(const std::vector<SourceTriangle>& sources,
  const HausdorffTargets& targets, double enough, double giveUp, std::size_t budget = 4096,
  const std::vector<double>* sourceOffsets = nullptr, std::vector<SingleTargetWitness>* witnesses = nullptr,
  double anyBoundWithin = 0.0);

} // namespace tpc
