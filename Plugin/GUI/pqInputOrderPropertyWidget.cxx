#include "pqInputOrderPropertyWidget.h"

#include "pqApplicationCore.h"
#include "pqCoreUtilities.h"
#include "pqOutputPort.h"
#include "pqPipelineSource.h"
#include "pqPropertiesPanel.h"
#include "pqServerManagerModel.h"
#include "vtkCommand.h"
#include "vtkSMInputProperty.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"

#include <QCheckBox>
#include <QLabel>
#include <QVBoxLayout>

namespace
{
/// The pipeline name of input `i` (with its port when the source has several).
QString InputName(vtkSMInputProperty* input, unsigned int i)
{
  vtkSMProxy* proxy = input->GetUncheckedProxy(i);
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  pqPipelineSource* source = proxy ? model->findItem<pqPipelineSource*>(proxy) : nullptr;
  QString name = source ? source->getSMName() : QString("(input %1)").arg(i);
  if (source && source->getNumberOfOutputPorts() > 1)
  {
    name += QString(" (%1)").arg(source->getOutputPort(static_cast<int>(input->GetUncheckedOutputPortForConnection(i)))->getPortName());
  }
  return name;
}
} // namespace

pqInputOrderPropertyWidget::pqInputOrderPropertyWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent)
  : Superclass(proxy, parent)
  , Reverse(new QCheckBox(tr("Reverse Input Order"), this))
  , Order(new QLabel(this))
{
  this->setShowLabel(false);
  this->Reverse->setObjectName("Reverse");
  this->Order->setObjectName("Order");
  this->Order->setWordWrap(true);
  this->Order->setToolTip(tr("The order in which the inputs are combined (ParaView connects them in the order "
                             "they were selected); in a Difference the first is the minuend."));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(pqPropertiesPanel::suggestedMargins());
  layout->setSpacing(pqPropertiesPanel::suggestedVerticalSpacing());
  layout->addWidget(this->Order);
  layout->addWidget(this->Reverse);
  this->addPropertyLink(this->Reverse, "checked", SIGNAL(toggled(bool)), property);
  QObject::connect(this->Reverse, &QCheckBox::toggled, this, &pqInputOrderPropertyWidget::updateOrder);
  for (const char* name : { "Input", "Operation", "ImplicitFunction" })
  {
    if (vtkSMProperty* watched = proxy->GetProperty(name))
    {
      pqCoreUtilities::connect(watched, vtkCommand::UncheckedPropertyModifiedEvent, this, SLOT(updateOrder()));
      pqCoreUtilities::connect(watched, vtkCommand::ModifiedEvent, this, SLOT(updateOrder()));
    }
  }
  this->updateOrder();
}

void pqInputOrderPropertyWidget::updateOrder()
{
  vtkSMProxy* proxy = this->proxy();
  auto* input = vtkSMInputProperty::SafeDownCast(proxy->GetProperty("Input"));
  QStringList names;
  const unsigned int count = input ? input->GetNumberOfUncheckedProxies() : 0;
  for (unsigned int k = 0; k < count; ++k)
  {
    names << InputName(input, this->Reverse->isChecked() ? count - 1 - k : k);
  }
  // (The panel's edits are unchecked values until Apply.)
  vtkSMPropertyHelper implicitHelper(proxy, "ImplicitFunction");
  implicitHelper.SetUseUnchecked(true);
  vtkSMProxy* implicit = implicitHelper.GetAsProxy();
  if (implicit && implicit->GetXMLName() && QString(implicit->GetXMLName()) != "None")
  {
    names << QString("the %1").arg(implicit->GetXMLName());
  }
  vtkSMPropertyHelper operationHelper(proxy, "Operation", /*quiet=*/true);
  operationHelper.SetUseUnchecked(true);
  const int operation = operationHelper.GetAsInt();
  const QString op = operation == 1 ? " ∩ " : operation == 2 ? " − " : " ∪ ";
  this->Order->setText(names.isEmpty() ? tr("No solid yet.") : tr("Combined: %1").arg(names.join(op)));
}
