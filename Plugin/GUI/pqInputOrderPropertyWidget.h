// The ReverseInputOrder property shown with what it decides: the input
// solids by their pipeline names, in the order the filter folds them, with
// the Operation between them - "Combined: Box1 − Sphere1 − the Cylinder" - and a
// check box reversing that order. ParaView connects a multi-input filter's
// inputs in the order they were selected and shows that order nowhere, while
// a Difference depends on it.
#ifndef pqInputOrderPropertyWidget_h
#define pqInputOrderPropertyWidget_h

#include "pqPropertyWidget.h"

class QCheckBox;
class QLabel;

class pqInputOrderPropertyWidget : public pqPropertyWidget
{
  Q_OBJECT
  typedef pqPropertyWidget Superclass;

public:
  pqInputOrderPropertyWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent = nullptr);
  ~pqInputOrderPropertyWidget() override = default;

private Q_SLOTS:
  /// Writes the fold order as the check box and the proxy's (unapplied)
  /// Input, Operation and ImplicitFunction have it.
  void updateOrder();

private:
  QCheckBox* Reverse;
  QLabel* Order;

  Q_DISABLE_COPY(pqInputOrderPropertyWidget)
};

#endif
