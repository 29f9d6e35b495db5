// Random CSG scenes of spheres, ellipsoids, rotated boxes and cylinders:
// whatever happens (including cells stopped by a low depth limit), the output
// is a closed, manifold, consistently oriented surface; and when two runs at
// different tolerances are both guaranteed they agree on the topology.
#include "CoreContour.h"
#include "SceneBuilder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <condition_variable>
#include <mutex>
#include <random>
#include <thread>

using tpc::Box3;
using tpc::CsgTerm;
using tpc::Quadric;
using tpc::Vec3;

namespace
{
struct Outcome
{
  tpc::TopologyReport Report;
  std::size_t Unresolved = 0;
  std::size_t Inconsistent = 0;
  int RepairRuns = 0;
};

Outcome Contour(const tpctest::Scene& scene, double tolerance, int depth, int placements)
{
  const tpctest::ContourRun r = tpctest::Contour(
    scene, { { -0.8, -0.8, -0.8 }, { 0.8, 0.8, 0.8 } }, tolerance, depth, placements);
  return { r.Report, r.Subdivision.UnresolvedCells, r.Extraction.InconsistentCells, r.RepairRuns };
}

/// A random solid: primitives folded with random operations, clipped to a box.
tpctest::Scene RandomScene(std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0), unit(0.0, 1.0);
  // Three draws as a vector, in a fixed order (the order in which GCC
  // evaluated the arguments of Vec3(u(rng), u(rng), u(rng)), unspecified in
  // C++: clang's made other scenes).
  const auto draw3 = [&rng](auto& d, double offset, double scale) {
    const double z = offset + scale * d(rng), y = offset + scale * d(rng), x = offset + scale * d(rng);
    return Vec3(x, y, z);
  };
  tpctest::SceneBuilder b;
  std::vector<CsgTerm> terms;
  const int count = 2 + static_cast<int>(rng() % 4);
  for (int i = 0; i < count; ++i)
  {
    const Vec3 c = draw3(u, 0.0, 0.5);
    switch (rng() % 4)
    {
      case 0:
        terms.push_back(b.Sphere(c, 0.15 + 0.35 * unit(rng)));
        break;
      case 1:
        terms.push_back(b.Ellipsoid(c, draw3(unit, 0.1, 0.4)));
        break;
      case 2:
      {
        const double radius = 0.05 + 0.2 * unit(rng);
        terms.push_back(b.Cylinder(c, draw3(u, 0.0, 1.0), radius));
        break;
      }
      default:
      {
        // A box rotated about z and x, as six composed planes.
        const double a = 3 * u(rng), t = 3 * u(rng);
        const double R[3][3] = { { std::cos(a), -std::sin(a) * std::cos(t), std::sin(a) * std::sin(t) },
          { std::sin(a), std::cos(a) * std::cos(t), -std::cos(a) * std::sin(t) },
          { 0, std::sin(t), std::cos(t) } };
        double m[16] = { 0 };
        for (int r = 0; r < 3; ++r)
        {
          for (int k = 0; k < 3; ++k)
          {
            m[4 * r + k] = R[r][k];
          }
          m[4 * r + 3] = -(R[r][0] * c[0] + R[r][1] * c[1] + R[r][2] * c[2]);
        }
        m[15] = 1;
        std::vector<CsgTerm> planes;
        for (int axis = 0; axis < 3; ++axis)
        {
          const double h = 0.1 + 0.3 * unit(rng);
          Vec3 n, o;
          n[axis] = 1;
          o[axis] = h;
          planes.push_back(b.Add(Quadric::Plane(o, n).Composed(m)));
          n[axis] = -1;
          o[axis] = -h;
          planes.push_back(b.Add(Quadric::Plane(o, n).Composed(m)));
        }
        terms.push_back(tpctest::SceneBuilder::Intersection(planes));
      }
    }
  }
  CsgTerm solid = terms[0];
  for (std::size_t i = 1; i < terms.size(); ++i)
  {
    const CsgTerm::Op op = rng() % 3 == 0 ? CsgTerm::Op::Union
                                          : (rng() % 2 ? CsgTerm::Op::Intersection : CsgTerm::Op::Difference);
    solid = CsgTerm::Combine(op, { solid, terms[i] });
  }
  b.Finish(tpctest::SceneBuilder::Intersection({ solid, b.Box({ -0.8, -0.8, -0.8 }, { 0.8, 0.8, 0.8 }) }));
  return b.Scene;
}

/// Scene 91 of seed 14 (CellsWhoseFinalPatchIsNotCertifiedAreSplitAndRunAgain).
tpctest::Scene SceneNeedingARepair()
{
  std::mt19937 rng(14);
  tpctest::Scene scene;
  for (int trial = 0; trial <= 91; ++trial)
  {
    scene = RandomScene(rng);
  }
  return scene;
}

/// The pieces of a split run in threads of one process, exchanging as MPI
/// ranks do (PieceOfRun::Sum, PieceExchange): every collective call waits
/// for all pieces and hands each the list of what every piece gave.
class InProcessPieces
{
public:
  explicit InProcessPieces(int pieces)
    : Given(static_cast<std::size_t>(pieces))
  {
  }
  std::vector<std::vector<double>> GatherAll(int piece, const std::vector<double>& mine)
  {
    std::unique_lock<std::mutex> lock(this->Mutex);
    const std::uint64_t call = this->Calls;
    this->Given[static_cast<std::size_t>(piece)] = mine;
    if (++this->Arrived == this->Given.size())
    {
      this->Gathered = this->Given;
      this->Arrived = 0;
      ++this->Calls;
      this->Done.notify_all();
    }
    else
    {
      this->Done.wait(lock, [&] { return this->Calls != call; });
    }
    // (No piece can complete the next call before this one has read it.)
    return this->Gathered;
  }
  tpc::PieceOfRun Piece(int piece)
  {
    tpc::PieceOfRun p;
    p.Piece = piece;
    p.Pieces = static_cast<int>(this->Given.size());
    p.Sum = [this, piece](std::size_t x) {
      std::size_t sum = 0;
      for (const std::vector<double>& v : this->GatherAll(piece, { static_cast<double>(x) }))
      {
        sum += static_cast<std::size_t>(v[0]);
      }
      return sum;
    };
    return p;
  }
  tpc::PieceExchange Exchange(int piece)
  {
    tpc::PieceExchange e;
    e.Max = [this, piece](double x) {
      double most = x;
      for (const std::vector<double>& v : this->GatherAll(piece, { x }))
      {
        most = std::max(most, v[0]);
      }
      return most;
    };
    e.GatherAll = [this, piece](const std::vector<double>& mine) { return this->GatherAll(piece, mine); };
    return e;
  }

private:
  std::mutex Mutex;
  std::condition_variable Done;
  std::vector<std::vector<double>> Given, Gathered;
  std::size_t Arrived = 0;
  std::uint64_t Calls = 0;
};
} // namespace

TEST(RandomScenes, AlwaysClosedManifoldAndConsistentWhenGuaranteed)
{
  std::mt19937 rng(2026);
  int limited = 0, compared = 0;
  for (int trial = 0; trial < 14; ++trial)
  {
    const tpctest::Scene scene = RandomScene(rng);
    // A low depth limit on one lattice placement leaves some cells
    // unresolved on purpose.
    const Outcome coarse = Contour(scene, 0.04, 9, 1);
    const Outcome fine = Contour(scene, 0.02, 12, tpc::LatticePlacements);
    for (const Outcome* o : { &coarse, &fine })
    {
      EXPECT_EQ(o->Inconsistent, 0u) << "trial " << trial;
      // (No repair round where cells are unresolved: it could not resolve
      // them, Contour.cxx RepairCellsFoundWanting.)
      EXPECT_TRUE(o->Unresolved == 0 || o->RepairRuns == 0) << "trial " << trial;
      if (o->Report.Faces > 0)
      {
        EXPECT_TRUE(o->Report.Closed) << "trial " << trial;
        EXPECT_TRUE(o->Report.Manifold) << "trial " << trial;
        EXPECT_TRUE(o->Report.Oriented) << "trial " << trial;
        EXPECT_GT(o->Report.SignedVolume, 0.0) << "trial " << trial;
      }
    }
    limited += coarse.Unresolved > 0 ? 1 : 0;
    if (coarse.Unresolved == 0 && fine.Unresolved == 0)
    {
      EXPECT_EQ(coarse.Report.Components, fine.Report.Components) << "trial " << trial;
      EXPECT_EQ(coarse.Report.Genus, fine.Report.Genus) << "trial " << trial;
      ++compared;
    }
  }
  EXPECT_GT(limited, 0);  // the limit path was exercised
  EXPECT_GT(compared, 3); // and so was the agreement check
}

TEST(RandomScenes, CellsWhoseFinalPatchIsNotCertifiedAreSplitAndRunAgain)
{
  // Scene 91 of seed 14 at 1/256: a crease cell larger than the tolerance
  // passed on the fan over its own loop, but a finer neighbour's tiling
  // replaced its own on a shared face, and the fan over the final loop has a
  // half chord whose certificate fails (QuadricCellError.h: Where the final
  // loop does not refine L). Without repair rounds the guarantee is
  // withdrawn; with them the cell is split and the subdivision runs again
  // (CellRepair.h) - twice here, the first round's split cell giving a
  // neighbour the same trouble - and the surface is guaranteed. (If another
  // change makes this scene pass without a repair, the first expectations
  // say so: pick a scene that needs one.)
  const tpctest::Scene scene = SceneNeedingARepair();
  tpc::ContourParameters p = tpctest::ParametersFor({ { -0.8, -0.8, -0.8 }, { 0.8, 0.8, 0.8 } }, 1.0 / 256);
  p.RepairRounds = 0;
  const tpctest::ContourRun unrepaired = tpctest::Contour(scene, p);
  EXPECT_GT(unrepaired.Extraction.UncertifiedCells, 0u);
  EXPECT_FALSE(unrepaired.Guaranteed);
  EXPECT_EQ(unrepaired.RepairRuns, 0);

  p.RepairRounds = tpc::DefaultRepairRounds;
  const tpctest::ContourRun repaired = tpctest::Contour(scene, p);
  EXPECT_GE(repaired.RepairRuns, 1);
  EXPECT_EQ(repaired.Extraction.UncertifiedCells, 0u);
  EXPECT_GE(repaired.Subdivision.SplitsByReason[static_cast<int>(tpc::SplitReason::PatchNotCertified)], 1u);
  EXPECT_TRUE(repaired.Guaranteed);
  EXPECT_LE(repaired.HausdorffBound, repaired.Tolerance * (1 + 1e-9));
  EXPECT_EQ(repaired.Report.Components, unrepaired.Report.Components);
  EXPECT_EQ(repaired.Report.Genus, unrepaired.Report.Genus);
  // Every cell the first surface found wanting was split, for that reason.
  for (const auto& [n, error] : unrepaired.Extraction.CellErrors)
  {
    const tpc::OctreeNode& cell = unrepaired.Subdivision.Octree.Nodes[n];
    if (error == HUGE_VAL)
    {
      const std::int64_t ijk[3] = { static_cast<std::int64_t>(cell.Ijk[0]), static_cast<std::int64_t>(cell.Ijk[1]),
        static_cast<std::int64_t>(cell.Ijk[2]) };
      const std::int64_t again = repaired.Subdivision.Octree.Find(cell.Level, ijk);
      ASSERT_GE(again, 0);
      const tpc::OctreeNode& split = repaired.Subdivision.Octree.Nodes[static_cast<std::size_t>(again)];
      EXPECT_EQ(split.Level, cell.Level);
      EXPECT_FALSE(split.IsLeaf());
      EXPECT_EQ(split.Reason, tpc::SplitReason::PatchNotCertified);
    }
  }
}

TEST(RandomScenes, PiecesOfASplitRunRepairTheSameCells)
{
  // The scene above in two pieces (as two MPI ranks): each piece names the
  // cells of its own trees found wanting, the pieces gather them all (a
  // piece's ghost ring holds the other's cells), and both run again alike:
  // the surface they make together is guaranteed, repaired as in one piece.
  const tpctest::Scene scene = SceneNeedingARepair();
  for (const int rounds : { 0, tpc::DefaultRepairRounds })
  {
    SCOPED_TRACE("repair rounds " + std::to_string(rounds));
    tpc::ContourParameters p = tpctest::ParametersFor({ { -0.8, -0.8, -0.8 }, { 0.8, 0.8, 0.8 } }, 1.0 / 256);
    p.RepairRounds = rounds;
    InProcessPieces exchange(2);
    std::vector<tpc::ContourResult> pieces(2);
    std::vector<std::thread> threads;
    for (int piece = 0; piece < 2; ++piece)
    {
      threads.emplace_back([&, piece] {
        pieces[static_cast<std::size_t>(piece)] = tpc::Contour(tpctest::ContourSceneOf(scene), p, tpc::SequentialFor,
          nullptr, exchange.Piece(piece), exchange.Exchange(piece));
      });
    }
    for (std::thread& t : threads)
    {
      t.join();
    }
    std::size_t uncertified = 0;
    for (const tpc::ContourResult& r : pieces)
    {
      ASSERT_EQ(r.Status, tpc::ContourResult::Outcome::Contoured);
      uncertified += r.Extraction.UncertifiedCells;
      EXPECT_EQ(r.Report.Guaranteed, rounds > 0);
      EXPECT_EQ(r.RepairRuns, pieces[0].RepairRuns);
      EXPECT_EQ(r.Report.UnresolvedCells, 0);
      EXPECT_EQ(r.Placed.Parameters.SplitFirst.Size(), pieces[0].Placed.Parameters.SplitFirst.Size());
      EXPECT_TRUE(r.Topology.Closed && r.Topology.Manifold); // (the whole surface's, from the pieces)
    }
    if (rounds > 0)
    {
      EXPECT_GE(pieces[0].RepairRuns, 1);
      EXPECT_EQ(uncertified, 0u);
    }
    else
    {
      EXPECT_EQ(pieces[0].RepairRuns, 0);
      EXPECT_GT(uncertified, 0u);
    }
  }
}
