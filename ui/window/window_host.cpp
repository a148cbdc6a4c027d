#include "ui/window/window_host.h"

#include "ui/canvas/canvas.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/window/language.h"
#include "ui/window/main_window.h"

#include <QAction>
#include <QStatusBar>
#include <QTimer>

namespace forcelab {

WindowHost::WindowHost(const QString& lesson, bool languageApplied, QObject* parent)
    : QObject(parent)
{
    QString problem;
    if (!languageApplied && !applyLanguage(rememberedLanguage(&problem)))
        applyLanguage(QStringLiteral("en"));
    adopt(new MainWindow(lesson));
    if (!problem.isEmpty())
        m_window->statusBar()->showMessage(problem, 30000);
}

WindowHost::~WindowHost() = default;

void WindowHost::adopt(MainWindow* window)
{
    m_window.reset(window);
    // Queued: the old window's menu is still on the stack when the choice is made.
    connect(window, &MainWindow::languageChosen, this, &WindowHost::switchLanguage, Qt::QueuedConnection);
}

bool WindowHost::switchLanguage(const QString& code)
{
    if (code == currentLanguage())
        return true;
    MainWindow* old = m_window.get();
    // What the class sees, taken from the old window before it goes.
    const Lesson lesson = old->lesson();
    const sim::World world = old->controller()->world();
    const bool playing = old->controller()->isPlaying();
    const int selected = old->canvas()->selectedBall();
    const bool staged = old->isStaged();
    const QByteArray geometry = old->savedGeometry();
    const QByteArray docks = old->savedDockState();
    const bool visible = old->isVisible();
    if (!applyLanguage(code))
        return false;
    rememberLanguage(code);
    // The old window goes first: it takes the display units with it, and
    // the new one sets its lesson's.
    old->controller()->pause();
    m_window.reset();

    auto* fresh = new MainWindow(lesson.source.isEmpty() ? lesson.id : lesson.source);
    fresh->setLesson(lesson);
    fresh->controller()->mutableWorld() = world;
    fresh->controller()->notifyBallsChanged();
    fresh->restoreGeometry(geometry);
    fresh->restoreState(docks);
    fresh->canvas()->setSelectedBall(selected < world.balls().size() ? selected : -1);
    adopt(fresh);
    if (visible)
        fresh->show();
    if (staged)
        fresh->findChild<QAction*>(QStringLiteral("presentationAction"))->setChecked(true);
    if (playing)
        fresh->controller()->play();
    emit windowReplaced(fresh);
    return true;
}

} // namespace forcelab
