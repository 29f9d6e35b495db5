/**
 * @class   vtkTopologyPreservingContour
 * @brief   Surface of a CSG solid with guaranteed topology, by adaptive subdivision.
 *
 * vtkTopologyPreservingContour implements Varadhan, Krishnan, Sriram and
 * Manocha, "Topology Preserving Surface Extraction Using Adaptive
 * Subdivision" (SGP 2004). It builds an adaptive octree over the solid's
 * field in which every cell that meets the surface passes the paper's
 * complex-cell test (complex voxel, face and edge; face and voxel sign
 * ambiguity) and star-shaped test (w.r.t. the voxel and each face, proven with
 * interval arithmetic), and is no larger than the tolerance. A Marching-Cubes-
 * like extraction with crack patching then gives a closed, manifold,
 * outward-oriented, embedded (no self-intersection or self-touching)
 * triangle surface with the same number of components and the same genus as
 * the exact surface, within a two-sided Hausdorff distance of Tolerance.
 *
 * Inputs
 * - Input port 0 (optional, repeatable): closed triangle meshes (vtkPolyData;
 *   polygons and strips are triangulated), one solid per connection. Each is
 *   checked and repaired (duplicate vertices, degenerate and duplicate
 *   triangles, orientation), with a warning saying what was done (points
 *   at exactly the same coordinates are merged silently); an open mesh is
 *   an error, or with FillHoles closed and reported; non-manifold or
 *   self-intersecting input is computed with TopologyGuaranteed = 0.
 *   Inside/outside is exact (ray parity with exact predicates).
 * - ImplicitFunction: vtkSphere, vtkQuadric, vtkBox, vtkCylinder, vtkPlane and
 *   vtkImplicitBoolean trees of them (Union, Intersection, Difference), each
 *   honouring its linear Transform. The solid is where the function is < 0.
 * - Operation folds the input solids in connection order (last to first
 *   with ReverseInputOrder), then the implicit function: ((S0 op S1) op ...)
 *   op F.
 *
 * Outputs
 * - Port 0, vtkPolyData: the surface, triangles with point "Normals" and
 *   cell data "GridCell" (the hyper tree grid cell each triangle was
 *   extracted from) and "SolidId" (the solid whose surface the triangle lies
 *   on: its input connection index, the number of input connections for the
 *   ImplicitFunction, -1 on a cap of Bounds). With SplitCreases, points along
 *   creases are split for shading and "SurfacePointId" maps them back.
 * - Port 1, vtkHyperTreeGrid: the adaptive grid. Cell data: "Depth" (level),
 *   "SplitReason" (why the cell was split, see SplitReasons; NOT_SPLIT on
 *   leaves), "SizeReason" (the parent's SplitReason: why the cell is as small
 *   as it is; the active scalars, as renderers draw leaves), "CellState"
 *   (0 inside, 1 outside, 2 surface cell that passed every test, 3 surface cell
 *   stopped by a limit or whose patch failed the embedding check after the
 *   repair rounds, 4 refined,
 *   5 exact: a cell of one input mesh the tests could not resolve, whose patch
 *   is that mesh clipped to it), "FailedTest" (for states 3 and 5, the
 *   test that failed, as a SplitReasons value) and "CertifiedError" (on
 *   surface cells where one quadric or one input mesh is the surface: the
 *   certified two-sided Hausdorff error of the cell's patch, which lets such
 *   cells be larger than epsilon; NaN elsewhere). Field data "SplitReasonNames" and
 *   "CellStateNames" (string arrays indexed by value) name the values.
 * - Field data on both: "Components", "Genus", "EulerCharacteristic",
 *   "TopologyGuaranteed" (1 only if every cell on the surface passed every
 *   test, the inputs meet the method's assumptions, and the output is closed,
 *   manifold, outward oriented and embedded), "UnresolvedCells" (surface cells
 *   stopped by a limit), "Closed", "Manifold", "Embedded" (1 when the exact
 *   check found no two triangles meeting but in a shared edge or vertex, no
 *   two vertices at the same coordinates and no degenerate triangle),
 *   "Outward" (1 when every component's normals point out of the solid:
 *   each one's enclosed volume has the sign its nesting in the others asks,
 *   checked on the whole surface; in a run split among processes, by the
 *   patches' construction),
 *   "HausdorffBound" (the proven two-sided bound: the largest diagonal of a
 *   cell holding surface, except that cells where the surface is a plane
 *   section count the finest lattice cell's and cells with a CertifiedError
 *   count that error (or their diagonal if smaller); NaN when not proven: a limit
 *   stopped a cell that may hold surface without a patch), "PlanarCells" (surface cells
 *   kept larger than epsilon because the surface in them is a plane section -
 *   a plane, a box face or coplanar mesh triangles - so their patch is exact),
 *   "ExactCells" (cells whose patch is the input mesh clipped to them)
 *   and "AbsoluteTolerance" (epsilon in world units).
 *
 * A cell whose final patch (drawn after crack patching, over its neighbours'
 * samples) is not certified within epsilon, or fails the embedding check, is
 * split and the subdivision runs again on the same lattice, up to three
 * rounds (SplitReason PATCH_NOT_CERTIFIED, PATCH_NOT_EMBEDDED); the
 * guarantee is decided on the last surface.
 *
 * An empty solid gives empty outputs, a warning, and the report of the
 * empty surface (guaranteed where the inputs meet the assumptions, 0
 * components, genus 0, closed; AbsoluteTolerance NaN when the solid's bounds
 * proved it empty before a domain was chosen and Tolerance is relative,
 * without Region).
 *
 * When the guarantee cannot be reached (tangential contact, depth or cell
 * limit) the filter still outputs a closed manifold surface, sets
 * TopologyGuaranteed to 0, marks the cells (CellState 3, SplitReason
 * LIMIT_REACHED) and warns. Where two surfaces face each other closer than
 * the finest cell (solids touching along a face, a slab or gap thinner than
 * the finest cell) refinement cannot succeed and grows like an area: such
 * cells are stopped as soon as they are as small as the tolerance asks
 * (CellState 3, SplitReason SURFACES_TOO_CLOSE).
 *
 * Progress and Abort: every stage reports progress in chunks (inputs
 * [0, 0.08], subdivision, extraction, embedding check and topology report
 * [0.08, 0.97], grid output [0.97, 1]) and checks AbortExecute at each
 * report. An abort (SetAbortExecute(1) during the run, ParaView's abort
 * button) returns empty outputs with a warning, clears AbortExecute, and
 * leaves the outputs up to date, as VTK filters did before 9.2: the filter
 * runs again when a property or an input changes, or after Modified().
 *
 * Threads: the subdivision and extraction loops use vtkSMPTools; set
 * VTK_SMP_BACKEND_IN_USE=STDThread (the default backend is sequential).
 */
#ifndef vtkTopologyPreservingContour_h
#define vtkTopologyPreservingContour_h

#include "vtkAlgorithm.h"
#include "vtkTopologyPreservingFiltersModule.h" // For export macro

class vtkImplicitFunction;
class vtkHyperTreeGrid;
class vtkPolyData;

class VTKTOPOLOGYPRESERVINGFILTERS_EXPORT vtkTopologyPreservingContour : public vtkAlgorithm
{
public:
  static vtkTopologyPreservingContour* New();
  vtkTypeMacro(vtkTopologyPreservingContour, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// How the solids are combined.
  enum Operations
  {
    UNION = 0,
    INTERSECTION = 1,
    DIFFERENCE = 2
  };

  /// Values of the "SplitReason" and "FailedTest" cell arrays.
  enum SplitReasons
  {
    NOT_SPLIT = 0,
    COMPLEX_VOXEL = 1,
    COMPLEX_FACE = 2,
    COMPLEX_EDGE = 3,
    FACE_AMBIGUITY = 4,
    VOXEL_AMBIGUITY = 5,
    NOT_STAR_SHAPED_VOXEL = 6,
    NOT_STAR_SHAPED_FACE = 7,
    HAUSDORFF_SIZE = 8,
    LIMIT_REACHED = 9,
    SURFACES_TOO_CLOSE = 10,
    PATCH_NOT_EMBEDDED = 11,
    CREASE_NOT_FOLLOWED = 12,
    PATCH_NOT_CERTIFIED = 13
  };

  ///@{
  /**
   * Mesh solids without a pipeline connection (like vtkPolyDataAlgorithm's):
   * SetInputData replaces the input port's connections with one mesh,
   * AddInputData adds one more solid.
   */
  void SetInputData(vtkDataObject* mesh) { this->SetInputDataObject(0, mesh); }
  void AddInputData(vtkDataObject* mesh) { this->AddInputDataObject(0, mesh); }
  ///@}

  ///@{
  /**
   * The implicit function defining (or combined with) the solid; the solid is
   * where it is negative. Default: none.
   */
  virtual void SetImplicitFunction(vtkImplicitFunction*);
  vtkGetObjectMacro(ImplicitFunction, vtkImplicitFunction);
  ///@}

  ///@{
  /**
   * Operation combining the input solids and the implicit function.
   * Default: UNION.
   */
  vtkSetClampMacro(Operation, int, UNION, DIFFERENCE);
  vtkGetMacro(Operation, int);
  void SetOperationToUnion() { this->SetOperation(UNION); }
  void SetOperationToIntersection() { this->SetOperation(INTERSECTION); }
  void SetOperationToDifference() { this->SetOperation(DIFFERENCE); }
  ///@}

  ///@{
  /**
   * Fold the input solids in the reverse of their connection order (the
   * last connected first: the minuend of a Difference). ParaView connects
   * inputs in the order they were selected; this reverses it without
   * reconnecting. Default: off.
   */
  vtkSetMacro(ReverseInputOrder, bool);
  vtkGetMacro(ReverseInputOrder, bool);
  vtkBooleanMacro(ReverseInputOrder, bool);
  ///@}

  ///@{
  /**
   * Close the holes of open input meshes (every loop of boundary edges, once
   * exactly coincident points are merged, is filled by a polygon) instead of
   * refusing them; the filled triangles are reported as a repair. Default:
   * off - an open mesh is refused with an error saying so.
   */
  vtkSetMacro(FillHoles, bool);
  vtkGetMacro(FillHoles, bool);
  vtkBooleanMacro(FillHoles, bool);
  ///@}

  ///@{
  /**
   * Domain (xmin, xmax, ymin, ymax, zmin, zmax). The solid is clipped to it
   * (and capped, so the surface stays closed) where it reaches a side of it;
   * a side that the solid's bounds lie strictly within cuts nothing and is
   * left out (a mesh inside Bounds is remeshed as one mesh). Default: invalid
   * (xmin > xmax), meaning "derive from the inputs"; an unbounded solid (a
   * plane, a cylinder) then needs explicit Bounds.
   */
  vtkSetVector6Macro(Bounds, double);
  vtkGetVector6Macro(Bounds, double);
  ///@}

  ///@{
  /**
   * Two-sided Hausdorff bound epsilon between the exact surface and the
   * output. Relative to the domain diagonal when ToleranceIsRelative is on
   * (default), absolute otherwise. Default 0.01.
   */
  vtkSetMacro(Tolerance, double);
  vtkGetMacro(Tolerance, double);
  vtkSetMacro(ToleranceIsRelative, bool);
  vtkGetMacro(ToleranceIsRelative, bool);
  vtkBooleanMacro(ToleranceIsRelative, bool);
  ///@}

  ///@{
  /**
   * Safety limits against runaway refinement (tangential contact never passes
   * the tests). Cells stopped by them are marked and the guarantee flag is 0.
   * MaximumDepth defaults to 40, the lattice's end (2^-41 of the domain; less
   * far from the origin, where the coordinates' doubles run out first):
   * refinement below the tolerance's cells happens only where a topology test
   * fails (a thin wedge's edge, a near contact), so the limit costs nothing
   * where it is not needed. Lower it to cap the time spent on such places.
   * Defaults: 40 and 10 000 000. Memory: at most about 100 MiB + 800 bytes x
   * MaximumNumberOfCells beyond the inputs.
   */
  vtkSetClampMacro(MaximumDepth, int, 0, 40);
  vtkGetMacro(MaximumDepth, int);
  vtkSetMacro(MaximumNumberOfCells, vtkIdType);
  vtkGetMacro(MaximumNumberOfCells, vtkIdType);
  ///@}

  ///@{
  /**
   * Decimate the surface after the extraction: vertices are removed by edge
   * collapses, each one kept only when it is certified - the two-sided
   * Hausdorff bound to the exact surface stays within Tolerance (each
   * triangle carries a proven bound, started from its cell's and carried
   * through every collapse by a branch and bound), no triangle meets another
   * other than in what they share (exact predicates), the link condition
   * holds (the topology is kept), and features stay: vertices on creases of
   * 30 degrees or more, or where two inputs' surfaces meet, move only along
   * them, corners never, and no collapse makes a new crease. The report
   * (HausdorffBound, Embedded, TopologyGuaranteed) describes the decimated
   * surface; its GridCell names the cell of the patch each triangle
   * descends from, which a decimated triangle may leave. Not applied in a
   * piece of a distributed run, nor when the extraction was not embedded.
   * Default: off.
   */
  vtkSetMacro(Decimate, bool);
  vtkGetMacro(Decimate, bool);
  vtkBooleanMacro(Decimate, bool);
  ///@}

  ///@{
  /**
   * Shade creases crisply: give each point of the surface where two or more
   * creases meet (edges whose triangles' normals differ by CreaseAngle
   * degrees or more) one point per wedge of triangles between them, each
   * with its wedge's normal, as vtkPolyDataNormals' Splitting does. The
   * copies keep their original's coordinates, so the surface is the same
   * closed, embedded point set and the topology report stands, but its
   * triangles no longer share points across creases: an edge-based check of
   * closedness then sees boundaries there. The point array "SurfacePointId"
   * maps every point to the point of the unsplit surface (of this piece,
   * in a distributed run); merging by it, or merging points at equal
   * coordinates (vtkStaticCleanPolyData, tolerance 0), recovers it. Default: off in VTK (the
   * output is the closed indexed surface), on in the ParaView plugin (its
   * default rendering). CreaseAngle: 30 degrees, clamped to [0, 180].
   */
  vtkSetMacro(SplitCreases, bool);
  vtkGetMacro(SplitCreases, bool);
  vtkBooleanMacro(SplitCreases, bool);
  vtkSetClampMacro(CreaseAngle, double, 0.0, 180.0);
  vtkGetMacro(CreaseAngle, double);
  ///@}

  /// Outputs: the surface (port 0) and the adaptive grid (port 1).
  vtkPolyData* GetSurfaceOutput();
  vtkHyperTreeGrid* GetGridOutput();

  vtkMTimeType GetMTime() override;

  vtkTypeBool ProcessRequest(
    vtkInformation* request, vtkInformationVector** inInfo, vtkInformationVector* outInfo) override;

protected:
  vtkTopologyPreservingContour();
  ~vtkTopologyPreservingContour() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*);

  vtkImplicitFunction* ImplicitFunction = nullptr;
  int Operation = UNION;
  bool ReverseInputOrder = false;
  bool FillHoles = false;
  double Bounds[6] = { 0.0, -1.0, 0.0, -1.0, 0.0, -1.0 };
  double Tolerance = 0.01;
  bool ToleranceIsRelative = true;
  int MaximumDepth = 40;
  vtkIdType MaximumNumberOfCells = 10000000;
  bool Decimate = false;
  bool SplitCreases = false;
  double CreaseAngle = 30.0;

private:
  vtkTopologyPreservingContour(const vtkTopologyPreservingContour&) = delete;
  void operator=(const vtkTopologyPreservingContour&) = delete;
};

#endif
