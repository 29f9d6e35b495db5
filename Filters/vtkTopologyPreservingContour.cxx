#include "vtkTopologyPreservingContour.h"

#include "ImplicitFunctionToCsg.h"
#include "OctreeToHyperTreeGrid.h"
#include "PolyDataToMesh.h"
#include "SelfIntersection.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkHyperTreeGrid.h"
#include "vtkIdTypeArray.h"
#include "vtkImplicitFunction.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkMultiProcessController.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "ExactCell.h"
#include "PieceTopology.h"
#include "SurfaceEmbedding.h"
#include "SurfaceExtraction.h"
#include "TopologyPreservingSubdivision.h"
#include "TopologyReport.h"

#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkTopologyPreservingContour);
vtkCxxSetObjectMacro(vtkTopologyPreservingContour, ImplicitFunction, vtkImplicitFunction);

namespace
{
void ParallelForSMP(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body)
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(count),
    [&](vtkIdType begin, vtkIdType end) {
      body(static_cast<std::size_t>(begin), static_cast<std::size_t>(end));
    });
}

struct Report
{
  long long Components = 0;
  long long Genus = -1;
  long long Euler = 0;
  int Guaranteed = 0;
  long long Unresolved = 0;
  int Closed = 0;
  int Manifold = 0;
  int Embedded = 0;
  long long PlanarCells = 0;
  long long ExactCells = 0;
  double HausdorffBound = 0.0;
  double Tolerance = 0.0;
};

void AddReport(vtkDataObject* output, const Report& r)
{
  vtkFieldData* fd = output->GetFieldData();
  auto addInt = [fd](const char* name, long long v) {
    vtkNew<vtkIntArray> a;
    a->SetName(name);
    a->InsertNextValue(static_cast<int>(v));
    fd->AddArray(a);
  };
  addInt("Components", r.Components);
  addInt("Genus", r.Genus);
  addInt("EulerCharacteristic", r.Euler);
  addInt("TopologyGuaranteed", r.Guaranteed);
  addInt("UnresolvedCells", r.Unresolved);
  addInt("Closed", r.Closed);
  addInt("Manifold", r.Manifold);
  addInt("Embedded", r.Embedded);
  addInt("PlanarCells", r.PlanarCells);
  addInt("ExactCells", r.ExactCells);
  vtkNew<vtkDoubleArray> h;
  h->SetName("HausdorffBound");
  h->InsertNextValue(r.HausdorffBound);
  fd->AddArray(h);
  vtkNew<vtkDoubleArray> t;
  t->SetName("AbsoluteTolerance");
  t->InsertNextValue(r.Tolerance);
  fd->AddArray(t);
}
} // namespace

//------------------------------------------------------------------------------
vtkTopologyPreservingContour::vtkTopologyPreservingContour()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(2);
}

vtkTopologyPreservingContour::~vtkTopologyPreservingContour()
{
  this->SetImplicitFunction(nullptr);
}

vtkMTimeType vtkTopologyPreservingContour::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->ImplicitFunction)
  {
    t = std::max(t, this->ImplicitFunction->GetMTime());
  }
  return t;
}

int vtkTopologyPreservingContour::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

int vtkTopologyPreservingContour::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkHyperTreeGrid" : "vtkPolyData");
  return 1;
}

vtkHyperTreeGrid* vtkTopologyPreservingContour::GetGridOutput()
{
  return vtkHyperTreeGrid::SafeDownCast(this->GetOutputDataObject(0));
}

vtkPolyData* vtkTopologyPreservingContour::GetSurfaceOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

vtkTypeBool vtkTopologyPreservingContour::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inInfo, vtkInformationVector* outInfo)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_INFORMATION()))
  {
    // Pieces are trees of the root grid (ForestPartition.h).
    for (int i = 0; i < outInfo->GetNumberOfInformationObjects(); ++i)
    {
      outInfo->GetInformationObject(i)->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
    }
    return 1;
  }
  if (request->Has(vtkStreamingDemandDrivenPipeline::REQUEST_UPDATE_EXTENT()))
  {
    // Every piece needs whole solids: the exact inside test casts rays across
    // the whole mesh. So each rank asks its inputs for all of them (meshes
    // are small next to the grid and surface, which are split).
    for (int c = 0; c < this->GetNumberOfInputConnections(0); ++c)
    {
      vtkInformation* in = inInfo[0]->GetInformationObject(c);
      in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
      in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
      in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    }
    return 1;
  }
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
  {
    return this->RequestData(request, inInfo, outInfo);
  }
  return this->Superclass::ProcessRequest(request, inInfo, outInfo);
}

//------------------------------------------------------------------------------
int vtkTopologyPreservingContour::RequestData(
  vtkInformation*, vtkInformationVector** inInfo, vtkInformationVector* outInfo)
{
  vtkHyperTreeGrid* gridOut = vtkHyperTreeGrid::GetData(outInfo, 0);
  vtkPolyData* surfaceOut = vtkPolyData::GetData(outInfo, 1);
  if (!gridOut || !surfaceOut)
  {
    vtkErrorMacro("Output data objects are missing.");
    return 0;
  }
  Report report;
  auto clearOutputs = [&]() {
    gridOut->Initialize();
    surfaceOut->Initialize();
    AddReport(gridOut, Report());
    AddReport(surfaceOut, Report());
  };
  clearOutputs();
  // Progress over the stages: inputs [0, 0.1], subdivision [0.1, 0.85],
  // extraction [0.85, 0.95], topology report and grid output [0.95, 1]. Every long loop reports
  // in chunks, so Abort stops any stage within a chunk (a fraction of a
  // second); the outputs are then empty.
  // The piece requested (UpdatePiece, or the rank under pvbatch/pvserver):
  // this rank subdivides its slab of root trees and a ghost ring and outputs
  // its own trees (ForestPartition.h). With the global controller spanning
  // the pieces, decisions and the report are agreed through reductions;
  // without it each piece decides alone on one lattice placement (the
  // pieces still fit) and reports its own piece only.
  tpc::PieceOfRun piece;
  for (int port = 0; port < 2; ++port) // (UpdatePiece asks on port 0, a surface consumer on port 1)
  {
    vtkInformation* requested = outInfo->GetInformationObject(port);
    const int pieces = requested->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
    if (pieces > piece.Pieces)
    {
      piece.Pieces = pieces;
      piece.Piece = std::max(0, requested->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()));
    }
  }
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool collective = piece.Pieces > 1 && controller &&
    controller->GetNumberOfProcesses() == piece.Pieces && controller->GetLocalProcessId() == piece.Piece;
  piece.Sum = [controller, collective](std::size_t x) {
    if (!collective)
    {
      return x;
    }
    const vtkIdType in = static_cast<vtkIdType>(x);
    vtkIdType out = 0;
    controller->AllReduce(&in, &out, 1, vtkCommunicator::SUM_OP);
    return static_cast<std::size_t>(out);
  };
  if (piece.Pieces > 1 && !collective)
  {
    vtkWarningMacro("Piece " << piece.Piece << " of " << piece.Pieces
                             << " without a global controller over " << piece.Pieces
                             << " processes: the report describes this piece only.");
  }
  // Ranks of a split run must all reach every collective call: there an
  // abort is only honoured where the ranks agree on it, after a lattice
  // placement (RunOnBestLatticePlacement); the other stages report only.
  const bool mayAbort = !collective;
  auto stage = [this](double lo, double hi, bool ask = true) -> tpc::ProgressCallback {
    return [this, lo, hi, ask](double f) {
      this->UpdateProgress(lo + (hi - lo) * f);
      return ask && this->GetAbortExecute() != 0;
    };
  };
  auto stop = [this, mayAbort]() { return mayAbort && this->GetAbortExecute() != 0; };
  auto aborted = [&]() {
    clearOutputs();
    vtkWarningMacro("Aborted: outputs are empty.");
    return 1;
  };

  // The solids: one per mesh input, then the implicit function.
  tpc::ImplicitScene scene;
  std::vector<tpc::CsgTerm> solids;
  std::vector<int> meshInputs; // input connection of each mesh primitive
  tpc::CsgTerm implicitTerm;
  bool assumptionsMet = true;
  std::string error;
  const int connections = this->GetNumberOfInputConnections(0);
  for (int i = 0; i < connections; ++i)
  {
    vtkPolyData* mesh = vtkPolyData::GetData(inInfo[0], i);
    if (!mesh || mesh->GetNumberOfCells() == 0)
    {
      vtkWarningMacro("Input " << i << " is empty: it is ignored.");
      continue;
    }
    tpc::vtkadapter::MeshInput in;
    const bool converted = tpc::vtkadapter::ConvertPolyData(
      mesh, in, error, ParallelForSMP, stage(0.08 * i / connections, 0.08 * (i + 1) / connections, mayAbort));
    if (stop())
    {
      return aborted();
    }
    if (!converted)
    {
      vtkErrorMacro("Input " << i << " cannot be used as a solid: " << error << ".");
      return 1;
    }
    if (in.IgnoredLines > 0 || in.IgnoredVertices > 0)
    {
      vtkWarningMacro("Input " << i << ": " << in.IgnoredLines << " line and " << in.IgnoredVertices
                               << " vertex cells are ignored; only polygons bound the solid.");
    }
    const std::string problems = in.Repair.Describe();
    if (!in.Repair.Closed())
    {
      vtkErrorMacro("Input " << i << " is not a closed surface (" << problems
                             << "), so it has no inside. Close it first (for example with "
                                "vtkFillHolesFilter) or pass only closed solids.");
      return 1;
    }
    if (!in.Repair.MeetsAssumptions())
    {
      assumptionsMet = false;
      vtkWarningMacro("Input " << i << " violates the method's assumptions (" << problems
                               << "); the surface is computed but TopologyGuaranteed will be 0.");
    }
    else if (!problems.empty())
    {
      vtkWarningMacro("Input " << i << " was repaired: " << problems << ".");
    }
    scene.Primitives.Meshes.push_back(std::move(in.Solid));
    meshInputs.push_back(i);
    solids.push_back(tpc::CsgTerm::Mesh(static_cast<int>(scene.Primitives.Meshes.size() - 1)));
  }
  // Two inputs with coincident faces whose solids touch there (faces facing
  // each other in a union or an intersection; flush faces where one side is
  // subtracted: a difference complements its later inputs) meet without
  // crossing: a tangential contact over an area, which no refinement
  // resolves and which refining to MaximumDepth turns into millions of cells.
  for (std::size_t a = 0; a < scene.Primitives.Meshes.size(); ++a)
  {
    for (std::size_t b = a + 1; b < scene.Primitives.Meshes.size(); ++b)
    {
      const bool oneSubtracted = this->Operation == DIFFERENCE && a == 0; // (the first mesh is the minuend)
      const tpc::MeshSolid& ma = scene.Primitives.Meshes[a];
      const tpc::MeshSolid& mb = scene.Primitives.Meshes[b];
      const std::size_t touching = !ma.Bounds().Overlaps(mb.Bounds())
        ? 0
        : tpc::CountCoincidentFaces(ma.Points(), ma.Triangles(), mb.Points(), mb.Triangles(), !oneSubtracted,
            100, ParallelForSMP, stage(0.08, 0.1, mayAbort));
      if (stop())
      {
        return aborted();
      }
      if (touching > 0)
      {
        assumptionsMet = false;
        vtkWarningMacro("Inputs " << meshInputs[a] << " and " << meshInputs[b] << " touch along coincident faces ("
                                  << touching << (touching >= 100 ? " or more" : "")
                                  << " pairs of triangles in one plane): their surfaces meet without crossing, a "
                                     "tangential contact that no refinement resolves. The surface is computed but "
                                     "TopologyGuaranteed will be 0; move one input slightly, or merge them into "
                                     "one mesh.");
      }
    }
  }
  if (this->ImplicitFunction)
  {
    if (!tpc::vtkadapter::ConvertImplicitFunction(this->ImplicitFunction, scene.Primitives, implicitTerm, error))
    {
      vtkErrorMacro("Unsupported ImplicitFunction: " << error << ".");
      return 1;
    }
    solids.push_back(implicitTerm);
  }
  if (solids.empty())
  {
    vtkErrorMacro("No solid to contour: connect closed triangle meshes to the input and/or set an "
                  "ImplicitFunction (the solid is where it is negative).");
    return 1;
  }
  // Fold in order: ((S0 op S1) op ...) op F.
  const tpc::CsgTerm::Op op = this->Operation == INTERSECTION ? tpc::CsgTerm::Op::Intersection
    : this->Operation == DIFFERENCE                          ? tpc::CsgTerm::Op::Difference
                                                             : tpc::CsgTerm::Op::Union;
  tpc::CsgTerm term = solids.front();
  for (std::size_t i = 1; i < solids.size(); ++i)
  {
    term = tpc::CsgTerm::Combine(op, { std::move(term), std::move(solids[i]) });
  }

  // Domain.
  const bool userBounds = this->Bounds[0] <= this->Bounds[1] &&
    this->Bounds[2] <= this->Bounds[3] && this->Bounds[4] <= this->Bounds[5];
  tpc::Box3 domain;
  if (userBounds)
  {
    for (int a = 0; a < 3; ++a)
    {
      domain.lo[a] = this->Bounds[2 * a];
      domain.hi[a] = this->Bounds[2 * a + 1];
    }
  }
  else
  {
    const tpc::SolidBounds sb = term.Bounds(scene.Primitives);
    if (sb.Empty)
    {
      vtkWarningMacro("The solid is empty: nothing to contour.");
      return 1;
    }
    if (!sb.Bounded())
    {
      vtkErrorMacro("The solid is unbounded (e.g. a plane or a cylinder is not intersected "
                    "with a bounded solid): set Bounds to the region to contour.");
      return 1;
    }
    domain = sb.Box;
  }
  const double diagonal = domain.Diagonal();
  if (!(diagonal > 0.0) || !std::isfinite(diagonal))
  {
    vtkErrorMacro("The domain is degenerate (diagonal " << diagonal << "): check Bounds.");
    return 1;
  }

  // Guard against subclasses whose evaluation the converter does not know.
  if (this->ImplicitFunction)
  {
    tpc::Box3 sampleBox = domain;
    for (int a = 0; a < 3; ++a)
    {
      sampleBox.lo[a] -= 0.1 * diagonal;
      sampleBox.hi[a] += 0.1 * diagonal;
    }
    const int bad = tpc::vtkadapter::CountSignDisagreements(
      this->ImplicitFunction, scene.Primitives, implicitTerm, sampleBox);
    if (bad > 0)
    {
      vtkErrorMacro("The ImplicitFunction (" << this->ImplicitFunction->GetClassName()
                                             << ") evaluates differently from its description at "
                                             << bad << " sample points: it is not supported.");
      return 1;
    }
  }

  const double tolerance = this->ToleranceIsRelative ? this->Tolerance * diagonal : this->Tolerance;
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
  {
    vtkErrorMacro("Tolerance must be positive (got " << this->Tolerance << ").");
    return 1;
  }

  tpc::Box3 rootDomain = domain;
  if (userBounds)
  {
    // Clip to the domain and cap it: intersect with the box's six planes.
    std::vector<tpc::CsgTerm> operands{ term };
    for (int a = 0; a < 3; ++a)
    {
      tpc::Vec3 n, o;
      n[a] = 1.0;
      o[a] = domain.hi[a];
      scene.Primitives.Quadrics.push_back(tpc::Quadric::Plane(o, n));
      operands.push_back(tpc::CsgTerm::Primitive(static_cast<int>(scene.Primitives.Quadrics.size() - 1)));
      n[a] = -1.0;
      o[a] = domain.lo[a];
      scene.Primitives.Quadrics.push_back(tpc::Quadric::Plane(o, n));
      operands.push_back(tpc::CsgTerm::Primitive(static_cast<int>(scene.Primitives.Quadrics.size() - 1)));
    }
    term = tpc::CsgTerm::Combine(tpc::CsgTerm::Op::Intersection, std::move(operands));
    for (int a = 0; a < 3; ++a)
    {
      rootDomain.lo[a] -= 1e-3 * diagonal;
      rootDomain.hi[a] += 1e-3 * diagonal;
    }
  }
  else
  {
    // A margin keeps the surface away from the grid's outer boundary.
    for (int a = 0; a < 3; ++a)
    {
      rootDomain.lo[a] -= 0.05 * diagonal;
      rootDomain.hi[a] += 0.05 * diagonal;
    }
  }
  scene.Expression = tpc::CsgExpression::FromTerm(term);

  tpc::SubdivisionParameters params;
  params.HausdorffTolerance = tolerance;
  params.MaximumDepth = this->MaximumDepth;
  params.MaximumNumberOfCells = static_cast<std::size_t>(std::max<vtkIdType>(this->MaximumNumberOfCells, 8));
  // Remeshing one valid closed mesh: where the tests cannot resolve a cell at
  // the tolerance's size, its patch is the mesh itself (ExactCell.h).
  params.ExactCells = assumptionsMet && tpc::IsOneMesh(*scene.Expression);
  if (!assumptionsMet)
  {
    // The guarantee is lost anyway, and self-intersections are complex at
    // every depth: refining them to MaximumDepth costs minutes and buys
    // nothing. Stop three levels below the cells the tolerance needs.
    const int toleranceLevel = tpc::ToleranceLevel(rootDomain, tolerance);
    if (toleranceLevel + 3 < params.MaximumDepth)
    {
      params.MaximumDepth = std::max(0, toleranceLevel + 3);
      vtkWarningMacro("The inputs violate the method's assumptions: refinement stops at depth "
        << params.MaximumDepth << " instead of MaximumDepth (" << this->MaximumDepth << ").");
    }
  }
  // Another lattice placement usually resolves cells a first one leaves to
  // the depth limit (a crease a hair from a lattice plane); inputs violating
  // the method's assumptions are not worth the retries.
  const int placements = assumptionsMet && (piece.Pieces == 1 || collective) ? tpc::LatticePlacements : 1;
  tpc::PlacedSubdivision placed = tpc::RunOnBestLatticePlacement(
    scene, rootDomain, params, placements, ParallelForSMP, stage(0.1, 0.85), piece);
  if (placed.Result.Aborted)
  {
    return aborted();
  }
  const tpc::RootGrid& rootGrid = placed.Grid;
  tpc::SubdivisionResult& sub = placed.Result;
  const int placementsTried = placed.PlacementsTried;
  const tpc::ExtractionResult extraction =
    tpc::ExtractSurface(sub.Octree, scene, ParallelForSMP, stage(0.85, 0.92, mayAbort));
  if (extraction.Aborted)
  {
    return aborted();
  }
  // The exact embedding check (SurfaceEmbedding.h); the cells it blames are
  // marked in the grid output.
  const tpc::EmbeddingReport embedding =
    tpc::CheckEmbedding(sub.Octree, extraction.Mesh, ParallelForSMP, stage(0.92, 0.95, mayAbort));
  if (embedding.Aborted)
  {
    return aborted();
  }
  for (const std::uint32_t n : embedding.Cells)
  {
    tpc::OctreeNode& node = sub.Octree.Nodes[n];
    node.State = tpc::CellState::Unresolved;
    node.Reason = node.FailedTest = tpc::SplitReason::PatchNotEmbedded;
  }
  const tpc::TopologyReport topo =
    tpc::ComputeTopologyReport(extraction.Mesh, ParallelForSMP, stage(0.95, 0.97, mayAbort));
  if (stop())
  {
    return aborted();
  }

  // Grid output.
  std::vector<vtkIdType> nodeToCell;
  if (!tpc::vtkadapter::ConvertOctree(sub.Octree, gridOut, nodeToCell, stage(0.97, 1.0, mayAbort)))
  {
    return aborted();
  }

  // Surface output.
  const tpc::TriangleMesh& mesh = extraction.Mesh;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.Points.size()));
  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(static_cast<vtkIdType>(mesh.Points.size()));
  for (std::size_t i = 0; i < mesh.Points.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), mesh.Points[i].x);
    normals->SetTypedTuple(static_cast<vtkIdType>(i), mesh.Normals[i].x);
  }
  vtkNew<vtkCellArray> triangles;
  triangles->AllocateExact(static_cast<vtkIdType>(mesh.Triangles.size()),
    static_cast<vtkIdType>(3 * mesh.Triangles.size()));
  vtkNew<vtkIdTypeArray> gridCell;
  gridCell->SetName("GridCell");
  gridCell->SetNumberOfValues(static_cast<vtkIdType>(mesh.Triangles.size()));
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    const vtkIdType ids[3] = { mesh.Triangles[t][0], mesh.Triangles[t][1], mesh.Triangles[t][2] };
    triangles->InsertNextCell(3, ids);
    gridCell->SetValue(static_cast<vtkIdType>(t), nodeToCell[mesh.TriangleCell[t]]);
  }
  surfaceOut->SetPoints(points);
  surfaceOut->SetPolys(triangles);
  surfaceOut->GetPointData()->SetNormals(normals);
  surfaceOut->GetCellData()->AddArray(gridCell);

  // Topology report: of the whole surface, also when this rank holds a
  // piece (counts summed, components joined across the seams: PieceTopology.h).
  tpc::SubdivisionResult all; // the statistics of all pieces
  all.UnresolvedCells = placed.UnresolvedCellsOfAllPieces;
  all.FacingSurfaceCells = piece.Sum(sub.FacingSurfaceCells);
  all.DepthLimitReached = piece.Sum(sub.DepthLimitReached ? 1 : 0) > 0;
  all.CellLimitReached = piece.Sum(sub.CellLimitReached ? 1 : 0) > 0;
  all.PlanarSurfaceCells = piece.Sum(sub.PlanarSurfaceCells);
  all.ExactCells = piece.Sum(sub.ExactCells);
  for (int r = 0; r < tpc::SplitReasonCount; ++r)
  {
    all.UnresolvedByReason[r] = piece.Sum(sub.UnresolvedByReason[r]);
  }
  all.HausdorffBound = sub.HausdorffBound;
  const std::size_t inconsistent = piece.Sum(extraction.InconsistentCells);
  const std::size_t withoutPatch = piece.Sum(extraction.CellsWithoutPatch);
  // Pieces' triangles can only meet across the seams (SurfaceEmbedding.h):
  // each rank tests its seam triangles against those of the ranks after it.
  std::size_t seamPairs = 0;
  if (collective)
  {
    const std::vector<double> mine = tpc::SeamTriangles(sub.Octree, extraction.Mesh);
    const long long length = static_cast<long long>(mine.size());
    std::vector<long long> lengths(static_cast<std::size_t>(piece.Pieces));
    controller->AllGather(&length, lengths.data(), 1);
    std::vector<vtkIdType> counts(lengths.begin(), lengths.end()), offsets(counts.size(), 0);
    for (std::size_t r = 1; r < counts.size(); ++r)
    {
      offsets[r] = offsets[r - 1] + counts[r - 1];
    }
    std::vector<double> seams(static_cast<std::size_t>(offsets.back() + counts.back()));
    controller->AllGatherV(mine.data(), seams.data(), static_cast<vtkIdType>(mine.size()), counts.data(),
      offsets.data());
    for (int r = piece.Piece + 1; r < piece.Pieces; ++r)
    {
      const auto from = seams.begin() + offsets[static_cast<std::size_t>(r)];
      seamPairs += tpc::CountImproperSeamPairs(
        mine, std::vector<double>(from, from + counts[static_cast<std::size_t>(r)]));
    }
  }
  const std::size_t notEmbedded = piece.Sum(embedding.Embedded() && seamPairs == 0 ? 0 : 1);
  const std::size_t improperPairs = piece.Sum(embedding.ImproperPairs + seamPairs);
  const std::size_t coincidentVertices = piece.Sum(embedding.CoincidentVertices);
  const std::size_t degenerate = piece.Sum(embedding.DegenerateTriangles + embedding.TrianglesOutsideCells);
  const std::size_t blamedCells = piece.Sum(embedding.Cells.size());
  tpc::TopologyReport whole = topo;
  if (collective)
  {
    controller->AllReduce(&sub.HausdorffBound, &all.HausdorffBound, 1, vtkCommunicator::MAX_OP);
    const std::vector<double> mine = tpc::DescribePiece(mesh).Serialize();
    vtkNew<vtkDoubleArray> send, received;
    send->SetArray(const_cast<double*>(mine.data()), static_cast<vtkIdType>(mine.size()), 1);
    controller->AllGatherV(send, received);
    whole = tpc::CombinePieces(tpc::PieceSeams::DeserializeAll(
      std::vector<double>(received->GetPointer(0), received->GetPointer(0) + received->GetNumberOfValues())));
  }
  // Surface in a cell without a patch is missing from the output: no bound.
  report.HausdorffBound = withoutPatch == 0 ? all.HausdorffBound : std::nan("");
  report.Embedded = notEmbedded == 0 ? 1 : 0;
  report.PlanarCells = static_cast<long long>(all.PlanarSurfaceCells);
  report.ExactCells = static_cast<long long>(all.ExactCells);
  report.Tolerance = tolerance;
  report.Components = whole.Components;
  report.Genus = whole.Genus;
  report.Euler = whole.EulerCharacteristic;
  report.Unresolved = static_cast<long long>(all.UnresolvedCells);
  report.Closed = whole.Closed ? 1 : 0;
  report.Manifold = whole.Manifold ? 1 : 0;
  const bool empty = whole.Faces == 0;
  report.Guaranteed = (assumptionsMet && all.UnresolvedCells == 0 && inconsistent == 0 && report.Embedded &&
                        (piece.Pieces == 1 || collective) &&
                        (empty || (whole.Closed && whole.Manifold && whole.Oriented)))
    ? 1
    : 0;
  surfaceOut->GetFieldData()->Initialize(); // (ConvertOctree initialized the grid)
  AddReport(gridOut, report);
  AddReport(surfaceOut, report);

  if (!report.Guaranteed && (!collective || piece.Piece == 0)) // (one rank says it)
  {
    std::ostringstream why;
    why << "The topology guarantee does not hold:";
    if (!assumptionsMet)
    {
      why << " the inputs violate the method's assumptions (see the warnings above);";
    }
    if (all.UnresolvedCells > 0)
    {
      why << " " << all.UnresolvedCells << " surface cell(s) were stopped";
      if (all.DepthLimitReached)
      {
        why << " by MaximumDepth (" << params.MaximumDepth << ")";
      }
      if (all.CellLimitReached)
      {
        why << " by MaximumNumberOfCells (" << this->MaximumNumberOfCells << ")";
      }
      why << " with a test still failing:";
      for (int r = 1; r < tpc::SplitReasonCount; ++r)
      {
        if (all.UnresolvedByReason[r] > 0)
        {
          why << " " << tpc::SplitReasonName(static_cast<tpc::SplitReason>(r)) << " "
              << all.UnresolvedByReason[r] << ";";
        }
      }
      if (all.FacingSurfaceCells > 0)
      {
        why << " " << all.FacingSurfaceCells
            << " of them because two surfaces face each other there closer than the finest cell ("
            << placed.FinestCell
            << "): solids touching along a face, or a gap or slab thinner than that, which no "
               "refinement separates (SplitReason 10, SURFACES_TOO_CLOSE);";
      }
      if (placementsTried > 1)
      {
        why << " (best of " << placementsTried << " lattice placements tried);";
      }
      why << " they are marked CellState=3 in the grid output.";
      if (all.UnresolvedCells > all.FacingSurfaceCells)
      {
        why << " Tangential contact between primitives never passes the tests; otherwise raise the "
               "limits.";
      }
      if (all.FacingSurfaceCells > 0)
      {
        why << " Overlap touching solids (or move them apart) by more than the finest cell; for a "
               "real thin gap or slab, raise MaximumDepth.";
      }
    }
    if (notEmbedded > 0)
    {
      why << " the surface is not embedded: " << improperPairs << " pair(s) of triangles meet other than in a "
          << "shared edge or vertex, " << coincidentVertices << " vertex pair(s) coincide, " << degenerate
          << " triangle(s) are degenerate (exact test of the output); their " << blamedCells
          << " cell(s) are marked CellState=3, SplitReason 11 (PATCH_NOT_EMBEDDED).";
    }
    if (inconsistent > 0)
    {
      why << " " << inconsistent << " cell(s) gave inconsistent loops.";
    }
    vtkWarningMacro(<< why.str());
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkTopologyPreservingContour::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ImplicitFunction: " << this->ImplicitFunction << "\n";
  os << indent << "Operation: " << this->Operation << "\n";
  os << indent << "Bounds: " << this->Bounds[0] << " " << this->Bounds[1] << " " << this->Bounds[2]
     << " " << this->Bounds[3] << " " << this->Bounds[4] << " " << this->Bounds[5] << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "ToleranceIsRelative: " << this->ToleranceIsRelative << "\n";
  os << indent << "MaximumDepth: " << this->MaximumDepth << "\n";
  os << indent << "MaximumNumberOfCells: " << this->MaximumNumberOfCells << "\n";
}
