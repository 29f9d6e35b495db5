// Adapter: a vtkPolyData input -> a repaired closed triangle mesh for the
// core (polygons triangulated exactly, strips split; lines and vertices
// ignored).
#ifndef PolyDataToMesh_h
#define PolyDataToMesh_h

#include "MeshRepair.h"
#include "MeshSolid.h"

#include <string>

class vtkPolyData;

namespace tpc
{
namespace vtkadapter
{

struct MeshInput
{
  MeshSolid Solid;
  MeshRepairReport Repair;
  std::size_t IgnoredLines = 0;    ///< line cells (not part of a surface)
  std::size_t IgnoredVertices = 0; ///< vertex cells
};

/// Converts and repairs (stopping early, with a partial result, when
/// `progress` asks to abort). Returns false (with `error` set) when the data
/// cannot describe a solid at all: no triangles, or non-finite coordinates.
/// With `fillHoles`, every hole (a loop of boundary edges, once exactly
/// coincident points are merged) is first closed by a polygon
/// (vtkFillHolesFilter), counted in the repair report.
bool ConvertPolyData(vtkPolyData* input, MeshInput& mesh, std::string& error, bool fillHoles = false,
  const ParallelFor& parallelFor = SequentialFor, const ProgressCallback& progress = nullptr);

} // namespace vtkadapter
} // namespace tpc

#endif
