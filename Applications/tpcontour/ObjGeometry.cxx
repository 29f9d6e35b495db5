#include "ObjGeometry.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <string_view>
#include <vector>

namespace tpcontour
{
namespace
{
/// The next whitespace-separated word of `line`, consumed.
std::string_view NextWord(std::string_view& line)
{
  const std::size_t begin = line.find_first_not_of(" \t\r");
  if (begin == std::string_view::npos)
  {
    line = {};
    return {};
  }
  const std::size_t end = std::min(line.find_first_of(" \t\r", begin), line.size());
  const std::string_view word = line.substr(begin, end - begin);
  line.remove_prefix(end);
  return word;
}

template <typename Number>
bool Parse(std::string_view word, Number& value)
{
  // from_chars: independent of the locale, unlike strtod and streams.
  const auto [end, status] = std::from_chars(word.data(), word.data() + word.size(), value);
  return status == std::errc() && end == word.data() + word.size();
}

struct ObjContent
{
  std::vector<double> Coordinates;
  std::vector<vtkIdType> Offsets{ 0 }, Connectivity;
  /// For each face vertex: the line that named it, to report a reference
  /// past the last vertex (positive indices may name vertices listed later).
  std::vector<long> FaceLines;
};

std::string ReadVertex(std::string_view rest, ObjContent& obj)
{
  double xyz[3];
  for (double& x : xyz)
  {
    if (!Parse(NextWord(rest), x))
    {
      return "a vertex needs three coordinates";
    }
  }
  obj.Coordinates.insert(obj.Coordinates.end(), xyz, xyz + 3);
  return "";
}

/// "f 1 2 3", "f 1/1 2/2 3/3", "f 1//1 ...", "f -3 -2 -1" (relative to the
/// vertices read so far): the part before the first '/' is the vertex.
std::string ReadFace(std::string_view rest, long lineNumber, ObjContent& obj)
{
  const vtkIdType verticesSoFar = static_cast<vtkIdType>(obj.Coordinates.size() / 3);
  std::size_t corners = 0;
  for (std::string_view word = NextWord(rest); !word.empty(); word = NextWord(rest), ++corners)
  {
    long long index = 0;
    if (!Parse(word.substr(0, word.find('/')), index) || index == 0)
    {
      return "'" + std::string(word) + "' is not a vertex index";
    }
    const vtkIdType id = index > 0 ? index - 1 : verticesSoFar + index;
    if (id < 0)
    {
      return "face refers to vertex " + std::to_string(index) + " with only " + std::to_string(verticesSoFar) +
        " vertices before it";
    }
    obj.Connectivity.push_back(id);
    obj.FaceLines.push_back(lineNumber);
  }
  if (corners < 3)
  {
    return "a face needs at least three vertices";
  }
  obj.Offsets.push_back(static_cast<vtkIdType>(obj.Connectivity.size()));
  return "";
}

vtkSmartPointer<vtkPolyData> ToPolyData(ObjContent& obj)
{
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(static_cast<vtkIdType>(obj.Coordinates.size() / 3));
  std::copy(obj.Coordinates.begin(), obj.Coordinates.end(), coordinates->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(obj.Offsets.size()));
  std::copy(obj.Offsets.begin(), obj.Offsets.end(), offsets->GetPointer(0));
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(obj.Connectivity.size()));
  std::copy(obj.Connectivity.begin(), obj.Connectivity.end(), connectivity->GetPointer(0));
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}
} // namespace

vtkSmartPointer<vtkPolyData> ReadObjGeometry(const std::string& file, std::string& error)
{
  std::ifstream in(file);
  if (!in)
  {
    error = "cannot open '" + file + "'";
    return nullptr;
  }
  ObjContent obj;
  std::string line, statement;
  long lineNumber = 0;
  while (std::getline(in, line))
  {
    ++lineNumber;
    statement += line;
    if (!statement.empty() && statement.back() == '\\') // continued on the next line
    {
      statement.back() = ' ';
      continue;
    }
    std::string_view rest(statement);
    const std::string_view keyword = NextWord(rest);
    const std::string problem = keyword == "v" ? ReadVertex(rest, obj)
      : keyword == "f"                        ? ReadFace(rest, lineNumber, obj)
                                              : std::string();
    if (!problem.empty())
    {
      error = "line " + std::to_string(lineNumber) + ": " + problem;
      return nullptr;
    }
    statement.clear();
  }
  const vtkIdType vertices = static_cast<vtkIdType>(obj.Coordinates.size() / 3);
  for (std::size_t k = 0; k < obj.Connectivity.size(); ++k)
  {
    if (obj.Connectivity[k] >= vertices)
    {
      error = "line " + std::to_string(obj.FaceLines[k]) + ": face refers to vertex " +
        std::to_string(obj.Connectivity[k] + 1) + ", but the file has " + std::to_string(vertices);
      return nullptr;
    }
  }
  return ToPolyData(obj);
}
} // namespace tpcontour
