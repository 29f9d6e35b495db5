"""Demo: the textbook CSG solid (cube ∩ sphere) − (three cylinders), and a real
closed mesh (CGAL's couplingdown.off, genus 9, from Debian's libcgal-demo)
remeshed - as extracted, and decimated (Decimate) - all with guaranteed
topology. Writes the adaptive grids (.htg), the
surfaces (.vtp), a picture (.png) and a topology report (.txt) into an output
folder.

Usage (the README's first command runs it):
    pvpython demo.py <build>/lib/python3/site-packages <output folder>
"""
import os
import sys
import tarfile
import time

sys.path.insert(0, sys.argv[1])
out = sys.argv[2] if len(sys.argv) > 2 else "demo-output"
os.makedirs(out, exist_ok=True)

from topologypreserving import vtkOFFReader, vtkTopologyPreservingContour  # noqa: E402
from vtkmodules.vtkCommonDataModel import (vtkBox, vtkCylinder, vtkImplicitBoolean,  # noqa: E402
                                           vtkPlane, vtkSphere)
from vtkmodules.vtkFiltersCore import vtkCutter  # noqa: E402
from vtkmodules.vtkFiltersHyperTree import vtkHyperTreeGridToUnstructuredGrid  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGWriter  # noqa: E402
from vtkmodules.vtkIOXML import (vtkXMLHyperTreeGridReader, vtkXMLHyperTreeGridWriter,  # noqa: E402
                                 vtkXMLPolyDataReader, vtkXMLPolyDataWriter)
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
contour.SplitCreasesOn()  # crisp edges where the primitives meet, as in ParaView

# --- A real mesh: CGAL's couplingdown.off (genus 9), remeshed at 1/64 ----------
CGAL_DATA = "/usr/share/doc/libcgal-dev/data.tar.gz"  # Debian package libcgal-demo
mesh_file = os.path.join(out, "couplingdown.off")
if not os.path.exists(mesh_file):
    with tarfile.open(CGAL_DATA) as archive:
        member = archive.getmember("data/meshes/couplingdown.off")
        with archive.extractfile(member) as src, open(mesh_file, "wb") as dst:
            dst.write(src.read())
reader = vtkOFFReader()
reader.SetFileName(mesh_file)
remesh = vtkTopologyPreservingContour()
remesh.SetInputConnection(reader.GetOutputPort())
remesh.SetTolerance(1.0 / 64)
# Points split along the part's creases, as the ParaView plugin does by
# default: its rims shade crisply (the report is the unsplit surface's).
remesh.SplitCreasesOn()


# --- The same part decimated: every edge collapse certified (Decimate) ---------
decimated = vtkTopologyPreservingContour()
decimated.SetInputConnection(reader.GetOutputPort())
decimated.SetTolerance(1.0 / 64)
decimated.DecimateOn()
decimated.SplitCreasesOn()


def run(name, algorithm, expected_genus):
    """Updates, writes <name>-grid.htg and <name>-surface.vtp, returns the report lines."""
    start = time.time()
    algorithm.Update()
    seconds = time.time() - start
    grid, surface = algorithm.GetOutputDataObject(1), algorithm.GetOutputDataObject(0)

    def field(key):
        return surface.GetFieldData().GetArray(key).GetTuple1(0)

    htg = vtkXMLHyperTreeGridWriter()
    htg.SetInputData(grid)
    htg.SetDataModeToBinary()  # VTK 9.2's default appended mode corrupts .htg files
    htg.SetFileName(os.path.join(out, f"{name}-grid.htg"))
    htg.Write()
    vtp = vtkXMLPolyDataWriter()
    vtp.SetInputData(surface)
    vtp.SetDataModeToBinary()  # large appended files are unreadable here (README, known issues)
    vtp.SetFileName(os.path.join(out, f"{name}-surface.vtp"))
    vtp.Write()
    ok = field("TopologyGuaranteed") == 1 and field("Genus") == expected_genus
    lines = [
        f"  components           {int(field('Components'))}",
        f"  genus                {int(field('Genus'))}   (exact: {expected_genus})",
        f"  Euler characteristic {int(field('EulerCharacteristic'))}",
        f"  closed / manifold    {int(field('Closed'))} / {int(field('Manifold'))}",
        f"  embedded             {int(field('Embedded'))}",
        f"  outward              {int(field('Outward'))}",
        f"  TopologyGuaranteed   {int(field('TopologyGuaranteed'))}",
        f"  UnresolvedCells      {int(field('UnresolvedCells'))}",
        f"  Hausdorff bound      {field('HausdorffBound'):.5f}  (tolerance {field('AbsoluteTolerance'):.5f})",
        f"  triangles            {surface.GetNumberOfPolys()}",
        f"  grid cells           {grid.GetNumberOfCells()}",
        f"  seconds              {seconds:.2f}",
    ]
    # The files must read back (see the README's known issues).
    readers = ((vtkXMLHyperTreeGridReader(), f"{name}-grid.htg", grid.GetNumberOfCells()),
               (vtkXMLPolyDataReader(), f"{name}-surface.vtp", surface.GetNumberOfCells()))
    for reader, file, cells in readers:
        reader.SetFileName(os.path.join(out, file))
        reader.Update()
        if reader.GetOutputDataObject(0).GetNumberOfCells() != cells:
            print(f"{file} does not read back")
            ok = False
    return grid, surface, lines, ok, field


grid, surface, csg_lines, csg_ok, field = run("csg", contour, 5)
mesh_grid, mesh_surface, mesh_lines, mesh_ok, mesh_field = run("mesh", remesh, 9)
_, _, decimated_lines, decimated_ok, _ = run("mesh-decimated", decimated, 9)
report = "\n".join(
    ["Topology preserving contour of (cube ∩ sphere) − (three cylinders), ε = 1 % of the diagonal"]
    + csg_lines
    + ["", f"CGAL's couplingdown.off ({reader.GetOutput().GetNumberOfPolys()} triangles, genus 9) "
       "remeshed, ε = 1/64 of the diagonal"]
    + mesh_lines
    + ["", "The same part decimated (Decimate: every edge collapse certified), ε = 1/64 of the diagonal"]
    + decimated_lines)
print(report)
with open(os.path.join(out, "report.txt"), "w") as f:
    f.write(report + "\n")

# --- Picture: the surface, and a slice of the adaptive grid by depth ----------
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(1500, 500)

def surface_renderer(polydata, color, left_edge, elevation, azimuth=0.0):
    """A third of the window showing one surface in a plain colour."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(polydata)
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    actor.GetProperty().SetSpecular(0.3)
    renderer = vtkRenderer()
    renderer.SetViewport(left_edge, 0.0, left_edge + 1 / 3, 1.0)
    renderer.SetBackground(1, 1, 1)
    renderer.AddActor(actor)
    renderer.GetActiveCamera().Azimuth(azimuth)
    renderer.GetActiveCamera().Elevation(elevation)
    renderer.ResetCamera()
    return renderer


left = surface_renderer(surface, (0.85, 0.72, 0.45), 0.0, 28, azimuth=35)
middle = surface_renderer(mesh_surface, (0.55, 0.68, 0.85), 1 / 3, -50)

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
right.SetViewport(2 / 3, 0.0, 1.0, 1.0)
right.SetBackground(1, 1, 1)
right.AddActor(cut_actor)
right.ResetCamera()
right.GetActiveCamera().Zoom(1.3)

for renderer, text in ((left, f"CSG: genus {int(field('Genus'))}, "
                               f"guaranteed {int(field('TopologyGuaranteed'))}"),
                       (middle, f"mesh remeshed: genus {int(mesh_field('Genus'))}, "
                                f"guaranteed {int(mesh_field('TopologyGuaranteed'))}"),
                       (right, "CSG grid at z = 0.1, coloured by depth")):
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
print(f"wrote {out}/csg-grid.htg, csg-surface.vtp, mesh-grid.htg, mesh-surface.vtp, mesh-decimated-grid.htg, "
      "mesh-decimated-surface.vtp, surface.png, report.txt")
sys.exit(0 if csg_ok and mesh_ok and decimated_ok else 1)
