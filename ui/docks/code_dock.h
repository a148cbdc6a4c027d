#pragma once
// The Code panel: the lines of sim/ that the current stage runs (the update
// step, the force laws that are on, the wall test, the collision response),
// with the code a switch turns on highlighted as it is switched.

#include "ui/docks/code_snippets.h"

#include <QDockWidget>

class QTextBrowser;

namespace forcelab {

class SimulationController;

class CodeDock : public QDockWidget {
    Q_OBJECT
public:
    explicit CodeDock(SimulationController* controller, QWidget* parent = nullptr);

    /// The lesson's controls (control names, e.g. "integrator"): regions that
    /// depend on their parameters are shown even when they do not run.
    void setLessonControls(const QStringList& controls);

    /// What is shown, in order, and which of it runs now (for tests).
    QStringList shownRegions() const;
    QStringList runningRegions() const;
    QList<int> highlightedLines(const QString& region) const; ///< source line numbers

private:
    void refresh();

    SimulationController* m_controller; // not owned
    QTextBrowser* m_view = nullptr;
    QStringList m_controlKeys; // parameter key paths of the lesson's controls
    QList<const CodeRegion*> m_shown;
};

} // namespace forcelab
