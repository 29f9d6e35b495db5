// The core's one entry point: everything a run decides, except converting
// VTK data.
//
// tpc::Contour takes the solids (meshes with their repair verdicts, implicit
// terms), how to combine them and the user's parameters, and owns the whole
// contouring policy: the checks on the inputs and what they imply (a mesh that
// is not closed is refused; one violating the paper's assumptions caps the
// depth and rules out the guarantee; coincident faces of two meshes are a
// tangential contact), the domain and its margins, clipping to Bounds, the
// lattice placements, the subdivision (paper 5.3), the extraction (4.3), the
// exact embedding check, the repair rounds (the subdivision run again with
// the cells whose final patch was not certified or not embedded split first:
// CellRepair.h), the certified decimation when asked (Decimate),
// the topology report of the whole surface (also when
// this process holds one piece of it), and *the* definition of
// TopologyGuaranteed with the reasons when it is 0.
//
// The VTK filter, the core tests, the fuzz target and the MPI piece path all
// call it, so a change of criterion is made here once and every test and the
// fuzzer see it.
#pragma once

#include "CsgExpression.h"
#include "MeshRepair.h"
#include "Parallel.h"
#include "SurfaceEmbedding.h"
#include "SurfaceExtraction.h"
#include "BestLatticePlacement.h"
#include "CertifiedDecimation.h"
#include "SolidBoundary.h"
#include "TopologyReport.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace tpc
{

/// One solid of the scene.
struct SceneInput
{
  std::string Name; ///< how messages call it ("Input 2", "The ImplicitFunction")
  /// What the output's triangles on this solid's surface carry as their
  /// solid (ContourResult::TriangleSolid); -1: the input's index in Inputs.
  int Id = -1;
  CsgTerm Solid;
  /// For an input mesh: its index in the scene's Primitives.Meshes.
  int Mesh = -1;
  /// For an input mesh: what repair found. Absent: the caller vouches that the
  /// mesh is closed, manifold and free of self-intersections (test scenes).
  std::optional<MeshRepairReport> Repair;
  /// Called once the domain is known, with the scene's primitives, this
  /// input's solid and a box around the domain: an error text when the
  /// solid's description disagrees with the caller's own evaluation of it
  /// (the VTK adapter samples its vtkImplicitFunction), empty otherwise.
  std::function<std::string(const PrimitiveSet&, const CsgTerm&, const Box3&)> Verify;
};

struct ContourScene
{
  PrimitiveSet Primitives;
  std::vector<SceneInput> Inputs;
  /// Folds the inputs in order: ((S0 op S1) op ...) op Sn. In a difference
  /// the first input is the minuend.
  CsgTerm::Op Operation = CsgTerm::Op::Union;
};

/// The deepest MaximumDepth: the lattice reaches 2^-41 of the domain
/// (LatticeBits in RootGrid.h; less where the coordinates' doubles run out).
constexpr int DeepestMaximumDepth = 40;

/// Repair rounds a run makes at most (ContourParameters::RepairRounds):
/// a round's split cells meet finer neighbours whose own final loops may
/// lose points in turn (the random CSG scene of Core.RandomScenes' repair
/// test needs two).
constexpr int DefaultRepairRounds = 3;

struct ContourParameters
{
  /// The two-sided Hausdorff bound epsilon, relative to the diagonal of the
  /// domain (Bounds, Region, or the solid's bounding box) or absolute.
  double Tolerance = 0.01;
  bool ToleranceIsRelative = true;
  /// A safety limit, not how the answer is reached: refinement below the
  /// tolerance's cells happens only where a topology test fails, so the
  /// default is the lattice's end (2^-41 of the domain; RootGrid.h).
  int MaximumDepth = DeepestMaximumDepth;
  std::size_t MaximumNumberOfCells = 10000000; ///< (at least 8 are used)
  /// Clip the solid to this box (capped: the planes of the faces it reaches
  /// bound the solid; ClipToBounds) and contour only there.
  std::optional<Box3> Bounds;
  /// Lay the lattice over this box (with the usual margin) instead of the
  /// solid's bounding box, without clipping; it must contain the solid (to
  /// 1 % of its diagonal). For tests that place the lattice on purpose.
  std::optional<Box3> Region;
  /// At most this many lattice placements (LatticePlacement.h: no more than
  /// LatticeShiftsPerAxis, 16); fewer when the inputs violate the
  /// assumptions or the pieces cannot agree.
  int LatticePlacements = tpc::LatticePlacements;
  /// Decimate the extracted surface, every collapse certified to keep the
  /// tolerance, the embedding, the topology and the features
  /// (CertifiedDecimation.h). Not in a piece of a split run, nor where the
  /// extraction did not end embedded with a patch in every surface cell.
  bool Decimate = false;
  /// At most this many runs again of the subdivision, on the same lattice,
  /// with the cells an earlier surface found wanting split first
  /// (CellRepair.h): cells whose final patch is not certified within the
  /// tolerance, or not embedded. 0: none (to measure, or to see what the
  /// repair hides). In a run split among processes only where the pieces
  /// exchange through a controller (PieceExchange): they gather every
  /// piece's cells and split them alike.
  int RepairRounds = DefaultRepairRounds;
};

/// The report every output carries (the filter's field data).
struct ContourReport
{
  long long Components = 0;
  long long Genus = -1;
  long long EulerCharacteristic = 0;
  bool Guaranteed = false;
  long long UnresolvedCells = 0;
  bool Closed = false;
  bool Manifold = false;
  bool Embedded = false;
  /// Every component's normals point out of the solid (SolidBoundary.h;
  /// in a run split among processes, by the patches' construction).
  bool Outward = false;
  long long PlanarCells = 0;
  long long ExactCells = 0;
  /// Proven two-sided Hausdorff bound; NaN when a limit left surface without
  /// a patch (then no bound is proven).
  double HausdorffBound = 0.0;
  double AbsoluteTolerance = 0.0;
};

struct ContourMessage
{
  enum class Level
  {
    Warning,
    Error
  };
  Level Severity = Level::Warning;
  std::string Text;
};

/// The exchanges a piece of a run split among processes needs, beyond
/// PieceOfRun::Sum. Unset: the piece decides alone and reports itself only.
struct PieceExchange
{
  std::function<double(double)> Max;
  /// Every piece's vector, in piece order.
  std::function<std::vector<std::vector<double>>(const std::vector<double>&)> GatherAll;

  bool Agreed() const { return static_cast<bool>(this->GatherAll) && static_cast<bool>(this->Max); }
};

struct ContourResult
{
  enum class Outcome
  {
    Contoured, ///< outputs below are set
    Refused,   ///< bad input or parameters: an Error message says why
    Empty,     ///< its bounds prove the solid empty (a Warning says so); Report is the
               ///< empty surface's (Contour.cxx: ReportEmptySolid)
    Aborted    ///< progress asked to stop; outputs are incomplete
  };
  Outcome Status = Outcome::Refused;
  std::vector<ContourMessage> Messages; ///< in the order they arose
  /// Every input met the paper's assumptions.
  bool AssumptionsMet = true;
  SubdivisionParameters Parameters; ///< as asked (depth cap included; a piece's and the cells split first: Placed)
  /// The subdivision's runs again on the same lattice with the cells an
  /// earlier surface found wanting split first (CellRepair.h).
  int RepairRuns = 0;
  PlacedSubdivision Placed;         ///< grid, octree (cells failing the embedding check marked)
  ExtractionResult Extraction;
  EmbeddingReport Embedding;        ///< of this piece (as extracted, before any decimation)
  DecimationResult Decimation;      ///< what the decimation did (nothing unless Decimate)
  TopologyReport Topology;          ///< of the whole surface (all pieces)
  /// Whether the surface bounds a solid with its normals pointing out
  /// (SolidBoundary.h): checked on a closed, manifold, oriented surface in
  /// a run of one piece (OutwardChecked).
  OutwardReport Outward;
  bool OutwardChecked = false;
  ContourReport Report;
  /// Per triangle of the surface: the Id of the input solid whose surface it
  /// lies on (where the field at its centroid is decided), -1 on a cap of
  /// Bounds.
  ReleasableArray<std::int32_t> TriangleSolid;
  /// Per triangle of the surface: every point of it lies within this
  /// distance of the exact surface - its cell's proven bound
  /// (TriangleErrorBounds.h), or after Decimate the certified bound of the
  /// collapse that made it; NaN where the cell's patch failed the embedding
  /// check. Where the report is guaranteed, the largest is at most
  /// Report.HausdorffBound.
  std::vector<double> TriangleErrorBound;

  /// The octree and the statistics of the subdivision that was kept.
  const SubdivisionResult& Subdivision() const { return this->Placed.Result; }
  const TriangleMesh& Surface() const { return this->Extraction.Mesh; }
};

/// Contours `scene` (see the header comment). `progress` runs over [0, 1]:
/// input checks to 0.02, subdivision to 0.86, extraction to 0.94, embedding
/// check to 0.98, each repair round (if any) over half of what is left
/// before 0.995, topology report to 1; its answer true asks to abort (a
/// split run honours it only where the pieces agree, after a placement).
ContourResult Contour(ContourScene scene, const ContourParameters& parameters,
  const ParallelFor& parallelFor = SequentialFor, const ProgressCallback& progress = nullptr,
  const PieceOfRun& piece = PieceOfRun(), const PieceExchange& exchange = PieceExchange());

} // namespace tpc
