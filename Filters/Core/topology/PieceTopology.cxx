#include "PieceTopology.h"

#include "MeshEdges.h"
#include "UnionFind.h"

#include <algorithm>
#include <array>
#include <map>

namespace tpc
{
namespace
{
using Point = std::array<double, 3>;
} // namespace

PieceSeams DescribePiece(const TriangleMesh& piece)
{
  PieceSeams s;
  const std::size_t nv = piece.Points.size();
  UnionFind parts(nv);
  std::vector<bool> used(nv, false);
  for (const Triangle& t : piece.Triangles)
  {
    used[t[0]] = used[t[1]] = used[t[2]] = true;
    parts.Join(t[0], t[1]);
    parts.Join(t[1], t[2]);
  }
  // Local component ids, in vertex order.
  std::vector<std::int64_t> component(nv, -1);
  for (std::size_t v = 0; v < nv; ++v)
  {
    if (used[v])
    {
      ++s.Vertices;
      const std::uint32_t r = parts.Find(static_cast<std::uint32_t>(v));
      if (component[r] < 0)
      {
        component[r] = s.Components++;
      }
    }
  }
  s.Faces = static_cast<std::int64_t>(piece.Triangles.size());
  std::vector<EdgeUse> uses;
  BuildEdgeTable(piece.Triangles.data(), piece.Triangles.size(), uses);
  ForEachEdge(uses, [&](std::size_t first, std::size_t count) {
    ++s.Edges;
    if (count == 1)
    {
      // A boundary edge, from and to in its triangle's order.
      const Triangle& t = piece.Triangles[uses[first].Triangle];
      const std::uint32_t from = t[uses[first].Corner], to = t[(uses[first].Corner + 1) % 3];
      for (const std::uint32_t v : { from, to })
      {
        const Vec3& p = piece.Points[v];
        s.BoundaryEdges.insert(s.BoundaryEdges.end(), { p[0], p[1], p[2] });
      }
      s.BoundaryComponents.push_back(component[parts.Find(from)]);
    }
    s.NonManifoldEdges += count > 2 ? 1 : 0;
    s.MisorientedEdges += count == 2 && uses[first].Ascending == uses[first + 1].Ascending ? 1 : 0;
  });
  return s;
}

std::vector<double> PieceSeams::Serialize() const
{
  std::vector<double> d = { static_cast<double>(this->Vertices), static_cast<double>(this->Edges),
    static_cast<double>(this->Faces), static_cast<double>(this->Components),
    static_cast<double>(this->NonManifoldEdges), static_cast<double>(this->MisorientedEdges),
    static_cast<double>(this->BoundaryComponents.size()) };
  for (std::size_t e = 0; e < this->BoundaryComponents.size(); ++e)
  {
    d.insert(d.end(), this->BoundaryEdges.begin() + static_cast<std::ptrdiff_t>(6 * e),
      this->BoundaryEdges.begin() + static_cast<std::ptrdiff_t>(6 * e + 6));
    d.push_back(static_cast<double>(this->BoundaryComponents[e]));
  }
  return d;
}

std::vector<PieceSeams> PieceSeams::DeserializeAll(const std::vector<double>& data)
{
  std::vector<PieceSeams> pieces;
  for (std::size_t i = 0; i + 7 <= data.size();)
  {
    PieceSeams s;
    s.Vertices = static_cast<std::int64_t>(data[i]);
    s.Edges = static_cast<std::int64_t>(data[i + 1]);
    s.Faces = static_cast<std::int64_t>(data[i + 2]);
    s.Components = static_cast<std::int64_t>(data[i + 3]);
    s.NonManifoldEdges = static_cast<std::int64_t>(data[i + 4]);
    s.MisorientedEdges = static_cast<std::int64_t>(data[i + 5]);
    const auto n = static_cast<std::size_t>(data[i + 6]);
    i += 7;
    for (std::size_t e = 0; e < n && i + 7 <= data.size(); ++e, i += 7)
    {
      s.BoundaryEdges.insert(s.BoundaryEdges.end(), data.begin() + static_cast<std::ptrdiff_t>(i),
        data.begin() + static_cast<std::ptrdiff_t>(i + 6));
      s.BoundaryComponents.push_back(static_cast<std::int64_t>(data[i + 6]));
    }
    pieces.push_back(std::move(s));
  }
  return pieces;
}

TopologyReport CombinePieces(const std::vector<PieceSeams>& pieces)
{
  TopologyReport r;
  std::int64_t misoriented = 0;
  // Global component ids: piece p's local component c is offset[p] + c.
  std::vector<std::uint32_t> offset(pieces.size() + 1, 0);
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    offset[p + 1] = offset[p] + static_cast<std::uint32_t>(pieces[p].Components);
    r.Vertices += pieces[p].Vertices;
    r.Edges += pieces[p].Edges;
    r.Faces += pieces[p].Faces;
    r.NonManifoldEdges += pieces[p].NonManifoldEdges;
    misoriented += pieces[p].MisorientedEdges;
  }
  UnionFind joined(offset.back());
  // Seam vertices: each distinct point counted once, joining the components
  // that reach it.
  std::map<Point, std::uint32_t> seamVertex; // point -> a global component
  std::map<std::pair<Point, Point>, int> directed;
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    const PieceSeams& s = pieces[p];
    std::map<Point, bool> seenHere;
    for (std::size_t e = 0; e < s.BoundaryComponents.size(); ++e)
    {
      const Point a{ s.BoundaryEdges[6 * e], s.BoundaryEdges[6 * e + 1], s.BoundaryEdges[6 * e + 2] };
      const Point b{ s.BoundaryEdges[6 * e + 3], s.BoundaryEdges[6 * e + 4], s.BoundaryEdges[6 * e + 5] };
      ++directed[{ a, b }];
      const std::uint32_t c = offset[p] + static_cast<std::uint32_t>(s.BoundaryComponents[e]);
      for (const Point& v : { a, b })
      {
        if (!seenHere.emplace(v, true).second)
        {
          continue; // this piece counted it once already
        }
        const auto it = seamVertex.emplace(v, c);
        if (!it.second)
        {
          --r.Vertices; // counted by another piece too
          joined.Join(c, it.first->second);
        }
      }
    }
  }
  // Seam edges: each boundary edge must meet its twin, in the other direction.
  for (const auto& d : directed)
  {
    const auto twin = directed.find({ d.first.second, d.first.first });
    if (twin == directed.end() || d.second != 1 || twin->second != 1)
    {
      ++r.BoundaryEdges;
    }
    else if (d.first.first < d.first.second)
    {
      --r.Edges; // counted by both pieces
    }
  }
  for (std::uint32_t c = 0; c < offset.back(); ++c)
  {
    r.Components += joined.Find(c) == c ? 1 : 0;
  }
  r.EulerCharacteristic = r.Vertices - r.Edges + r.Faces;
  r.Closed = r.Faces > 0 && r.BoundaryEdges == 0;
  r.Manifold = r.Closed && r.NonManifoldEdges == 0;
  r.Oriented = r.Manifold && misoriented == 0;
  if (r.Manifold)
  {
    r.Genus = GenusFromEuler(r.Components, r.EulerCharacteristic);
  }
  return r;
}

} // namespace tpc
