// Vertices whose star - the triangles around them - is proven embedded by a
// projection, so that no pair of those triangles needs a test of its own
// (SelfIntersection.h: the input's check; SurfaceEmbedding.h: the output's).
//
// Why: on a closed mesh most candidate pairs of a self-intersection test are
// neighbours - on CGAL's armadillo 277 000 pairs sharing a vertex and 84 000
// sharing an edge against 16 000 sharing nothing - and each was decided by a
// dozen exact orientations. One proof per vertex settles all of its pairs.
//
// The proof. Let v's star be the m triangles holding v, and say each is
// (v, a, b) in its own cyclic order; its link edge runs a -> b. Suppose
// (i) the link edges form one cycle w_1 -> w_2 -> ... -> w_m -> w_1 through
// m distinct vertices, none of them v (triangle T_i = (v, w_i, w_i+1));
// (ii) dropping one axis, pi, every projected triangle (pi v, pi w_i,
// pi w_i+1) has the same strict orientation s (exact Orient2D);
// (iii) the link winds once around pi v: the wedges W_i at pi v between the
// directions to pi w_i and pi w_i+1 (each of angle in (0, pi), by (ii))
// cover the turn exactly once.
// Then pi is injective on each T_i (its projection has area) and the wedges'
// interiors are disjoint, consecutive wedges sharing the ray towards
// pi w_i+1 and others only pi v. Take x in T_i and y in T_j, i != j, with
// x = y. Then pi x lies in W_i and W_j. Not consecutive: pi x = pi v, so
// x = v (injective on T_i, v in T_i). Consecutive (j = i + 1): pi x lies
// on the shared ray, and T_i meets that ray only along its edge [v, w_i+1],
// so x lies on that edge. Either way T_i and T_j meet only in what they
// share: every pair of v's star meets properly, as TrianglesMeetImproperly
// would find (a pair of triangles sharing a vertex holds it in both, so
// lies in that vertex's star; (i) makes the pairs sharing an edge exactly
// the consecutive ones).
// (iii) is counted exactly: the direction d towards pi w_1 lies in the
// half-open wedge (w_i, w_i+1] when s Orient2D(pi v, pi w_i, pi w_1) > 0 and
// s Orient2D(pi v, pi w_1, pi w_i+1) >= 0 (a wedge under a half turn never
// holds d's opposite with those signs); the half-open wedges partition the
// angle swept, 2 pi k for a link winding k times, and each holds at most one
// of the k passes through d, so the count is k, and k = 1 is asked.
// Vertices that fail any of these - a sharp corner that no axis sees from
// one side, a pinched or non-manifold vertex, an inconsistent orientation,
// a fold - prove nothing: their pairs are tested one by one, as before.
#pragma once

#include "Parallel.h"
#include "TriangleMesh.h"
#include "VertexLinks.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tpc
{

class EmbeddedStars
{
public:
  /// Proves what it can of the `count` triangles at `triangles` (vertex ids
  /// below `vertexCount`, coordinates at `points`), the vertices in parallel.
  /// The triangles must stay where they are while CountNonManifoldVertices
  /// may be asked.
  EmbeddedStars(const Vec3* points, std::size_t vertexCount, const Triangle* triangles, std::size_t count,
    const ParallelFor& parallelFor = SequentialFor);

  /// Whether triangles t1 and t2 of that list are proven to meet only in
  /// what they share: they share one or two vertices, one of them proven.
  /// (The stars are those of that list: a pair from another list proves
  /// nothing. A proven vertex's triangles repeat no vertex and no triangle
  /// of its star repeats another, so two of them share at most two ids;
  /// the count is checked all the same.)
  bool ProveProper(const Triangle& t1, const Triangle& t2) const
  {
    int shared = 0;
    bool proven = false;
    for (const std::uint32_t a : t1)
    {
      for (const std::uint32_t b : t2)
      {
        if (a == b)
        {
          ++shared;
          proven = proven || this->Link[a] == ProvenStar;
        }
      }
    }
    return proven && shared <= 2;
  }
  /// Vertex v's star is proven embedded.
  bool IsProven(std::uint32_t v) const { return this->Link[v] == ProvenStar; }
  /// How many vertices are.
  std::size_t ProvenCount() const;

  /// VertexLinks.h's CountNonManifoldVertices over the same triangles, the
  /// same count: a vertex whose link (i) found one cycle - every proven
  /// vertex, and those that failed only (ii) or (iii) - is a manifold point
  /// (m distinct link vertices joined in one cycle is what the count asks),
  /// so only the others' links are looked at again, with the table of the
  /// triangles around each vertex built here. (The input's check and its
  /// pinched vertices, MeshRepair.cxx, each built that table and walked
  /// every link: 4.7 and 4.6 ms of armadillo's input on two threads.)
  bool CountNonManifoldVertices(
    std::int64_t& count, const ParallelFor& parallelFor = SequentialFor, const ProgressCallback& progress = nullptr) const;

private:
  /// What a vertex's star is: its link not one cycle (i), one cycle but not
  /// proven by a projection, or proven.
  enum : std::uint8_t
  {
    NotOneCycle = 0,
    OneCycle = 1,
    ProvenStar = 2
  };

  const Triangle* Triangles;
  VertexTriangles Around;
  std::vector<std::uint8_t> Link; ///< per vertex, one of the above
};

} // namespace tpc
