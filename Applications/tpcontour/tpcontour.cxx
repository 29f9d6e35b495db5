// tpcontour: vtkTopologyPreservingContour for files, from the command line.
// Reads closed meshes (STL, OBJ, PLY, VTP, OFF) and either combines them into
// one surface (a Boolean, asked for with --operation) or contours each on its
// own (--batch); writes the surfaces and grids, prints the topology report.
// `--help` says it all.
#include "CommandLine.h"
#include "RunContour.h"
#include "RunReport.h"

#include "vtkSMPTools.h"

#include <cstdlib>
#include <filesystem>
#include <iostream>

using namespace tpcontour;

namespace
{
int Fail(const std::string& message)
{
  std::cerr << "tpcontour: " << message << "\n";
  return 1;
}

/// Runs the filter's loops on `threads` threads (0: every processor). A
/// command-line run owns its process, so unlike the filter in a pipeline it
/// chooses VTK's backend: STDThread (ParaView's VTK defaults to Sequential,
/// which would leave every core but one idle), unless VTK_SMP_BACKEND_IN_USE
/// names one.
void UseThreads(int threads)
{
  if (!std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    vtkSMPTools::SetBackend("STDThread"); // (false where unavailable: Sequential stays)
  }
  vtkSMPTools::Initialize(threads);
}

/// The inputs combined into one surface.
int RunOnce(const Options& o)
{
  const RunReport report = RunContour(o, { o.Inputs, o.Output, o.Grid }, "");
  if (report.ExitStatus == 1)
  {
    return Fail(report.Error);
  }
  std::cout << (o.Json ? JsonReport(report) + "\n" : TextReport(report));
  return report.ExitStatus;
}

/// Each input on its own; a failure is reported and the batch goes on.
int RunBatch(const Options& o)
{
  std::error_code error;
  std::filesystem::create_directories(o.OutputDirectory, error);
  if (error)
  {
    return Fail("cannot create --output-dir '" + o.OutputDirectory + "': " + error.message());
  }
  std::vector<RunReport> reports;
  for (std::size_t i = 0; i < o.Inputs.size(); ++i)
  {
    const std::string base = (std::filesystem::path(o.OutputDirectory) / (Stem(o.Inputs[i]) + "-tpc.")).string();
    const std::string label = "[" + std::to_string(i + 1) + "/" + std::to_string(o.Inputs.size()) + "] ";
    reports.push_back(RunContour(o, { { o.Inputs[i] }, base + o.Format, o.Grids ? base + "htg" : "" }, label));
    if (reports.back().ExitStatus == 1)
    {
      std::cerr << "tpcontour: " << reports.back().Error << "\n";
    }
  }
  std::cout << (o.Json ? JsonReports(reports) : BatchTable(reports));
  return WorstExitStatus(reports);
}
} // namespace

int main(int argc, char* argv[])
{
  Options options;
  const std::string error = ParseCommandLine(std::vector<std::string>(argv + 1, argv + argc), options);
  if (!error.empty())
  {
    return Fail(error);
  }
  if (options.Help)
  {
    std::cout << Help;
    return 0;
  }
  UseThreads(options.Threads);
  return options.Batch ? RunBatch(options) : RunOnce(options);
}
