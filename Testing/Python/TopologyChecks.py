"""Independent topology checks on a vtkPolyData, with VTK's own filters."""
from vtkmodules.vtkFiltersCore import (vtkExtractEdges, vtkFeatureEdges,
                                       vtkPolyDataConnectivityFilter)
from vtkmodules.vtkCommonCore import vtkIdList, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData


def unsplit(surface):
    """The closed surface behind one whose points were split along creases
    (SplitCreases): each triangle's points replaced by their SurfacePointId.
    A surface without that array is returned as it is."""
    ids = surface.GetPointData().GetArray("SurfacePointId")
    if ids is None or ids.GetNumberOfTuples() == 0:
        return surface
    count = int(max(ids.GetValue(i) for i in range(ids.GetNumberOfTuples()))) + 1
    points = vtkPoints()
    points.SetNumberOfPoints(count)
    for i in range(ids.GetNumberOfTuples()):
        points.SetPoint(ids.GetValue(i), surface.GetPoint(i))
    polys = vtkCellArray()
    cell = vtkIdList()
    for c in range(surface.GetNumberOfCells()):
        surface.GetCellPoints(c, cell)
        polys.InsertNextCell(cell.GetNumberOfIds(), [ids.GetValue(cell.GetId(k)) for k in range(cell.GetNumberOfIds())])
    merged = vtkPolyData()
    merged.SetPoints(points)
    merged.SetPolys(polys)
    return merged


def measure(surface):
    """Components, boundary edges, non-manifold edges, Euler characteristic, genus (of the
    unsplit surface when its points were split along creases)."""
    surface = unsplit(surface)
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
