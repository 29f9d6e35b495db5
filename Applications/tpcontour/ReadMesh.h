// One input file read as a mesh, with a message naming the file when it
// cannot be.
#ifndef tpcontour_ReadMesh_h
#define tpcontour_ReadMesh_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace tpcontour
{
/// The mesh in `file` (.stl, .obj, .ply, .vtp, .off), or null with `error`
/// set; the reader's warnings are added to `warnings`. A file its reader
/// complained about is refused whole: part of a mesh would be open, or a
/// different solid.
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& file, std::string& error, std::vector<std::string>& warnings);
} // namespace tpcontour

#endif
