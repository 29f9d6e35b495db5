#include "RunReport.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace tpcontour
{
namespace
{
std::string JsonString(const std::string& s)
{
  std::string out = "\"";
  for (const char c : s)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
    }
    out += c == '\n' ? ' ' : c;
  }
  return out + "\"";
}

std::string Number(double v, const char* missing)
{
  std::ostringstream n;
  if (std::isfinite(v))
  {
    n << v;
  }
  else
  {
    n << missing;
  }
  return n.str();
}

const char* Bool(bool b)
{
  return b ? "true" : "false";
}

/// The first sentence of a message, for the table (the whole message goes
/// to standard error).
std::string FirstSentence(const std::string& text)
{
  const std::size_t end = std::min(text.find(". "), text.find('\n'));
  return end == std::string::npos ? text : text.substr(0, end + (text[end] == '.'));
}
} // namespace

void RunReport::ReadFieldData(vtkFieldData* field)
{
  auto value = [&](const char* name) { return field->GetArray(name)->GetTuple1(0); };
  this->AbsoluteTolerance = value("AbsoluteTolerance");
  this->Components = value("Components");
  this->Genus = value("Genus");
  this->EulerCharacteristic = value("EulerCharacteristic");
  this->UnresolvedCells = value("UnresolvedCells");
  this->HausdorffBound = value("HausdorffBound");
  this->Closed = value("Closed") == 1;
  this->Manifold = value("Manifold") == 1;
  this->Embedded = value("Embedded") == 1;
  this->Outward = value("Outward") == 1;
  this->Guaranteed = value("TopologyGuaranteed") == 1;
}

std::string TextReport(const RunReport& r)
{
  std::ostringstream t;
  t << "components           " << r.Components << "\n"
    << "genus                " << r.Genus << "\n"
    << "Euler characteristic " << r.EulerCharacteristic << "\n"
    << "closed / manifold    " << r.Closed << " / " << r.Manifold << "\n"
    << "embedded             " << r.Embedded << "\n"
    << "outward              " << r.Outward << "\n"
    << "TopologyGuaranteed   " << r.Guaranteed << "\n"
    << "UnresolvedCells      " << r.UnresolvedCells << "\n"
    << "Hausdorff bound      " << Number(r.HausdorffBound, "not proven") << " (tolerance " << Number(r.AbsoluteTolerance, "unknown")
    << ")\n"
    << "triangles            " << r.Triangles << "\n"
    << "seconds              " << r.Seconds << " (" << r.Threads << (r.Threads == 1 ? " thread, " : " threads, ")
    << r.Backend << ")\n"
    << "wrote " << r.Surface << (r.Grid.empty() ? "" : " and " + r.Grid) << "\n";
  return t.str();
}

std::string JsonReport(const RunReport& r)
{
  std::ostringstream j;
  j << "{\n  \"inputs\": [";
  for (std::size_t i = 0; i < r.Inputs.size(); ++i)
  {
    j << (i ? ", " : "") << JsonString(r.Inputs[i]);
  }
  j << "],\n  \"operation\": " << (r.Operation.empty() ? "null" : JsonString(r.Operation))
    << ",\n  \"exit_status\": " << r.ExitStatus
    << ",\n  \"error\": " << (r.ExitStatus == 1 ? JsonString(r.Error) : "null");
  if (r.ExitStatus != 1)
  {
    j << ",\n  \"absolute_tolerance\": " << Number(r.AbsoluteTolerance, "null") << ",\n  \"components\": " << r.Components
      << ",\n  \"genus\": " << r.Genus << ",\n  \"euler_characteristic\": " << r.EulerCharacteristic
      << ",\n  \"closed\": " << Bool(r.Closed) << ",\n  \"manifold\": " << Bool(r.Manifold)
      << ",\n  \"embedded\": " << Bool(r.Embedded) << ",\n  \"outward\": " << Bool(r.Outward)
      << ",\n  \"guaranteed\": " << Bool(r.Guaranteed)
      << ",\n  \"unresolved_cells\": " << r.UnresolvedCells
      << ",\n  \"hausdorff_bound\": " << Number(r.HausdorffBound, "null") << ",\n  \"triangles\": " << r.Triangles
      << ",\n  \"grid_cells\": " << r.GridCells << ",\n  \"seconds\": " << r.Seconds
      << ",\n  \"threads\": " << r.Threads << ",\n  \"smp_backend\": " << JsonString(r.Backend)
      << ",\n  \"surface\": " << JsonString(r.Surface)
      << ",\n  \"grid\": " << (r.Grid.empty() ? "null" : JsonString(r.Grid));
  }
  j << "\n}";
  return j.str();
}

std::string JsonReports(const std::vector<RunReport>& reports)
{
  std::string out = "[";
  for (std::size_t i = 0; i < reports.size(); ++i)
  {
    out += (i ? ",\n" : "\n") + JsonReport(reports[i]);
  }
  return out + "\n]\n";
}

std::string BatchTable(const std::vector<RunReport>& reports)
{
  std::size_t width = 5;
  for (const RunReport& r : reports)
  {
    width = std::max(width, r.Inputs.front().size());
  }
  std::ostringstream t;
  char line[256];
  std::snprintf(line, sizeof line, "%-*s  %4s  %9s  %10s  %5s  %10s  %10s  %7s\n", static_cast<int>(width), "input",
    "exit", "triangles", "components", "genus", "guaranteed", "bound", "seconds");
  t << line;
  int counts[3] = { 0, 0, 0 };
  for (const RunReport& r : reports)
  {
    ++counts[r.ExitStatus];
    if (r.ExitStatus == 1)
    {
      std::snprintf(line, sizeof line, "%-*s  %4d  ", static_cast<int>(width), r.Inputs.front().c_str(), 1);
      t << line << FirstSentence(r.Error) << "\n";
      continue;
    }
    std::snprintf(line, sizeof line, "%-*s  %4d  %9lld  %10g  %5g  %10s  %10s  %7.2f\n", static_cast<int>(width),
      r.Inputs.front().c_str(), r.ExitStatus, r.Triangles, r.Components, r.Genus, r.Guaranteed ? "yes" : "no",
      Number(r.HausdorffBound, "not proven").c_str(), r.Seconds);
    t << line;
  }
  t << reports.size() << " input" << (reports.size() == 1 ? "" : "s") << ": " << counts[0] << " guaranteed, "
    << counts[2] << " without the guarantee, " << counts[1] << " failed; exit status " << WorstExitStatus(reports)
    << "\n";
  return t.str();
}

int WorstExitStatus(const std::vector<RunReport>& reports)
{
  const auto has = [&](int status) {
    return std::any_of(reports.begin(), reports.end(), [&](const RunReport& r) { return r.ExitStatus == status; });
  };
  return has(1) ? 1 : has(2) ? 2 : 0;
}
} // namespace tpcontour
