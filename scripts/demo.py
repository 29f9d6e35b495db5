"""Demo: the textbook CSG solid (cube ∩ sphere) − (three cylinders), contoured
with guaranteed topology. Writes the adaptive grid (.htg), the surface (.vtp),
a picture (.png) and a topology report (.txt) into an output folder.

Usage (the README's first command runs it):
    pvpython demo.py <build>/lib/python3/site-packages <output folder>
"""
import os
import sys
import time

sys.path.insert(0, sys.argv[1])
out = sys.argv[2] if len(sys.argv) > 2 else "demo-output"
os.makedirs(out, exist_ok=True)

from topologypreserving import vtkTopologyPreservingContour  # noqa: E402
from vtkmodules.vtkCommonDataModel import (vtkBox, vtkCylinder, vtkImplicitBoolean,  # noqa: E402
                                           vtkPlane, vtkSphere)
from vtkmodules.vtkFiltersCore import vtkCutter  # noqa: E402
from vtkmodules.vtkFiltersHyperTree import vtkHyperTreeGridToUnstructuredGrid  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGWriter  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLHyperTreeGridWriter, vtkXMLPolyDataWriter  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction,  # noqa: E402
                                         vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkTextActor, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingFreeType  # noqa: E402,F401 (text rendering)
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401 (render window implementation)

# --- The solid: (cube ∩ sphere) − (x, y and z cylinders) -----------------------
cube = vtkBox()
cube.SetBounds(-0.5, 0.5, -0.5, 0.5, -0.5, 0.5)
ball = vtkSphere()
ball.SetRadius(0.68)
body = vtkImplicitBoolean()
body.SetOperationTypeToIntersection()
body.AddFunction(cube)
body.AddFunction(ball)
holes = vtkImplicitBoolean()
holes.SetOperationTypeToUnion()
for axis in ((1, 0, 0), (0, 1, 0), (0, 0, 1)):
    c = vtkCylinder()
    c.SetAxis(*axis)
    c.SetRadius(0.25)
    holes.AddFunction(c)
solid = vtkImplicitBoolean()
solid.SetOperationTypeToDifference()
solid.AddFunction(body)
solid.AddFunction(holes)

# --- Contour with guaranteed topology -----------------------------------------
contour = vtkTopologyPreservingContour()
contour.SetImplicitFunction(solid)
contour.SetTolerance(0.01)  # two-sided Hausdorff bound: 1 % of the domain diagonal
start = time.time()
contour.Update()
seconds = time.time() - start
grid = contour.GetOutputDataObject(0)
surface = contour.GetOutputDataObject(1)


def field(name):
    return surface.GetFieldData().GetArray(name).GetTuple1(0)


report = "\n".join([
    "Topology preserving contour of (cube ∩ sphere) − (three cylinders)",
    f"  components           {int(field('Components'))}",
    f"  genus                {int(field('Genus'))}   (exact solid: 5)",
    f"  Euler characteristic {int(field('EulerCharacteristic'))}",
    f"  closed / manifold    {int(field('Closed'))} / {int(field('Manifold'))}",
    f"  TopologyGuaranteed   {int(field('TopologyGuaranteed'))}",
    f"  UnresolvedCells      {int(field('UnresolvedCells'))}",
    f"  Hausdorff bound      {field('HausdorffBound'):.5f}  (tolerance {field('AbsoluteTolerance'):.5f})",
    f"  triangles            {surface.GetNumberOfPolys()}",
    f"  grid cells           {grid.GetNumberOfCells()}",
    f"  seconds              {seconds:.2f}",
])
print(report)
with open(os.path.join(out, "report.txt"), "w") as f:
    f.write(report + "\n")

# --- Files --------------------------------------------------------------------
htg = vtkXMLHyperTreeGridWriter()
htg.SetInputData(grid)
htg.SetDataModeToBinary()  # VTK 9.2's default appended mode corrupts .htg files
htg.SetFileName(os.path.join(out, "grid.htg"))
htg.Write()
vtp = vtkXMLPolyDataWriter()
vtp.SetInputData(surface)
vtp.SetFileName(os.path.join(out, "surface.vtp"))
vtp.Write()

# --- Picture: the surface, and a slice of the adaptive grid by depth ----------
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(1200, 600)

surface_mapper = vtkPolyDataMapper()
surface_mapper.SetInputData(surface)
surface_mapper.ScalarVisibilityOff()
surface_actor = vtkActor()
surface_actor.SetMapper(surface_mapper)
surface_actor.GetProperty().SetColor(0.85, 0.72, 0.45)
surface_actor.GetProperty().SetSpecular(0.3)
left = vtkRenderer()
left.SetViewport(0.0, 0.0, 0.5, 1.0)
left.SetBackground(1, 1, 1)
left.AddActor(surface_actor)
left.GetActiveCamera().Azimuth(35)
left.GetActiveCamera().Elevation(28)
left.ResetCamera()

plane = vtkPlane()
plane.SetOrigin(0, 0, 0.1)
plane.SetNormal(0, 0, 1)
leaves = vtkHyperTreeGridToUnstructuredGrid()
leaves.SetInputData(grid)
cut = vtkCutter()
cut.SetInputConnection(leaves.GetOutputPort())
cut.SetCutFunction(plane)
cut.GenerateTrianglesOff()
cut.Update()
depth_colors = vtkColorTransferFunction()
depth_colors.AddRGBPoint(0, 0.23, 0.30, 0.75)
depth_colors.AddRGBPoint(5, 0.87, 0.87, 0.87)
depth_colors.AddRGBPoint(10, 0.71, 0.02, 0.15)
cut_mapper = vtkPolyDataMapper()
cut_mapper.SetInputConnection(cut.GetOutputPort())
cut_mapper.SetScalarModeToUseCellFieldData()
cut_mapper.SetColorModeToMapScalars()  # Depth is unsigned char: map it, not as RGB
cut_mapper.SelectColorArray("Depth")
cut_mapper.SetLookupTable(depth_colors)
cut_mapper.SetUseLookupTableScalarRange(True)
cut_actor = vtkActor()
cut_actor.SetMapper(cut_mapper)
cut_actor.GetProperty().EdgeVisibilityOn()
cut_actor.GetProperty().SetEdgeColor(0.2, 0.2, 0.2)
right = vtkRenderer()
right.SetViewport(0.5, 0.0, 1.0, 1.0)
right.SetBackground(1, 1, 1)
right.AddActor(cut_actor)
right.ResetCamera()
right.GetActiveCamera().Zoom(1.3)

for renderer, text in ((left, f"surface: genus {int(field('Genus'))}, "
                               f"guaranteed {int(field('TopologyGuaranteed'))}"),
                       (right, "adaptive grid at z = 0.1, coloured by depth")):
    label = vtkTextActor()
    label.SetInput(text)
    label.GetTextProperty().SetColor(0, 0, 0)
    label.GetTextProperty().SetFontSize(20)
    label.SetPosition(15, 15)
    renderer.AddActor2D(label)
    window.AddRenderer(renderer)
window.Render()
shot = vtkWindowToImageFilter()
shot.SetInput(window)
shot.Update()
png = vtkPNGWriter()
png.SetInputConnection(shot.GetOutputPort())
png.SetFileName(os.path.join(out, "surface.png"))
png.Write()
print(f"wrote {out}/grid.htg, {out}/surface.vtp, {out}/surface.png, {out}/report.txt")
sys.exit(0 if field("TopologyGuaranteed") == 1 and field("Genus") == 5 else 1)
