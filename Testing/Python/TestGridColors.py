"""The adaptive grid's categorical colour maps (run under xvfb-run pvpython).

- the names the filter writes (field data SplitReasonNames, CellStateNames)
  are the annotations of the shipped presets, value for value;
- topologypreserving.colors.ColorByCategories colours the grid categorically
  with every value present in the grid named in the legend;
- the presets file imports into ParaView (as a GUI user does with Choose
  Preset > Import) and applying a preset gives the same annotations.

Usage: pvpython TestGridColors.py <plugin .so> <site-packages> <output dir>
"""
import os
import sys

sys.path.insert(0, sys.argv[2])
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
outdir = sys.argv[3]
os.makedirs(outdir, exist_ok=True)

from paraview import servermanager  # noqa: E402
from paraview.simple import (CreateRenderView, GetColorTransferFunction, Hide,  # noqa: E402
                             GetScalarBar, HideUnusedScalarBars, ImportPresets, LoadPlugin, OutputPort, Render,
                             SaveScreenshot, Show, Slice, Sphere)
from TopologyChecks import check  # noqa: E402
from topologypreserving.colors import PRESETS_FILE, ColorByCategories, Presets  # noqa: E402

failures = []
LoadPlugin(sys.argv[1], ns=globals())

# A sphere drilled by a cylinder: refinement for several reasons.
ball = Sphere(Radius=0.5, ThetaResolution=32, PhiResolution=24)
contour = TopologyPreservingContour(Input=ball, ImplicitFunction="Cylinder")  # noqa: F821
contour.ImplicitFunction.Radius = 0.2
contour.ImplicitFunction.Axis = [0, 0, 1]
contour.Operation = "Difference"
contour.Tolerance = 0.03
contour.UpdatePipeline()
grid = servermanager.Fetch(contour, idx=1)


def names(array_name):
    a = grid.GetFieldData().GetAbstractArray(array_name)
    return [a.GetValue(i) for i in range(a.GetNumberOfValues())] if a else None


def pairs(annotations):
    return [(int(annotations[i]), annotations[i + 1]) for i in range(0, len(annotations), 2)]


presets = Presets()
for array, preset in (("SplitReasonNames", "TPC Split Reason"), ("CellStateNames", "TPC Cell State")):
    written = names(array)
    shipped = pairs(presets[preset]["Annotations"])
    check(written == [name for _, name in shipped] and [v for v, _ in shipped] == list(range(len(shipped))),
          f"{array} written by the filter ({written}) are the annotations of '{preset}'", failures)
    check(len(presets[preset]["IndexedColors"]) == 3 * len(shipped),
          f"'{preset}' has one colour per annotation", failures)

view = CreateRenderView()
display = Show(OutputPort(contour, 1), view)
display.SetRepresentationType("Surface")
for array in ("SplitReason", "SizeReason", "CellState", "FailedTest"):
    lut = ColorByCategories(display, array, view)
    named = dict(pairs(list(lut.Annotations)))
    present = grid.GetCellData().GetArray(array).GetRange()
    check(lut.InterpretValuesAsCategories == 1, f"{array}: categorical", failures)
    check(all(v in named for v in range(int(present[0]), int(present[1]) + 1)),
          f"{array}: every value in the grid {present} is named in the legend {named}", failures)
    check(len(lut.IndexedColors) == 3 * len(named), f"{array}: one colour per name", failures)
reasons = grid.GetCellData().GetArray("SizeReason").GetRange()
check(reasons[1] > reasons[0], f"the grid's cells are as small as they are for several reasons {reasons}",
      failures)

# A picture for the README: the grid sliced through the axis of the hole,
# coloured by SizeReason: why each cell is as small as it is.
Hide(OutputPort(contour, 1), view)
HideUnusedScalarBars(view)
cut = Slice(Input=OutputPort(contour, 1))
cut.HyperTreeGridSlicer.Normal = [0, 1, 0]  # (SliceType is for other data)
cut.HyperTreeGridSlicer.Origin = [0, 0.001, 0]
cut.UpdatePipeline()
bounds = cut.GetDataInformation().GetBounds()
check(cut.GetDataInformation().GetNumberOfCells() > 0 and bounds[2] == bounds[3],
      f"the grid is sliced across y (bounds {bounds})", failures)
cells = Show(cut, view)
cells.SetRepresentationType("Surface With Edges")
cells.EdgeColor = [0.15, 0.15, 0.15]
lut = ColorByCategories(cells, "SizeReason", view)
bar = GetScalarBar(lut, view)
bar.WindowLocation = "Any Location"
bar.Position = [0.72, 0.1]
bar.ScalarBarLength = 0.8
bar.TitleFontSize = bar.LabelFontSize = 9
view.OrientationAxesVisibility = 0
Render(view)  # (the first Render resets the camera)
view.CameraPosition = [0, -3, 0]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
view.ResetCamera()
view.CameraFocalPoint = [1.05, 0, 0]  # room for the legend on the right
view.CameraPosition = [1.05, -4.6, 0]
Render(view)
SaveScreenshot(os.path.join(outdir, "grid-split-reasons.png"), view, ImageResolution=[900, 450])

try:
    ColorByCategories(display, "Depth", view)
    check(False, "Depth is refused (not categorical)", failures)
except ValueError:
    pass

# The GUI path: import the file as presets, apply one by name.
check(ImportPresets(PRESETS_FILE), "the presets file imports into ParaView", failures)
lut = GetColorTransferFunction("CellState")
lut.Annotations = []
lut.ApplyPreset("TPC Cell State", False)  # rescaling would drop categorical annotations
check(pairs(list(lut.Annotations)) == pairs(presets["TPC Cell State"]["Annotations"]),
      "applying the imported 'TPC Cell State' preset sets its annotations", failures)

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("PASS")
