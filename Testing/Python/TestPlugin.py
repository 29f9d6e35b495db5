"""The ParaView plugin: load it in pvpython, run the proxy, compare with the wrapped class.

Usage: pvpython TestPlugin.py <plugin .so> <build>/lib/python3/site-packages
"""
import os
import sys

sys.path.insert(0, sys.argv[2])
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from paraview import servermanager  # noqa: E402
from paraview.simple import LoadPlugin  # noqa: E402
from TopologyChecks import check, field, measure  # noqa: E402

failures = []
LoadPlugin(sys.argv[1], ns=globals())

proxy = TopologyPreservingContour(ImplicitFunction="Sphere")  # noqa: F821 (from the plugin)
proxy.ImplicitFunction.Center = [0.1, 0.2, 0.3]
proxy.ImplicitFunction.Radius = 0.5
proxy.Tolerance = 0.02
proxy.UpdatePipeline()

check(proxy.GetDataInformation(0).GetDataSetTypeAsString() == "vtkHyperTreeGrid",
      "output port 0 is the adaptive grid", failures)
check(proxy.GetDataInformation(1).GetDataSetTypeAsString() == "vtkPolyData",
      "output port 1 is the surface", failures)
check(proxy.GetDataInformation(1).GetNumberOfCells() > 0, "surface has triangles", failures)

surface = servermanager.Fetch(proxy, idx=1)
m = measure(surface)
check(field(surface, "TopologyGuaranteed") == 1, "guarantee holds", failures)
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
f.Update()
direct = f.GetOutputDataObject(1)
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
    out = servermanager.Fetch(widget, idx=1)
    m = measure(out)
    check(field(out, "TopologyGuaranteed") == 1 and m["genus"] == genus and m["components"] == 1
          and m["boundary"] == 0, f"ParaView's {name} widget function", failures)
    if name == "Plane":
        fn = widget.ImplicitFunction  # the solid is behind the plane moved by Offset along its normal
        expected = fn.Origin[0] + fn.Offset * fn.Normal[0]
        check(list(fn.Normal) == [1, 0, 0] and abs(out.GetBounds()[1] - expected) < 1e-6,
              f"the plane's Offset is honoured ({out.GetBounds()[1]} vs {expected})", failures)

print("plugin:", "OK" if not failures else failures)
sys.exit(1 if failures else 0)
