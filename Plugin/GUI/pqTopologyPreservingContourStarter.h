// What ParaView 5.11's GUI does not do for this filter, done when the plugin
// loads (an auto-start component; the filter itself is XML only):
//
// - The grid's categorical colour maps ("TPC Split Reason", "TPC Cell
//   State") are registered as presets, and made the default colour maps of
//   the arrays they name (SizeReason, SplitReason, FailedTest, CellState), so
//   the grid is coloured by named categories on Apply, without an Import or
//   Interpret Values As Categories.
// - The progress bar's abort button (x) stops the filter. In 5.11 that button
//   is wired to nothing (pqProgressManager::abort() has no receiver, the
//   button stays disabled), no event is processed while a filter runs, and
//   pqProgressManager's filter of input events during progress drops the
//   press on the application's window before it could reach the button. So
//   while this filter runs (its progress reports) the button is enabled and
//   pending events are processed every 0.1 s (timers and sockets wait: a
//   render or a server message would re-enter the running pipeline); a
//   mouse press on the button is taken here, before ParaView's filter drops
//   it (input anywhere else stays blocked), and sets the filter's
//   AbortExecute, which it checks at every progress report (CheckAbort);
//   the aborted filter's outputs stay empty until a property or an input
//   changes (the filter clears the flag: VTK 9.2 would otherwise run it
//   again at once, for the next port or view that asks). In
//   a builtin session (ParaView's default); connected to a server, the
//   filter runs there.
#ifndef pqTopologyPreservingContourStarter_h
#define pqTopologyPreservingContourStarter_h

#include <QElapsedTimer>
#include <QObject>

#include <vector>

class vtkAlgorithm;

class pqTopologyPreservingContourStarter : public QObject
{
  Q_OBJECT
  typedef QObject Superclass;

public:
  pqTopologyPreservingContourStarter(QObject* parent = nullptr);
  ~pqTopologyPreservingContourStarter() override = default;

  void onStartup();
  void onShutdown() {}

  /// While the filter runs: a mouse press on the abort button aborts it.
  bool eventFilter(QObject* watched, QEvent* event) override;

private Q_SLOTS:
  void onProgress(const QString& text, int value);
  void onAbort();
  void onProgressEnd();

private:
  /// The VTK objects of the session's Topology Preserving Contours.
  static std::vector<vtkAlgorithm*> Filters();

  bool Running = false;
  bool InEvents = false;
  QElapsedTimer SinceEvents;

  Q_DISABLE_COPY(pqTopologyPreservingContourStarter)
};

#endif
