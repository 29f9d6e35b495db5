#include "pqTopologyPreservingContourStarter.h"

#include "TopologyPreservingColorMapsJson.h" // (generated from Plugin/TopologyPreservingColorMaps.json)

#include "pqActiveObjects.h"
#include "pqApplicationCore.h"
#include "pqPipelineSource.h"
#include "pqProgressManager.h"
#include "pqServer.h"
#include "pqServerManagerModel.h"
#include "vtkAlgorithm.h"
#include "vtkSMSettings.h"
#include "vtkSMSourceProxy.h"
#include "vtkSMTransferFunctionPresets.h"

#include <QApplication>
#include <QEventLoop>
#include <QMouseEvent>
#include <QWidget>

#include <string>
#include <vector>

namespace
{
/// The filter's progress text (its class name, without the "vtk" that
/// pqProgressManager drops) and its proxy's name.
const QString ProgressText = "TopologyPreservingContour";
const QString ProxyName = "TopologyPreservingContour";

/// Each preset of the shipped file replaces a preset of its name (an older
/// copy from an earlier version stays otherwise). Presets added this way are
/// ParaView's "custom" presets: listed by Choose Preset, saved with the
/// user's settings.
void RegisterPresets()
{
  vtkSMTransferFunctionPresets* presets = vtkSMTransferFunctionPresets::GetInstance();
  for (const auto& preset : tpc::plugin::ColorMaps)
  {
    for (unsigned int i = presets->GetNumberOfPresets(); i-- > 0;)
    {
      if (presets->GetPresetName(i) == preset.Name)
      {
        presets->RemovePreset(i);
      }
    }
    presets->AddPreset(preset.Name, std::string(preset.Text));
  }
}

/// The arrays' default colour maps, below the user's own settings.
void RegisterDefaultColorMaps()
{
  vtkSMSettings::GetInstance()->AddCollectionFromString(R"({ "standard_presets": {
      "SizeReason": "TPC Split Reason", "SplitReason": "TPC Split Reason",
      "FailedTest": "TPC Split Reason", "CellState": "TPC Cell State" } })",
    0.25);
}
} // namespace

pqTopologyPreservingContourStarter::pqTopologyPreservingContourStarter(QObject* parent)
  : Superclass(parent)
{
}

void pqTopologyPreservingContourStarter::onStartup()
{
  RegisterPresets();
  RegisterDefaultColorMaps();
  pqProgressManager* progress = pqApplicationCore::instance()->getProgressManager();
  QObject::connect(progress, &pqProgressManager::progress, this, &pqTopologyPreservingContourStarter::onProgress);
  QObject::connect(progress, &pqProgressManager::abort, this, &pqTopologyPreservingContourStarter::onAbort);
  QObject::connect(
    progress, &pqProgressManager::progressEndEvent, this, &pqTopologyPreservingContourStarter::onProgressEnd);
  // (Installed after pqProgressManager's filter, so asked before it.)
  QApplication::instance()->installEventFilter(this);
  this->SinceEvents.start();
}

bool pqTopologyPreservingContourStarter::eventFilter(QObject* watched, QEvent* event)
{
  if (this->Running && event->type() == QEvent::MouseButtonPress)
  {
    QWidget* target = QApplication::widgetAt(static_cast<QMouseEvent*>(event)->globalPos());
    if (target && target->objectName() == "AbortButton" && target->isEnabled())
    {
      pqApplicationCore::instance()->getProgressManager()->triggerAbort();
      return true;
    }
  }
  return this->Superclass::eventFilter(watched, event);
}

void pqTopologyPreservingContourStarter::onProgress(const QString& text, int)
{
  if (text != ProgressText)
  {
    return;
  }
  if (!this->Running)
  {
    // Connected to a server the filter runs there, out of this process's reach.
    pqServer* server = pqActiveObjects::instance().activeServer();
    if (!server || server->isRemote())
    {
      return;
    }
    this->Running = true;
    pqApplicationCore::instance()->getProgressManager()->setEnableAbort(true);
  }
  if (this->InEvents || this->SinceEvents.elapsed() < 100)
  {
    return;
  }
  // (Timers and socket notifiers wait: a timer's render or a server message
  // would re-enter the pipeline that is running.)
  this->InEvents = true;
  QApplication::processEvents(QEventLoop::ExcludeSocketNotifiers | QEventLoop::X11ExcludeTimers);
  this->InEvents = false;
  this->SinceEvents.restart();
}

void pqTopologyPreservingContourStarter::onAbort()
{
  if (!this->Running)
  {
    return;
  }
  // The filters that have not finished (a finished run reports progress 1):
  // the running one, and any not run yet.
  for (vtkAlgorithm* algorithm : this->Filters())
  {
    if (algorithm->GetProgress() < 1.0)
    {
      algorithm->SetAbortExecute(1);
    }
  }
}

void pqTopologyPreservingContourStarter::onProgressEnd()
{
  if (!this->Running)
  {
    return;
  }
  // The aborted filter cleared its flag (its outputs stay empty until
  // something changes); one that did not run since the click must not abort
  // its next run.
  for (vtkAlgorithm* algorithm : this->Filters())
  {
    if (algorithm->GetAbortExecute())
    {
      algorithm->SetAbortExecute(0);
    }
  }
  this->Running = false;
  pqApplicationCore::instance()->getProgressManager()->setEnableAbort(false);
}

std::vector<vtkAlgorithm*> pqTopologyPreservingContourStarter::Filters()
{
  std::vector<vtkAlgorithm*> filters;
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  for (pqPipelineSource* source : model->findItems<pqPipelineSource*>())
  {
    vtkSMProxy* proxy = source->getProxy();
    if (proxy && proxy->GetXMLName() && ProxyName == proxy->GetXMLName())
    {
      if (auto* algorithm = vtkAlgorithm::SafeDownCast(proxy->GetClientSideObject()))
      {
        filters.push_back(algorithm);
      }
    }
  }
  return filters;
}
