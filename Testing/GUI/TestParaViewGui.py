"""Runs inside the ParaView GUI (paraview --script=... --exit, under xvfb-run):
loads the plugin, applies Topology Preserving Contour to a sphere source with
the Cylinder implicit function (Difference), shows both ports (the grid as
an outline by default) with the interactive cylinder widget, and compares a
screenshot with the baseline.
Writes PASS or FAIL (with why) to $TPC_RESULT; the GUI's own exit status
cannot carry it. With $TPC_BASELINE missing, writes it (to review and commit).
"""
import os
import traceback

result = os.environ["TPC_RESULT"]
try:
    from paraview.simple import (GetActiveViewOrCreate, Hide, LoadPlugin, OutputPort, Render,
                                 SaveScreenshot, Show, Sphere)
    from vtkmodules.vtkImagingCore import vtkImageDifference
    from vtkmodules.vtkIOImage import vtkPNGReader

    LoadPlugin(os.environ["TPC_PLUGIN"], ns=globals())
    ball = Sphere(Radius=0.5, ThetaResolution=32, PhiResolution=24)
    contour = TopologyPreservingContour(Input=ball, ImplicitFunction="Cylinder")  # noqa: F821
    contour.ImplicitFunction.Radius = 0.2
    contour.ImplicitFunction.Axis = [0, 0, 1]
    contour.Operation = "Difference"
    contour.Tolerance = 0.02
    view = GetActiveViewOrCreate("RenderView")
    grid = Show(OutputPort(contour, 0), view)
    display = Show(OutputPort(contour, 1), view)
    display.DiffuseColor = [0.85, 0.72, 0.45]
    Hide(ball, view)
    view.OrientationAxesVisibility = 0
    view.CameraPosition = [1.6, -2.2, 1.8]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 0, 1]
    Render(view)

    genus = contour.GetDataInformation(1).DataInformation.GetFieldDataInformation() \
        .GetArrayInformation("Genus").GetComponentRange(0)[0]
    names = [contour.GetOutputPortName(i) for i in range(2)] if hasattr(contour, "GetOutputPortName") \
        else [contour.SMProxy.GetOutputPortName(i) for i in range(2)]
    shot = os.environ["TPC_SHOT"]
    SaveScreenshot(shot, view, ImageResolution=[300, 300])
    baseline = os.environ["TPC_BASELINE"]
    if not os.path.exists(baseline):
        os.replace(shot, baseline)
        raise RuntimeError(f"no baseline: wrote {baseline}, review it and commit it")
    images = []
    for path in (shot, baseline):
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        images.append(reader.GetOutput())
    diff = vtkImageDifference()
    diff.SetInputData(images[0])
    diff.SetImageData(images[1])
    diff.Update()
    error = diff.GetThresholdedError()
    problems = []
    if genus != 1:
        problems.append(f"genus {genus}, expected 1 (a sphere drilled through)")
    if grid.Representation != "Outline":
        problems.append(f"the grid shows as {grid.Representation}, expected Outline")
    if names != ["Adaptive Grid", "Surface"]:
        problems.append(f"output ports named {names}")
    if error > 10:
        problems.append(f"screenshot differs from the baseline (thresholded error {error:.1f})")
    with open(result, "w") as f:
        f.write("PASS\n" if not problems else "FAIL " + "; ".join(problems) + "\n")
except Exception:
    with open(result, "w") as f:
        f.write("FAIL " + traceback.format_exc())
