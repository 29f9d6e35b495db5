#include "vtkOFFReader.h"

#include "vtkCellArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOFFReader);

namespace
{
/// Next line with content, comments removed; false at end of file.
bool NextLine(std::istream& in, std::string& line);

/// The next line with content, as a stream of fields.
bool NextFields(std::istream& in, std::string& line, std::istringstream& fields)
{
  if (!NextLine(in, line))
  {
    return false;
  }
  fields.clear();
  fields.str(line);
  return true;
}

bool NextLine(std::istream& in, std::string& line)
{
  while (std::getline(in, line))
  {
    const auto hash = line.find('#');
    if (hash != std::string::npos)
    {
      line.erase(hash);
    }
    if (line.find_first_not_of(" \t\r") != std::string::npos)
    {
      return true;
    }
  }
  return false;
}
/// The header ([ST][C][N][4][n]OFF, possibly followed by the counts) and the
/// vertex and face counts; what is wrong (after the file's name), or empty.
std::string ReadCounts(std::istream& in, long long& nv, long long& nf)
{
  std::string line;
  if (!NextLine(in, line))
  {
    return " is empty.";
  }
  std::istringstream header(line);
  std::string keyword;
  header >> keyword;
  if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
  {
    return " is not an OFF file (header '" + keyword + "').";
  }
  if (keyword.find('4') != std::string::npos || keyword.find('n') != std::string::npos)
  {
    return ": " + keyword + " (non 3-D) files are not supported.";
  }
  if (!(header >> nv >> nf))
  {
    if (!NextLine(in, line))
    {
      return ": missing vertex and face counts.";
    }
    std::istringstream counts(line);
    if (!(counts >> nv >> nf))
    {
      return ": bad counts line '" + line + "'.";
    }
  }
  return nv < 0 || nf < 0 ? ": negative counts." : "";
}

/// `nv` vertices (x y z first on each line); what is wrong, or empty.
std::string ReadVertices(std::istream& in, long long nv, vtkPoints* points)
{
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(nv));
  std::string line;
  for (long long v = 0; v < nv; ++v)
  {
    double p[3];
    std::istringstream fields;
    if (!NextFields(in, line, fields) || !(fields >> p[0] >> p[1] >> p[2]))
    {
      return ": vertex " + std::to_string(v) + " of " + std::to_string(nv) + " is missing or malformed.";
    }
    points->SetPoint(static_cast<vtkIdType>(v), p);
  }
  return "";
}

/// `nf` faces (a count, then that many vertex indices below `nv`); what is
/// wrong, or empty.
std::string ReadFaces(std::istream& in, long long nf, long long nv, vtkCellArray* polys)
{
  std::string line;
  std::vector<vtkIdType> ids;
  for (long long f = 0; f < nf; ++f)
  {
    long long n = 0;
    std::istringstream fields;
    if (!NextFields(in, line, fields) || !(fields >> n) || n < 1)
    {
      return ": face " + std::to_string(f) + " of " + std::to_string(nf) + " is missing or malformed.";
    }
    ids.resize(static_cast<std::size_t>(n));
    for (auto& id : ids)
    {
      long long index = -1;
      if (!(fields >> index) || index < 0 || index >= nv)
      {
        return ": face " + std::to_string(f) + " has a bad vertex index.";
      }
      id = static_cast<vtkIdType>(index);
    }
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  return "";
}
} // namespace

vtkOFFReader::vtkOFFReader()
{
  this->SetNumberOfInputPorts(0);
}

int vtkOFFReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outInfo)
{
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  if (this->FileName.empty())
  {
    vtkErrorMacro("No FileName set.");
    return 0;
  }
  std::ifstream in(this->FileName);
  if (!in)
  {
    vtkErrorMacro("Cannot open " << this->FileName << ".");
    return 0;
  }
  long long nv = -1, nf = -1;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  std::string error = ReadCounts(in, nv, nf);
  error = error.empty() ? ReadVertices(in, nv, points) : error;
  error = error.empty() ? ReadFaces(in, nf, nv, polys) : error;
  if (!error.empty())
  {
    vtkErrorMacro(<< this->FileName << error);
    return 0;
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  return 1;
}

void vtkOFFReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}
