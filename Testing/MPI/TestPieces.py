"""The filter under MPI: every rank computes its piece (UpdatePiece(rank, N, 0)
in a plain VTK pipeline, with pvbatch's global controller); the pieces,
welded by their exact coordinates, form one closed manifold surface with the
topology of a one-piece run, the report on every rank is the whole surface's,
and each rank's grid holds only its own trees.

Usage: mpirun -np N pvbatch --symmetric TestPieces.py <folder with the topologypreserving package> <work folder>
(with Testing/Python on PYTHONPATH)
"""
import os
import sys

sys.path.insert(0, sys.argv[1])
work = sys.argv[2]

from topologypreserving import vtkTopologyPreservingContour  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImplicitBoolean, vtkSphere, vtkCylinder  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkCleanPolyData  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter  # noqa: E402
from vtkmodules.vtkParallelCore import vtkMultiProcessController  # noqa: E402

from TopologyChecks import field, measure  # noqa: E402

controller = vtkMultiProcessController.GetGlobalController()
rank, ranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
os.makedirs(work, exist_ok=True)


def scene():
    """A sphere with a hole through it (genus 1) and a second sphere: 2 components."""
    body = vtkSphere()
    body.SetCenter(0.1, 0.2, 0.3)
    body.SetRadius(0.5)
    hole = vtkCylinder()
    hole.SetCenter(0.05, 0.0, 0.25)
    hole.SetRadius(0.2)
    pierced = vtkImplicitBoolean()
    pierced.SetOperationTypeToDifference()
    pierced.AddFunction(body)
    pierced.AddFunction(hole)
    other = vtkSphere()
    other.SetCenter(0.95, 0.2, 0.3)
    other.SetRadius(0.25)
    both = vtkImplicitBoolean()
    both.AddFunction(pierced)
    both.AddFunction(other)
    f = vtkTopologyPreservingContour()
    f.SetImplicitFunction(both)
    f.SetBounds(-0.45, 1.25, -0.35, 0.75, -0.25, 0.85)
    f.SetTolerance(0.01)
    return f


f = scene()
f.UpdatePiece(rank, ranks, 0)
piece = f.GetSurfaceOutput()
grid = f.GetGridOutput()
writer = vtkXMLPolyDataWriter()
writer.SetDataModeToBinary()
writer.SetInputData(piece)
writer.SetFileName(os.path.join(work, f"piece{rank}.vtp"))
writer.Write()
report = {name: field(piece, name) for name in ("Components", "Genus", "EulerCharacteristic", "TopologyGuaranteed",
                                                "Closed", "Manifold", "Embedded")}
trees = grid.GetMaxNumberOfTrees()
present = sum(1 for t in range(trees) if grid.GetTree(t) is not None)
print(f"rank {rank}: {piece.GetNumberOfPolys()} triangles, {present} of {trees} trees, report {report}", flush=True)
controller.Barrier()

failures = 0


def check(ok, what):
    global failures
    print(("ok   " if ok else "FAIL ") + f"rank {rank}: " + what, flush=True)
    failures += 0 if ok else 1


check(report["Components"] == 2 and report["Genus"] == 1 and report["Closed"] == 1 and report["Manifold"] == 1
      and report["Embedded"] == 1 and report["TopologyGuaranteed"] == 1, f"the report describes the whole surface: {report}")
check(0 < present < trees, "the grid holds this rank's own trees only")
if rank == 0:
    # The same scene as one piece (no collective call: piece 0 of 1).
    single = scene()
    single.Update()
    one = measure(single.GetSurfaceOutput())
    append = vtkAppendPolyData()
    for r in range(ranks):
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(os.path.join(work, f"piece{r}.vtp"))
        reader.Update()
        check(reader.GetOutput().GetNumberOfPolys() > 0, f"piece {r} has triangles")
        append.AddInputData(reader.GetOutput())
    weld = vtkCleanPolyData()  # exact: the pieces' seam vertices are bit-identical
    weld.SetInputConnection(append.GetOutputPort())
    weld.SetTolerance(0.0)
    weld.PointMergingOn()
    weld.Update()
    merged = measure(weld.GetOutput())
    print("one piece:", one, "merged pieces:", merged, flush=True)
    check(merged["boundary"] == 0 and merged["nonmanifold"] == 0, "the merged pieces are closed and manifold")
    check((merged["components"], merged["genus"]) == (one["components"], one["genus"]) == (2, 1),
          "the merged pieces have the topology of the one-piece run (2 components, genus 1)")
    check(report["EulerCharacteristic"] == merged["euler"], "the reported Euler characteristic is the merged one")
controller.Barrier()
if failures:
    # (Not sys.exit: pvbatch must finalize MPI; an exception makes it exit 1.)
    raise RuntimeError(f"rank {rank}: {failures} check(s) failed")
