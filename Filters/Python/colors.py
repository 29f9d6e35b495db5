"""Categorical colour maps for the adaptive grid (output port 1), in pvpython.

    from topologypreserving.colors import ColorByCategories
    grid = Show(OutputPort(contour, 1)); grid.SetRepresentationType("Surface")
    ColorByCategories(grid, "SizeReason", view)  # or "CellState", "FailedTest"

Each value gets its own colour and its name in the colour legend ("complex
edge", "not star-shaped w.r.t. a face", ...). The colours and names are the
presets of TopologyPreservingColorMaps.json, which the ParaView plugin
registers when it loads in the GUI (there they are the default colour maps of
these arrays); pvpython and pvbatch run no GUI component, so scripts apply
them with this module.
"""
import json
import os

PRESETS_FILE = os.path.join(os.path.dirname(__file__), "TopologyPreservingColorMaps.json")

# SizeReason (the parent's SplitReason) and FailedTest (the test a stopped
# cell still failed) hold SplitReason values.
_PRESET_OF_ARRAY = {
    "SplitReason": "TPC Split Reason",
    "SizeReason": "TPC Split Reason",
    "FailedTest": "TPC Split Reason",
    "CellState": "TPC Cell State",
}


def Presets():
    """The presets of TopologyPreservingColorMaps.json, by name."""
    with open(PRESETS_FILE) as f:
        return {p["Name"]: p for p in json.load(f)}


def ColorByCategories(display, array="SizeReason", view=None):
    """Colours `display` (a grid representation) by a cell array of the grid
    with one colour and one named legend entry per value; shows the legend in
    `view` when given. Returns the lookup table."""
    from paraview import simple

    if array not in _PRESET_OF_ARRAY:
        raise ValueError(f"{array!r} is not a categorical array of the grid; "
                         f"use one of {sorted(_PRESET_OF_ARRAY)}")
    preset = Presets()[_PRESET_OF_ARRAY[array]]
    simple.ColorBy(display, ("CELLS", array))
    lut = simple.GetColorTransferFunction(array)
    # Set the properties directly rather than importing the preset, so that
    # scripts do not add copies of it to the user's preset list.
    lut.InterpretValuesAsCategories = 1
    lut.AnnotationsInitialized = 1
    lut.Annotations = preset["Annotations"]
    lut.IndexedColors = preset["IndexedColors"]
    lut.NanColor = preset["NanColor"]
    if view is not None:
        display.SetScalarBarVisibility(view, True)
    return lut
