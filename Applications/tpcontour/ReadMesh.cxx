#include "ReadMesh.h"

#include "CommandLine.h"
#include "MessageLog.h"
#include "ObjGeometry.h"
#include "vtkOFFReader.h"

#include "vtkExecutive.h"
#include "vtkPLYReader.h"
#include "vtkPolyData.h"
#include "vtkSTLReader.h"
#include "vtkXMLPolyDataReader.h"

#include <sys/stat.h>

namespace tpcontour
{
namespace
{
/// The VTK reader for the file's extension; null for an unknown one.
vtkSmartPointer<vtkAlgorithm> MakeReader(const std::string& file)
{
  const std::string e = Extension(file);
  if (e == "stl")
  {
    auto stl = vtkSmartPointer<vtkSTLReader>::New();
    stl->SetFileName(file.c_str());
    stl->MergingOn(); // STL repeats vertices per triangle
    return stl;
  }
  if (e == "ply")
  {
    auto ply = vtkSmartPointer<vtkPLYReader>::New();
    ply->SetFileName(file.c_str());
    return ply;
  }
  if (e == "vtp")
  {
    auto vtp = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    vtp->SetFileName(file.c_str());
    return vtp;
  }
  if (e == "off")
  {
    auto off = vtkSmartPointer<vtkOFFReader>::New();
    off->SetFileName(file.c_str());
    return off;
  }
  return nullptr;
}

/// Runs a VTK reader; its own messages (a parse error and its line) say best
/// what is wrong with a broken file.
vtkSmartPointer<vtkPolyData> RunReader(
  vtkAlgorithm* reader, const std::string& file, std::string& error, std::vector<std::string>& warnings)
{
  MessageLog log;
  log.Observe(reader);
  log.Observe(reader->GetExecutive());
  reader->Update();
  if (!log.Errors.empty())
  {
    const std::size_t echo = log.Errors.find("\nAlgorithm "); // the executive's repetition
    error = "cannot read '" + file + "': " + log.Errors.substr(0, echo);
    return nullptr;
  }
  for (const std::string& w : log.Warnings)
  {
    warnings.push_back("reading '" + file + "': " + w);
  }
  return vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
}
} // namespace

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& file, std::string& error, std::vector<std::string>& warnings)
{
  struct stat st;
  if (stat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
  {
    error = "cannot read '" + file + "': no such file";
    return nullptr;
  }
  vtkSmartPointer<vtkPolyData> mesh;
  if (Extension(file) == "obj")
  {
    mesh = ReadObjGeometry(file, error);
    error = error.empty() ? error : "cannot read '" + file + "': " + error;
  }
  else if (vtkSmartPointer<vtkAlgorithm> reader = MakeReader(file))
  {
    mesh = RunReader(reader, file, error, warnings);
  }
  else
  {
    error = "'" + file + "': unknown format (expected .stl, .obj, .ply, .vtp or .off)";
  }
  if (error.empty() && (!mesh || mesh->GetNumberOfPolys() + mesh->GetNumberOfStrips() == 0))
  {
    error = "'" + file + "' holds no triangles (empty, or no polygons in it)";
  }
  return error.empty() ? mesh : nullptr;
}
} // namespace tpcontour
