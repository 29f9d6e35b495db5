// tpcontour: vtkTopologyPreservingContour for files, from the command line.
// Reads closed meshes (STL, OBJ, PLY, VTP, OFF), combines them, writes the
// surface and the adaptive grid, prints the topology report. `--help` says it all.
#include "vtkOFFReader.h"
#include "vtkTopologyPreservingContour.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkHyperTreeGrid.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPolyData.h"
#include "vtkSTLReader.h"
#include "vtkSTLWriter.h"
#include "vtkSmartPointer.h"
#include "vtkXMLHyperTreeGridWriter.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace
{
const char* const Help = R"(Usage: tpcontour [options] INPUT [INPUT ...]

Surface of the solid bounded by closed triangle meshes, with the same number of
components and the same genus as the exact surface, within a two-sided
Hausdorff distance epsilon (Varadhan et al., SGP 2004).

Inputs: closed meshes, one solid each: .stl, .obj, .ply, .vtp, .off.
Several inputs are combined in order by --operation: ((A op B) op C) ...

Options:
  -o, --output FILE      surface to write: .vtp (with the report as field data)
                         or .stl (default: <first input's name>-tpc.vtp in the
                         current directory)
  -g, --grid FILE        adaptive grid to write (.htg, a vtkHyperTreeGrid with
                         cell data Depth, SplitReason, SizeReason, CellState,
                         FailedTest)
      --operation OP     union (default), intersection or difference
  -t, --tolerance E      epsilon relative to the diagonal of the inputs' box
                         (default 0.01)
      --absolute-tolerance E
                         epsilon in the inputs' units (instead of --tolerance)
      --max-depth N      refinement limit, 0..19 (default 16)
      --max-cells N      octree cell limit (default 10000000)
      --json             print the report as JSON (on standard output)
  -q, --quiet            no progress bar, no warnings
  -h, --help             this text

The report: components, genus, Euler characteristic, closed/manifold,
embedded (no self-intersection, checked exactly), whether the topology
guarantee holds, the proven Hausdorff bound ("not proven", null in JSON, where
refinement stopped with surface possibly missing). Warnings (repaired
input, unresolved cells) go to standard error.

Exit status: 0 the surface was written and the topology guarantee holds;
             1 bad usage or bad input (the message says what is wrong);
             2 the surface was written but the guarantee does not hold
               (tangential contact, self-intersecting input, or a limit:
               the grid marks the cells with CellState = 3).

Threads: set VTK_SMP_BACKEND_IN_USE=STDThread to use all cores.
)";

struct Options
{
  std::vector<std::string> Inputs;
  std::string Output, Grid, Operation = "union";
  double Tolerance = 0.01;
  bool Absolute = false;
  int MaxDepth = 16;
  long long MaxCells = 10000000;
  bool Json = false, Quiet = false;
};

int Fail(const std::string& message)
{
  std::cerr << "tpcontour: " << message << "\n";
  return 1;
}

std::string Extension(const std::string& file)
{
  const std::size_t dot = file.rfind('.');
  std::string e = dot == std::string::npos ? "" : file.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

bool ParseNumber(const std::string& text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end && *end == '\0';
}

template <typename Reader>
vtkSmartPointer<Reader> MakeReader(const std::string& file)
{
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(file.c_str());
  return reader;
}

/// Collects the filter's errors and warnings; draws the progress bar.
struct Messages
{
  std::string Errors;
  std::vector<std::string> Warnings;
  bool Bar = false;
  int LastPercent = -1;
};

void OnEvent(vtkObject* caller, unsigned long event, void* clientData, void* callData)
{
  auto* m = static_cast<Messages*>(clientData);
  if (event == vtkCommand::ProgressEvent)
  {
    if (!m->Bar)
    {
      return;
    }
    const double f = *static_cast<double*>(callData);
    const int percent = static_cast<int>(100 * f);
    if (percent != m->LastPercent)
    {
      m->LastPercent = percent;
      const int filled = percent * 40 / 100;
      std::fprintf(stderr, "\r[%s%s] %3d%%", std::string(filled, '#').c_str(),
        std::string(40 - filled, ' ').c_str(), percent);
      std::fflush(stderr);
    }
    return;
  }
  std::string text = callData ? static_cast<const char*>(callData) : "";
  // VTK's messages start with "ERROR: In file, line N\nclass (0x...): " -
  // keep what the filter says.
  const std::size_t colon = text.find("): ");
  if (colon != std::string::npos)
  {
    text = text.substr(colon + 3);
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
  {
    text.pop_back();
  }
  (void)caller;
  if (event == vtkCommand::ErrorEvent)
  {
    m->Errors += (m->Errors.empty() ? "" : "\n") + text;
  }
  else
  {
    m->Warnings.push_back(text);
  }
}

/// Reads one mesh, or returns null with `error` set; the reader's warnings
/// are added to `warnings`.
vtkSmartPointer<vtkPolyData> Read(const std::string& file, std::string& error, std::vector<std::string>& warnings)
{
  struct stat st;
  if (stat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
  {
    error = "cannot read '" + file + "': no such file";
    return nullptr;
  }
  const std::string e = Extension(file);
  vtkSmartPointer<vtkAlgorithm> reader;
  if (e == "stl")
  {
    auto stl = MakeReader<vtkSTLReader>(file);
    stl->MergingOn(); // STL repeats vertices per triangle
    reader = stl;
  }
  else if (e == "obj")
  {
    reader = MakeReader<vtkOBJReader>(file);
  }
  else if (e == "ply")
  {
    reader = MakeReader<vtkPLYReader>(file);
  }
  else if (e == "vtp")
  {
    reader = MakeReader<vtkXMLPolyDataReader>(file);
  }
  else if (e == "off")
  {
    reader = MakeReader<vtkOFFReader>(file);
  }
  else
  {
    error = "'" + file + "': unknown format (expected .stl, .obj, .ply, .vtp or .off)";
    return nullptr;
  }
  // The reader's own messages (a parse error and its line) say best what is
  // wrong with a broken file; a file it complained about is refused whole
  // (part of a mesh would be open or a different solid).
  Messages messages;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(&OnEvent);
  observer->SetClientData(&messages);
  for (vtkObject* source : { static_cast<vtkObject*>(reader), static_cast<vtkObject*>(reader->GetExecutive()) })
  {
    source->AddObserver(vtkCommand::ErrorEvent, observer);
    source->AddObserver(vtkCommand::WarningEvent, observer);
  }
  reader->Update();
  auto* mesh = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  const std::size_t failure = messages.Errors.find("\nAlgorithm "); // the executive's echo
  if (!messages.Errors.empty())
  {
    error = "cannot read '" + file + "': " + messages.Errors.substr(0, failure);
    return nullptr;
  }
  if (!mesh || mesh->GetNumberOfPolys() + mesh->GetNumberOfStrips() == 0)
  {
    error = "'" + file + "' holds no triangles (empty, or no polygons in it)";
    return nullptr;
  }
  for (const std::string& w : messages.Warnings)
  {
    warnings.push_back("reading '" + file + "': " + w);
  }
  return mesh;
}


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
    out += k < files.size() ? "'" + files[k] + "' (input " + std::to_string(k) + ")" : it->str();
    last = static_cast<std::size_t>(it->position() + it->length());
  }
  return out + text.substr(last);
}

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
} // namespace

int main(int argc, char* argv[])
{
  Options o;
  std::vector<std::string> args(argv + 1, argv + argc);
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= args.size())
      {
        return false;
      }
      out = args[++i];
      return true;
    };
    std::string v;
    double x = 0.0;
    if (a == "-h" || a == "--help")
    {
      std::cout << Help;
      return 0;
    }
    else if (a == "-o" || a == "--output")
    {
      if (!value(o.Output))
      {
        return Fail(a + " needs a file name (see --help)");
      }
    }
    else if (a == "-g" || a == "--grid")
    {
      if (!value(o.Grid))
      {
        return Fail(a + " needs a file name (see --help)");
      }
    }
    else if (a == "--operation")
    {
      if (!value(o.Operation) ||
        (o.Operation != "union" && o.Operation != "intersection" && o.Operation != "difference"))
      {
        return Fail("--operation must be union, intersection or difference");
      }
    }
    else if (a == "-t" || a == "--tolerance" || a == "--absolute-tolerance")
    {
      if (!value(v) || !ParseNumber(v, x) || !(x > 0.0))
      {
        return Fail(a + " needs a positive number");
      }
      o.Tolerance = x;
      o.Absolute = a == "--absolute-tolerance";
    }
    else if (a == "--max-depth")
    {
      if (!value(v) || !ParseNumber(v, x) || x < 0 || x > 19 || x != static_cast<int>(x))
      {
        return Fail("--max-depth needs an integer from 0 to 19");
      }
      o.MaxDepth = static_cast<int>(x);
    }
    else if (a == "--max-cells")
    {
      if (!value(v) || !ParseNumber(v, x) || x < 8 || x != static_cast<long long>(x))
      {
        return Fail("--max-cells needs an integer of at least 8");
      }
      o.MaxCells = static_cast<long long>(x);
    }
    else if (a == "--json")
    {
      o.Json = true;
    }
    else if (a == "-q" || a == "--quiet")
    {
      o.Quiet = true;
    }
    else if (!a.empty() && a[0] == '-')
    {
      return Fail("unknown option " + a + " (see --help)");
    }
    else
    {
      o.Inputs.push_back(a);
    }
  }
  if (o.Inputs.empty())
  {
    return Fail("no input file (see --help)");
  }
  if (o.Output.empty())
  {
    // In the current directory, named after the first input.
    std::string first = o.Inputs.front();
    const std::size_t slash = first.rfind('/');
    first = slash == std::string::npos ? first : first.substr(slash + 1);
    o.Output = first.substr(0, first.rfind('.')) + "-tpc.vtp";
  }
  const std::string outExt = Extension(o.Output);
  if (outExt != "vtp" && outExt != "stl")
  {
    return Fail("--output must end in .vtp or .stl");
  }
  if (!o.Grid.empty() && Extension(o.Grid) != "htg")
  {
    return Fail("--grid must end in .htg");
  }

  vtkNew<vtkTopologyPreservingContour> filter;
  std::vector<vtkSmartPointer<vtkPolyData>> meshes;
  std::vector<std::string> readWarnings;
  for (const std::string& file : o.Inputs)
  {
    std::string error;
    vtkSmartPointer<vtkPolyData> mesh = Read(file, error, readWarnings);
    if (!mesh)
    {
      return Fail(error);
    }
    filter->AddInputData(mesh);
    meshes.push_back(mesh);
  }
  filter->SetOperation(o.Operation == "union" ? vtkTopologyPreservingContour::UNION
      : o.Operation == "intersection"         ? vtkTopologyPreservingContour::INTERSECTION
                                              : vtkTopologyPreservingContour::DIFFERENCE);
  filter->SetTolerance(o.Tolerance);
  filter->SetToleranceIsRelative(!o.Absolute);
  filter->SetMaximumDepth(o.MaxDepth);
  filter->SetMaximumNumberOfCells(o.MaxCells);

  Messages messages;
  messages.Warnings = readWarnings;
  messages.Bar = !o.Quiet && isatty(STDERR_FILENO);
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(&OnEvent);
  observer->SetClientData(&messages);
  filter->AddObserver(vtkCommand::ErrorEvent, observer);
  filter->AddObserver(vtkCommand::WarningEvent, observer);
  filter->AddObserver(vtkCommand::ProgressEvent, observer);
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (messages.Bar)
  {
    std::fprintf(stderr, "\r%60s\r", "");
  }
  for (std::string& w : messages.Warnings)
  {
    w = NameInputs(w, o.Inputs);
  }
  messages.Errors = NameInputs(messages.Errors, o.Inputs);
  if (!o.Quiet)
  {
    for (const std::string& w : messages.Warnings)
    {
      std::cerr << "tpcontour: warning: " << w << "\n";
    }
  }
  auto* surface = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(1));
  auto* grid = vtkHyperTreeGrid::SafeDownCast(filter->GetOutputDataObject(0));
  if (!messages.Errors.empty() || !surface || !surface->GetFieldData()->GetArray("Genus"))
  {
    return Fail(messages.Errors.empty() ? "no surface was computed" : messages.Errors);
  }

  if (outExt == "stl")
  {
    vtkNew<vtkSTLWriter> w;
    w->SetInputData(surface);
    w->SetFileName(o.Output.c_str());
    w->SetFileTypeToBinary();
    if (!w->Write())
    {
      return Fail("cannot write " + o.Output);
    }
  }
  else
  {
    vtkNew<vtkXMLPolyDataWriter> w;
    w->SetInputData(surface);
    w->SetDataModeToBinary(); // large appended files are unreadable with Debian 12's expat
    w->SetFileName(o.Output.c_str());
    if (!w->Write())
    {
      return Fail("cannot write " + o.Output);
    }
  }
  if (!o.Grid.empty())
  {
    vtkNew<vtkXMLHyperTreeGridWriter> w;
    w->SetInputData(grid);
    w->SetDataModeToBinary(); // VTK 9.2's default appended mode writes corrupt .htg files
    w->SetFileName(o.Grid.c_str());
    if (!w->Write())
    {
      return Fail("cannot write " + o.Grid);
    }
  }

  auto field = [&](const char* name) { return surface->GetFieldData()->GetArray(name)->GetTuple1(0); };
  const bool guaranteed = field("TopologyGuaranteed") == 1;
  // NaN: refinement stopped where surface may be missing, so no bound is proven.
  const double bound = field("HausdorffBound");
  auto jsonNumber = [](double v) {
    std::ostringstream n;
    if (std::isfinite(v))
    {
      n << v;
    }
    else
    {
      n << "null";
    }
    return n.str();
  };
  if (o.Json)
  {
    std::ostringstream j;
    j << "{\n  \"inputs\": [";
    for (std::size_t i = 0; i < o.Inputs.size(); ++i)
    {
      j << (i ? ", " : "") << JsonString(o.Inputs[i]);
    }
    j << "],\n  \"operation\": " << JsonString(o.Operation)
      << ",\n  \"absolute_tolerance\": " << field("AbsoluteTolerance")
      << ",\n  \"components\": " << field("Components") << ",\n  \"genus\": " << field("Genus")
      << ",\n  \"euler_characteristic\": " << field("EulerCharacteristic")
      << ",\n  \"closed\": " << (field("Closed") == 1 ? "true" : "false")
      << ",\n  \"manifold\": " << (field("Manifold") == 1 ? "true" : "false")
      << ",\n  \"embedded\": " << (field("Embedded") == 1 ? "true" : "false")
      << ",\n  \"guaranteed\": " << (guaranteed ? "true" : "false")
      << ",\n  \"unresolved_cells\": " << field("UnresolvedCells")
      << ",\n  \"hausdorff_bound\": " << jsonNumber(bound)
      << ",\n  \"triangles\": " << surface->GetNumberOfPolys()
      << ",\n  \"grid_cells\": " << (grid ? grid->GetNumberOfCells() : 0) << ",\n  \"seconds\": " << seconds
      << ",\n  \"surface\": " << JsonString(o.Output)
      << ",\n  \"grid\": " << (o.Grid.empty() ? "null" : JsonString(o.Grid)) << "\n}\n";
    std::cout << j.str();
  }
  else
  {
    std::cout << "components           " << field("Components") << "\n"
              << "genus                " << field("Genus") << "\n"
              << "Euler characteristic " << field("EulerCharacteristic") << "\n"
              << "closed / manifold    " << field("Closed") << " / " << field("Manifold") << "\n"
              << "embedded             " << field("Embedded") << "\n"
              << "TopologyGuaranteed   " << (guaranteed ? 1 : 0) << "\n"
              << "UnresolvedCells      " << field("UnresolvedCells") << "\n"
              << "Hausdorff bound      " << (std::isfinite(bound) ? jsonNumber(bound) : "not proven")
              << " (tolerance " << field("AbsoluteTolerance") << ")\n"
              << "triangles            " << surface->GetNumberOfPolys() << "\n"
              << "seconds              " << seconds << "\n"
              << "wrote " << o.Output << (o.Grid.empty() ? "" : " and " + o.Grid) << "\n";
  }
  return guaranteed ? 0 : 2;
}
