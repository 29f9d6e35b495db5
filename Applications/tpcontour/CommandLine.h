// tpcontour's command line: the options, their checks and the help text.
#ifndef tpcontour_CommandLine_h
#define tpcontour_CommandLine_h

#include <string>
#include <vector>

namespace tpcontour
{
extern const char* const Help;

struct Options
{
  std::vector<std::string> Inputs;
  /// Empty when not given: several inputs then need --operation or --batch,
  /// so that a Boolean is never computed by accident.
  std::string Operation;
  bool Batch = false;
  // One run: the files to write.
  std::string Output, Grid;
  // A batch: where and how each input's results are written.
  std::string OutputDirectory = ".";
  std::string Format = "vtp";
  bool Grids = false;
  double Tolerance = 0.01;
  bool Absolute = false;
  int MaxDepth = 40;
  long long MaxCells = 10000000;
  bool FillHoles = false;
  bool Decimate = false;     ///< the filter's Decimate (certified decimation)
  bool SplitCreases = false; ///< the filter's SplitCreases (crisp shading)
  /// Threads to run on; 0: VTK's default, every processor.
  int Threads = 0;
  bool Json = false, Quiet = false, Help = false;
};

/// Reads the arguments into `options`; returns what is wrong with them, or
/// an empty string. Fills the defaults that depend on the inputs (the
/// output's name) and expands folders given to --batch into their meshes.
std::string ParseCommandLine(const std::vector<std::string>& arguments, Options& options);

/// "x.stl" -> "stl" (lower case); "" without an extension.
std::string Extension(const std::string& file);

/// "dir/part.stl" -> "part".
std::string Stem(const std::string& file);
} // namespace tpcontour

#endif
