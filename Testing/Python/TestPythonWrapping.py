"""The Python-wrapped filter: `from topologypreserving import vtkTopologyPreservingContour`.

Usage: pvpython TestPythonWrapping.py <build>/lib/python3/site-packages
"""
import os
import sys

sys.path.insert(0, sys.argv[1])
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from topologypreserving import vtkTopologyPreservingContour  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkBox, vtkCylinder, vtkImplicitBoolean, vtkSphere  # noqa: E402
from vtkmodules.vtkCommonTransforms import vtkTransform  # noqa: E402
from TopologyChecks import check, field, measure  # noqa: E402

failures = []

# Box minus a cylinder through it: genus 1.
box = vtkBox()
box.SetBounds(-0.5, 0.5, -0.5, 0.5, -0.3, 0.3)
cylinder = vtkCylinder()
cylinder.SetAxis(0, 0, 1)
cylinder.SetRadius(0.2)
difference = vtkImplicitBoolean()
difference.SetOperationTypeToDifference()
difference.AddFunction(box)
difference.AddFunction(cylinder)

f = vtkTopologyPreservingContour()
f.SetImplicitFunction(difference)
f.SetTolerance(0.02)
f.Update()
surface = f.GetOutputDataObject(0)
grid = f.GetOutputDataObject(1)
m = measure(surface)
check(surface.GetNumberOfPolys() > 0, "surface has triangles", failures)
check(grid.GetClassName() == "vtkHyperTreeGrid", "port 0 is a vtkHyperTreeGrid", failures)
check(field(surface, "TopologyGuaranteed") == 1, "guarantee holds", failures)
check(field(surface, "Genus") == 1 and m["genus"] == 1, "genus 1 (reported and measured)", failures)
check(field(surface, "Components") == 1 and m["components"] == 1, "one component", failures)
check(m["boundary"] == 0 and m["nonmanifold"] == 0, "closed and manifold", failures)
check(field(grid, "Genus") == 1, "the grid carries the report too", failures)
check(surface.GetPointData().GetNormals() is not None, "point normals", failures)

# A transformed (rotated, scaled) sphere: an ellipsoid, genus 0.
sphere = vtkSphere()
sphere.SetRadius(1.0)
t = vtkTransform()
t.RotateZ(25)
t.Scale(1 / 0.6, 1 / 0.3, 1 / 0.2)
sphere.SetTransform(t)
f.SetImplicitFunction(sphere)
f.SetTolerance(0.02)
f.Update()
surface = f.GetOutputDataObject(0)
m = measure(surface)
check(field(surface, "TopologyGuaranteed") == 1, "ellipsoid: guarantee holds", failures)
check(m["genus"] == 0 and m["components"] == 1, "ellipsoid: genus 0, one component", failures)
bounds = surface.GetBounds()
check(abs(bounds[5] - 0.2) < 0.02, "ellipsoid z extent honours the transform", failures)

print("python wrapping:", "OK" if not failures else failures)
sys.exit(1 if failures else 0)
