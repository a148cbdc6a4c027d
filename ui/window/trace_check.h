#pragma once
// File → Check a Student's Trace: the workbench's side of `forcelab-cli
// compare`. A student's CSV or JSON trace of the lesson on screen is checked
// against the run with the live settings (sim::matchTrace on a worker
// thread); the result names the first step and ball that depart, by how
// much, and the known mistake the numbers follow (sim::diagnose). The
// canvas then shows the run at that step, the ball selected and the
// student's position marked.

#include "lessons/student_trace.h"
#include "sim/studies/trace_compare.h"

#include <QFutureWatcher>
#include <QObject>
#include <QPointer>
#include <QString>

#include <optional>

class QAction;
class QMessageBox;
class QWidget;

namespace forcelab {

class Canvas;
class SimulationController;

class TraceCheck : public QObject {
    Q_OBJECT
public:
    /// A value departs when |student − run| > this × max(1, |run|), as compare's default.
    static constexpr double kTolerance = 1e-6;
    /// The canvas steps the run to a departure this early at most (a later
    /// one is reported, not shown: stepping there would take too long).
    static constexpr std::int64_t kMostStepsShown = 100'000;

    TraceCheck(SimulationController* controller, Canvas* canvas, QWidget* window);
    ~TraceCheck() override;

    QAction* action() const { return m_action; }
    /// Checks the trace at `path`: false (and `error` says why, one line
    /// naming the file and the field) when it cannot be read; else the check
    /// runs and finished() follows.
    bool checkFile(const QString& path);
    bool isRunning() const { return m_watcher.isRunning(); }
    /// The last result as shown (empty before the first).
    const QString& lastResult() const { return m_lastResult; }

signals:
    void error(const QString& message);
    void finished(const QString& result);

private:
    struct Outcome {
        sim::TraceMatch match;
        std::optional<sim::Diagnosis> diagnosis;
    };
    void chooseFile();
    void showOutcome();
    void showOnCanvas(const sim::Departure& d);

    SimulationController* m_controller; // not owned
    Canvas* m_canvas;                   // not owned
    QPointer<QWidget> m_window;
    QAction* m_action = nullptr;
    QFutureWatcher<Outcome> m_watcher;
    lessons::StudentTrace m_trace; // the rows being checked
    QString m_file;
    double m_dt = 0.0;
    QString m_lastResult;
    QPointer<QMessageBox> m_box;
};

} // namespace forcelab
