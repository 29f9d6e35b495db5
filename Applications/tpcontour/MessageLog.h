// The messages of VTK objects (readers, the filter) gathered for the user,
// and the progress bar on a terminal.
#ifndef tpcontour_MessageLog_h
#define tpcontour_MessageLog_h

#include "vtkCallbackCommand.h"
#include "vtkNew.h"

#include <string>
#include <vector>

class vtkObject;

namespace tpcontour
{
class MessageLog
{
public:
  MessageLog();
  MessageLog(const MessageLog&) = delete;
  MessageLog& operator=(const MessageLog&) = delete;

  /// Collects `object`'s errors and warnings (and its progress, drawn as a
  /// bar on standard error when `bar` is set).
  void Observe(vtkObject* object, bool progress = false);
  /// Draws a bar while observed objects report progress; `label` precedes it.
  void ShowProgressBar(const std::string& label);
  /// Erases the bar (before anything else is printed).
  void ClearProgressBar();

  /// The errors, newline-separated, without VTK's "ERROR: In file, line"
  /// prefixes: what the object says.
  std::string Errors;
  std::vector<std::string> Warnings;

private:
  static void OnEvent(vtkObject* caller, unsigned long event, void* clientData, void* callData);
  void DrawBar(double fraction);

  vtkNew<vtkCallbackCommand> Observer;
  bool Bar = false;
  std::string Label;
  int LastPercent = -1;
};
} // namespace tpcontour

#endif
