"""The plugin under `mpirun -np 2 pvbatch` (the script runs on rank 0, the
filter on both ranks, as for pvserver): a sphere mesh minus an implicit
cylinder (genus 1). The surface fetched from both ranks is closed and
manifold with the topology of a one-piece run, the report is the whole
surface's, and ParaView renders the distributed grid and surface.

Usage: mpirun -np 2 pvbatch TestParaViewRanks.py <plugin .so> <build>/lib/python3/site-packages <work folder>
(with Testing/Python on PYTHONPATH)
"""
import os
import sys

plugin, site_packages, work = sys.argv[1:4]
sys.path.insert(0, site_packages)
os.makedirs(work, exist_ok=True)

from paraview import servermanager  # noqa: E402
from paraview.simple import (CreateRenderView, LoadPlugin, OutputPort, Render, SaveScreenshot,  # noqa: E402
                             Show, Sphere)
from TopologyChecks import check, field, measure  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkCleanPolyData  # noqa: E402

failures = []
LoadPlugin(plugin, ns=globals())
check(servermanager.ActiveConnection.GetNumberOfDataPartitions() == 2, "the filter runs on 2 ranks", failures)

ball = Sphere(Radius=0.5, ThetaResolution=64, PhiResolution=64)
contour = TopologyPreservingContour(Input=ball, ImplicitFunction="Cylinder", Operation="Difference")  # noqa: F821
contour.ImplicitFunction.Radius = 0.2
contour.Tolerance = 0.02
contour.UpdatePipeline()

surface = servermanager.Fetch(contour)  # the ranks' pieces, appended
weld = vtkCleanPolyData()
weld.SetInputData(surface)
weld.SetTolerance(0.0)
weld.Update()
# Welding also merges the copies SplitCreases (the plugin's default) made
# along creases; their SurfacePointId numbers each rank's own piece, so it
# is dropped rather than followed.
weld.GetOutput().GetPointData().RemoveArray("SurfacePointId")
m = measure(weld.GetOutput())
print("fetched surface:", m, flush=True)
check(m["boundary"] == 0 and m["nonmanifold"] == 0, "the pieces weld into a closed manifold surface", failures)
check((m["components"], m["genus"]) == (1, 1), "one component of genus 1", failures)
check(field(surface, "TopologyGuaranteed") == 1 and field(surface, "Genus") == 1
      and field(surface, "EulerCharacteristic") == m["euler"], "the report is the whole surface's", failures)

# The same as one piece, with the wrapped class on this process.
from topologypreserving import vtkTopologyPreservingContour  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkCylinder  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkSphereSource  # noqa: E402

source = vtkSphereSource()
source.SetRadius(0.5)
source.SetThetaResolution(64)
source.SetPhiResolution(64)
hole = vtkCylinder()
hole.SetRadius(0.2)
one = vtkTopologyPreservingContour()
one.SetInputConnection(source.GetOutputPort())
one.SetImplicitFunction(hole)
one.SetOperationToDifference()
one.SetTolerance(0.02)
one.Update()
single = measure(one.GetSurfaceOutput())
check((single["components"], single["genus"], single["euler"]) == (m["components"], m["genus"], m["euler"]),
      f"the same topology as one piece {single}", failures)

view = CreateRenderView()
view.ViewSize = [400, 300]
Show(OutputPort(contour, 1), view).SetRepresentationType("Outline")
Show(OutputPort(contour, 0), view)
Render(view)
picture = os.path.join(work, "two-ranks.png")
SaveScreenshot(picture, view)
check(os.path.exists(picture) and os.path.getsize(picture) > 2000, "ParaView renders the distributed outputs", failures)

if failures:
    raise RuntimeError(f"{len(failures)} check(s) failed")
