#include "LatticePlacement.h"

#include "MeshEdges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace tpc
{
namespace
{
/// Distance from x to the nearest of the values origin + k spacing.
double DistanceToLattice(double x, double origin, double spacing)
{
  double f = (x - origin) / spacing;
  f -= std::floor(f);
  return std::min(f, 1.0 - f) * spacing;
}

/// Integral over [0, u] (in spacings) of the periodic tent that is 1 on the
/// lattice values and 0 beyond `w` (< 1/2) spacings from them.
double TentIntegral(double u, double w)
{
  const double periods = std::floor(u);
  const double f = u - periods;
  double g = 0.5 * w;
  if (f < w)
  {
    g = f - f * f / (2.0 * w);
  }
  else if (f > 1.0 - w)
  {
    g = 0.5 * w + (f - 1.0 + w) - (w * w - (1.0 - f) * (1.0 - f)) / (2.0 * w);
  }
  return w * periods + g;
}

/// Weight of a flat edge coming within `band` of a plane: its length, in
/// cells of `spacing`, times the mean tent along it (exact: an edge spanning
/// several planes weighs the same at every origin).
double FlatPenalty(const FlatCreaseEdge& e, double origin, double spacing, double band, double cell)
{
  const double w = std::min(0.49, band / spacing);
  const double lo = (e.Lo - origin) / spacing, hi = (e.Hi - origin) / spacing;
  double mean = 0.0;
  if (hi - lo > 1e-9)
  {
    mean = (TentIntegral(hi, w) - TentIntegral(lo, w)) / (hi - lo);
  }
  else
  {
    const double d = DistanceToLattice(e.Lo, origin, spacing) / spacing;
    mean = d < w ? 1.0 - d / w : 0.0;
  }
  return mean * e.Length / cell;
}

} // namespace

namespace
{
/// The mesh edge from p to q between facets with third vertices r1 and r2,
/// classified per axis: a ridge or valley along it, or lying in its plane.
void AddCreaseEdge(const Vec3& p, const Vec3& q, const Vec3& r1, const Vec3& r2, double ridgeThickness,
  double planeThickness, LatticeCreases& creases)
{
  const double length = Norm(q - p);
  for (int a = 0; a < 3; ++a)
  {
    // A crease that is a ridge or valley along the axis: both facets
    // leave it on the same side, so a plane below the ridge cuts both,
    // along two lines delta (cot A1 + cot A2) apart (Ai: angle of facet
    // i with the plane). That sliver is unresolvable once it is thinner
    // than the finest spacing: the band of delta to stay out of.
    // Facets lying in the plane themselves (a flat face of a CAD part)
    // sit a hair from a lattice plane just as badly.
    const bool extremal = (r1[a] - std::max(p[a], q[a])) * (r2[a] - std::max(p[a], q[a])) > 0.0 &&
      (r1[a] - std::min(p[a], q[a])) * (r2[a] - std::min(p[a], q[a])) > 0.0;
    const double extent = std::fabs(q[a] - p[a]);
    if (extent < planeThickness && std::fabs(r1[a] - p[a]) < planeThickness &&
      std::fabs(r2[a] - p[a]) < planeThickness && length > 0.0)
    {
      creases.InPlane[a].push_back({ std::min(p[a], q[a]), std::max(p[a], q[a]), length, 0.0 });
    }
    else if (extremal && extent < ridgeThickness && length > 0.0)
    {
      double cotangents = 0.0;
      for (const Vec3* r : { &r1, &r2 })
      {
        Vec3 n = Cross(q - p, *r - p);
        const double norm = Norm(n);
        const double cosine = norm > 0.0 ? std::min(1.0, std::fabs(n[a]) / norm) : 1.0;
        cotangents += cosine / std::max(1e-12, std::sqrt(1.0 - cosine * cosine));
      }
      creases.Ridges[a].push_back({ std::min(p[a], q[a]), std::max(p[a], q[a]), length, 1.0 / std::max(cotangents, 1e-12) });
    }
  }
}
} // namespace

namespace
{
/// The edges of more than two triangles (a non-manifold mesh, contoured
/// without the guarantee), their uses taken in pairs by triangle number as
/// an edge table gives them (MeshEdges.h); usually none, found where a
/// triangle has no neighbour across an edge. (Edges of one triangle add
/// nothing: no ridge.)
LatticeCreases UnpairedEdges(const MeshSolid& mesh, double ridgeThickness, double planeThickness)
{
  const auto& triangles = mesh.Triangles();
  std::vector<EdgeUse> uses;
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
  {
    for (std::uint8_t k = 0; k < 3; ++k)
    {
      if (mesh.Across(t, k) == MeshSolid::NoTriangle)
      {
        const std::uint32_t from = triangles[t][k], to = triangles[t][(k + 1) % 3];
        uses.push_back({ EdgeKey(from, to), t, k, from < to });
      }
    }
  }
  std::sort(uses.begin(), uses.end());
  const auto third = [&](const EdgeUse& u) { return mesh.Points()[triangles[u.Triangle][(u.Corner + 2) % 3]]; };
  LatticeCreases creases;
  ForEachEdge(uses, [&](std::size_t first, std::size_t count) {
    for (std::size_t k = first; k + 1 < first + count; k += 2)
    {
      AddCreaseEdge(mesh.Points()[EdgeLow(uses[k].Key)], mesh.Points()[EdgeHigh(uses[k].Key)], third(uses[k]),
        third(uses[k + 1]), ridgeThickness, planeThickness, creases);
    }
  });
  return creases;
}
} // namespace

LatticeCreases FindLatticeCreases(const PrimitiveSet& primitives, double ridgeThickness, double planeThickness,
  const ParallelFor& parallelFor)
{
  LatticeCreases creases;
  for (const MeshSolid& mesh : primitives.Meshes)
  {
    // Each edge with two triangles once, from the lower-numbered triangle
    // (MeshSolid keeps every triangle's neighbour across each edge: no edge
    // table of its own, which cost as much as the penalties below on
    // armadillo). Blocks of triangles classified in parallel, then appended
    // in block order: the lists are in triangle order whatever the threads.
    // (Until 73e6822 they were in the order of the edges' vertex numbers:
    // the same edges, so the same penalties up to the rounding of their
    // sums, which only a near tie between two shifts could feel.)
    const std::size_t triangles = mesh.Triangles().size();
    constexpr std::size_t Blocks = 64;
    std::vector<LatticeCreases> found(Blocks);
    parallelFor(Blocks, [&](std::size_t begin, std::size_t end) {
      for (std::size_t b = begin; b < end; ++b)
      {
        for (std::size_t t = triangles * b / Blocks; t < triangles * (b + 1) / Blocks; ++t)
        {
          const auto& corners = mesh.Triangles()[t];
          for (int k = 0; k < 3; ++k)
          {
            const std::uint32_t other = mesh.Across(static_cast<std::uint32_t>(t), k);
            if (other == MeshSolid::NoTriangle || other <= t)
            {
              continue;
            }
            const std::uint32_t from = corners[k], to = corners[(k + 1) % 3];
            std::uint32_t third = 0;
            for (const std::uint32_t v : mesh.Triangles()[other])
            {
              third = v != from && v != to ? v : third;
            }
            // (From the edge's lower vertex number to its higher, as an
            // edge table keyed by them would give it.)
            AddCreaseEdge(mesh.Points()[std::min(from, to)], mesh.Points()[std::max(from, to)],
              mesh.Points()[corners[(k + 2) % 3]], mesh.Points()[third], ridgeThickness, planeThickness, found[b]);
          }
        }
      }
    });
    found.push_back(UnpairedEdges(mesh, ridgeThickness, planeThickness));
    for (int a = 0; a < 3; ++a)
    {
      std::size_t ridges = creases.Ridges[a].size(), inPlane = creases.InPlane[a].size();
      for (const LatticeCreases& f : found)
      {
        ridges += f.Ridges[a].size();
        inPlane += f.InPlane[a].size();
      }
      creases.Ridges[a].reserve(ridges);
      creases.InPlane[a].reserve(inPlane);
      for (const LatticeCreases& f : found)
      {
        creases.Ridges[a].insert(creases.Ridges[a].end(), f.Ridges[a].begin(), f.Ridges[a].end());
        creases.InPlane[a].insert(creases.InPlane[a].end(), f.InPlane[a].begin(), f.InPlane[a].end());
      }
    }
  }
  return creases;
}

double LatticeAxisPenalty(const LatticeCreases& creases, int axis, double origin, const LatticeSpacings& spacings)
{
  // Ridges meet the planes of the cells at the tolerance's level (present all
  // along the surface); a sliver is unresolvable below a few finest spacings
  // (face refinement samples). Faces in a plane meet the planes of cells
  // down to the deepest; the farther from them the better.
  const double slivers = 4.0 * spacings.Finest;
  double penalty = 0.0;
  for (const FlatCreaseEdge& e : creases.Ridges[axis])
  {
    penalty += FlatPenalty(e, origin, spacings.Surface, slivers * e.BandPerSeparation, spacings.Deepest);
  }
  for (const FlatCreaseEdge& e : creases.InPlane[axis])
  {
    penalty += FlatPenalty(e, origin, spacings.Deepest, 0.5 * spacings.Deepest, spacings.Deepest);
  }
  return penalty;
}

LatticeSpacings LatticeSpacingsOf(const RootGrid& base, double hausdorffTolerance, int maximumDepth)
{
  LatticeSpacings spacings;
  int level = 0;
  while (level < base.MaxDepth && base.CellDiagonal(level) > hausdorffTolerance * (1.0 + 1e-9))
  {
    ++level;
  }
  spacings.Surface = std::ldexp(base.RootSize, -std::min(level + 1, base.MaxDepth));
  spacings.Deepest = std::ldexp(base.RootSize, -std::min(maximumDepth, base.MaxDepth));
  spacings.Finest = std::ldexp(base.RootSize, -SampleDepth(base, maximumDepth));
  return spacings;
}

double LatticeAxisShift(std::size_t k, int axis, double spacing)
{
  // (The R3 sequence's steps, one per axis.)
  const Vec3 step(0.8191725134, 0.6710436067, 0.5497004779);
  const double f = static_cast<double>(k) * step[axis];
  return (f - std::floor(f)) * spacing;
}

namespace
{
struct PricedShift
{
  double Penalty = 0.0;
  double Shift = 0.0;
};

/// The first `picks` of one axis's shifts (`priced`, in the sequence's
/// order), best first, picked one at a time: the first in the sequence of
/// those left whose penalty is within LatticeNearTie of the least left (a
/// penalty that is not a number counts as infinite). The penalty weighs
/// lengths by a judgement of closeness, and which edges count as flat turns
/// on their coordinates' rounding: the 16 x 12 sphere of Filter.BadInputs
/// scaled by 1e9 has 83.96 where the unit one has 86.57 (and 85.27 at
/// another shift), and the lattice should not move for that.
std::vector<double> AxisShiftsInOrder(const std::vector<PricedShift>& priced, std::size_t picks)
{
  const auto penalty = [&](std::size_t k) {
    return std::isnan(priced[k].Penalty) ? HUGE_VAL : priced[k].Penalty;
  };
  std::vector<std::uint8_t> taken(priced.size(), 0);
  std::vector<double> shifts;
  while (shifts.size() < std::min(picks, priced.size()))
  {
    std::size_t least = priced.size();
    for (std::size_t k = 0; k < priced.size(); ++k)
    {
      least = !taken[k] && (least == priced.size() || penalty(k) < penalty(least)) ? k : least;
    }
    std::size_t pick = 0;
    while (pick < least && (taken[pick] || penalty(pick) > penalty(least) * (1.0 + LatticeNearTie)))
    {
      ++pick;
    }
    taken[pick] = 1;
    shifts.push_back(priced[pick].Shift);
  }
  return shifts;
}
} // namespace

std::vector<Vec3> RankLatticeShifts(const PrimitiveSet& primitives, const RootGrid& base,
  double hausdorffTolerance, int maximumDepth, int count, const ParallelFor& parallelFor,
  const ProgressCallback& progress)
{
  const LatticeSpacings spacings = LatticeSpacingsOf(base, hausdorffTolerance, maximumDepth);
  const std::size_t picks = static_cast<std::size_t>(std::clamp(count, 0, static_cast<int>(LatticeShiftsPerAxis)));
  const LatticeCreases creases = primitives.Meshes.empty()
    ? LatticeCreases{}
    : FindLatticeCreases(primitives, 4.0 * spacings.Surface, spacings.Finest, parallelFor);
  if (progress && progress(0.1))
  {
    return {};
  }
  std::vector<Vec3> shifts;
  if (primitives.Meshes.empty())
  {
    // Nothing grazes: the sequence in order, the unshifted lattice first.
    for (std::size_t k = 0; k < picks; ++k)
    {
      const double s = spacings.Surface;
      shifts.emplace_back(LatticeAxisShift(k, 0, s), LatticeAxisShift(k, 1, s), LatticeAxisShift(k, 2, s));
    }
    return shifts;
  }
  // The penalty is a sum of one term per axis, each a function of the
  // origin's coordinate along that axis alone (LatticeAxisPenalty): each
  // axis's shifts are ranked on their own, and the k-th shift returned is
  // made of the k-th best along each axis (AxisShiftsInOrder) - first, one
  // within LatticeNearTie of the best of all LatticeShiftsPerAxis^3
  // combinations (each axis's term is), for the price of 3
  // LatticeShiftsPerAxis penalties (until 2026-12-07, 64 shifts of the joint
  // sequence, each priced whole: 4.8 % of armadillo's instructions at
  // 1/128) - and each retry moves the lattice along every axis, whichever
  // axis made the near-coincidence it is there to move
  // (BestLatticePlacement.h).
  std::array<std::vector<PricedShift>, 3> priced; // in the sequence's order, per axis
  for (auto& p : priced)
  {
    p.resize(LatticeShiftsPerAxis);
  }
  const bool done = ChunkedFor(3 * LatticeShiftsPerAxis, 4, parallelFor, [&](std::size_t begin, std::size_t end) {
    for (std::size_t j = begin; j < end; ++j)
    {
      const int a = static_cast<int>(j / LatticeShiftsPerAxis);
      const std::size_t k = j % LatticeShiftsPerAxis;
      const double shift = LatticeAxisShift(k, a, spacings.Surface);
      priced[a][k] = { LatticeAxisPenalty(creases, a, base.Origin[a] - shift, spacings), shift };
    }
  }, ProgressRange(progress, 0.1, 1.0));
  if (!done)
  {
    return {};
  }
  const std::array<std::vector<double>, 3> picked = { AxisShiftsInOrder(priced[0], picks),
    AxisShiftsInOrder(priced[1], picks), AxisShiftsInOrder(priced[2], picks) };
  for (std::size_t k = 0; k < picks; ++k)
  {
    shifts.emplace_back(picked[0][k], picked[1][k], picked[2][k]);
  }
  return shifts;
}

} // namespace tpc
