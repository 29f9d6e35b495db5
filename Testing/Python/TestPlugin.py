"""The ParaView plugin: load it in pvpython, run the proxy, compare with the wrapped class;
paraview.simple's functions that take a proxy's first port get the surface; the default
implicit functions cut a round part generically; SolidId and the input order.

Usage: pvpython TestPlugin.py <plugin .so> <build>/lib/python3/site-packages
"""
import os
import sys

sys.path.insert(0, sys.argv[2])
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from paraview import servermanager  # noqa: E402
from paraview.simple import Clean, Cylinder, LoadPlugin, SaveData, Sphere  # noqa: E402
from TopologyChecks import check, field, measure  # noqa: E402

failures = []
LoadPlugin(sys.argv[1], ns=globals())

proxy = TopologyPreservingContour(ImplicitFunction="Sphere")  # noqa: F821 (from the plugin)
proxy.ImplicitFunction.Center = [0.1, 0.2, 0.3]
proxy.ImplicitFunction.Radius = 0.5
proxy.Tolerance = 0.02
proxy.UpdatePipeline()

check(proxy.GetDataInformation(0).GetDataSetTypeAsString() == "vtkPolyData",
      "output port 0 is the surface", failures)
check(proxy.GetDataInformation(1).GetDataSetTypeAsString() == "vtkHyperTreeGrid",
      "output port 1 is the adaptive grid", failures)
check(proxy.GetDataInformation(0).GetNumberOfCells() > 0, "surface has triangles", failures)

surface = servermanager.Fetch(proxy)
m = measure(surface)
check(field(surface, "TopologyGuaranteed") == 1, "guarantee holds", failures)
check(field(surface, "Outward") == 1, "every component points out of the solid", failures)
check(field(surface, "Components") == 1 and m["components"] == 1, "one component", failures)
check(field(surface, "Genus") == 0 and m["genus"] == 0, "genus 0", failures)
check(m["boundary"] == 0 and m["nonmanifold"] == 0, "closed and manifold", failures)

# The same scene with the Python-wrapped class gives the same surface.
from topologypreserving import vtkTopologyPreservingContour  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkSphere  # noqa: E402

sphere = vtkSphere()
sphere.SetCenter(0.1, 0.2, 0.3)
sphere.SetRadius(0.5)
f = vtkTopologyPreservingContour()
f.SetImplicitFunction(sphere)
f.SetTolerance(0.02)
f.SplitCreasesOn()  # the plugin's default (VTK's is off)
f.Update()
direct = f.GetOutputDataObject(0)
check(direct.GetNumberOfPolys() == surface.GetNumberOfPolys()
      and direct.GetNumberOfPoints() == surface.GetNumberOfPoints(),
      "plugin and wrapped class give the same surface", failures)

# ParaView's implicit-function widgets (as Clip offers them), with Bounds
# equal to the box's own bounds (coincident planes) and a plane Offset.
for name, setup, genus in (("Plane", lambda fn: setattr(fn, "Offset", 0.3), 0),
                           ("Box", lambda fn: None, 0),
                           ("Sphere", lambda fn: None, 0),
                           ("Cylinder", lambda fn: None, 0)):
    widget = TopologyPreservingContour(Input=[], ImplicitFunction=name)  # noqa: F821
    setup(widget.ImplicitFunction)
    widget.Bounds = [-1, 1, -1, 1, -1, 1]
    widget.Tolerance = 0.02
    widget.UpdatePipeline()
    out = servermanager.Fetch(widget)
    m = measure(out)
    check(field(out, "TopologyGuaranteed") == 1 and m["genus"] == genus and m["components"] == 1
          and m["boundary"] == 0, f"ParaView's {name} widget function", failures)
    if name == "Plane":
        fn = widget.ImplicitFunction  # the solid is behind the plane moved by Offset along its normal
        expected = fn.Origin[0] + fn.Offset * fn.Normal[0]
        check(list(fn.Normal) == [1, 0, 0] and abs(out.GetBounds()[1] - expected) < 1e-6,
              f"the plane's Offset is honoured ({out.GetBounds()[1]} vs {expected})", failures)

# Issue 17: the plugin splits points along creases (SplitCreases, on by
# default here, off in VTK), so a cube's every point carries its face's
# normals and the edges shade crisply (no crease has its two triangles sharing
# points, 91 do unsplit; 184 before crease cells were fanned from a crease
# point, which draws a crease as one output edge per cell instead of two).
# The cube is tilted off the lattice's axes, its edges rebuilt as output edges
# (crease tiles).
def shared_creases(mesh):
    """Edges of 30 degrees or more whose two triangles share both points: where point
    normals are averaged across a crease."""
    from vtkmodules.vtkFiltersCore import vtkFeatureEdges
    edges = vtkFeatureEdges()
    edges.SetInputData(mesh)
    edges.BoundaryEdgesOff()
    edges.NonManifoldEdgesOff()
    edges.ManifoldEdgesOff()
    edges.FeatureEdgesOn()
    edges.SetFeatureAngle(30.0)
    edges.Update()
    return edges.GetOutput().GetNumberOfCells()


from paraview.simple import Box, Transform  # noqa: E402
tilted = Transform(Input=Box(XLength=1.0, YLength=1.0, ZLength=1.0))
tilted.Transform.Rotate = [17.0, 29.0, 41.0]
crisp = TopologyPreservingContour(Input=tilted)  # noqa: F821
crisp.Tolerance = 1.0 / 64
crisp.UpdatePipeline()
split = servermanager.Fetch(crisp)
crisp.SplitCreases = 0
crisp.UpdatePipeline()
closed = servermanager.Fetch(crisp)
m = measure(split)  # through SurfacePointId
check(field(split, "TopologyGuaranteed") == 1 and m["boundary"] == 0 and m["genus"] == 0
      and split.GetPointData().GetArray("SurfacePointId") is not None
      and closed.GetPointData().GetArray("SurfacePointId") is None
      and split.GetNumberOfPoints() > closed.GetNumberOfPoints()
      and shared_creases(split) == 0 and shared_creases(closed) > 45,
      f"SplitCreases gives each face of a tilted cube its own points ({split.GetNumberOfPoints()} points,"
      f" {closed.GetNumberOfPoints()} unsplit; creases across shared points {shared_creases(split)}, unsplit"
      f" {shared_creases(closed)})", failures)

# Decimate (off by default): the tilted cube's faces lose their inner
# vertices, the guarantee and the topology stay.
crisp.Decimate = 1
crisp.UpdatePipeline()
decimated = servermanager.Fetch(crisp)
m = measure(decimated)
check(field(decimated, "TopologyGuaranteed") == 1 and m["boundary"] == 0 and m["genus"] == 0
      and field(decimated, "HausdorffBound") <= field(decimated, "AbsoluteTolerance") * (1 + 1e-9)
      and 2 * decimated.GetNumberOfPolys() < closed.GetNumberOfPolys(),
      f"Decimate: the tilted cube guaranteed on {decimated.GetNumberOfPolys()} triangles"
      f" ({closed.GetNumberOfPolys()} without)", failures)
crisp.Decimate = 0

# Issue 18: the surface is port 0, so what paraview.simple does with a proxy's
# first port - SaveData, Fetch, a filter's Input - takes the surface.
work = os.environ.get("TPC_WORK", os.getcwd())
stl = os.path.join(work, "plugin-surface.stl")
SaveData(stl, proxy=proxy)
from vtkmodules.vtkIOGeometry import vtkSTLReader  # noqa: E402
reader = vtkSTLReader()
reader.SetFileName(stl)
reader.Update()
check(reader.GetOutput().GetNumberOfPolys() == surface.GetNumberOfPolys(),
      f"SaveData(stl, proxy=...) writes the surface ({reader.GetOutput().GetNumberOfPolys()} triangles)", failures)
cleaned = Clean(Input=proxy)
cleaned.UpdatePipeline()
check(cleaned.GetDataInformation().GetDataSetTypeAsString() == "vtkPolyData"
      and cleaned.GetDataInformation().GetNumberOfCells() == surface.GetNumberOfPolys(),
      "Clean(Input=tpc) cleans the surface", failures)

# The default implicit functions, subtracted from a round capped part whose
# wall ParaView's own default cylinder touches: a generic cut, guaranteed,
# that leaves a solid of one component (the part's wall is not cut through).
# ParaView's default sphere (radius 0.74 about the part's centre) holds the
# whole part - the difference would be empty, checking nothing - so the
# sphere is moved to the top face and shrunk: it cuts a dimple.
part = Cylinder(Radius=0.5, Height=1.0, Resolution=64, Capping=1)
for name in ("Sphere", "Box", "Cylinder", "Plane"):
    cut = TopologyPreservingContour(Input=part, ImplicitFunction=name, Operation="Difference")  # noqa: F821
    if name == "Sphere":
        cut.ImplicitFunction.Center = [0.0, 0.5, 0.0]
        cut.ImplicitFunction.Radius = 0.3
    cut.Tolerance = 0.02
    cut.UpdatePipeline()
    out = servermanager.Fetch(cut)
    m = measure(out)
    check(out.GetNumberOfPolys() > 0 and field(out, "TopologyGuaranteed") == 1
          and field(out, "UnresolvedCells") == 0 and field(out, "Components") == 1 and m["components"] == 1
          and m["boundary"] == 0 and m["nonmanifold"] == 0,
          f"the default {name} cuts a round part generically ({out.GetNumberOfPolys()} triangles, guaranteed "
          f"{field(out, 'TopologyGuaranteed')}, {field(out, 'UnresolvedCells')} unresolved)", failures)

# SolidId: the part is connection 0, the ball connection 1; reversed, the
# ball comes first: part - ball and ball - part have different volumes.
ball = Sphere(Radius=0.3, Center=[0.35, 0, 0], ThetaResolution=32, PhiResolution=24)
pair = TopologyPreservingContour(Input=[part, ball], Operation="Difference")  # noqa: F821
pair.Tolerance = 0.02
pair.UpdatePipeline()
forward = servermanager.Fetch(pair)
ids = forward.GetCellData().GetArray("SolidId")
check(ids is not None and sorted(set(ids.GetValue(i) for i in range(ids.GetNumberOfTuples()))) == [0, 1],
      "SolidId names the part (0) and the ball (1)", failures)
certified = forward.GetCellData().GetArray("CertifiedError")
check(certified is not None and certified.GetNumberOfTuples() == forward.GetNumberOfPolys()
      and 0 < certified.GetRange()[1] <= field(forward, "HausdorffBound") * (1 + 1e-12),
      "CertifiedError: one bound per triangle, the largest at most HausdorffBound", failures)
pair.ReverseInputOrder = 1
pair.UpdatePipeline()
reverse = servermanager.Fetch(pair)


def volume(mesh):
    from vtkmodules.vtkFiltersCore import vtkMassProperties
    mass = vtkMassProperties()
    mass.SetInputData(mesh)
    mass.Update()
    return mass.GetVolume()


check(volume(reverse) < 0.5 * volume(forward),
      f"ReverseInputOrder: ball - part is the smaller solid ({volume(reverse):.3f} vs {volume(forward):.3f})",
      failures)

print("plugin:", "OK" if not failures else failures)
sys.exit(1 if failures else 0)
