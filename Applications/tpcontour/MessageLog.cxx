#include "MessageLog.h"

#include "vtkCommand.h"
#include "vtkObject.h"

#include <cstdio>

namespace tpcontour
{
MessageLog::MessageLog()
{
  this->Observer->SetCallback(&MessageLog::OnEvent);
  this->Observer->SetClientData(this);
}

void MessageLog::Observe(vtkObject* object, bool progress)
{
  object->AddObserver(vtkCommand::ErrorEvent, this->Observer);
  object->AddObserver(vtkCommand::WarningEvent, this->Observer);
  if (progress)
  {
    object->AddObserver(vtkCommand::ProgressEvent, this->Observer);
  }
}

void MessageLog::ShowProgressBar(const std::string& label)
{
  this->Bar = true;
  this->Label = label;
  this->LastPercent = -1;
}

void MessageLog::ClearProgressBar()
{
  if (this->Bar)
  {
    std::fprintf(stderr, "\r%*s\r", static_cast<int>(this->Label.size()) + 48, "");
    std::fflush(stderr);
  }
  this->Bar = false;
}

void MessageLog::DrawBar(double fraction)
{
  const int percent = static_cast<int>(100 * fraction);
  if (percent == this->LastPercent)
  {
    return;
  }
  this->LastPercent = percent;
  const int filled = percent * 40 / 100;
  std::fprintf(stderr, "\r%s[%s%s] %3d%%", this->Label.c_str(), std::string(filled, '#').c_str(),
    std::string(40 - filled, ' ').c_str(), percent);
  std::fflush(stderr);
}

void MessageLog::OnEvent(vtkObject*, unsigned long event, void* clientData, void* callData)
{
  auto* log = static_cast<MessageLog*>(clientData);
  if (event == vtkCommand::ProgressEvent)
  {
    if (log->Bar)
    {
      log->DrawBar(*static_cast<double*>(callData));
    }
    return;
  }
  std::string text = callData ? static_cast<const char*>(callData) : "";
  // VTK's messages start with "ERROR: In file, line N\nclass (0x...): " -
  // keep what the object says.
  const std::size_t colon = text.find("): ");
  if (colon != std::string::npos)
  {
    text = text.substr(colon + 3);
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
  {
    text.pop_back();
  }
  if (event == vtkCommand::ErrorEvent)
  {
    log->Errors += (log->Errors.empty() ? "" : "\n") + text;
  }
  else
  {
    log->Warnings.push_back(text);
  }
}
} // namespace tpcontour
