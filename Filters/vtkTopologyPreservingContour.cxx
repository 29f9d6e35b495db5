#include "vtkTopologyPreservingContour.h"

#include "ImplicitFunctionToCsg.h"
#include "OctreeToHyperTreeGrid.h"
#include "PolyDataToMesh.h"

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
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTypeInt32Array.h"

#include "Contour.h"
#include "ExecutionThreads.h"
#include "CreaseSplit.h"

#include <algorithm>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkTopologyPreservingContour);
vtkCxxSetObjectMacro(vtkTopologyPreservingContour, ImplicitFunction, vtkImplicitFunction);

namespace
{
/// The report as field data (one value per array).
void AddReport(vtkDataObject* output, const tpc::ContourReport& r)
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
  addInt("EulerCharacteristic", r.EulerCharacteristic);
  addInt("TopologyGuaranteed", r.Guaranteed);
  addInt("UnresolvedCells", r.UnresolvedCells);
  addInt("Closed", r.Closed);
  addInt("Manifold", r.Manifold);
  addInt("Embedded", r.Embedded);
  addInt("Outward", r.Outward);
  addInt("PlanarCells", r.PlanarCells);
  addInt("ExactCells", r.ExactCells);
  vtkNew<vtkDoubleArray> h;
  h->SetName("HausdorffBound");
  h->InsertNextValue(r.HausdorffBound);
  fd->AddArray(h);
  vtkNew<vtkDoubleArray> t;
  t->SetName("AbsoluteTolerance");
  t->InsertNextValue(r.AbsoluteTolerance);
  fd->AddArray(t);
}

/// The piece the pipeline asks for (on either port: UpdatePiece asks on
/// port 0, a grid consumer on port 1).
tpc::PieceOfRun RequestedPiece(vtkInformationVector* outInfo)
{
  tpc::PieceOfRun piece;
  for (int port = 0; port < 2; ++port)
  {
    vtkInformation* requested = outInfo->GetInformationObject(port);
    const int pieces = requested->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
    if (pieces > piece.Pieces)
    {
      piece.Pieces = pieces;
      piece.Piece = std::max(0, requested->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()));
    }
  }
  return piece;
}

/// The reductions the pieces agree through, over `controller`.
void ExchangeThrough(vtkMultiProcessController* controller, tpc::PieceOfRun& piece, tpc::PieceExchange& exchange)
{
  piece.Sum = [controller](std::size_t x) {
    const vtkIdType in = static_cast<vtkIdType>(x);
    vtkIdType out = 0;
    controller->AllReduce(&in, &out, 1, vtkCommunicator::SUM_OP);
    return static_cast<std::size_t>(out);
  };
  exchange.Max = [controller](double x) {
    double out = x;
    controller->AllReduce(&x, &out, 1, vtkCommunicator::MAX_OP);
    return out;
  };
  exchange.GatherAll = [controller](const std::vector<double>& mine) {
    const long long length = static_cast<long long>(mine.size());
    std::vector<long long> lengths(static_cast<std::size_t>(controller->GetNumberOfProcesses()));
    controller->AllGather(&length, lengths.data(), 1);
    std::vector<vtkIdType> counts(lengths.begin(), lengths.end()), offsets(counts.size(), 0);
    for (std::size_t r = 1; r < counts.size(); ++r)
    {
      offsets[r] = offsets[r - 1] + counts[r - 1];
    }
    std::vector<double> all(static_cast<std::size_t>(offsets.back() + counts.back()));
    controller->AllGatherV(
      mine.data(), all.data(), static_cast<vtkIdType>(mine.size()), counts.data(), offsets.data());
    std::vector<std::vector<double>> pieces;
    for (std::size_t r = 0; r < counts.size(); ++r)
    {
      pieces.emplace_back(all.begin() + offsets[r], all.begin() + offsets[r] + counts[r]);
    }
    return pieces;
  };
}

/// A data array that takes over the memory of `values`, each `Width` array
/// values (no copy; it frees it with free(), as ReleasableArray allocated
/// it), in tuples of `components`.
template <typename ArrayT, int Width, typename T>
vtkSmartPointer<ArrayT> TakeOver(tpc::ReleasableArray<T>& values, int components)
{
  using Value = typename ArrayT::ValueType;
  static_assert(sizeof(T) == Width * sizeof(Value), "a value is Width array values");
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetNumberOfComponents(components);
  const auto count = static_cast<vtkIdType>(Width * values.size());
  array->SetArray(reinterpret_cast<Value*>(values.Release()), count, /*save=*/0, ArrayT::VTK_DATA_ARRAY_FREE);
  return array;
}

/// The surface with its normals, each triangle's grid cell, solid and
/// certified error, its points split along creases first when `creaseAngle`
/// is set (CreaseSplit.h; "SurfacePointId" then maps them back). The core's
/// points, normals, triangles and solids become the output's arrays without
/// a copy (ReleasableArray.h); the result's mesh is left empty.
void MoveSurface(tpc::ContourResult& result, const std::vector<vtkIdType>& nodeToCell,
  std::optional<double> creaseAngle, vtkPolyData* out)
{
  tpc::TriangleMesh& mesh = result.Extraction.Mesh;
  if (creaseAngle)
  {
    std::vector<std::uint32_t> surfacePoint;
    tpc::SplitAtCreases(mesh, *creaseAngle, surfacePoint);
    vtkNew<vtkIdTypeArray> surfacePointId;
    surfacePointId->SetName("SurfacePointId");
    surfacePointId->SetNumberOfValues(static_cast<vtkIdType>(surfacePoint.size()));
    std::copy(surfacePoint.begin(), surfacePoint.end(), surfacePointId->GetPointer(0));
    out->GetPointData()->AddArray(surfacePointId);
  }
  auto solidId = TakeOver<vtkIntArray, 1>(result.TriangleSolid, 1);
  solidId->SetName("SolidId");
  vtkNew<vtkIdTypeArray> gridCell;
  gridCell->SetName("GridCell");
  gridCell->SetNumberOfValues(static_cast<vtkIdType>(mesh.TriangleCell.size()));
  for (std::size_t t = 0; t < mesh.TriangleCell.size(); ++t)
  {
    gridCell->SetValue(static_cast<vtkIdType>(t), nodeToCell[mesh.TriangleCell[t]]);
  }
  // Point ids fit 32-bit connectivity (VTK reads it natively) below 2^31.
  vtkNew<vtkCellArray> triangles;
  if (mesh.Points.size() <= static_cast<std::size_t>(VTK_TYPE_INT32_MAX))
  {
    triangles->SetData(3, TakeOver<vtkTypeInt32Array, 3>(mesh.Triangles, 1));
  }
  else
  {
    vtkNew<vtkIdTypeArray> ids;
    ids->SetNumberOfValues(static_cast<vtkIdType>(3 * mesh.Triangles.size()));
    for (std::size_t k = 0; k < 3 * mesh.Triangles.size(); ++k)
    {
      ids->SetValue(static_cast<vtkIdType>(k), mesh.Triangles[k / 3][k % 3]);
    }
    triangles->SetData(3, ids);
  }
  vtkNew<vtkPoints> points;
  points->SetData(TakeOver<vtkDoubleArray, 3>(mesh.Points, 3));
  auto normals = TakeOver<vtkDoubleArray, 3>(mesh.Normals, 3);
  normals->SetName("Normals");
  out->SetPoints(points);
  out->SetPolys(triangles);
  out->GetPointData()->SetNormals(normals);
  out->GetCellData()->AddArray(gridCell);
  out->GetCellData()->AddArray(solidId);
  if (result.TriangleErrorBound.size() == static_cast<std::size_t>(triangles->GetNumberOfCells()))
  {
    vtkNew<vtkDoubleArray> certified;
    certified->SetName("CertifiedError");
    certified->SetNumberOfValues(static_cast<vtkIdType>(result.TriangleErrorBound.size()));
    std::copy(result.TriangleErrorBound.begin(), result.TriangleErrorBound.end(), certified->GetPointer(0));
    out->GetCellData()->AddArray(certified);
  }
  mesh = tpc::TriangleMesh();
}
enum class InputConversion
{
  Converted,
  Refused, ///< an error was reported
  Aborted
};

/// The filter's input meshes (converted and repaired) and its implicit
/// function as the core's scene.
InputConversion AddInputSolids(vtkTopologyPreservingContour* self, vtkInformationVector* inputs,
  tpc::ContourScene& scene, const std::function<tpc::ProgressCallback(double, double)>& stage, const bool& aborted,
  const tpc::ParallelFor& parallelFor)
{
  const int connections = self->GetNumberOfInputConnections(0);
  for (int k = 0; k < connections; ++k)
  {
    const int i = self->GetReverseInputOrder() ? connections - 1 - k : k;
    vtkPolyData* mesh = vtkPolyData::GetData(inputs, i);
    if (!mesh || mesh->GetNumberOfCells() == 0)
    {
      vtkWarningWithObjectMacro(self, "Input " << i << " is empty: it is ignored.");
      continue;
    }
    tpc::vtkadapter::MeshInput in;
    std::string error;
    const bool converted = tpc::vtkadapter::ConvertPolyData(mesh, in, error, self->GetFillHoles(), parallelFor,
      stage(0.08 * k / connections, 0.08 * (k + 1) / connections));
    if (aborted)
    {
      return InputConversion::Aborted;
    }
    if (!converted)
    {
      vtkErrorWithObjectMacro(self, "Input " << i << " cannot be used as a solid: " << error << ".");
      return InputConversion::Refused;
    }
    if (in.IgnoredLines > 0 || in.IgnoredVertices > 0)
    {
      vtkWarningWithObjectMacro(self, "Input " << i << ": " << in.IgnoredLines << " line and " << in.IgnoredVertices
                               << " vertex cells are ignored; only polygons bound the solid.");
    }
    scene.Primitives.Meshes.push_back(std::move(in.Solid));
    tpc::SceneInput solid;
    solid.Name = "Input " + std::to_string(i);
    solid.Id = i;
    solid.Mesh = static_cast<int>(scene.Primitives.Meshes.size() - 1);
    solid.Solid = tpc::CsgTerm::Mesh(solid.Mesh);
    solid.Repair = in.Repair;
    scene.Inputs.push_back(std::move(solid));
  }
  if (self->GetImplicitFunction())
  {
    tpc::SceneInput implicit;
    implicit.Name = "The ImplicitFunction";
    implicit.Id = connections;
    std::string error;
    if (!tpc::vtkadapter::ConvertImplicitFunction(self->GetImplicitFunction(), scene.Primitives, implicit.Solid, error))
    {
      vtkErrorWithObjectMacro(self, "Unsupported ImplicitFunction: " << error << ".");
      return InputConversion::Refused;
    }
    // Guards against subclasses whose evaluation the converter does not know.
    vtkImplicitFunction* function = self->GetImplicitFunction();
    implicit.Verify = [function](const tpc::PrimitiveSet& primitives, const tpc::CsgTerm& term, const tpc::Box3& box) {
      const int bad = tpc::vtkadapter::CountSignDisagreements(function, primitives, term, box);
      std::ostringstream text;
      if (bad > 0)
      {
        text << "The ImplicitFunction (" << function->GetClassName() << ") evaluates differently from its "
             << "description at " << bad << " sample points: it is not supported.";
      }
      return text.str();
    };
    scene.Inputs.push_back(std::move(implicit));
  }
  scene.Operation = self->GetOperation() == vtkTopologyPreservingContour::INTERSECTION ? tpc::CsgTerm::Op::Intersection
    : self->GetOperation() == vtkTopologyPreservingContour::DIFFERENCE                 ? tpc::CsgTerm::Op::Difference
                                                    : tpc::CsgTerm::Op::Union;
  return InputConversion::Converted;
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
  // The surface, the main result, first (ParaView's simple API, Fetch and
  // SaveData take port 0); the adaptive grid second.
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkPolyData" : "vtkHyperTreeGrid");
  return 1;
}

vtkHyperTreeGrid* vtkTopologyPreservingContour::GetGridOutput()
{
  return vtkHyperTreeGrid::SafeDownCast(this->GetOutputDataObject(1));
}

vtkPolyData* vtkTopologyPreservingContour::GetSurfaceOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(0));
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
  vtkPolyData* surfaceOut = vtkPolyData::GetData(outInfo, 0);
  vtkHyperTreeGrid* gridOut = vtkHyperTreeGrid::GetData(outInfo, 1);
  if (!gridOut || !surfaceOut)
  {
    vtkErrorMacro("Output data objects are missing.");
    return 0;
  }
  auto clearOutputs = [&](const tpc::ContourReport& report = tpc::ContourReport()) {
    gridOut->Initialize();
    surfaceOut->Initialize();
    AddReport(gridOut, report);
    AddReport(surfaceOut, report);
  };
  clearOutputs();
  // The piece requested (UpdatePiece, or the rank under pvbatch/pvserver):
  // this rank subdivides its slab of root trees and a ghost ring and outputs
  // its own trees (ForestPartition.h). With the global controller spanning
  // the pieces, decisions and the report are agreed through reductions;
  // without it each piece decides alone on one lattice placement (the
  // pieces still fit) and reports its own piece only.
  tpc::PieceOfRun piece = RequestedPiece(outInfo);
  tpc::PieceExchange exchange;
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool collective = piece.Pieces > 1 && controller &&
    controller->GetNumberOfProcesses() == piece.Pieces && controller->GetLocalProcessId() == piece.Piece;
  if (collective)
  {
    ExchangeThrough(controller, piece, exchange);
  }
  else if (piece.Pieces > 1)
  {
    vtkWarningMacro("Piece " << piece.Piece << " of " << piece.Pieces << " without a global controller over "
                             << piece.Pieces << " processes: the report describes this piece only.");
  }
  // Progress: inputs [0, 0.08], the core [0.08, 0.97] (Contour.h), grid
  // output [0.97, 1]. Every long loop reports in chunks, so Abort stops any
  // stage within a chunk (a fraction of a second); the outputs are then
  // empty. (The core decides where a split run may abort.)
  // A split run's ranks must all reach every collective call, so there the
  // filter's own stages never stop; the core's stage passes every request on
  // (it knows where the pieces agree). CheckAbort sees this filter's
  // AbortExecute and an abort of the whole pipeline or of a container filter.
  bool abortRequested = false; // (one this process may honour alone)
  auto stage = [this, collective, &abortRequested](double lo, double hi) -> tpc::ProgressCallback {
    return [this, lo, hi, collective, &abortRequested](double f) {
      this->UpdateProgress(lo + (hi - lo) * f);
      abortRequested = abortRequested || (!collective && this->CheckAbort());
      return abortRequested;
    };
  };
  auto coreStage = [this](double f) {
    this->UpdateProgress(0.08 + 0.89 * f);
    return this->CheckAbort();
  };
  auto aborted = [&]() {
    clearOutputs();
    vtkWarningMacro("Aborted: outputs are empty.");
    // This filter's own abort leaves its outputs empty and up to date: it
    // runs again when a property or an input changes (or after Modified()).
    // Left set, AbortOutput makes VTK 9.2's executive mark the outputs
    // ABORTED, and the next request - ParaView makes one per output port and
    // view right after Apply - runs the whole contour again, so the abort
    // button seemed to do nothing. (Changes made during RequestData do not
    // make the filter out of date.) An abort of an upstream filter stays one.
    if (this->GetAbortExecute())
    {
      this->SetAbortExecute(0);
      this->SetAbortOutput(false);
    }
    return 1;
  };

  // The core's loops run on threads started once for this execution
  // (ExecutionThreads.h).
  tpc::vtkadapter::ExecutionThreads threads;
  const tpc::ParallelFor parallelFor = threads.Loop();
  tpc::ContourScene scene;
  const InputConversion inputs = AddInputSolids(this, inInfo[0], scene, stage, abortRequested, parallelFor);
  if (inputs != InputConversion::Converted)
  {
    return inputs == InputConversion::Aborted ? aborted() : 1;
  }
  tpc::ContourParameters parameters;
  if (this->Bounds[0] <= this->Bounds[1] && this->Bounds[2] <= this->Bounds[3] && this->Bounds[4] <= this->Bounds[5])
  {
    parameters.Bounds = tpc::Box3{ { this->Bounds[0], this->Bounds[2], this->Bounds[4] },
      { this->Bounds[1], this->Bounds[3], this->Bounds[5] } };
  }
  parameters.Tolerance = this->Tolerance;
  parameters.ToleranceIsRelative = this->ToleranceIsRelative;
  parameters.MaximumDepth = this->MaximumDepth;
  parameters.MaximumNumberOfCells = static_cast<std::size_t>(std::max<vtkIdType>(this->MaximumNumberOfCells, 0));
  parameters.Decimate = this->Decimate;
  tpc::ContourResult result =
    tpc::Contour(std::move(scene), parameters, parallelFor, coreStage, piece, exchange);
  for (const tpc::ContourMessage& m : result.Messages)
  {
    if (m.Severity == tpc::ContourMessage::Level::Error)
    {
      vtkErrorMacro(<< m.Text);
    }
    else
    {
      vtkWarningMacro(<< m.Text);
    }
  }
  if (result.Status == tpc::ContourResult::Outcome::Empty)
  {
    // (Empty outputs, with the report of an empty surface: Contour.cxx,
    // ReportEmptySolid.)
    clearOutputs(result.Report);
    return 1;
  }
  if (result.Status != tpc::ContourResult::Outcome::Contoured)
  {
    return result.Status == tpc::ContourResult::Outcome::Aborted ? aborted() : 1;
  }
  std::vector<vtkIdType> nodeToCell;
  if (!tpc::vtkadapter::ConvertOctree(result.Subdivision().Octree, gridOut, nodeToCell, stage(0.97, 1.0)) ||
    abortRequested)
  {
    return aborted();
  }
  tpc::vtkadapter::AddCertifiedErrors(gridOut, nodeToCell, result.Extraction.CellErrors);
  MoveSurface(result, nodeToCell,
    this->SplitCreases ? std::optional<double>(this->CreaseAngle) : std::nullopt, surfaceOut);
  surfaceOut->GetFieldData()->Initialize(); // (ConvertOctree initialized the grid)
  AddReport(gridOut, result.Report);
  AddReport(surfaceOut, result.Report);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkTopologyPreservingContour::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ImplicitFunction: " << this->ImplicitFunction << "\n";
  os << indent << "Operation: " << this->Operation << "\n";
  os << indent << "ReverseInputOrder: " << this->ReverseInputOrder << "\n";
  os << indent << "FillHoles: " << this->FillHoles << "\n";
  os << indent << "Bounds: " << this->Bounds[0] << " " << this->Bounds[1] << " " << this->Bounds[2]
     << " " << this->Bounds[3] << " " << this->Bounds[4] << " " << this->Bounds[5] << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "ToleranceIsRelative: " << this->ToleranceIsRelative << "\n";
  os << indent << "MaximumDepth: " << this->MaximumDepth << "\n";
  os << indent << "MaximumNumberOfCells: " << this->MaximumNumberOfCells << "\n";
  os << indent << "Decimate: " << this->Decimate << "\n";
  os << indent << "SplitCreases: " << this->SplitCreases << "\n";
  os << indent << "CreaseAngle: " << this->CreaseAngle << "\n";
}
