#include "RunContour.h"

#include "MessageLog.h"
#include "ReadMesh.h"
#include "vtkTopologyPreservingContour.h"

#include "vtkFieldData.h"
#include "vtkHyperTreeGrid.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSTLWriter.h"
#include "vtkXMLHyperTreeGridWriter.h"
#include "vtkXMLPolyDataWriter.h"

#include <chrono>
#include <iostream>
#include <regex>
#include <unistd.h>

namespace tpcontour
{
namespace
{
/// The filter calls its inputs "Input k"; the user knows them by file name.
std::string NameInputs(const std::string& text, const std::vector<std::string>& files)
{
  static const std::regex input(R"(\bInput (\d+)\b)");
  std::string out;
  std::size_t last = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), input); it != std::sregex_iterator(); ++it)
  {
    const std::size_t k = std::stoul((*it)[1].str());
    out += text.substr(last, static_cast<std::size_t>(it->position()) - last);
    const std::string which = files.size() > 1 ? " (input " + std::to_string(k) + ")" : "";
    out += k < files.size() ? "'" + files[k] + "'" + which : it->str();
    last = static_cast<std::size_t>(it->position() + it->length());
  }
  return out + text.substr(last);
}

void Configure(vtkTopologyPreservingContour* filter, const Options& o)
{
  filter->SetOperation(o.Operation == "intersection" ? vtkTopologyPreservingContour::INTERSECTION
      : o.Operation == "difference"                  ? vtkTopologyPreservingContour::DIFFERENCE
                                                     : vtkTopologyPreservingContour::UNION);
  filter->SetTolerance(o.Tolerance);
  filter->SetToleranceIsRelative(!o.Absolute);
  filter->SetMaximumDepth(o.MaxDepth);
  filter->SetMaximumNumberOfCells(o.MaxCells);
  filter->SetFillHoles(o.FillHoles);
  filter->SetDecimate(o.Decimate);
  filter->SetSplitCreases(o.SplitCreases);
}

/// Writes the surface (.stl or .vtp) and the grid (.htg, if asked for);
/// returns what could not be written, or "".
std::string WriteOutputs(vtkPolyData* surface, vtkHyperTreeGrid* grid, const RunFiles& files)
{
  if (Extension(files.Surface) == "stl")
  {
    vtkNew<vtkSTLWriter> w;
    w->SetInputData(surface);
    w->SetFileName(files.Surface.c_str());
    w->SetFileTypeToBinary();
    if (!w->Write())
    {
      return "cannot write " + files.Surface;
    }
  }
  else
  {
    vtkNew<vtkXMLPolyDataWriter> w;
    w->SetInputData(surface);
    w->SetDataModeToBinary(); // large appended files are unreadable with Debian 12's expat
    w->SetFileName(files.Surface.c_str());
    if (!w->Write())
    {
      return "cannot write " + files.Surface;
    }
  }
  if (!files.Grid.empty())
  {
    vtkNew<vtkXMLHyperTreeGridWriter> w;
    w->SetInputData(grid);
    w->SetDataModeToBinary(); // VTK 9.2's default appended mode writes corrupt .htg files
    w->SetFileName(files.Grid.c_str());
    if (!w->Write())
    {
      return "cannot write " + files.Grid;
    }
  }
  return "";
}

void PrintWarnings(const std::vector<std::string>& warnings, const std::vector<std::string>& files)
{
  for (const std::string& w : warnings)
  {
    std::cerr << "tpcontour: warning: " << NameInputs(w, files) << "\n";
  }
}
} // namespace

RunReport RunContour(const Options& o, const RunFiles& files, const std::string& barLabel)
{
  RunReport report;
  report.Inputs = files.Inputs;
  report.Operation = o.Operation;
  vtkNew<vtkTopologyPreservingContour> filter;
  std::vector<std::string> readWarnings;
  for (const std::string& file : files.Inputs)
  {
    vtkSmartPointer<vtkPolyData> mesh = ReadMesh(file, report.Error, readWarnings);
    if (!mesh)
    {
      return report;
    }
    filter->AddInputData(mesh);
  }
  Configure(filter, o);

  MessageLog log;
  log.Observe(filter, true);
  if (!o.Quiet && isatty(STDERR_FILENO))
  {
    log.ShowProgressBar(barLabel);
  }
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  report.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.Backend = vtkSMPTools::GetBackend();
  report.Threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  log.ClearProgressBar();
  if (!o.Quiet)
  {
    PrintWarnings(readWarnings, files.Inputs);
    PrintWarnings(log.Warnings, files.Inputs);
  }
  auto* surface = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0));
  auto* grid = vtkHyperTreeGrid::SafeDownCast(filter->GetOutputDataObject(1));
  if (!log.Errors.empty() || !surface || !surface->GetFieldData()->GetArray("Genus"))
  {
    report.Error = log.Errors.empty() ? "no surface was computed" : NameInputs(log.Errors, files.Inputs);
    return report;
  }
  report.Error = WriteOutputs(surface, grid, files);
  if (!report.Error.empty())
  {
    return report;
  }
  report.ReadFieldData(surface->GetFieldData());
  report.Triangles = surface->GetNumberOfPolys();
  report.GridCells = grid ? grid->GetNumberOfCells() : 0;
  report.Surface = files.Surface;
  report.Grid = files.Grid;
  report.ExitStatus = report.Guaranteed ? 0 : 2;
  return report;
}
} // namespace tpcontour
