"""Independent topology checks on a vtkPolyData, with VTK's own filters."""
from vtkmodules.vtkFiltersCore import (vtkExtractEdges, vtkFeatureEdges,
                                       vtkPolyDataConnectivityFilter)


def measure(surface):
    """Components, boundary edges, non-manifold edges, Euler characteristic, genus."""
    conn = vtkPolyDataConnectivityFilter()
    conn.SetInputData(surface)
    conn.SetExtractionModeToAllRegions()
    conn.Update()
    components = conn.GetNumberOfExtractedRegions()

    fe = vtkFeatureEdges()
    fe.SetInputData(surface)
    fe.FeatureEdgesOff()
    fe.ManifoldEdgesOff()
    fe.BoundaryEdgesOn()
    fe.NonManifoldEdgesOff()
    fe.Update()
    boundary = fe.GetOutput().GetNumberOfCells()
    fe.BoundaryEdgesOff()
    fe.NonManifoldEdgesOn()
    fe.Update()
    nonmanifold = fe.GetOutput().GetNumberOfCells()

    edges = vtkExtractEdges()
    edges.SetInputData(surface)
    edges.UseAllPointsOn()
    edges.Update()
    euler = (surface.GetNumberOfPoints() - edges.GetOutput().GetNumberOfLines()
             + surface.GetNumberOfPolys())
    return {"components": components, "boundary": boundary, "nonmanifold": nonmanifold,
            "euler": euler, "genus": (2 * components - euler) // 2}


def field(data, name):
    array = data.GetFieldData().GetArray(name)
    return array.GetTuple1(0) if array is not None else None


def check(condition, message, failures):
    if not condition:
        failures.append(message)
        print("FAILED:", message)
