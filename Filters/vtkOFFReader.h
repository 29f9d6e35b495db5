/**
 * @class   vtkOFFReader
 * @brief   Reads Object File Format (.off) polygon meshes into vtkPolyData.
 *
 * Geomview's OFF format (also COFF, NOFF, CNOFF, STOFF variants: extra
 * per-vertex fields and per-face colours are skipped). One vertex and one
 * face per line after the header; '#' starts a comment. Faces of any size
 * become polygons. VTK has no OFF reader; CGAL's test meshes are OFF files.
 */
#ifndef vtkOFFReader_h
#define vtkOFFReader_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkTopologyPreservingFiltersModule.h" // For export macro

#include <string>

class VTKTOPOLOGYPRESERVINGFILTERS_EXPORT vtkOFFReader : public vtkPolyDataAlgorithm
{
public:
  static vtkOFFReader* New();
  vtkTypeMacro(vtkOFFReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The .off file to read.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);

protected:
  vtkOFFReader();
  ~vtkOFFReader() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FileName;

private:
  vtkOFFReader(const vtkOFFReader&) = delete;
  void operator=(const vtkOFFReader&) = delete;
};

#endif
