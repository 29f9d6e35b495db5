// One run of vtkTopologyPreservingContour on files: read the inputs, combine
// them, write the surface (and the grid), report.
#ifndef tpcontour_RunContour_h
#define tpcontour_RunContour_h

#include "CommandLine.h"
#include "RunReport.h"

#include <string>
#include <vector>

namespace tpcontour
{
struct RunFiles
{
  std::vector<std::string> Inputs;
  std::string Surface; // .vtp or .stl
  std::string Grid;    // .htg, or empty
};

/// Runs the filter with `options`' settings on `files.Inputs` (combined by
/// options.Operation) and writes `files.Surface` and `files.Grid`. Warnings
/// go to standard error unless options.Quiet; a progress bar, preceded by
/// `barLabel`, when standard error is a terminal. Failures are in the report
/// (ExitStatus 1, Error), not printed.
RunReport RunContour(const Options& options, const RunFiles& files, const std::string& barLabel);
} // namespace tpcontour

#endif
