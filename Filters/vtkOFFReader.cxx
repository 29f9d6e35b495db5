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
  std::string line;
  if (!NextLine(in, line))
  {
    vtkErrorMacro(<< this->FileName << " is empty.");
    return 0;
  }
  // Header: [ST][C][N][4][n]OFF, possibly followed by the counts.
  std::istringstream header(line);
  std::string keyword;
  header >> keyword;
  if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
  {
    vtkErrorMacro(<< this->FileName << " is not an OFF file (header '" << keyword << "').");
    return 0;
  }
  if (keyword.find('4') != std::string::npos || keyword.find('n') != std::string::npos)
  {
    vtkErrorMacro(<< this->FileName << ": " << keyword << " (non 3-D) files are not supported.");
    return 0;
  }
  long long nv = -1, nf = -1;
  if (!(header >> nv >> nf))
  {
    if (!NextLine(in, line))
    {
      vtkErrorMacro(<< this->FileName << ": missing vertex and face counts.");
      return 0;
    }
    std::istringstream counts(line);
    if (!(counts >> nv >> nf))
    {
      vtkErrorMacro(<< this->FileName << ": bad counts line '" << line << "'.");
      return 0;
    }
  }
  if (nv < 0 || nf < 0)
  {
    vtkErrorMacro(<< this->FileName << ": negative counts.");
    return 0;
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(nv));
  for (long long v = 0; v < nv; ++v)
  {
    double p[3];
    std::istringstream fields;
    if (!NextFields(in, line, fields) || !(fields >> p[0] >> p[1] >> p[2]))
    {
      vtkErrorMacro(<< this->FileName << ": vertex " << v << " of " << nv << " is missing or malformed.");
      return 0;
    }
    points->SetPoint(static_cast<vtkIdType>(v), p);
  }
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> ids;
  for (long long f = 0; f < nf; ++f)
  {
    long long n = 0;
    std::istringstream fields;
    if (!NextFields(in, line, fields) || !(fields >> n) || n < 1)
    {
      vtkErrorMacro(<< this->FileName << ": face " << f << " of " << nf << " is missing or malformed.");
      return 0;
    }
    ids.resize(static_cast<std::size_t>(n));
    for (auto& id : ids)
    {
      long long index = -1;
      if (!(fields >> index) || index < 0 || index >= nv)
      {
        vtkErrorMacro(<< this->FileName << ": face " << f << " has a bad vertex index.");
        return 0;
      }
      id = static_cast<vtkIdType>(index);
    }
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
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
