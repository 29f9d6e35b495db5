// What one run of the filter gave - the surface's topology report, the files
// written, or why it failed - and how tpcontour prints it: text, JSON, and
// the batch's table.
#ifndef tpcontour_RunReport_h
#define tpcontour_RunReport_h

#include <limits>
#include <string>
#include <vector>

class vtkFieldData;

namespace tpcontour
{
struct RunReport
{
  std::vector<std::string> Inputs;
  std::string Operation;
  /// 0 guaranteed, 2 written without the guarantee, 1 failed (Error says why).
  int ExitStatus = 1;
  std::string Error;
  // The surface's field data (the filter's topology report).
  double AbsoluteTolerance = 0, Components = 0, Genus = 0, EulerCharacteristic = 0, UnresolvedCells = 0;
  /// NaN: refinement stopped where surface may be missing, so no bound is proven.
  double HausdorffBound = std::numeric_limits<double>::quiet_NaN();
  bool Closed = false, Manifold = false, Embedded = false, Outward = false, Guaranteed = false;
  long long Triangles = 0, GridCells = 0;
  double Seconds = 0;
  /// VTK's SMP backend and how many threads it ran the loops on.
  std::string Backend;
  int Threads = 1;
  std::string Surface, Grid;

  /// Copies the topology report from the surface's field data.
  void ReadFieldData(vtkFieldData* field);
};

std::string TextReport(const RunReport& report);
std::string JsonReport(const RunReport& report);
/// A batch: a JSON array of the reports.
std::string JsonReports(const std::vector<RunReport>& reports);
/// A batch: one line per input, then a count of each outcome.
std::string BatchTable(const std::vector<RunReport>& reports);
/// The batch's exit status: 1 if any input failed, else 2 if any lacks the
/// guarantee, else 0.
int WorstExitStatus(const std::vector<RunReport>& reports);
} // namespace tpcontour

#endif
