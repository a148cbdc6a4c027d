#pragma once
// The Code panel: the lines of sim/ that the current stage runs (the update
// step, the force laws that are on, the wall test, the collision response),
// with the code a switch turns on highlighted as it is switched. A switch at
// the top shows the same stage in the course's language instead: the
// JavaScript pieces (lessons/code/*.js) its settings run, the code students
// write, which test_script_reference runs against the engine.

#include "ui/docks/code_snippets.h"

#include <QDockWidget>

class QTextBrowser;
class QToolButton;

namespace forcelab {

class SimulationController;

class CodeDock : public QDockWidget {
    Q_OBJECT
public:
    enum class Language { Cpp, JavaScript };
    explicit CodeDock(SimulationController* controller, QWidget* parent = nullptr);
    /// Which code is shown: the engine's C++ or the course's JavaScript.
    void setLanguage(Language language);
    Language language() const { return m_language; }
    /// The JavaScript pieces shown (file names), in load order; empty for C++.
    QStringList shownPieces() const;
    /// The text shown, as plain text (for tests).
    QString shownText() const;

    /// The lesson's controls (control names, e.g. "integrator"): regions that
    /// depend on their parameters are shown even when they do not run.
    void setLessonControls(const QStringList& controls);

    /// What is shown, in order, and which of it runs now (for tests).
    QStringList shownRegions() const;
    QStringList runningRegions() const;
    QList<int> highlightedLines(const QString& region) const; ///< source line numbers

private:
    void refresh();
    QString cppHtml(const sim::WorldSettings& s);
    QString javaScriptHtml(const sim::WorldSettings& s);

    SimulationController* m_controller; // not owned
    QTextBrowser* m_view = nullptr;
    QToolButton* m_cppButton = nullptr;
    QToolButton* m_jsButton = nullptr;
    Language m_language = Language::Cpp;
    QStringList m_pieces; // the JavaScript pieces shown
    QStringList m_controlKeys; // parameter key paths of the lesson's controls
    QList<const CodeRegion*> m_shown;
};

} // namespace forcelab
