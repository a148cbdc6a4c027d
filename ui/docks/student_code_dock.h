#pragma once
// Your Code: a student rewrites any file of the stage's JavaScript (the
// update step, a force, the wall rule, the detection loop, the response)
// and runs it beside the reference. The chosen file opens with the course's
// text as a start; Run puts the student's version in its place and the
// canvas shows the two runs side by side from the same state, each with
// its energy, and marks where the student's first departs. An error names
// its file and line (and moves the cursor there); an endless loop is
// stopped after 1 s. The edits are kept per lesson (and remembered between
// sessions), and File → Save Lesson writes them into the lesson.
#include "lessons/lesson.h"
#include "ui/script/student_run.h"

#include <QDockWidget>
#include <QHash>

class QComboBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;

namespace forcelab {

class SimulationController;

class StudentCodeDock : public QDockWidget {
    Q_OBJECT
public:
    explicit StudentCodeDock(SimulationController* controller, QWidget* parent = nullptr);

    /// A new lesson: its edits are the ones kept for it (or the file's own
    /// "student_code", when it has some); the student's run stops.
    void setLesson(const Lesson& lesson);
    /// The current lesson's edits (file → text), only files that differ from the course's.
    const ScriptEdits& edits() const { return m_edits; }

    /// Opens `file` (one of files()) in the editor.
    void chooseFile(const QString& file);
    QString currentFile() const;
    /// The stage's JavaScript files, in load order.
    QStringList files() const;
    QPlainTextEdit* editor() const { return m_editor; }
    /// Runs the edits beside the reference (the Run button).
    void run();
    void stop();
    /// The line under the editor: how the run is going, or what went wrong.
    QString statusText() const;

private:
    void refreshFiles();
    void refreshStatus();
    void textEdited();
    void revertFile();
    void markError(const ScriptError& error);
    void remember();

    SimulationController* m_controller; // not owned
    QComboBox* m_files = nullptr;
    QPlainTextEdit* m_editor = nullptr;
    QPushButton* m_run = nullptr;
    QPushButton* m_stop = nullptr;
    QPushButton* m_revert = nullptr;
    QLabel* m_status = nullptr;
    QString m_lessonId;
    ScriptEdits m_edits;
    QHash<QString, ScriptEdits> m_byLesson; // every lesson's edits this session
    QString m_markedError; // the error last marked in the editor
    bool m_loading = false; // the editor is being filled, not typed in
};

} // namespace forcelab
