#include "Contour.h"

#include "ExactCell.h"
#include "ExactCellCriterion.h"
#include "PieceTopology.h"
#include "SelfIntersection.h"
#include "TopologyGuarantee.h"
#include "TriangleErrorBounds.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tpc
{
namespace
{
// Shares of the progress range (Contour.h).
constexpr double ChecksEnd = 0.02;
constexpr double SubdivisionEnd = 0.86;
constexpr double ExtractionEnd = 0.94;
constexpr double EmbeddingEnd = 0.98;

/// The run's state shared by its passes: messages, progress and aborts.
struct Run
{
  ContourResult& Result;
  const ProgressCallback& Progress;
  const PieceOfRun& Piece;
  const PieceExchange& Exchange;
  /// Ranks of a split run must all reach every collective call: there an
  /// abort is only honoured where the ranks agree on it, after a lattice
  /// placement (RunOnBestLatticePlacement); the other stages report only.
  bool MayAbort = true;
  bool AbortAsked = false;
  double Reported = 0.0;

  void Warn(const std::string& text) { this->Result.Messages.push_back({ ContourMessage::Level::Warning, text }); }
  bool Refuse(const std::string& text)
  {
    this->Result.Messages.push_back({ ContourMessage::Level::Error, text });
    this->Result.Status = ContourResult::Outcome::Refused;
    return false;
  }
  /// Progress over [lo, hi] of the run's range; asks to abort only where this
  /// piece may decide alone (or `ask` when the callee agrees on it itself).
  ProgressCallback Stage(double lo, double hi, bool ask)
  {
    if (!this->Progress)
    {
      return nullptr;
    }
    return [this, lo, hi, ask](double f) {
      // (Never backwards: the stages' own fractions, composed, may round
      // below the last report.)
      this->Reported = std::max(this->Reported, lo + (hi - lo) * f);
      const bool stop = this->Progress(this->Reported) && ask;
      this->AbortAsked = this->AbortAsked || stop;
      return stop;
    };
  }
  ProgressCallback Stage(double lo, double hi) { return this->Stage(lo, hi, this->MayAbort); }
  bool Aborted()
  {
    if (this->AbortAsked)
    {
      this->Result.Status = ContourResult::Outcome::Aborted;
    }
    return this->AbortAsked;
  }
  std::size_t Sum(std::size_t x) const { return this->Piece.SumOverPieces(x); }
  /// This process holds one piece and exchanges with the others.
  bool Collective() const { return this->Piece.Pieces > 1 && this->Exchange.Agreed(); }
};

/// Meshes beyond the coordinates their geometry is trusted with
/// (MeshSolid.h: WithinTrustedMeshRange) are refused, not contoured wrong.
bool CheckMeshRanges(const ContourScene& scene, Run& run)
{
  for (std::size_t m = 0; m < scene.Primitives.Meshes.size(); ++m)
  {
    const Box3& box = scene.Primitives.Meshes[m].Bounds();
    if (!WithinTrustedMeshRange(box))
    {
      std::string name = "A mesh input";
      for (const SceneInput& input : scene.Inputs)
      {
        name = input.Mesh == static_cast<int>(m) ? input.Name : name;
      }
      std::ostringstream text;
      text << name << " has coordinates up to " << box.Magnitude() << " and is " << box.Diagonal()
           << " across: the filter computes with meshes whose coordinates stay within " << LargestTrustedMeshCoordinate
           << " and that are at least " << SmallestTrustedMeshDiagonal
           << " across (their distances and normals take fourth powers of lengths). Scale the input (a "
              "vtkTransformFilter, ParaView's Transform) and the result back.";
      return run.Refuse(text.str());
    }
  }
  return true;
}

/// Repair verdicts: a mesh that is not closed has no inside (refused); one
/// violating the paper's assumptions is contoured without the guarantee.
bool CheckRepairVerdicts(const ContourScene& scene, Run& run)
{
  for (const SceneInput& input : scene.Inputs)
  {
    if (!input.Repair)
    {
      continue;
    }
    const std::string problems = input.Repair->Describe();
    if (!input.Repair->Closed())
    {
      return run.Refuse(input.Name + " is not a closed surface (" + problems +
        "), so it has no inside. Turn on FillHoles (Fill Holes, an advanced property in ParaView) to close its "
        "holes; if it is open only because its points do not quite meet (as in many STL files), merge them first "
        "(ParaView's Clean filter with a small Tolerance).");
    }
    if (!input.Repair->MeetsAssumptions())
    {
      run.Result.AssumptionsMet = false;
      run.Warn(input.Name + " violates the method's assumptions (" + problems +
        "); the surface is computed but TopologyGuaranteed will be 0.");
    }
    else if (input.Repair->Repaired())
    {
      // (Exactly coincident vertices are merged silently: a closed mesh with
      // one copy of each corner per face, as ParaView's Box source makes it,
      // needs no repair.)
      run.Warn(input.Name + " was repaired: " + problems + ".");
    }
  }
  return true;
}

/// Two input meshes with coincident faces whose solids touch there (faces
/// facing each other in a union or an intersection; flush faces where one
/// side is subtracted: a difference complements its later inputs) meet
/// without crossing: a tangential contact over an area, which no refinement
/// resolves and which refining to MaximumDepth turns into millions of cells.
bool CheckCoincidentFaces(const ContourScene& scene, const ParallelFor& parallelFor, Run& run)
{
  for (std::size_t a = 0; a < scene.Inputs.size(); ++a)
  {
    for (std::size_t b = a + 1; b < scene.Inputs.size(); ++b)
    {
      const SceneInput& ia = scene.Inputs[a];
      const SceneInput& ib = scene.Inputs[b];
      if (ia.Mesh < 0 || ib.Mesh < 0)
      {
        continue;
      }
      const bool oneSubtracted = scene.Operation == CsgTerm::Op::Difference && a == 0; // (the minuend)
      const MeshSolid& ma = scene.Primitives.Meshes[static_cast<std::size_t>(ia.Mesh)];
      const MeshSolid& mb = scene.Primitives.Meshes[static_cast<std::size_t>(ib.Mesh)];
      const std::size_t touching = !ma.Bounds().Overlaps(mb.Bounds())
        ? 0
        : CountCoincidentFaces(ma.Points(), ma.Triangles(), mb.Points(), mb.Triangles(), !oneSubtracted, 100,
            parallelFor, run.Stage(0.0, ChecksEnd));
      if (run.Aborted())
      {
        return false;
      }
      if (touching > 0)
      {
        run.Result.AssumptionsMet = false;
        std::ostringstream text;
        text << ia.Name << " and " << ib.Name << " touch along coincident faces (" << touching
             << (touching >= 100 ? " or more" : "")
             << " pairs of triangles in one plane): their surfaces meet without crossing, a tangential contact "
                "that no refinement resolves. The surface is computed but TopologyGuaranteed will be 0; move one "
                "input slightly, or merge them into one mesh.";
        run.Warn(text.str());
      }
    }
  }
  return true;
}

/// The Id of the input each primitive belongs to (SceneInput::Id), by
/// primitive kind and index; primitives added later (the planes of Bounds)
/// belong to none.
struct PrimitiveOwners
{
  std::vector<std::int32_t> Quadrics, Meshes;

  explicit PrimitiveOwners(const ContourScene& scene)
    : Quadrics(scene.Primitives.Quadrics.size(), -1)
    , Meshes(scene.Primitives.Meshes.size(), -1)
  {
    for (std::size_t i = 0; i < scene.Inputs.size(); ++i)
    {
      const int id = scene.Inputs[i].Id >= 0 ? scene.Inputs[i].Id : static_cast<int>(i);
      this->Claim(scene.Inputs[i].Solid, id);
    }
  }
  std::int32_t Of(const CsgLeaf& leaf) const
  {
    const auto& owners = leaf.Kind == PrimitiveKind::Mesh ? this->Meshes : this->Quadrics;
    return leaf.Primitive < owners.size() ? owners[leaf.Primitive] : -1;
  }

private:
  void Claim(const CsgTerm& term, std::int32_t id)
  {
    if (term.Operation == CsgTerm::Op::Primitive)
    {
      auto& owners = term.Kind == PrimitiveKind::Mesh ? this->Meshes : this->Quadrics;
      owners[static_cast<std::size_t>(term.PrimitiveIndex)] = id;
    }
    for (const CsgTerm& operand : term.Operands)
    {
      this->Claim(operand, id);
    }
  }
};

/// The input each triangle lies on: the leaf of its cell's expression that
/// decides the field at the triangle's centroid (the only leaf in most cells).
ReleasableArray<std::int32_t> TriangleSolids(const AdaptiveOctree& octree, const TriangleMesh& mesh,
  const PrimitiveSet& primitives, const PrimitiveOwners& owners, const ParallelFor& parallelFor)
{
  ReleasableArray<std::int32_t> solids;
  solids.resize(mesh.Triangles.size());
  parallelFor(mesh.Triangles.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
    {
      const CsgExpression& e = *octree.Expressions[mesh.TriangleCell[t]];
      int leaf = static_cast<int>(e.Root());
      if (e.NodeAt(e.Root()).NodeKind != CsgExpression::Node::Kind::Leaf)
      {
        const Triangle& tri = mesh.Triangles[t];
        e.Value((mesh.Points[tri[0]] + mesh.Points[tri[1]] + mesh.Points[tri[2]]) * (1.0 / 3.0), primitives, &leaf);
      }
      solids[t] = owners.Of(e.NodeAt(static_cast<std::size_t>(leaf)).LeafData);
    }
  });
  return solids;
}

CsgTerm FoldInputs(const ContourScene& scene)
{
  CsgTerm term = scene.Inputs.front().Solid;
  for (std::size_t i = 1; i < scene.Inputs.size(); ++i)
  {
    term = CsgTerm::Combine(scene.Operation, { std::move(term), scene.Inputs[i].Solid });
  }
  return term;
}

/// The box to contour: Bounds, else Region, else the solid's bounding box.
std::optional<Box3> ChooseDomain(const CsgTerm& solid, const ContourScene& scene, const ContourParameters& p, Run& run)
{
  Box3 domain;
  if (p.Bounds)
  {
    domain = *p.Bounds;
  }
  else
  {
    const SolidBounds sb = solid.Bounds(scene.Primitives);
    if (sb.Empty)
    {
      run.Warn("The solid is empty: nothing to contour.");
      run.Result.Status = ContourResult::Outcome::Empty;
      return std::nullopt;
    }
    if (!sb.Bounded() && !p.Region)
    {
      run.Refuse("The solid is unbounded (e.g. a plane or a cylinder is not intersected with a bounded solid): "
                 "set Bounds to the region to contour.");
      return std::nullopt;
    }
    domain = sb.Box;
    if (p.Region)
    {
      // (The lattice extends 5 % beyond the Region; a solid's box derived
      // from its primitives may exceed a Region drawn at the solid's faces by
      // rounding, hence the 1 % slack.)
      const Box3 r = p.Region->Grown(0.01);
      const bool inside = sb.Bounded() && r.Contains(domain.lo) && r.Contains(domain.hi);
      if (!inside)
      {
        run.Refuse("The Region does not contain the solid: the surface outside it would be lost; clip with Bounds "
                   "instead.");
        return std::nullopt;
      }
      domain = *p.Region;
    }
  }
  const double diagonal = domain.Diagonal();
  if (!(diagonal > 0.0) || !std::isfinite(diagonal))
  {
    std::ostringstream text;
    text << "The domain is degenerate (diagonal " << diagonal << "): check Bounds.";
    run.Refuse(text.str());
    return std::nullopt;
  }
  return domain;
}

/// The inputs' own checks (Verify), over the domain grown by 10 %.
bool VerifyInputs(const ContourScene& scene, const Box3& domain, Run& run)
{
  const Box3 sampleBox = domain.Grown(0.1);
  for (const SceneInput& input : scene.Inputs)
  {
    const std::string error = input.Verify ? input.Verify(scene.Primitives, input.Solid, sampleBox) : std::string();
    if (!error.empty())
    {
      return run.Refuse(error);
    }
  }
  return true;
}

/// Whether `value` - the Tolerance asked, or that in world units - is
/// positive and finite; else the run is refused, naming the Tolerance asked.
bool ToleranceUsable(double value, const ContourParameters& p, Run& run)
{
  if (value > 0.0 && std::isfinite(value))
  {
    return true;
  }
  std::ostringstream text;
  text << "Tolerance must be positive (got " << p.Tolerance << ").";
  return run.Refuse(text.str());
}

/// Grows `box` by the boxes of the bounded, non-empty terms of `term`, the
/// largest ones (a term's own where it has one, else its operands').
void AddBoundedTerms(const CsgTerm& term, const PrimitiveSet& primitives, std::optional<Box3>& box)
{
  const SolidBounds b = term.Bounds(primitives);
  if (b.Bounded() && !b.Empty)
  {
    const Box3 before = box ? *box : b.Box;
    const Vec3 corners[4] = { b.Box.lo, b.Box.hi, before.lo, before.hi };
    box = BoundsOf(corners, 4);
    return;
  }
  for (const CsgTerm& operand : term.Operands)
  {
    AddBoundedTerms(operand, primitives, box);
  }
}

/// The report of a solid its bounds prove empty (ChooseDomain): its surface
/// is empty, and so is the output, exactly - the same report as a run whose
/// cells all turn out inside or outside (guaranteed where the inputs meet
/// the assumptions; 0 components, genus 0, Hausdorff distance 0). The
/// bounds are those of the core's description of each input, so the
/// inputs' own checks (Verify) run first, over the box of its bounded terms
/// (the spheres of an intersection of spheres apart); where none is, an
/// input with a check goes unchecked and the guarantee is not given. The tolerance in world units is that of the
/// Region where it is relative and one is given, else unknown (NaN).
void ReportEmptySolid(const ContourScene& scene, const ContourParameters& p, Run& run)
{
  ContourResult& r = run.Result;
  std::optional<Box3> bounded;
  bool checked = true;
  for (const SceneInput& input : scene.Inputs)
  {
    AddBoundedTerms(input.Solid, scene.Primitives, bounded);
    checked = checked && !input.Verify;
  }
  if (bounded && !VerifyInputs(scene, *bounded, run))
  {
    return; // (refused: the messages say why)
  }
  ContourReport& report = r.Report;
  report.Components = report.Genus = report.EulerCharacteristic = 0;
  report.Closed = report.Manifold = report.Embedded = report.Outward = true; // (DecideGuarantee: empty)
  report.HausdorffBound = 0.0;
  report.AbsoluteTolerance = !p.ToleranceIsRelative ? p.Tolerance
    : p.Region                                     ? p.Tolerance * p.Region->Diagonal()
                                                   : std::nan("");
  // (Bounds are the same for every piece of a split run: each knows the
  // whole surface is empty.)
  GuaranteeConditions conditions;
  conditions.AssumptionsMet = r.AssumptionsMet && (checked || bounded);
  conditions.EveryCellResolved = conditions.LoopsConsistent = conditions.Embedded = true;
  conditions.WithinTolerance = conditions.WholeSurface = conditions.ClosedOrientedManifold = true;
  conditions.Outward = true;
  report.Guaranteed = TopologyGuaranteed(conditions);
}

/// Intersects `solid` with the planes of `box` it may reach (capping it
/// there) and returns the root domain: `box` grown by 1e-3 of its diagonal,
/// which keeps the cap faces off the grid's outer boundary without enlarging
/// the grid. A face whose side the solid's box (a superset of the solid,
/// CsgTerm::Bounds) lies strictly inside of cuts nothing: leaving it out
/// keeps the solid as it is - a mesh inside Bounds stays one mesh, with exact
/// cells and crease tiles (IsOneMesh), instead of a mesh cut by six planes
/// that never meet it.
Box3 ClipToBounds(CsgTerm& solid, PrimitiveSet& primitives, const Box3& box)
{
  const SolidBounds reach = solid.Bounds(primitives);
  // (Far beyond the bounds' rounding - exact for meshes, padded for boxes and
  // quadrics - relative to the box and to its coordinates' magnitude; were a
  // quadric's bounds off by more, the solid would poke out of Bounds by that
  // much, uncapped, still inside the root domain.)
  const double margin = 1e-9 * box.Diagonal() + 1e-12 * box.Magnitude();
  std::vector<CsgTerm> operands{ solid };
  const auto cap = [&](const Vec3& origin, const Vec3& normal) {
    primitives.Quadrics.push_back(Quadric::Plane(origin, normal));
    operands.push_back(CsgTerm::Primitive(static_cast<int>(primitives.Quadrics.size() - 1)));
  };
  for (int a = 0; a < 3; ++a)
  {
    Vec3 normal, origin;
    normal[a] = 1.0;
    origin[a] = box.hi[a];
    if (!(reach.Box.hi[a] < box.hi[a] - margin))
    {
      cap(origin, normal);
    }
    normal[a] = -1.0;
    origin[a] = box.lo[a];
    if (!(reach.Box.lo[a] > box.lo[a] + margin))
    {
      cap(origin, normal);
    }
  }
  if (operands.size() > 1)
  {
    solid = CsgTerm::Combine(CsgTerm::Op::Intersection, std::move(operands));
  }
  return box.Grown(1e-3);
}

/// What the subdivision is asked: the tolerance, the limits, exact cells for
/// one valid mesh, and a depth cap where the guarantee is lost anyway.
SubdivisionParameters ChooseSubdivisionParameters(
  const ContourParameters& p, const ImplicitScene& scene, const Box3& rootDomain, double tolerance, Run& run)
{
  SubdivisionParameters params;
  params.HausdorffTolerance = tolerance;
  params.MaximumDepth = p.MaximumDepth;
  params.MaximumNumberOfCells = std::max<std::size_t>(p.MaximumNumberOfCells, 8);
  // Remeshing one valid closed mesh: where the tests cannot resolve a cell at
  // the tolerance's size, its patch is the mesh itself (ExactCell.h).
  params.ExactCells = run.Result.AssumptionsMet && IsOneMesh(*scene.Expression);
  if (params.ExactCells)
  {
    const CsgExpression::Node& mesh = scene.Expression->NodeAt(scene.Expression->Root());
    params.SurfaceDiagonal = scene.Primitives.Meshes[mesh.LeafData.Primitive].Bounds().Diagonal();
  }
  if (!run.Result.AssumptionsMet)
  {
    // The guarantee is lost anyway, and self-intersections are complex at
    // every depth: refining them to MaximumDepth costs minutes and buys
    // nothing. Stop three levels below the cells the tolerance needs.
    const int toleranceLevel = ToleranceLevel(rootDomain, tolerance);
    if (toleranceLevel + 3 < params.MaximumDepth)
    {
      params.MaximumDepth = std::max(0, toleranceLevel + 3);
      std::ostringstream text;
      text << "The inputs violate the method's assumptions: refinement stops at depth " << params.MaximumDepth
           << " instead of MaximumDepth (" << p.MaximumDepth << ").";
      run.Warn(text.str());
    }
  }
  return params;
}

/// The extraction of the kept subdivision over progress [lo, mid] and the
/// exact embedding check of its surface over [mid, hi].
bool ExtractAndCheck(
  const ImplicitScene& scene, const ParallelFor& parallelFor, double lo, double mid, double hi, Run& run)
{
  ContourResult& r = run.Result;
  const AdaptiveOctree& octree = r.Placed.Result.Octree;
  r.Extraction = ExtractSurface(octree, scene, parallelFor, run.Stage(lo, mid));
  if (r.Extraction.Aborted || run.Aborted())
  {
    r.Status = ContourResult::Outcome::Aborted;
    return false;
  }
  r.Embedding = CheckEmbedding(octree, r.Extraction.Mesh, parallelFor, run.Stage(mid, hi));
  if (r.Embedding.Aborted || run.Aborted())
  {
    r.Status = ContourResult::Outcome::Aborted;
    return false;
  }
  return true;
}

/// Adds to `cells` this piece's cells found wanting (CellRepair.h) that a
/// next run can split: own error-bounded cells larger than the tolerance
/// whose final patch is not certified within it (as GatherCertifiedBound and
/// DecideGuarantee count them), and surface cells whose patch failed the
/// embedding check, above the depth limit (at it, a split cell would only
/// turn Unresolved).
void AddCellsFoundWanting(const ContourResult& r, CellsToSplit& cells)
{
  const AdaptiveOctree& octree = r.Placed.Result.Octree;
  const int deepest = std::min(r.Placed.Parameters.MaximumDepth, octree.Grid.MaxDepth);
  const auto add = [&](std::uint32_t n, SplitReason reason) {
    const OctreeNode& node = octree.Nodes[n];
    if (node.State == CellState::Surface && node.Level < deepest)
    {
      cells.Add({ node.Level, { node.Ijk[0], node.Ijk[1], node.Ijk[2] }, reason });
    }
  };
  for (const auto& [n, error] : r.Extraction.CellErrors)
  {
    const double diagonal = octree.Grid.CellDiagonal(octree.Nodes[n].Level);
    if (std::min(error, diagonal) > octree.HausdorffTolerance * (1.0 + 1e-9))
    {
      add(n, SplitReason::PatchNotCertified);
    }
  }
  for (const std::uint32_t n : r.Embedding.Cells)
  {
    add(n, SplitReason::PatchNotEmbedded);
  }
}

/// Adds `found` to `all`, and in a split run every other piece's too (each
/// piece's ghost ring holds cells another piece owns: every piece must split
/// the same cells). A collective call in a split run.
void ShareAmongPieces(const CellsToSplit& found, CellsToSplit& all, const Run& run)
{
  if (!run.Collective())
  {
    all.AddSerialized(found.Serialize());
    return;
  }
  for (const std::vector<double>& piece : run.Exchange.GatherAll(found.Serialize()))
  {
    all.AddSerialized(piece);
  }
}

/// A repair round's subdivision grows the tree by about this many cells per
/// cell it splits first (its children and the neighbours they make finer,
/// with room to spare): a round that could not fit under
/// MaximumNumberOfCells is not started, since a run stopped by the cell
/// limit loses the guarantee a repair was to restore.
constexpr std::size_t RepairCellsPerSplit = 64;

/// Repair rounds (CellRepair.h): while the surface has cells found wanting,
/// the subdivision runs again on the same lattice with them - and those of
/// the rounds before - split first, and its surface replaces the last (the
/// last one's tree and surface are freed first: one run's memory at a
/// time). Rounds, not one: a cell split so meets finer neighbours, and their
/// own final loops may lose points in turn. The rounds end when no new cell
/// is found wanting (one at the depth limit is not named), when a round
/// leaves cells unresolved, after `rounds`, or before a round that would not
/// fit under the cell limit; whatever the last surface is, the guarantee is
/// decided on it. Only where a repair can give the guarantee: the inputs
/// meet the assumptions and no cell is unresolved (repairs decide every
/// other cell alike, so they cannot resolve one). In a run split among
/// processes the pieces agree on every decision (the named cells are
/// gathered from all pieces, the other decisions summed), and without a
/// controller (pieces that cannot agree) no repair is made. Each round
/// reports progress over half of what is left of [its start, 0.995].
bool RepairCellsFoundWanting(const ImplicitScene& scene, const ParallelFor& parallelFor, int rounds, Run& run)
{
  ContourResult& r = run.Result;
  if (rounds <= 0 || !r.AssumptionsMet || (run.Piece.Pieces > 1 && !run.Collective()) ||
    r.Placed.UnresolvedCellsOfAllPieces > 0)
  {
    return true;
  }
  SubdivisionParameters& parameters = r.Placed.Parameters;
  for (int round = 0; round < rounds; ++round)
  {
    CellsToSplit found, next = parameters.SplitFirst;
    AddCellsFoundWanting(r, found);
    ShareAmongPieces(found, next, run);
    const std::size_t added = next.Size() - parameters.SplitFirst.Size(); // (the same in every piece)
    if (added == 0)
    {
      break;
    }
    const bool fits =
      r.Placed.Result.Octree.Nodes.size() + RepairCellsPerSplit * added <= parameters.MaximumNumberOfCells;
    if (run.Sum(fits ? 0 : 1) > 0)
    {
      run.Warn("No repair round was made for the " + std::to_string(added) +
        " cell(s) whose final patch is not certified or not embedded: it could exceed MaximumNumberOfCells.");
      break;
    }
    parameters.SplitFirst = std::move(next);
    const double lo = run.Reported, hi = lo + 0.5 * (0.995 - lo);
    const auto at = [lo, hi](double stage) { // (the first run's stages, mapped into [lo, hi])
      return lo + (hi - lo) * (stage - ChecksEnd) / (EmbeddingEnd - ChecksEnd);
    };
    r.Extraction = ExtractionResult();
    r.Embedding = EmbeddingReport();
    if (!ReleaseExpressions(r.Placed.Result.Octree, run.Stage(lo, lo), lo) || run.Aborted())
    {
      r.Status = ContourResult::Outcome::Aborted;
      return false;
    }
    r.Placed.Result = SubdivisionResult();
    r.Placed.Result = RunTopologyPreservingSubdivision(
      scene, r.Placed.Grid, parameters, parallelFor, run.Stage(lo, at(SubdivisionEnd)));
    if (r.Placed.Result.Aborted || run.Aborted())
    {
      r.Status = ContourResult::Outcome::Aborted;
      return false;
    }
    r.Placed.UnresolvedCellsOfAllPieces = run.Sum(r.Placed.Result.UnresolvedCells);
    ++r.RepairRuns;
    if (!ExtractAndCheck(scene, parallelFor, at(SubdivisionEnd), at(ExtractionEnd), hi, run))
    {
      return false;
    }
    if (r.Placed.UnresolvedCellsOfAllPieces > 0)
    {
      break;
    }
  }
  return true;
}

/// Subdivision on the best lattice placement, extraction and the exact
/// embedding check, repaired where cells were found wanting; the cells
/// that still fail the embedding check are marked in the octree.
bool SubdivideAndExtract(const ImplicitScene& scene, const Box3& rootDomain, int placements,
  int repairRounds, const ParallelFor& parallelFor, Run& run)
{
  ContourResult& r = run.Result;
  r.Placed = RunOnBestLatticePlacement(scene, rootDomain, r.Parameters, placements, parallelFor,
    run.Stage(ChecksEnd, SubdivisionEnd, true), run.Piece);
  if (r.Placed.Result.Aborted)
  {
    r.Status = ContourResult::Outcome::Aborted;
    return false;
  }
  if (run.Collective())
  {
    // (The pieces agreed not to stop - RunOnBestLatticePlacement: an abort
    // asked of this piece after the last agreement, while a discarded run
    // was freed, would make it leave the collective calls below alone.)
    run.AbortAsked = false;
  }
  if (!ExtractAndCheck(scene, parallelFor, SubdivisionEnd, ExtractionEnd, EmbeddingEnd, run) ||
    !RepairCellsFoundWanting(scene, parallelFor, repairRounds, run))
  {
    return false;
  }
  AdaptiveOctree& octree = r.Placed.Result.Octree;
  for (const std::uint32_t n : r.Embedding.Cells)
  {
    OctreeNode& node = octree.Nodes[n];
    node.State = CellState::Unresolved;
    node.Reason = node.FailedTest = SplitReason::PatchNotEmbedded;
  }
  return true;
}

/// The certified decimation (CertifiedDecimation.h), where what it rests on
/// holds: an embedded surface (the exact check) in which every cell closed
/// its loops and has its patch, so that each triangle's cell bound holds
/// (TriangleErrorBounds.h); and a run in one piece, since a split run's
/// seams are shared with other processes.
void DecimateSurface(ContourResult& r, double tolerance, const ExactMesh& surface, const ParallelFor& parallelFor,
  Run& run)
{
  const ExtractionResult& e = r.Extraction;
  if (run.Piece.Pieces != 1)
  {
    r.Messages.push_back({ ContourMessage::Level::Warning,
      "Decimate is not applied in a piece of a distributed run (the pieces' seams are shared with other "
      "processes): the surface is as extracted. Run in one process to decimate." });
    return;
  }
  if (!r.Embedding.Embedded() || e.InconsistentCells != 0 || e.CellsWithoutPatch != 0)
  {
    r.Messages.push_back({ ContourMessage::Level::Warning,
      "Decimate is not applied: the extracted surface is not embedded or has cells without a patch, and the "
      "decimation's certificates start from an embedded surface with every cell's bound (see the guarantee's "
      "reasons); the surface is as extracted." });
    return;
  }
  DecimationParameters parameters;
  parameters.Tolerance = tolerance;
  parameters.Progress = run.Stage(EmbeddingEnd, EmbeddingEnd);
  r.Decimation =
    DecimateCertified(r.Extraction.Mesh, r.TriangleErrorBound, r.TriangleSolid, parameters, surface, parallelFor);
  if (r.Decimation.NotAClosedManifold)
  {
    r.Messages.push_back({ ContourMessage::Level::Warning,
      "Decimate is not applied: the extracted surface is not a closed, consistently oriented manifold (see the "
      "topology report), which the decimation's link condition and certificates assume; the surface is as "
      "extracted. An embedded surface whose cells all have patches should be one: please report this." });
    return;
  }
  if (r.Decimation.Collapses == 0)
  {
    return;
  }
  // Each collapse was checked exactly against every triangle it could meet;
  // the whole surface is checked once more, exactly, so that Embedded
  // describes the surface delivered whatever the bookkeeping did.
  const TriangleMesh& mesh = r.Extraction.Mesh;
  const std::size_t improper = CountSelfIntersections(std::vector<Vec3>(mesh.Points.begin(), mesh.Points.end()),
    std::vector<std::array<std::uint32_t, 3>>(mesh.Triangles.begin(), mesh.Triangles.end()), 1, parallelFor);
  r.Embedding.ImproperPairs += improper;
}

/// Pairs of this piece's seam triangles meeting improperly those of the
/// pieces after it (pieces' triangles can only meet across the seams:
/// SurfaceEmbedding.h).
std::size_t CountImproperPairsAcrossSeams(const ContourResult& r, const Run& run)
{
  const std::vector<std::vector<double>> seams =
    run.Exchange.GatherAll(SeamTriangles(r.Placed.Result.Octree, r.Extraction.Mesh));
  const std::vector<double>& mine = seams[static_cast<std::size_t>(run.Piece.Piece)];
  std::size_t pairs = 0;
  for (std::size_t other = static_cast<std::size_t>(run.Piece.Piece) + 1; other < seams.size(); ++other)
  {
    pairs += CountImproperSeamPairs(mine, seams[other]);
  }
  return pairs;
}

/// Components of the whole surface: each piece's counts summed, components
/// joined across the seams (PieceTopology.h).
TopologyReport WholeTopology(const ContourResult& r, const Run& run)
{
  if (!run.Collective())
  {
    return r.Topology;
  }
  std::vector<double> all;
  for (const std::vector<double>& piece : run.Exchange.GatherAll(DescribePiece(r.Extraction.Mesh).Serialize()))
  {
    all.insert(all.end(), piece.begin(), piece.end());
  }
  return CombinePieces(PieceSeams::DeserializeAll(all));
}

/// What the embedding check found over all pieces.
struct EmbeddingOfAllPieces
{
  std::size_t NotEmbeddedPieces = 0;
  std::size_t ImproperPairs = 0;
  std::size_t CoincidentVertices = 0;
  std::size_t Degenerate = 0;
  std::size_t BlamedCells = 0;
};

EmbeddingOfAllPieces SumEmbedding(const ContourResult& r, const Run& run)
{
  const std::size_t seamPairs = run.Collective() ? CountImproperPairsAcrossSeams(r, run) : 0;
  const EmbeddingReport& e = r.Embedding;
  EmbeddingOfAllPieces all;
  all.NotEmbeddedPieces = run.Sum(e.Embedded() && seamPairs == 0 ? 0 : 1);
  all.ImproperPairs = run.Sum(e.ImproperPairs + seamPairs);
  all.CoincidentVertices = run.Sum(e.CoincidentVertices);
  all.Degenerate = run.Sum(e.DegenerateTriangles + e.TrianglesOutsideCells);
  all.BlamedCells = run.Sum(e.Cells.size());
  return all;
}

/// The subdivision's statistics over all pieces.
SubdivisionResult SumSubdivision(const ContourResult& r, const Run& run)
{
  const SubdivisionResult& sub = r.Placed.Result;
  SubdivisionResult all;
  all.UnresolvedCells = r.Placed.UnresolvedCellsOfAllPieces;
  all.FacingSurfaceCells = run.Sum(sub.FacingSurfaceCells);
  all.DepthLimitReached = run.Sum(sub.DepthLimitReached ? 1 : 0) > 0;
  all.CellLimitReached = run.Sum(sub.CellLimitReached ? 1 : 0) > 0;
  all.PlanarSurfaceCells = run.Sum(sub.PlanarSurfaceCells);
  all.ExactCells = run.Sum(sub.ExactCells);
  for (int reason = 0; reason < SplitReasonCount; ++reason)
  {
    all.UnresolvedByReason[reason] = run.Sum(sub.UnresolvedByReason[reason]);
  }
  all.HausdorffBound = run.Collective() ? run.Exchange.Max(sub.HausdorffBound) : sub.HausdorffBound;
  return all;
}

/// Why the guarantee does not hold, for the cells a limit stopped.
void DescribeUnresolvedCells(std::ostringstream& why, const SubdivisionResult& all, const ContourResult& r,
  const ContourParameters& p)
{
  why << " " << all.UnresolvedCells << " surface cell(s) were stopped";
  if (all.DepthLimitReached)
  {
    why << " by MaximumDepth (" << r.Parameters.MaximumDepth << ")";
  }
  if (all.CellLimitReached)
  {
    why << " by MaximumNumberOfCells (" << p.MaximumNumberOfCells << ")";
  }
  why << " with a test still failing:";
  for (int reason = 1; reason < SplitReasonCount; ++reason)
  {
    if (all.UnresolvedByReason[reason] > 0)
    {
      why << " " << SplitReasonName(static_cast<SplitReason>(reason)) << " " << all.UnresolvedByReason[reason] << ";";
    }
  }
  if (all.FacingSurfaceCells > 0)
  {
    why << " " << all.FacingSurfaceCells
        << " of them because two surfaces face each other there closer than the finest cell (" << r.Placed.FinestCell
        << ") and no plane between them was found: solids touching along a face or at a point, a gap narrower "
           "than a few lattice spacings ("
        << std::ldexp(r.Placed.Grid.RootSize, -r.Placed.Grid.MaxDepth)
        << "), or the edge of a very thin wedge, which no refinement separates (SplitReason 10, SURFACES_TOO_CLOSE);";
  }
  if (r.Placed.PlacementsTried > 1)
  {
    why << " (best of " << r.Placed.PlacementsTried << " lattice placements tried);";
  }
  why << " they are marked CellState=3 in the grid output.";
  if (all.UnresolvedCells > all.FacingSurfaceCells)
  {
    why << " Tangential contact between primitives never passes the tests; otherwise raise the limits.";
  }
  if (all.FacingSurfaceCells > 0)
  {
    why << " Overlap touching solids, or move them apart, by more than a few lattice spacings";
    // (At the default depth the finest cell is the lattice's: raising it is no remedy.)
    why << (p.MaximumDepth < DeepestMaximumDepth ? "; for a thin wedge, raise MaximumDepth." : ".");
  }
}

/// TopologyGuaranteed, and the report: the conditions of
/// TopologyGuarantee.h gathered over the pieces. Says why, once, when they
/// do not all hold.
void DecideGuarantee(ContourResult& r, const ContourParameters& p, double tolerance, const Run& run)
{
  const SubdivisionResult all = SumSubdivision(r, run);
  const EmbeddingOfAllPieces embedding = SumEmbedding(r, run);
  const std::size_t inconsistent = run.Sum(r.Extraction.InconsistentCells);
  const std::size_t withoutPatch = run.Sum(r.Extraction.CellsWithoutPatch);
  r.Topology = WholeTopology(r, run);
  const TopologyReport& whole = r.Topology;
  ContourReport& report = r.Report;
  // The cells bounded by their size and the cells certified on their patches
  // (QuadricCellError.h); surface in a cell without a patch is missing from
  // the output: no bound.
  const ExtractionResult& e = r.Extraction;
  const double certified = run.Collective() ? run.Exchange.Max(e.CertifiedBound) : e.CertifiedBound;
  const std::size_t uncertified = run.Sum(e.UncertifiedCells);
  // (A decimated surface's bound is its triangles' largest e_t, at least
  // their cells' bounds: CertifiedDecimation.h.)
  report.HausdorffBound =
    withoutPatch == 0 ? std::max({ all.HausdorffBound, certified, r.Decimation.Bound }) : std::nan("");
  // (NaN compares false: a missing bound withdraws the guarantee too.)
  const bool withinTolerance = report.HausdorffBound <= tolerance * (1.0 + 1e-9);
  report.Embedded = embedding.NotEmbeddedPieces == 0;
  report.PlanarCells = static_cast<long long>(all.PlanarSurfaceCells);
  report.ExactCells = static_cast<long long>(all.ExactCells);
  report.AbsoluteTolerance = tolerance;
  report.Components = whole.Components;
  report.EulerCharacteristic = whole.EulerCharacteristic;
  report.UnresolvedCells = static_cast<long long>(all.UnresolvedCells);
  const bool empty = whole.Faces == 0;
  // (The empty surface - the boundary of an empty solid - is closed and
  // manifold, of genus 0, though TopologyReport counts a closed surface only
  // where it has faces.)
  report.Closed = empty || whole.Closed;
  report.Manifold = empty || whole.Manifold;
  report.Genus = empty ? 0 : whole.Genus;
  // (A split run's pieces each hold part of the surface: there the outward
  // orientation rests on the extraction's construction - SolidBoundary.h -
  // and no collapse runs.)
  const bool outward = empty || run.Piece.Pieces > 1 || (r.OutwardChecked && r.Outward.Outward());
  report.Outward = outward;
  GuaranteeConditions conditions;
  conditions.AssumptionsMet = r.AssumptionsMet;
  conditions.EveryCellResolved = all.UnresolvedCells == 0;
  conditions.LoopsConsistent = inconsistent == 0;
  conditions.Embedded = report.Embedded;
  conditions.WithinTolerance = withinTolerance;
  conditions.WholeSurface = run.Piece.Pieces == 1 || run.Collective();
  conditions.ClosedOrientedManifold = empty || (whole.Closed && whole.Manifold && whole.Oriented);
  conditions.Outward = outward;
  report.Guaranteed = TopologyGuaranteed(conditions);
  if (run.Collective() && run.Piece.Piece != 0) // (one piece says it)
  {
    return;
  }
  if (empty && conditions.WholeSurface && all.UnresolvedCells == 0 && withoutPatch == 0)
  {
    // (As where the solid's bounds prove it, ChooseDomain: the cells proved it.)
    r.Messages.push_back({ ContourMessage::Level::Warning,
      p.Bounds ? "The solid does not reach into Bounds: nothing to contour."
               : "The solid is empty: nothing to contour." });
  }
  if (report.Guaranteed)
  {
    return;
  }
  std::ostringstream why;
  why << "The topology guarantee does not hold:";
  if (!r.AssumptionsMet)
  {
    why << " the inputs violate the method's assumptions (see the warnings above);";
  }
  if (all.UnresolvedCells > 0)
  {
    DescribeUnresolvedCells(why, all, r, p);
  }
  if (embedding.NotEmbeddedPieces > 0)
  {
    why << " the surface is not embedded: " << embedding.ImproperPairs
        << " pair(s) of triangles meet other than in a shared edge or vertex, " << embedding.CoincidentVertices
        << " vertex pair(s) coincide, " << embedding.Degenerate
        << " triangle(s) are degenerate (exact test of the output)";
    if (embedding.BlamedCells > 0)
    {
      why << "; their " << embedding.BlamedCells
          << " cell(s) are marked CellState=3, SplitReason 11 (PATCH_NOT_EMBEDDED).";
    }
    else if (r.Decimation.Collapses > 0)
    {
      // (Found by the check of the decimated surface, which no cell made.)
      why << ", in the decimated surface (each collapse was checked exactly against every triangle it could "
             "meet, so this is a defect: please report it); turn Decimate off for the surface as extracted.";
    }
    else
    {
      why << ".";
    }
  }
  if (inconsistent > 0)
  {
    why << " " << inconsistent << " cell(s) gave inconsistent loops.";
  }
  if (!conditions.ClosedOrientedManifold && conditions.WholeSurface) // (a lone piece is open along its seams)
  {
    why << " the surface is not a closed, consistently oriented manifold (" << whole.BoundaryEdges
        << " boundary edge(s), " << whole.NonManifoldEdges << " non-manifold edge(s), " << whole.NonManifoldVertices
        << " non-manifold vertex(es)" << (whole.Oriented ? "" : ", inconsistently oriented") << ").";
  }
  if (!conditions.WholeSurface)
  {
    why << " this is piece " << run.Piece.Piece << " of " << run.Piece.Pieces
        << " of a split run whose pieces do not agree through a controller: run them under MPI as one job.";
  }
  if (r.OutwardChecked && !r.Outward.Outward())
  {
    why << " the surface is not the boundary of a solid: " << r.Outward.InsideOut
        << " of its components are inside out (oriented against the solids they lie in) and "
        << r.Outward.Undecided << " enclose a volume too small to tell"
        << (r.Decimation.Collapses > 0 ? " after decimating (a defect: please report it; turn Decimate off for the "
                                         "surface as extracted)."
                                       : " (a defect: please report it).");
  }
  if (!withinTolerance && all.UnresolvedCells == 0)
  {
    why << " the proven Hausdorff bound (" << report.HausdorffBound << ") exceeds the tolerance (" << tolerance
        << "): " << uncertified << " cell(s) kept larger than the tolerance could not certify their patch's error.";
  }
  r.Messages.push_back({ ContourMessage::Level::Warning, why.str() });
}
} // namespace

ContourResult Contour(ContourScene scene, const ContourParameters& parameters, const ParallelFor& parallelFor,
  const ProgressCallback& progress, const PieceOfRun& piece, const PieceExchange& exchange)
{
  ContourResult result;
  Run run{ result, progress, piece, exchange };
  run.MayAbort = !run.Collective();
  if (scene.Inputs.empty())
  {
    run.Refuse("No solid to contour: connect closed triangle meshes to the input and/or set an ImplicitFunction "
               "(the solid is where it is negative).");
    return result;
  }
  // (The range first: beyond it the repair's own findings mean nothing.)
  if (!CheckMeshRanges(scene, run) || !CheckRepairVerdicts(scene, run) || !CheckCoincidentFaces(scene, parallelFor, run))
  {
    return result;
  }
  if (!ToleranceUsable(parameters.Tolerance, parameters, run))
  {
    return result;
  }
  CsgTerm solid = FoldInputs(scene);
  const std::optional<Box3> domain = ChooseDomain(solid, scene, parameters, run);
  if (result.Status == ContourResult::Outcome::Empty)
  {
    ReportEmptySolid(scene, parameters, run);
    return result;
  }
  if (!domain || !VerifyInputs(scene, *domain, run))
  {
    return result;
  }
  const double tolerance =
    parameters.ToleranceIsRelative ? parameters.Tolerance * domain->Diagonal() : parameters.Tolerance;
  if (!ToleranceUsable(tolerance, parameters, run))
  {
    return result;
  }
  // A margin of 5 % keeps the surface away from the grid's outer boundary;
  // with Bounds, the root domain is the Bounds grown by 1e-3, and the solid is
  // capped where it reaches them (ClipToBounds).
  const PrimitiveOwners owners(scene);
  const Box3 rootDomain =
    parameters.Bounds ? ClipToBounds(solid, scene.Primitives, *domain) : domain->Grown(0.05);
  ImplicitScene implicitScene{ std::move(scene.Primitives), CsgExpression::FromTerm(solid) };
  result.Parameters = ChooseSubdivisionParameters(parameters, implicitScene, rootDomain, tolerance, run);
  // Another lattice placement usually resolves cells a first one leaves to
  // the depth limit (a crease a hair from a lattice plane); inputs violating
  // the method's assumptions are not worth the retries.
  const int placements =
    result.AssumptionsMet && (piece.Pieces == 1 || run.Collective()) ? parameters.LatticePlacements : 1;
  if (!SubdivideAndExtract(implicitScene, rootDomain, placements, parameters.RepairRounds, parallelFor, run))
  {
    return result;
  }
  result.TriangleSolid = TriangleSolids(
    result.Placed.Result.Octree, result.Extraction.Mesh, implicitScene.Primitives, owners, parallelFor);
  result.TriangleErrorBound = TriangleErrorBounds(result.Placed.Result.Octree, result.Extraction);
  if (parameters.Decimate)
  {
    // (Where the exact surface is one input mesh - one mesh leaf, not capped
    // by Bounds - the collapses are measured against it: CertifiedDecimation.h,
    // Against the mesh.)
    ExactMesh surface;
    if (IsOneMesh(*implicitScene.Expression))
    {
      const CsgExpression& e = *implicitScene.Expression;
      surface.Mesh = &implicitScene.Primitives.Meshes[e.NodeAt(e.Root()).LeafData.Primitive];
    }
    DecimateSurface(result, tolerance, surface, parallelFor, run);
    if (run.Aborted())
    {
      return result;
    }
  }
  result.Topology =
    ComputeTopologyReport(result.Extraction.Mesh, parallelFor, run.Stage(EmbeddingEnd, 1.0));
  if (run.Aborted())
  {
    return result;
  }
  const TopologyReport& surface = result.Topology;
  // (Ray parity means nothing on a surface that is not embedded; the
  // guarantee is withheld there anyway.)
  if (piece.Pieces == 1 && surface.Closed && surface.Manifold && surface.Oriented && result.Embedding.Embedded())
  {
    result.Outward = CheckOutward(result.Extraction.Mesh, parallelFor);
    result.OutwardChecked = true;
  }
  DecideGuarantee(result, parameters, tolerance, run);
  result.Status = ContourResult::Outcome::Contoured;
  return result;
}

} // namespace tpc
