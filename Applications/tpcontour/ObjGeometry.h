// The geometry of a Wavefront OBJ file: its vertices and faces, nothing else.
//
// Hand-written instead of vtkOBJReader because VTK 9.2's reader indexes its
// texture-coordinate arrays with the file's indices unchecked: a file whose
// faces name more texture coordinates than it lists - as VTK's own
// vtkOBJWriter writes for vtkCubeSource - corrupts the heap and aborts the
// program ("realloc(): invalid pointer"). A solid needs only positions and
// faces; texture coordinates, normals, materials, groups, lines and points
// are skipped, and every vertex reference is checked.
#ifndef tpcontour_ObjGeometry_h
#define tpcontour_ObjGeometry_h

#include "vtkSmartPointer.h"

#include <string>

class vtkPolyData;

namespace tpcontour
{
/// The faces of `file` as polygons; null with `error` set (naming the line)
/// when the file cannot be opened or a vertex or face is malformed.
vtkSmartPointer<vtkPolyData> ReadObjGeometry(const std::string& file, std::string& error);
} // namespace tpcontour

#endif
