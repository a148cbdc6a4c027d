// The main window's File commands: open a lesson, save the scene as a
// lesson, pictures of the stage, the trajectory and the teacher's handbook.
// Every file is written atomically. Part of MainWindow (main_window.h).
#include "ui/window/main_window.h"

#include "ui/docks/student_code_dock.h"

#include "lessons/atomic_file.h"
#include "lessons/lesson_markup.h"
#include "ui/drawing/png_file.h"

#include "ui/docks/accuracy_dock.h"
#include "ui/canvas/canvas.h"
#include "ui/window/overlay_actions.h"
#include "ui/window/save_lesson_dialog.h"
#include "ui/stage/stage_view.h"
#include "ui/drawing/handbook.h"
#include "ui/window/language.h"
#include "ui/docks/code_dock.h"
#include "ui/controls/settings_editor.h"
#include "ui/docks/inspector_dock.h"
#include "ui/docks/lessons_dock.h"
#include "ui/controls/parameter_panel.h"
#include "ui/docks/plots_dock.h"
#include "ui/docks/predict_dock.h"
#include "ui/docks/stopwatch_dock.h"
#include "ui/docks/force_editor_dock.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/window/theme.h"
#include "ui/docks/trajectory_export.h"

#include "lessons/lesson_loader.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QPainter>
#include <QPixmap>
#include <QRegularExpression>
#include <QSaveFile>
#include <QScreen>
#include <QScrollArea>
#include <QShortcut>
#include <QSplitter>
#include <QToolButton>
#include <QBoxLayout>
#include <QSettings>
#include <QStatusBar>
#include <QVBoxLayout>
#include <QStyle>
#include <QTabBar>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>

#include <algorithm>
#include <cmath>

namespace forcelab {

void MainWindow::openLessonFile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Lesson"), lessonsFolder(),
                                                      tr("Lesson files (*.json);;All files (*)"));
    if (path.isEmpty())
        return;
    m_lastDirectory = QFileInfo(path).absolutePath();
    const LoadResult result = LessonLoader::loadFile(path);
    if (!result.ok()) {
        showLoadErrors(result.errors());
        return;
    }
    setLesson(*result.lesson);
}

QString MainWindow::suggestedFileName(const QString& extension) const
{
    const QString stem = m_lesson.id.isEmpty() ? QStringLiteral("scene") : m_lesson.id;
    return QDir(m_lastDirectory.isEmpty() ? QDir::homePath() : m_lastDirectory)
        .filePath(QStringLiteral("%1-t%2.%3").arg(stem).arg(m_controller->world().time(), 0, 'f', 1).arg(extension));
}

Lesson MainWindow::currentSceneAsLesson() const
{
    Lesson lesson = m_lesson;
    const sim::World& world = m_controller->world();
    lesson.scene.settings = world.settings();
    lesson.scene.spawn = m_controller->spawn();
    lesson.scene.spawn.count = 0; // every ball is listed
    const sim::BallState& balls = world.balls();
    lesson.scene.balls.clear();
    lesson.scene.balls.reserve(static_cast<std::size_t>(balls.size()));
    for (int i = 0; i < balls.size(); ++i)
        lesson.scene.balls.push_back(balls.ball(i));
    if (lesson.id.isEmpty())
        lesson.id = QStringLiteral("saved-scene");
    return lesson;
}

bool MainWindow::saveLessonTo(const QString& path)
{
    return saveLessonTo(path, lessons::defaultDeriveChoices(m_lesson));
}

bool MainWindow::saveLessonTo(const QString& path, const lessons::DeriveChoices& choices)
{
    // A new lesson, not the old one with another scene: its own title, text
    // and id, and only the claims and questions that hold on this scene.
    lessons::DeriveChoices wished = choices;
    wished.ids.prepend(QFileInfo(path).completeBaseName()); // the file's name as its id, when it makes a valid one
    QApplication::setOverrideCursor(Qt::WaitCursor);        // the claims run here, as `forcelab-cli check` runs them
    const lessons::DerivedLesson derived = lessons::deriveLesson(m_lesson, currentSceneAsLesson().scene, wished);
    QApplication::restoreOverrideCursor();
    if (!derived.ok()) {
        showError(tr("Lesson not saved: %1").arg(derived.problems.join(QLatin1Char(' '))));
        return false;
    }
    Lesson lesson = derived.lesson;
    lesson.studentCode = m_studentCodeDock->edits(); // the student's own code goes with the lesson
    QString why;
    if (!lessons::writeFileAtomically(path, saveLesson(lesson), &why)) {
        showError(tr("Lesson not saved: %1").arg(why));
        return false;
    }
    statusBar()->showMessage(tr("Saved %n ball(s) and the settings to %1 as “%2”. %3", nullptr,
                                int(derived.lesson.scene.balls.size()))
                                 .arg(QDir::toNativeSeparators(path),
                                      lessons::markupToPlainText(derived.lesson.title), lessons::deriveSummary(derived)),
                             30000);
    return true;
}

void MainWindow::saveLessonFile()
{
    const QString suggested =
        QDir(m_lastDirectory.isEmpty() ? QDir::homePath() : m_lastDirectory)
            .filePath(lessons::deriveId({}, lessons::defaultDeriveChoices(m_lesson).title, m_lesson.id) +
                      QStringLiteral(".json"));
    SaveLessonDialog dialog(m_lesson, suggested, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    m_lastDirectory = QFileInfo(dialog.path()).absolutePath();
    saveLessonTo(dialog.path(), dialog.choices());
}

QString MainWindow::lessonsFolder()
{
    // Installed (share/forcelab/lessons), beside the program, or the source
    // tree's folder for a build that was not installed.
    const QDir app(QCoreApplication::applicationDirPath());
    const QStringList candidates{app.filePath(QStringLiteral("../share/forcelab/lessons")),
                                 app.filePath(QStringLiteral("lessons")), app.filePath(QStringLiteral("../lessons")),
                                 QStringLiteral(FORCELAB_SOURCE_LESSONS)};
    for (const QString& folder : candidates)
        if (QFileInfo(folder).isDir() && !QDir(folder).entryList({QStringLiteral("*.json")}, QDir::Files).isEmpty())
            return QDir::cleanPath(folder);
    return QDir::homePath();
}

QSize MainWindow::pictureSize() const
{
    // The stage as large as the whole screen would show it, whatever the
    // size of the canvas now: a small window still gives a large picture.
    const QScreen* s = m_canvas->screen() ? m_canvas->screen() : QGuiApplication::primaryScreen();
    const QSize screenSize = s ? s->size() : m_canvas->size();
    const QSizeF canvas = QSizeF(m_canvas->size());
    if (canvas.isEmpty())
        return screenSize;
    const double fit = std::min(screenSize.width() / canvas.width(), screenSize.height() / canvas.height());
    return (canvas * std::max(1.0, fit)).toSize();
}

bool MainWindow::saveScreenshotTo(const QString& path, double scale)
{
    const QScreen* s = m_canvas->screen() ? m_canvas->screen() : QGuiApplication::primaryScreen();
    const double dpr = (s ? s->devicePixelRatio() : 1.0) * scale;
    const QImage image = m_canvas->renderImage(pictureSize(), dpr);
    QString why;
    if (!writePngAtomically(path, image, &why)) {
        showError(tr("Picture not saved: %1").arg(why));
        return false;
    }
    statusBar()->showMessage(tr("Saved the picture to %1").arg(QDir::toNativeSeparators(path)), 5000);
    return true;
}

void MainWindow::saveScreenshot(double scale)
{
    const QString title = scale > 1.0 ? tr("Save Picture at Double Size") : tr("Save Picture");
    const QString path = QFileDialog::getSaveFileName(this, title, suggestedFileName("png"), tr("PNG images (*.png)"));
    if (path.isEmpty())
        return;
    m_lastDirectory = QFileInfo(path).absolutePath();
    saveScreenshotTo(path, scale);
}

void MainWindow::exportHandbook()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Teacher Handbook"),
                                                      QStringLiteral("forcelab-handbook.html"), tr("HTML (*.html)"));
    if (path.isEmpty())
        return;
    QString why;
    if (!lessons::writeFileAtomically(path, builtInHandbookHtml(currentLanguage()).toUtf8(), &why)) {
        QMessageBox::warning(this, tr("Export Teacher Handbook"),
                             tr("%1\nThe handbook was not written; an old file there is unchanged.").arg(why));
        return;
    }
    statusBar()->showMessage(tr("Handbook written to %1").arg(path), 4000);
}

void MainWindow::exportTrajectory()
{
    if (m_trajectory->rows().empty()) {
        statusBar()->showMessage(tr("Nothing recorded yet: switch on Record Trajectory (Ctrl+Shift+R) first"), 5000);
        return;
    }
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Trajectory"), suggestedFileName("csv"),
                                                      tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    m_lastDirectory = QFileInfo(path).absolutePath();
    if (auto error = m_trajectory->save(path)) {
        showError(*error);
        return;
    }
    statusBar()->showMessage(tr("Wrote %L1 rows to %2").arg(m_trajectory->rows().size())
                                 .arg(QDir::toNativeSeparators(path)), 5000);
}

} // namespace forcelab
