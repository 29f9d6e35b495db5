#include "CommandLine.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>

namespace tpcontour
{
const char* const Help = R"(Usage: tpcontour [options] INPUT                       one solid
       tpcontour --operation OP [options] INPUT INPUT ...   their Boolean
       tpcontour --batch [options] INPUT|FOLDER ...        each on its own

Surface of the solid bounded by closed triangle meshes, with the same number of
components and the same genus as the exact surface, within a two-sided
Hausdorff distance epsilon (Varadhan et al., SGP 2004).

Inputs: closed meshes, one solid each: .stl, .obj, .ply, .vtp, .off.
Several inputs are either combined in order by --operation, ((A op B) op C)
..., into one surface, or contoured one by one with --batch.

Options:
  -o, --output FILE      surface to write: .vtp (with the report as field data)
                         or .stl (default: <first input's name>-tpc.vtp in the
                         current directory)
  -g, --grid FILE        adaptive grid to write (.htg, a vtkHyperTreeGrid with
                         cell data Depth, SplitReason, SizeReason, CellState,
                         FailedTest, CertifiedError)
      --operation OP     union, intersection or difference of the inputs;
                         required with more than one input (without --batch)
      --batch            one surface per input (a folder stands for the .stl,
                         .obj, .ply, .vtp and .off files in it); prints a table
      --output-dir DIR   with --batch: where each <input>-tpc.<format> is
                         written (default: the current directory)
      --format F         with --batch: vtp (default) or stl
      --grids            with --batch: also write each grid, <input>-tpc.htg
  -t, --tolerance E      epsilon relative to the diagonal of the inputs' box,
                         a number or a fraction: 0.01 (default), 1/64
      --absolute-tolerance E
                         epsilon in the inputs' units (instead of --tolerance)
      --max-depth N      refinement limit, 0..40 (default 40,
                         the lattice's end; refinement goes deep only
                         where a topology test fails)
      --max-cells N      octree cell limit (default 10000000)
      --fill-holes       close the holes of open inputs (the filter's FillHoles,
                         vtkFillHolesFilter; reported as a repair) instead of
                         refusing them
      --decimate         decimate the surface, every collapse certified: the
                         Hausdorff bound, embedding, topology and creases kept
      --split-creases    split the surface's points along its creases (edges
                         of 30 degrees or more) for crisp shading: each copy
                         has its side's normal, SurfacePointId maps it back
                         (the .vtp is then no longer closed by shared points:
                         leave it off for CAD or mesh Booleans)
      --threads N        threads to run on (default and at most: one per
                         processor); the output is the same on any number
      --json             print the report as JSON on standard output (with
                         --batch: an array, one report per input)
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
A batch goes on past inputs it cannot read and exits with the worst status
of its inputs: 1 if any failed, else 2 if any lacks the guarantee, else 0.

Threads: VTK's STDThread backend unless VTK_SMP_BACKEND_IN_USE names
another (Sequential runs on one thread whatever --threads says); the report
says how many threads ran.
)";

namespace
{
const char* const MeshExtensions[] = { "stl", "obj", "ply", "vtp", "off" };

bool IsMeshFile(const std::filesystem::path& file)
{
  const std::string e = Extension(file.string());
  return std::find(std::begin(MeshExtensions), std::end(MeshExtensions), e) != std::end(MeshExtensions);
}

bool ParseDecimal(const std::string& text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end && *end == '\0';
}

/// A decimal number, or a fraction "1/64" (tolerances are usually powers of
/// two, which a fraction writes exactly).
bool ParseNumber(const std::string& text, double& value)
{
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos)
  {
    return ParseDecimal(text, value);
  }
  double numerator = 0.0, denominator = 0.0;
  if (!ParseDecimal(text.substr(0, slash), numerator) || !ParseDecimal(text.substr(slash + 1), denominator) ||
    denominator == 0.0)
  {
    return false;
  }
  value = numerator / denominator;
  return true;
}

/// One option and its value, if it takes one; returns what is wrong, or "".
std::string ParseOption(const std::string& a, const std::vector<std::string>& args, std::size_t& i, Options& o)
{
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
    o.Help = true;
  }
  else if (a == "-o" || a == "--output" || a == "-g" || a == "--grid" || a == "--output-dir")
  {
    std::string& target = a == "--output-dir" ? o.OutputDirectory : (a == "-o" || a == "--output") ? o.Output : o.Grid;
    if (!value(target) || target.empty())
    {
      return a + " needs a " + (a == "--output-dir" ? "folder" : "file") + " name (see --help)";
    }
  }
  else if (a == "--operation")
  {
    if (!value(o.Operation) ||
      (o.Operation != "union" && o.Operation != "intersection" && o.Operation != "difference"))
    {
      return "--operation must be union, intersection or difference";
    }
  }
  else if (a == "--format")
  {
    if (!value(o.Format) || (o.Format != "vtp" && o.Format != "stl"))
    {
      return "--format must be vtp or stl";
    }
  }
  else if (a == "-t" || a == "--tolerance" || a == "--absolute-tolerance")
  {
    if (!value(v) || !ParseNumber(v, x) || !(x > 0.0) || !std::isfinite(x))
    {
      return a + " needs a positive number or fraction (0.01, 1/64)";
    }
    o.Tolerance = x;
    o.Absolute = a == "--absolute-tolerance";
  }
  else if (a == "--max-depth")
  {
    if (!value(v) || !ParseDecimal(v, x) || x < 0 || x > 40 || x != static_cast<int>(x))
    {
      return "--max-depth needs an integer from 0 to 40";
    }
    o.MaxDepth = static_cast<int>(x);
  }
  else if (a == "--threads")
  {
    if (!value(v) || !ParseDecimal(v, x) || x < 1 || x > 4096 || x != static_cast<int>(x))
    {
      return "--threads needs an integer from 1 to 4096";
    }
    o.Threads = static_cast<int>(x);
  }
  else if (a == "--max-cells")
  {
    if (!value(v) || !ParseDecimal(v, x) || x < 8 || x > 9e18 || x != static_cast<long long>(x))
    {
      return "--max-cells needs an integer of at least 8";
    }
    o.MaxCells = static_cast<long long>(x);
  }
  else if (a == "--batch" || a == "--grids" || a == "--fill-holes" || a == "--decimate" || a == "--split-creases" || a == "--json" || a == "-q" || a == "--quiet")
  {
    bool& flag = a == "--batch" ? o.Batch
      : a == "--grids"          ? o.Grids
      : a == "--fill-holes"     ? o.FillHoles
      : a == "--decimate"       ? o.Decimate
      : a == "--split-creases"  ? o.SplitCreases
      : a == "--json"           ? o.Json
                                : o.Quiet;
    flag = true;
  }
  else
  {
    return "unknown option " + a + " (see --help)";
  }
  return "";
}

/// --batch: a folder stands for its mesh files, in name order; each output
/// name must be used once.
std::string ExpandBatchInputs(Options& o)
{
  std::vector<std::string> files;
  for (const std::string& input : o.Inputs)
  {
    std::error_code error;
    if (!std::filesystem::is_directory(input, error))
    {
      files.push_back(input);
      continue;
    }
    std::vector<std::string> inFolder;
    for (const auto& entry : std::filesystem::directory_iterator(input, error))
    {
      if (entry.is_regular_file(error) && IsMeshFile(entry.path()))
      {
        inFolder.push_back(entry.path().string());
      }
    }
    if (inFolder.empty())
    {
      return "folder '" + input + "' holds no .stl, .obj, .ply, .vtp or .off file";
    }
    std::sort(inFolder.begin(), inFolder.end());
    files.insert(files.end(), inFolder.begin(), inFolder.end());
  }
  std::set<std::string> stems;
  for (const std::string& file : files)
  {
    if (!stems.insert(Stem(file)).second)
    {
      return "two inputs would both be written to " + Stem(file) + "-tpc." + o.Format +
        ": give them different names, or run a batch per folder with its own --output-dir";
    }
  }
  o.Inputs = files;
  return "";
}

/// The combinations of options that mean nothing, and the defaults that
/// depend on the inputs.
std::string CheckModes(Options& o)
{
  if (o.Inputs.empty())
  {
    return "no input file (see --help)";
  }
  if (o.Batch)
  {
    if (!o.Operation.empty() || !o.Output.empty() || !o.Grid.empty())
    {
      return "--batch writes one surface per input: use --output-dir, --format and --grids "
             "(not --output, --grid or --operation)";
    }
    return ExpandBatchInputs(o);
  }
  if (o.OutputDirectory != "." || o.Format != "vtp" || o.Grids)
  {
    return "--output-dir, --format and --grids belong to --batch (one run writes --output and --grid)";
  }
  for (const std::string& input : o.Inputs)
  {
    std::error_code error;
    if (std::filesystem::is_directory(input, error))
    {
      return "'" + input + "' is a folder: --batch contours each mesh in it";
    }
  }
  if (o.Inputs.size() > 1 && o.Operation.empty())
  {
    return std::to_string(o.Inputs.size()) +
      " inputs: give --operation union, intersection or difference to combine them into one solid, "
      "or --batch for one surface per input";
  }
  o.Operation = o.Operation.empty() ? "union" : o.Operation;
  o.Output = o.Output.empty() ? Stem(o.Inputs.front()) + "-tpc.vtp" : o.Output;
  const std::string outExt = Extension(o.Output);
  if (outExt != "vtp" && outExt != "stl")
  {
    return "--output must end in .vtp or .stl";
  }
  if (!o.Grid.empty() && Extension(o.Grid) != "htg")
  {
    return "--grid must end in .htg";
  }
  return "";
}
} // namespace

std::string Extension(const std::string& file)
{
  std::string e = std::filesystem::path(file).extension().string();
  e = e.empty() ? e : e.substr(1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

std::string Stem(const std::string& file)
{
  return std::filesystem::path(file).stem().string();
}

std::string ParseCommandLine(const std::vector<std::string>& args, Options& o)
{
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    if (a.size() > 1 && a[0] == '-')
    {
      const std::string error = ParseOption(a, args, i, o);
      if (!error.empty())
      {
        return error;
      }
    }
    else
    {
      o.Inputs.push_back(a);
    }
  }
  return o.Help ? "" : CheckModes(o);
}
} // namespace tpcontour
