// One benchmark run: a method on a scene at one epsilon, in its own process
// (so that its peak memory is its own). Prints one JSON object. The driver,
// run_benchmark.py, runs every case and prints the tables.
//
//   tpc_benchmark --method tpc|vtk|vdb --scene NAME --epsilon E --threads N
//                 --meshes DIR [--cell-size H] [--max-depth D] [--max-cells N] [--abort-at P]
//                 [--fingerprint 1|geometry] [--adaptivity A] [--decimate 1]
//
// tpc: vtkTopologyPreservingContour, epsilon relative to the diagonal of
//      the scene's domain (Bounds set to it);
// vtk: VTK's usual recipe, vtkSampleFunction of the solid's implicit function
//      (meshes through vtkImplicitPolyDataDistance) -> vtkFlyingEdges3D, at
//      sample spacing H;
// vdb: OpenVDB, meshes (and tessellated ellipsoids, the plate's box, exact
//      spheres) -> narrow-band level sets -> level-set CSG -> volumeToMesh,
//      at voxel size H (with --adaptivity A, volumeToMesh's adaptivity:
//      0 uniform, up to 1 merging flat regions' polygons).
// H is the edge of the filter's surface cells at epsilon (the driver passes
// it), so all three resolve the surface at the same finest cell size.
// With --fingerprint 1 the filter's run also prints a hash of everything it
// output (run_benchmark.py --compare: the same output from two builds); with
// --fingerprint geometry, of everything but the certified errors (the grid's
// and the surface's CertifiedError, the HausdorffBound field): a change that
// moves only those keeps it.
// With --measure 1 on a scene of one mesh, the output's two-sided Hausdorff
// distance to it, by CGAL (a test oracle; the sphere's is always measured).
// With --decimate 1 the filter decimates its surface (Decimate).
#include "BenchmarkScenes.h"
#include "CgalHausdorff.h"

#include "MeshSolid.h"

#include "TopologyReport.h"
#include "TriangleMesh.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFlyingEdges3D.h"
#include "vtkHyperTree.h"
#include "vtkHyperTreeGrid.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkSampleFunction.h"
#include "vtkStringArray.h"
#include "vtkTopologyPreservingContour.h"
#include "vtkTriangleFilter.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <tbb/global_control.h>

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

struct RunResult
{
  double Seconds = 0.0;
  long long Triangles = 0;
  long long GridCells = 0;
  tpc::TopologyReport Topology;
  double SurfaceCellSize = 0.0; ///< tpc only
  long PlanarCells = 0;         ///< tpc only
  /// tpc only: cells split by a repair round (SplitReason 11 or 13 on a
  /// refined cell: an earlier surface found them wanting, CellRepair.h).
  long RepairedCells = 0;
  bool Guaranteed = false;      ///< tpc only
  /// tpc only: the longest time between two progress reports (the filter
  /// checks Abort at each), the progress it started from, and with
  /// --abort-at the time from the abort request to the filter's return.
  double LongestProgressGap = 0.0;
  double LongestProgressGapAt = 0.0;
  double AbortLatency = -1.0;
  std::string Fingerprint; ///< tpc with --fingerprint only
  double HausdorffBound = -1.0; ///< tpc only: the reported bound (absolute)
  tpc::TriangleMesh Surface;    ///< the output (for the measured distance)
};

/// The measured two-sided Hausdorff distance between `surface` and the ball
/// `ball` (centre, radius)'s sphere: from the surface, on a barycentric grid
/// of every triangle (the exact distance to a sphere is | |x - c| - r |);
/// to the surface, from 20 000 points spread on the sphere (exact distances
/// to the nearest triangles). Sampled, so a lower estimate of the maximum.
double MeasuredBallHausdorff(const tpc::TriangleMesh& surface, const std::array<double, 4>& ball, double reach)
{
  const tpc::Vec3 c(ball[0], ball[1], ball[2]);
  const double radius = ball[3];
  double worst = 0.0;
  for (const auto& t : surface.Triangles)
  {
    constexpr int Steps = 6;
    for (int i = 0; i <= Steps; ++i)
    {
      for (int j = 0; i + j <= Steps; ++j)
      {
        const double a = double(i) / Steps, b = double(j) / Steps;
        const tpc::Vec3 x =
          surface.Points[t[0]] * (1 - a - b) + surface.Points[t[1]] * a + surface.Points[t[2]] * b;
        worst = std::max(worst, std::fabs(tpc::Norm(x - c) - radius));
      }
    }
  }
  const tpc::MeshSolid mesh(surface.Points.ToVector(), surface.Triangles.ToVector());
  constexpr int Samples = 20000;
  for (int k = 0; k < Samples; ++k)
  {
    // Fibonacci sphere: evenly spread, deterministic.
    const double z = 1.0 - (2.0 * k + 1.0) / Samples, phi = k * 2.399963229728653;
    const double s = std::sqrt(1.0 - z * z);
    const tpc::Vec3 q = c + tpc::Vec3(s * std::cos(phi), s * std::sin(phi), z) * radius;
    const tpc::Vec3 r(reach, reach, reach);
    const tpc::TriangleList near = mesh.Overlapping({ q - r, q + r });
    worst = std::max(worst, near.empty() ? reach : std::fabs(mesh.ApproximateSignedDistance(q, near)));
  }
  return worst;
}

/// The two-sided Hausdorff distance between `surface` and the scene's one
/// mesh, by CGAL's certified bounded-error method (test oracle,
/// Testing/Oracles/CgalHausdorff.h): the larger upper estimate of the two
/// directions, each within `errorBound` of the true distance.
double MeasuredMeshHausdorff(const tpc::TriangleMesh& surface, vtkPolyData* input, double errorBound)
{
  tpcoracle::TriangleSoup output, exact;
  for (const tpc::Vec3& p : surface.Points)
  {
    output.Points.push_back({ p[0], p[1], p[2] });
  }
  output.Triangles = surface.Triangles.ToVector();
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    const double* p = input->GetPoint(i);
    exact.Points.push_back({ p[0], p[1], p[2] });
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    input->GetCellPoints(c, ids);
    for (vtkIdType k = 1; k + 1 < ids->GetNumberOfIds(); ++k)
    {
      exact.Triangles.push_back({ static_cast<std::uint32_t>(ids->GetId(0)),
        static_cast<std::uint32_t>(ids->GetId(k)), static_cast<std::uint32_t>(ids->GetId(k + 1)) });
    }
  }
  return std::max(tpcoracle::DirectedHausdorffWithCgal(output, exact, errorBound).Upper,
    tpcoracle::DirectedHausdorffWithCgal(exact, output, errorBound).Upper);
}

/// FNV-1a over bytes: a fingerprint, not a cryptographic hash.
struct Fnv1a
{
  std::uint64_t Hash = 1469598103934665603ULL;
  void Add(const void* data, std::size_t bytes)
  {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i)
    {
      this->Hash = (this->Hash ^ b[i]) * 1099511628211ULL;
    }
  }
  template <typename T>
  void AddValue(T value)
  {
    this->Add(&value, sizeof(value));
  }
  /// An array's name, shape and values: numbers as doubles, whatever type
  /// stores them (exact for ids below 2^53), so that a change of storage
  /// (32- or 64-bit ids) keeps the fingerprint; strings as text.
  void AddArray(vtkAbstractArray* a)
  {
    if (!a)
    {
      return;
    }
    const std::string name = a->GetName() ? a->GetName() : "";
    this->Add(name.data(), name.size());
    this->AddValue(a->GetNumberOfTuples());
    this->AddValue(a->GetNumberOfComponents());
    if (auto* strings = vtkStringArray::SafeDownCast(a))
    {
      for (vtkIdType i = 0; i < strings->GetNumberOfValues(); ++i)
      {
        this->Add(strings->GetValue(i).data(), strings->GetValue(i).size());
      }
      return;
    }
    if (auto* numbers = vtkDataArray::SafeDownCast(a))
    {
      for (vtkIdType t = 0; t < numbers->GetNumberOfTuples(); ++t)
      {
        for (int c = 0; c < numbers->GetNumberOfComponents(); ++c)
        {
          this->AddValue(numbers->GetComponent(t, c));
        }
      }
    }
  }
  /// Every array but the one named `skipped` (if any).
  void AddArrays(vtkFieldData* arrays, const char* skipped = nullptr)
  {
    for (int i = 0; i < arrays->GetNumberOfArrays(); ++i)
    {
      vtkAbstractArray* a = arrays->GetAbstractArray(i);
      if (!skipped || !a->GetName() || std::string(a->GetName()) != skipped)
      {
        this->AddArray(a);
      }
    }
  }
};

/// Everything the filter output: the surface's points, triangles, point,
/// cell and field data; the grid's trees (vertices and levels of each), cell
/// and field data (the cells' depths, states and reasons among them).
/// Without the certified errors (`errors` false): the same but the grid's and
/// the surface's CertifiedError and the HausdorffBound field.
std::string Fingerprint(vtkPolyData* surface, vtkHyperTreeGrid* grid, bool errors)
{
  Fnv1a h;
  const char* bound = errors ? nullptr : "HausdorffBound";
  h.AddArray(surface->GetPoints()->GetData());
  h.AddArray(surface->GetPolys()->GetOffsetsArray());
  h.AddArray(surface->GetPolys()->GetConnectivityArray());
  h.AddArrays(surface->GetPointData());
  h.AddArrays(surface->GetCellData(), errors ? nullptr : "CertifiedError");
  h.AddArrays(surface->GetFieldData(), bound);
  for (vtkIdType t = 0; t < grid->GetMaxNumberOfTrees(); ++t)
  {
    vtkHyperTree* tree = grid->GetTree(t);
    h.AddValue(tree ? tree->GetNumberOfVertices() : vtkIdType(-1));
    h.AddValue(tree ? tree->GetNumberOfLevels() : 0u);
  }
  h.AddArrays(grid->GetCellData(), errors ? nullptr : "CertifiedError");
  h.AddArrays(grid->GetFieldData(), bound);
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(h.Hash));
  return text;
}

/// Records the filter's progress reports; requests an abort at `AbortAt`.
struct ProgressWatch
{
  vtkAlgorithm* Filter = nullptr;
  double AbortAt = 2.0;
  Clock::time_point Start = Clock::now();
  Clock::time_point AbortRequested;
  bool Aborted = false;
  std::vector<std::pair<double, double>> Reports; ///< (seconds, progress)

  static void OnProgress(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* w = static_cast<ProgressWatch*>(clientData);
    const double f = *static_cast<double*>(callData);
    w->Reports.emplace_back(std::chrono::duration<double>(Clock::now() - w->Start).count(), f);
    if (!w->Aborted && f >= w->AbortAt)
    {
      w->Aborted = true;
      w->AbortRequested = Clock::now();
      w->Filter->SetAbortExecute(1);
    }
  }
};

/// Resident memory now, in MiB.
double ResidentMiB()
{
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

double PeakMiB()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/// The triangles of `surface` (polygons triangulated), as the core's mesh.
tpc::TriangleMesh Triangulated(vtkPolyData* surface)
{
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(surface);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  vtkPolyData* t = triangulate->GetOutput();
  tpc::TriangleMesh mesh;
  mesh.Points.resize(static_cast<std::size_t>(t->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < t->GetNumberOfPoints(); ++i)
  {
    t->GetPoint(i, mesh.Points[static_cast<std::size_t>(i)].x);
  }
  vtkIdType n;
  const vtkIdType* ids;
  auto polys = vtk::TakeSmartPointer(t->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    polys->GetCurrentCell(n, ids);
    mesh.Triangles.push_back({ static_cast<std::uint32_t>(ids[0]), static_cast<std::uint32_t>(ids[1]),
      static_cast<std::uint32_t>(ids[2]) });
  }
  return mesh;
}

double Diagonal(const std::array<double, 6>& b)
{
  return std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
}

RunResult RunFilter(const tpcbench::Scene& scene, double epsilon, int maximumDepth, long long maximumCells,
  double abortAt, const std::string& fingerprint, bool decimate)
{
  vtkNew<vtkTopologyPreservingContour> filter;
  filter->SetDecimate(decimate);
  ProgressWatch watch;
  watch.Filter = filter;
  watch.AbortAt = abortAt > 0.0 ? abortAt : 2.0;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetCallback(&ProgressWatch::OnProgress);
  onProgress->SetClientData(&watch);
  filter->AddObserver(vtkCommand::ProgressEvent, onProgress);
  if (maximumCells > 0)
  {
    filter->SetMaximumNumberOfCells(static_cast<vtkIdType>(maximumCells));
  }
  for (const auto& mesh : scene.Meshes)
  {
    filter->AddInputData(mesh);
  }
  if (!scene.Holes.empty() || scene.HasPlate || scene.Implicit)
  {
    filter->SetImplicitFunction(scene.Meshes.empty() ? scene.SolidFunction() : scene.HolesFunction());
  }
  filter->SetOperationToDifference(); // (meshes minus holes; unused without meshes)
  if (scene.HasBounds)
  {
    filter->SetBounds(const_cast<double*>(scene.Bounds.data()));
  }
  filter->SetTolerance(epsilon);
  filter->SetToleranceIsRelative(true);
  if (maximumDepth > 0)
  {
    filter->SetMaximumDepth(maximumDepth);
  }
  const auto start = Clock::now();
  watch.Start = start;
  filter->Update();
  const auto end = Clock::now();
  RunResult r;
  r.Seconds = std::chrono::duration<double>(end - start).count();
  double last = 0.0, lastProgress = 0.0;
  watch.Reports.emplace_back(r.Seconds, 1.0);
  for (const auto& report : watch.Reports)
  {
    if (report.first - last > r.LongestProgressGap)
    {
      r.LongestProgressGap = report.first - last;
      r.LongestProgressGapAt = lastProgress;
    }
    last = report.first;
    lastProgress = report.second;
  }
  if (watch.Aborted)
  {
    r.AbortLatency = std::chrono::duration<double>(end - watch.AbortRequested).count();
    return r;
  }
  auto* surface = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0));
  auto* grid = vtkHyperTreeGrid::SafeDownCast(filter->GetOutputDataObject(1));
  r.Triangles = surface->GetNumberOfPolys();
  r.GridCells = grid->GetNumberOfCells();
  r.Surface = Triangulated(surface);
  r.Topology = tpc::ComputeTopologyReport(r.Surface);
  vtkFieldData* fd = surface->GetFieldData();
  r.HausdorffBound = fd->GetArray("HausdorffBound")->GetTuple1(0);
  r.Guaranteed = fd->GetArray("TopologyGuaranteed")->GetTuple1(0) == 1.0;
  // The edge of the cells the size criterion stops at (diagonal <= the
  // absolute tolerance; plane sections may stay larger): root size / 2^level.
  const double tolerance = fd->GetArray("AbsoluteTolerance")->GetTuple1(0);
  const double rootSize = grid->GetXCoordinates()->GetTuple1(1) - grid->GetXCoordinates()->GetTuple1(0);
  r.SurfaceCellSize = std::ldexp(rootSize, -static_cast<int>(std::ceil(std::log2(rootSize * std::sqrt(3.0) / tolerance) - 1e-9)));
  r.PlanarCells = static_cast<long>(fd->GetArray("PlanarCells")->GetTuple1(0));
  // (Refined cells only: a leaf whose patch still fails the embedding check
  // carries PATCH_NOT_EMBEDDED too.)
  vtkDataArray* reasons = grid->GetCellData()->GetArray("SplitReason");
  vtkDataArray* states = grid->GetCellData()->GetArray("CellState");
  for (vtkIdType c = 0; reasons && states && c < reasons->GetNumberOfTuples(); ++c)
  {
    const int reason = static_cast<int>(reasons->GetTuple1(c));
    const bool refined = states->GetTuple1(c) == 4;
    r.RepairedCells += refined &&
        (reason == vtkTopologyPreservingContour::PATCH_NOT_EMBEDDED ||
          reason == vtkTopologyPreservingContour::PATCH_NOT_CERTIFIED)
      ? 1
      : 0;
  }
  if (!fingerprint.empty())
  {
    r.Fingerprint = Fingerprint(surface, grid, fingerprint != "geometry");
  }
  return r;
}

RunResult RunVtkRecipe(const tpcbench::Scene& scene, double h)
{
  const auto start = Clock::now();
  vtkNew<vtkSampleFunction> sample;
  sample->SetImplicitFunction(scene.SolidFunction());
  double bounds[6];
  int dims[3];
  for (int a = 0; a < 3; ++a)
  {
    bounds[2 * a] = scene.Bounds[2 * a] - 2.0 * h;
    dims[a] = static_cast<int>(std::ceil((scene.Bounds[2 * a + 1] - scene.Bounds[2 * a] + 4.0 * h) / h)) + 1;
    bounds[2 * a + 1] = bounds[2 * a] + (dims[a] - 1) * h;
  }
  sample->SetModelBounds(bounds);
  sample->SetSampleDimensions(dims);
  sample->SetOutputScalarTypeToFloat();
  sample->ComputeNormalsOff();
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputConnection(sample->GetOutputPort());
  contour->SetValue(0, 0.0);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  RunResult r;
  r.Seconds = std::chrono::duration<double>(Clock::now() - start).count();
  r.Triangles = contour->GetOutput()->GetNumberOfPolys();
  r.GridCells = static_cast<long long>(dims[0]) * dims[1] * dims[2];
  r.Surface = Triangulated(contour->GetOutput());
  r.Topology = tpc::ComputeTopologyReport(r.Surface);
  return r;
}

openvdb::FloatGrid::Ptr MeshLevelSet(vtkPolyData* surface, const openvdb::math::Transform& xform)
{
  const tpc::TriangleMesh mesh = Triangulated(surface);
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  for (const tpc::Vec3& p : mesh.Points)
  {
    points.emplace_back(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
  }
  for (const auto& t : mesh.Triangles)
  {
    triangles.emplace_back(t[0], t[1], t[2]);
  }
  return openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(xform, points, triangles, 3.0f);
}

RunResult RunOpenVdb(const tpcbench::Scene& scene, double h, double adaptivity)
{
  if (scene.Implicit && !scene.IsBall)
  {
    throw std::runtime_error("the OpenVDB baseline takes meshes, spheres and the plate, not " + scene.Name);
  }
  openvdb::initialize();
  const auto start = Clock::now();
  const auto xform = openvdb::math::Transform::createLinearTransform(h);
  openvdb::FloatGrid::Ptr solid;
  if (scene.IsBall)
  {
    const auto& b = scene.Ball;
    solid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(static_cast<float>(b[3]),
      openvdb::Vec3f(static_cast<float>(b[0]), static_cast<float>(b[1]), static_cast<float>(b[2])),
      static_cast<float>(h), 3.0f);
  }
  if (scene.HasPlate)
  {
    vtkNew<vtkCubeSource> plate;
    plate->SetBounds(scene.PlateBounds.data());
    plate->Update();
    solid = MeshLevelSet(plate->GetOutput(), *xform);
  }
  for (const auto& mesh : scene.Meshes)
  {
    openvdb::FloatGrid::Ptr next = MeshLevelSet(mesh, *xform);
    if (solid)
    {
      openvdb::tools::csgDifference(*solid, *next);
    }
    else
    {
      solid = next;
    }
  }
  for (const tpcbench::Ellipsoid& e : scene.Holes)
  {
    openvdb::FloatGrid::Ptr hole;
    if (e.SemiAxes[0] == e.SemiAxes[1] && e.SemiAxes[1] == e.SemiAxes[2])
    {
      hole = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(static_cast<float>(e.SemiAxes[0]),
        openvdb::Vec3f(static_cast<float>(e.Center[0]), static_cast<float>(e.Center[1]),
          static_cast<float>(e.Center[2])),
        static_cast<float>(h), 3.0f);
    }
    else
    {
      hole = MeshLevelSet(tpcbench::TessellateEllipsoid(e, 0.25 * h), *xform);
    }
    openvdb::tools::csgDifference(*solid, *hole);
  }
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*solid, points, triangles, quads, 0.0, adaptivity);
  RunResult r;
  r.Seconds = std::chrono::duration<double>(Clock::now() - start).count();
  r.Triangles = static_cast<long long>(triangles.size() + 2 * quads.size());
  r.GridCells = static_cast<long long>(solid->activeVoxelCount());
  tpc::TriangleMesh mesh;
  for (const auto& p : points)
  {
    mesh.Points.push_back(tpc::Vec3(p[0], p[1], p[2]));
  }
  for (const auto& t : triangles)
  {
    mesh.Triangles.push_back({ t[0], t[1], t[2] });
  }
  for (const auto& q : quads)
  {
    mesh.Triangles.push_back({ q[0], q[1], q[2] });
    mesh.Triangles.push_back({ q[0], q[2], q[3] });
  }
  r.Topology = tpc::ComputeTopologyReport(mesh);
  r.Surface = std::move(mesh);
  return r;
}
} // namespace

int main(int argc, char* argv[])
{
  std::map<std::string, std::string> args;
  for (int i = 1; i + 1 < argc; i += 2)
  {
    args[argv[i]] = argv[i + 1];
  }
  for (const char* required : { "--method", "--scene", "--epsilon", "--threads", "--meshes" })
  {
    if (!args.count(required))
    {
      std::cerr << "usage: tpc_benchmark --method tpc|vtk|vdb --scene NAME --epsilon E --threads N "
                   "--meshes DIR [--cell-size H] [--max-depth D] [--max-cells N] [--abort-at P] "
                   "[--fingerprint 1|geometry] [--adaptivity A] [--measure 1] [--decimate 1]\n";
      return 1;
    }
  }
  if (args.count("--fingerprint") && args["--fingerprint"] != "1" && args["--fingerprint"] != "geometry")
  {
    std::cerr << "tpc_benchmark: --fingerprint takes 1 (everything) or geometry (everything but the certified "
                 "errors), not " << args["--fingerprint"] << "\n";
    return 1;
  }
  const std::string method = args["--method"];
  const int threads = std::stoi(args["--threads"]);
  const double epsilon = std::stod(args["--epsilon"]);
  vtkSMPTools::Initialize(threads);
  tbb::global_control limitThreads(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));

  try
  {
    const tpcbench::Scene scene = tpcbench::MakeScene(args["--scene"], args["--meshes"]);
    const double h = args.count("--cell-size") ? std::stod(args["--cell-size"])
                                                : epsilon * Diagonal(scene.Bounds) / std::sqrt(3.0);
    const double before = ResidentMiB();
    RunResult r;
    if (method == "tpc")
    {
      r = RunFilter(scene, epsilon, args.count("--max-depth") ? std::stoi(args["--max-depth"]) : 0,
        args.count("--max-cells") ? std::stoll(args["--max-cells"]) : 0,
        args.count("--abort-at") ? std::stod(args["--abort-at"]) : 0.0,
        args.count("--fingerprint") ? args["--fingerprint"] : std::string(),
        args.count("--decimate") && args["--decimate"] == "1");
    }
    else if (method == "vtk")
    {
      r = RunVtkRecipe(scene, h);
    }
    else if (method == "vdb")
    {
      r = RunOpenVdb(scene, h, args.count("--adaptivity") ? std::stod(args["--adaptivity"]) : 0.0);
    }
    else
    {
      std::cerr << "unknown method " << method << "\n";
      return 1;
    }
    const double peak = std::max(0.0, PeakMiB() - before);
    const tpc::TopologyReport& t = r.Topology;
    const bool closed = t.BoundaryEdges == 0 && t.NonManifoldEdges == 0 && t.NonManifoldVertices == 0;
    std::ostringstream json;
    json << "{\"method\": \"" << method << "\", \"scene\": \"" << scene.Name << "\", \"epsilon\": " << epsilon
         << ", \"threads\": " << threads << ", \"seconds\": " << r.Seconds << ", \"peak_mib\": " << peak
         << ", \"triangles\": " << r.Triangles << ", \"grid_cells\": " << r.GridCells
         << ", \"components\": " << t.Components << ", \"genus\": " << t.Genus
         << ", \"closed_manifold\": " << (closed ? "true" : "false")
         << ", \"exact_components\": " << scene.Components << ", \"exact_genus\": " << scene.Genus
         << ", \"topology_right\": "
         << (closed && t.Components == scene.Components && t.Genus == scene.Genus ? "true" : "false")
         << ", \"cell_size\": " << (method == "tpc" ? r.SurfaceCellSize : h)
         << ", \"planar_cells\": " << r.PlanarCells << ", \"repaired_cells\": " << r.RepairedCells
         << ", \"guaranteed\": " << (r.Guaranteed ? "true" : "false")
         << ", \"longest_progress_gap_s\": " << r.LongestProgressGap
         << ", \"longest_progress_gap_at\": " << r.LongestProgressGapAt
         << ", \"abort_latency_s\": " << r.AbortLatency;
    // Errors relative to epsilon (absolute: epsilon times the domain's diagonal).
    const double absolute = epsilon * Diagonal(scene.Bounds);
    if (r.HausdorffBound >= 0.0)
    {
      json << ", \"hausdorff_bound_over_eps\": " << r.HausdorffBound / absolute;
    }
    if (scene.IsBall)
    {
      json << ", \"measured_hausdorff_over_eps\": "
           << MeasuredBallHausdorff(r.Surface, scene.Ball, 4 * absolute) / absolute;
    }
    else if (scene.Meshes.size() == 1 && scene.Holes.empty() && args.count("--measure"))
    {
      json << ", \"measured_hausdorff_over_eps\": "
           << MeasuredMeshHausdorff(r.Surface, scene.Meshes[0], 0.01 * absolute) / absolute;
    }
    if (!r.Fingerprint.empty())
    {
      json << ", \"fingerprint\": \"" << r.Fingerprint << "\", \"fingerprint_of\": \""
           << (args["--fingerprint"] == "geometry" ? "geometry" : "everything") << "\"";
    }
    json << "}";
    std::cout << json.str() << std::endl;
  }
  catch (const std::exception& e)
  {
    std::cerr << "tpc_benchmark: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
