#include "ui/window/main_window.h"
#include "ui/canvas/scene_description.h"
#include "ui/controls/focus_ring.h"

#include "lessons/atomic_file.h"
#include "lessons/lesson_languages.h"
#include "ui/window/language.h"
#include "lessons/lesson_markup.h"
#include "ui/drawing/png_file.h"

#include "ui/docks/accuracy_dock.h"
#include "ui/canvas/canvas.h"
#include "ui/controls/ball_table.h"
#include "ui/window/overlay_actions.h"
#include "ui/stage/stage_tool_title.h"
#include "ui/stage/stage_view.h"
#include "ui/drawing/handbook.h"
#include "ui/docks/code_dock.h"
#include "ui/docks/student_code_dock.h"
#include "ui/docks/step_apart_dock.h"
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
#include "lessons/lesson_tools.h"
#include "ui/docks/trajectory_export.h"

#include "lessons/lesson_loader.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QTableView>
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
#include <QToolTip>
#include <QAccessible>
#include <QKeyEvent>
#include <QPushButton>
#include <QAbstractButton>
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

namespace {
const QString kGeometryKey = QStringLiteral("mainWindow/geometry");
const QString kStateKey = QStringLiteral("mainWindow/layout2"); // the docks since the plots moved to the right
const QString kLastLessonKey = QStringLiteral("lesson/last");
const QString kDirectoryKey = QStringLiteral("lesson/directory");
const QString kThemeKey = QStringLiteral("view/projectorTheme");
const QString kTextScaleKey = QStringLiteral("view/textScale");

// The tabs of docks stacked in one place keep their whole names and scroll
// when the column is too narrow for all of them. Qt's own tab bars for docks
// shorten every name instead: at 1024x768 the right column's six tabs read
// "Ins…", "P…", "P…", "Stop…", "Force …", "C…", and nobody can tell Plots
// from Predict. The main window makes those bars itself, when docks are
// stacked (at start, on a saved layout, when the user drags one), so each
// is set up here when it is first polished, and Tab reaches it so the
// keyboard can bring a stacked panel forward.
class ReadableDockTabs : public QObject {
public:
    using QObject::QObject;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::ChildPolished)
            if (auto* bar = qobject_cast<QTabBar*>(static_cast<QChildEvent*>(event)->child())) {
                bar->setElideMode(Qt::ElideNone);
                bar->setUsesScrollButtons(true);
                // Reached with Tab, its arrows pick a panel: the keyboard's way to the stacked ones.
                bar->setFocusPolicy(Qt::TabFocus);
            }
        return QObject::eventFilter(watched, event);
    }
};

// Space runs and pauses the simulation from anywhere, as a window-wide
// shortcut, even while a check box or a slider has the keyboard. A keyboard
// user still has to press buttons: Enter presses the focused button (or
// ticks the focused box), and Space presses a focused push button, whose
// label says what pressing it does ("Start", "Lock in and run").
class KeysToFocusedButton : public QObject {
public:
    using QObject::QObject;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        auto* button = qobject_cast<QAbstractButton*>(watched);
        if (!button || (event->type() != QEvent::ShortcutOverride && event->type() != QEvent::KeyPress))
            return QObject::eventFilter(watched, event);
        auto* key = static_cast<QKeyEvent*>(event);
        const bool enter = key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter;
        const bool space = key->key() == Qt::Key_Space && qobject_cast<QPushButton*>(button);
        if (key->modifiers() != Qt::NoModifier || !(enter || space))
            return QObject::eventFilter(watched, event);
        if (event->type() == QEvent::ShortcutOverride) {
            event->accept(); // the key goes to the button, not to a shortcut
            return true;
        }
        if (enter) { // a push button outside a dialog, or a check box, does nothing with Enter by itself
            button->click();
            return true;
        }
        return QObject::eventFilter(watched, event); // Space: the button presses itself
    }
};

} // namespace

MainWindow::MainWindow(const QString& lesson, QWidget* parent)
    : QMainWindow(parent)
{
    m_controller = new SimulationController(this);
    m_controller->setSuspended(true); // until the window is shown
    // Every control edits through one editor, which keeps the undo steps.
    m_editor = new SettingsEditor(m_controller, this);
    m_stage = new StageView(m_controller, m_editor, this);
    m_canvas = m_stage->canvas();
    setCentralWidget(m_stage);
    m_trajectory = new TrajectoryExport(m_controller, this);

    createSimulationActions();
    createBallActions();
    createCameraActions();
    createFileActions();
    createUnitActions();
    m_overlayActions = new OverlayActions(m_canvas, this);
    m_stage->createBar({m_playAction, m_stepAction, m_resetAction, m_slowerAction, m_fasterAction});
    // Escape leaves the stage view.
    // In the normal view it takes the keyboard back to the canvas, where the keys of the simulation work.
    auto* leave = new QShortcut(QKeySequence(Qt::Key_Escape), this);
    connect(leave, &QShortcut::activated, this, [this] {
        if (m_stage->isStaged())
            m_presentationAction->setChecked(false);
        else
            m_canvas->setFocus(Qt::ShortcutFocusReason);
    });
    qApp->installEventFilter(new KeysToFocusedButton(this));
    new FocusRing(this); // where the keys go, seen from the back row
    createMenus();
    createToolBars();
    createTimeActions(); // Step Back and the timeline bar
    installEventFilter(new ReadableDockTabs(this));
    createDocks();
    createStatusBar();
    readSettings();
    openInitialLesson(lesson);
    if (!m_settingsProblems.isEmpty())
        showError(m_settingsProblems.join(QStringLiteral(" · ")));
    m_canvas->setFocus();
}

MainWindow::~MainWindow()
{
    // The units are the application's (the painters read them); the window
    // that set them takes its choice along, so a panel or a picture made
    // after it (a test, the next window) starts in pixels.
    forcelab::setDisplayUnits({});
}

void MainWindow::createDocks()
{
    m_lessonsDock = new LessonsDock(this);
    m_lessonsDock->setCourse(LessonsDock::builtInCourse());
    m_lessonsDock->setNavigationActions(m_previousAction, m_nextAction);
    connect(m_lessonsDock, &LessonsDock::lessonChosen, this, &MainWindow::chooseLesson);
    addDockWidget(Qt::LeftDockWidgetArea, m_lessonsDock);

    m_parameters = new ParameterPanel(m_controller, m_editor);
    auto* scroll = new QScrollArea;
    scroll->setWidget(m_parameters);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_parametersDock = new QDockWidget(tr("Parameters"), this);
    m_parametersDock->setObjectName(QStringLiteral("parametersDock"));
    m_parametersDock->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, m_parametersDock);

    m_inspectorDock = new InspectorDock(m_controller, this);
    addDockWidget(Qt::RightDockWidgetArea, m_inspectorDock);
    splitDockWidget(m_parametersDock, m_inspectorDock, Qt::Vertical);
    connect(m_canvas, &Canvas::selectedBallChanged, m_inspectorDock, &InspectorDock::setSelectedBall);
    // The inspector's trail switch: a trail behind the selected ball alone,
    // or back to what the lesson shows.
    connect(m_inspectorDock, &InspectorDock::trailToggled, this, [this](bool on) {
        m_canvas->setTrailScope(on ? TrailRecorder::Scope::Selected : TrailRecorder::Scope::All);
        m_canvas->setTrailsEnabled(on || m_lesson.overlays.contains(QStringLiteral("trails")));
    });

    // The plots, the code and the accuracy tools share the right column with
    // the Inspector, as tabs under the parameters: the stage keeps the whole
    // height of the window, and opening one of them never shrinks it.
    m_ballTable = new BallTable(m_controller, m_editor, {m_addBallAction, m_duplicateBallAction, m_deleteBallAction});
    m_ballsDock = new QDockWidget(tr("Balls"), this);
    m_ballsDock->setObjectName(QStringLiteral("ballsDock"));
    m_ballsDock->setWidget(m_ballTable);
    connect(m_canvas, &Canvas::selectedBallChanged, m_ballTable, &BallTable::setSelectedBall);
    connect(m_ballTable, &BallTable::ballSelected, m_canvas, &Canvas::setSelectedBall);
    connect(m_canvas, &Canvas::editBallRequested, this, &MainWindow::editBall);

    m_plotsDock = new PlotsDock(m_controller, this);
    m_accuracyDock = new AccuracyDock(m_controller, m_canvas, this); // closed at first: its books cost evaluations
    m_codeDock = new CodeDock(m_controller, this);
    m_studentCodeDock = new StudentCodeDock(m_controller, this);
    m_stepApartDock = new StepApartDock(m_controller, this);
    connect(m_canvas, &Canvas::selectedBallChanged, m_stepApartDock, &StepApartDock::setSelectedBall);
    m_predictDock = new PredictDock(m_controller, this);
    m_stopwatchDock = new StopwatchDock(m_controller, this);
    m_forceEditorDock = new ForceEditorDock(m_controller, m_editor, this);
    connect(m_canvas, &Canvas::selectedBallChanged, m_stopwatchDock, &StopwatchDock::setBall);
    for (QDockWidget* dock : {static_cast<QDockWidget*>(m_plotsDock), static_cast<QDockWidget*>(m_predictDock),
                              static_cast<QDockWidget*>(m_stopwatchDock), static_cast<QDockWidget*>(m_forceEditorDock),
                              static_cast<QDockWidget*>(m_codeDock), static_cast<QDockWidget*>(m_studentCodeDock),
                              static_cast<QDockWidget*>(m_ballsDock),
                              static_cast<QDockWidget*>(m_accuracyDock), static_cast<QDockWidget*>(m_stepApartDock)}) {
        addDockWidget(Qt::RightDockWidgetArea, dock);
        tabifyDockWidget(m_inspectorDock, dock);
    }
    m_plotsDock->raise();
    m_accuracyDock->hide();
    m_accuracyMenu->addAction(m_accuracyDock->tradeOffAction());
    m_accuracyMenu->addAction(m_accuracyDock->convergenceAction());
    m_accuracyMenu->addSeparator();
    m_accuracyMenu->addAction(m_accuracyDock->toggleViewAction());

    m_undoAction = m_editor->undoStack()->createUndoAction(this, tr("&Undo"));
    m_undoAction->setObjectName(QStringLiteral("undoAction"));
    m_undoAction->setShortcut(QKeySequence::Undo);
    m_undoAction->setIcon(style()->standardIcon(QStyle::SP_ArrowLeft));
    m_redoAction = m_editor->undoStack()->createRedoAction(this, tr("&Redo"));
    m_redoAction->setObjectName(QStringLiteral("redoAction"));
    m_redoAction->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    m_redoAction->setIcon(style()->standardIcon(QStyle::SP_ArrowRight));
    if (QMenu* edit = menuBar()->findChild<QMenu*>(QStringLiteral("editMenu"))) {
        const QList<QAction*> after = edit->actions();
        edit->insertAction(after.value(0), m_undoAction);
        edit->insertAction(after.value(0), m_redoAction);
    }
    m_simulationToolBar->addSeparator();
    m_simulationToolBar->addAction(m_undoAction);
    m_simulationToolBar->addAction(m_redoAction);
    addActions({m_undoAction, m_redoAction}); // Ctrl+Z works on the stage too, where menus and toolbars are hidden

    m_viewMenu->addAction(m_lessonsDock->toggleViewAction());
    m_viewMenu->addAction(m_parametersDock->toggleViewAction());
    m_viewMenu->addAction(m_plotsDock->toggleViewAction());
    m_viewMenu->addAction(m_inspectorDock->toggleViewAction());
    m_viewMenu->addAction(m_ballsDock->toggleViewAction());
    m_viewMenu->addAction(m_accuracyDock->toggleViewAction());
    m_viewMenu->addAction(m_codeDock->toggleViewAction());
    m_viewMenu->addAction(m_studentCodeDock->toggleViewAction());
    m_viewMenu->addAction(m_stepApartDock->toggleViewAction());
    m_viewMenu->addAction(m_predictDock->toggleViewAction());
    m_viewMenu->addAction(m_stopwatchDock->toggleViewAction());
    m_viewMenu->addAction(m_forceEditorDock->toggleViewAction());
    m_viewMenu->addAction(m_lessonsDock->teacherNotesAction());
    resizeDocks({m_lessonsDock, m_parametersDock}, {230, 310}, Qt::Horizontal);
    resizeDocks({m_parametersDock, m_inspectorDock}, {360, 300}, Qt::Vertical);
}

void MainWindow::useCompactDocks()
{
    // In a window narrower than kCompactWidth two dock columns would leave
    // the box about a third of the window. The lesson goes into the right
    // column as a tab beside the Parameters, so the box takes about half.
    addDockWidget(Qt::RightDockWidgetArea, m_lessonsDock);
    tabifyDockWidget(m_parametersDock, m_lessonsDock);
    m_lessonsDock->raise();
    resizeDocks({m_parametersDock}, {std::min(340, width() / 3)}, Qt::Horizontal);
    // Once laid out: most of the column's height for the lesson, and most of
    // the lesson's for its text (the course list above it).
    QTimer::singleShot(0, this, [this] {
        if (m_presentationAction->isChecked())
            return; // the docks are hidden on the stage
        resizeDocks({m_parametersDock, m_inspectorDock}, {height() * 2 / 3, height() / 3}, Qt::Vertical);
        if (auto* split = m_lessonsDock->findChild<QSplitter*>(QStringLiteral("lessonsSplitter"))) {
            const int total = split->height();
            split->setSizes({total / 4, total - total / 4});
        }
    });
    // The file commands as icons (their names in tooltips): both toolbars
    // fit in one row, nothing hides behind a » menu.
    m_fileToolBar->setToolButtonStyle(Qt::ToolButtonIconOnly);
}

void MainWindow::createStatusBar()
{
    auto label = [this](const QString& name, const QString& tip) {
        auto* l = new QLabel(this);
        l->setObjectName(name);
        l->setToolTip(tip);
        statusBar()->addPermanentWidget(l);
        return l;
    };
    m_droppedLabel = label(QStringLiteral("droppedLabel"),
                           tr("The computer could not keep up: simulated time was skipped"));
    m_droppedLabel->setStyleSheet(QStringLiteral("color: #b00020; font-weight: bold"));
    m_timeLabel = label(QStringLiteral("timeLabel"), tr("Simulated time"));
    m_speedLabel = label(QStringLiteral("speedLabel"), tr("Simulated seconds per real second ([ slower, ] faster)"));
    m_fpsLabel = label(QStringLiteral("fpsLabel"), tr("Frames drawn per second, and the time to draw one"));
    m_costLabel = label(QStringLiteral("costLabel"), tr("Wall-clock time of the last simulation step"));
    m_ballsLabel = label(QStringLiteral("ballsLabel"), tr("Number of balls"));
    m_pairsLabel = label(QStringLiteral("pairsLabel"),
                         tr("Ball pairs tested for contact in the last step, and the contacts found"));

    connect(m_controller, &SimulationController::errorOccurred, this, &MainWindow::showError);
    connect(m_controller, &SimulationController::timeDropped, this, &MainWindow::showTimeDropped);
    connect(m_controller, &SimulationController::timeScaleChanged, this, &MainWindow::updateStatus);
    // A new lesson or a single step while paused shows at once (while it
    // runs, the timer below is often enough).
    connect(m_controller, &SimulationController::sceneChanged, this, &MainWindow::updateStatus);
    connect(m_controller, &SimulationController::stepped, this, [this] {
        if (!m_controller->isPlaying())
            updateStatus();
    });

    m_droppedTimer = new QTimer(this);
    m_droppedTimer->setSingleShot(true);
    m_droppedTimer->setInterval(3000);
    connect(m_droppedTimer, &QTimer::timeout, m_droppedLabel, &QLabel::clear);

    // Four times a second: often enough to read, rarely enough to cost nothing.
    m_statusTimer = new QTimer(this);
    m_statusTimer->setInterval(250);
    connect(m_statusTimer, &QTimer::timeout, this, &MainWindow::updateStatus);
    m_statusTimer->start();
    m_statusClock.start();
    updateStatus();
}

void MainWindow::readSettings()
{
    // The settings file can be damaged, hand-edited or written by another
    // version. A value that does not fit is replaced by the default, and the
    // status bar names the file and the key (shown once the lesson is open).
    const QSettings settings;
    const QString file = QDir::toNativeSeparators(settings.fileName());
    auto refuse = [&](const QString& key, const QString& what) {
        m_settingsProblems << tr("%1: %2: %3").arg(file, key, what);
    };
    const QVariant geometry = settings.value(kGeometryKey);
    if (geometry.isNull() || !restoreGeometry(geometry.toByteArray())) {
        if (!geometry.isNull())
            refuse(kGeometryKey, tr("not a saved window geometry; using the default size"));
        const QRect available = screen() ? screen()->availableGeometry() : QRect(0, 0, 1400, 900);
        resize(std::min(1400, available.width() * 9 / 10), std::min(900, available.height() * 9 / 10));
    }
    const QVariant state = settings.value(kStateKey);
    if (!state.isNull() && !restoreState(state.toByteArray()))
        refuse(kStateKey, tr("not a saved layout of the docks; using the default layout"));
    else if (!state.isNull())
        m_dockLayoutChosen = true; // the user's layout stands
    m_lastLesson = settings.value(kLastLessonKey).toString();
    const QString directory = settings.value(kDirectoryKey).toString();
    if (!directory.isEmpty() && !QFileInfo(directory).isDir())
        refuse(kDirectoryKey, tr("%1 is not a folder; using the home folder").arg(directory));
    else
        m_lastDirectory = directory;
    const QVariant theme = settings.value(kThemeKey, false);
    if (theme.typeId() != QMetaType::Bool && theme.toString() != QLatin1String("true") &&
        theme.toString() != QLatin1String("false"))
        refuse(kThemeKey, tr("not true or false; using the plain theme"));
    else if (theme.toBool())
        m_themeAction->setChecked(true); // applied through toggled
    const QVariant textScale = settings.value(kTextScaleKey, 1.0);
    bool number = false;
    const double scale = textScale.toDouble(&number);
    if (!number || !(scale >= kSmallestTextScale && scale <= kLargestTextScale))
        refuse(kTextScaleKey, tr("not a text size from %1 to %2; using the usual size")
                                  .arg(kSmallestTextScale)
                                  .arg(kLargestTextScale));
    else if (scale != 1.0)
        setTextScale(scale);
}

void MainWindow::writeSettings() const
{
    QSettings settings;
    // Quitting from the stage view keeps the normal layout for next time.
    const bool staged = m_stage->isStaged();
    settings.setValue(kGeometryKey, staged ? m_normalGeometry : saveGeometry());
    settings.setValue(kStateKey, staged ? m_normalDocks : saveState());
    if (!m_lesson.source.isEmpty())
        settings.setValue(kLastLessonKey, m_lesson.source);
    settings.setValue(kDirectoryKey, m_lastDirectory);
    settings.setValue(kThemeKey, m_themeAction->isChecked());
    settings.setValue(kTextScaleKey, m_textScale);
}

void MainWindow::openInitialLesson(const QString& requested)
{
    if (!requested.isEmpty() && openLesson(requested))
        return;
    // The last lesson without a dialog: a file that has gone away is no
    // reason to stop the start, but the status bar says what happened.
    if (requested.isEmpty() && !m_lastLesson.isEmpty()) {
        LoadResult last = LessonLoader::load(m_lastLesson);
        if (last.ok() && setLesson(*last.lesson))
            return;
        if (!last.ok())
            m_settingsProblems << tr("%1: %2: %3; opened the first lesson instead")
                                      .arg(QDir::toNativeSeparators(QSettings().fileName()), kLastLessonKey,
                                           last.errors().value(0));
    }
    // The first built-in lesson (the showcase). A built-in lesson that does
    // not load is a bug of the build: say so in the status bar, not a dialog.
    const QStringList builtIn = LessonLoader::builtInFiles();
    if (builtIn.isEmpty()) {
        showError(tr("no built-in lessons were found"));
        return;
    }
    LoadResult first = LessonLoader::load(builtIn.first());
    if (first.ok())
        setLesson(*first.lesson);
    else
        showError(first.errors().value(0));
}

bool MainWindow::openLesson(const QString& pathOrId)
{
    LoadResult result = LessonLoader::load(pathOrId);
    if (!result.ok()) {
        showLoadErrors(result.errors());
        return false;
    }
    return setLesson(*result.lesson);
}

bool MainWindow::setLesson(const Lesson& loaded)
{
    // The lesson's words in the program's language when it has them, else
    // in its own; the lesson panel says which (lessons/lesson_languages.h).
    const Lesson lesson = lessons::shownIn(loaded, currentLanguage());
    // The old lesson's panes go first: their settings may not suit the new scene.
    m_controller->setComparePanes({});
    if (m_controller->setScene(lesson.scene)) {
        m_controller->setComparePanes(m_lesson.compare);
        return false; // the controller has signalled the error
    }
    m_controller->setComparePanes(lesson.compare);
    m_lesson = lesson;
    Overlays overlays = Overlays::fromNames(lesson.overlays);
    overlays.ghost = m_accuracyDock->isGhostDrawn(); // the student's switch, not the lesson's
    m_stage->setOverlays(overlays);
    m_overlayActions->sync(); // the lesson's choice is the default; the Show menu follows it
    // A lesson whose readout talks about ball 0 opens with ball 0 selected
    // for real (the ring it draws round it is the selection's), so the
    // Inspector, the ball table and a click agree with what the ring says.
    const int start = overlays.readout && !m_controller->world().balls().empty() ? 0 : -1;
    m_canvas->setSelectedBall(-1);
    m_canvas->setSelectedBall(start);
    m_canvas->fitBox(); // a lesson opens on its whole box
    m_canvas->setTrailScope(TrailRecorder::Scope::All);
    m_inspectorDock->setSelectedBall(start);
    m_plotsDock->setHistogramShown(lesson.overlays.contains(QStringLiteral("histogram")));
    m_codeDock->setLessonControls(lesson.controls);
    m_studentCodeDock->setLesson(lesson);
    m_predictDock->setLesson(lesson);
    if (m_predictDock->hasQuestions())
        m_predictDock->raise(); // the lesson asks first
    else if (lesson.scene.settings.custom.enabled)
        m_forceEditorDock->raise(); // the lesson is about writing a law
    else if (!m_plotsDock->isHidden())
        m_plotsDock->raise();
    m_stage->setLesson(lesson);
    setLessonTools(lessons::stageTools(lesson));
    setWindowTitle(lesson.title.isEmpty() ? tr("ForceLab")
                                          : tr("%1 — ForceLab").arg(lessons::markupToPlainText(lesson.title)));
    m_lessonsDock->setCurrentLesson(lesson);
    m_parameters->setLessonControls(lesson.controls);
    // The lesson's units; without any, pixels (the programming stages).
    DisplayUnits units;
    if (lesson.units)
        units = {.si = true, .pxPerMetre = lesson.units->pxPerMetre, .kgPerMass = lesson.units->kgPerMass};
    setUnits(units);
    // Undo steps belong to the lesson they were made in.
    m_editor->undoStack()->clear();
    // The keyboard goes to the stage, not to whatever field had it in the
    // last lesson (a Speed field with the focus took Space as text).
    m_canvas->setFocus(Qt::OtherFocusReason);
    // A lesson waits at t = 0 at its own speed (1×) until the class is
    // looking: the canvas shows "Space: run".
    m_controller->pause();
    m_controller->setTimeScale(1.0);
    return true;
}

void MainWindow::chooseLesson(const QString& source)
{
    if (source.isEmpty() || source == m_lesson.source)
        return;
    if (!openLesson(source))
        m_lessonsDock->setCurrentLesson(m_lesson); // back to the running lesson
}

void MainWindow::previousLesson()
{
    chooseLesson(m_lessonsDock->previousSource());
}

void MainWindow::nextLesson()
{
    chooseLesson(m_lessonsDock->nextSource());
}

void MainWindow::resetLesson()
{
    // The lesson's own values and balls. The undo history goes with them:
    // its steps were made on a world that no longer exists.
    m_controller->reset();
    m_controller->setTimeScale(1.0); // a slow-motion experiment does not carry into the rerun
    m_editor->undoStack()->clear();
}

void MainWindow::scaleTime(double factor)
{
    const double now = m_controller->timeScale();
    // Slower and Faster climb a fixed ladder of speeds that passes through 1×:
    // 1/16, 1/8, 1/4, 1/2, 1, 2, 4, 8, 16. From a speed typed in between,
    // the next rung up or down (from 0.05× Faster gives 1/16×, not 0.1×).
    static constexpr double kLadder[] = {1.0 / 16, 1.0 / 8, 1.0 / 4, 1.0 / 2, 1.0, 2.0, 4.0, 8.0, 16.0};
    double wanted = now;
    if (factor > 1.0) {
        for (const double rung : kLadder)
            if (rung > now * (1.0 + 1e-9)) {
                wanted = rung;
                break;
            }
    } else {
        for (auto it = std::rbegin(kLadder); it != std::rend(kLadder); ++it)
            if (*it < now * (1.0 - 1e-9)) {
                wanted = *it;
                break;
            }
    }
    if (wanted == now) {
        statusBar()->showMessage(factor < 1.0 ? tr("Already the slowest speed, %1×").arg(now)
                                              : tr("Already the fastest speed, %1×").arg(now), 3000);
        return;
    }
    m_editor->editTimeScale(wanted);
    statusBar()->showMessage(tr("Speed %1×").arg(wanted), 2000);
}

void MainWindow::slower()
{
    scaleTime(0.5);
}

void MainWindow::faster()
{
    scaleTime(2.0);
}

void MainWindow::showLoadErrors(const QStringList& errors)
{
    constexpr qsizetype kShown = 8;
    QMessageBox box(QMessageBox::Warning, tr("Cannot open lesson"),
                    tr("The lesson could not be opened; the running lesson goes on."), QMessageBox::Ok, this);
    box.setObjectName(QStringLiteral("loadErrors"));
    // A message quotes the file ("<img src=\"/dev/zero\">"), and a label
    // would render such a quote as rich text and load it: every line is
    // escaped, so the dialog shows the characters and reads nothing.
    QStringList shown;
    for (const QString& line : errors.mid(0, kShown))
        shown << line.toHtmlEscaped();
    if (errors.size() > kShown) {
        shown << tr("… and %n more. Show Details… lists every problem.", nullptr, int(errors.size() - kShown));
        box.setDetailedText(errors.join(QLatin1Char('\n'))); // shown as plain text
    }
    box.setTextFormat(Qt::RichText);
    box.setInformativeText(QStringLiteral("<p>%1</p>").arg(shown.join(QStringLiteral("<br>"))));
    box.exec();
}

void MainWindow::setProjectorTheme(bool on)
{
    if (m_themeAction->isChecked() != on)
        m_themeAction->setChecked(on); // comes back here through toggled
    applyProjectorFonts(this, on, m_textScale);
    applyCanvasLook();
}

// The lesson's tools (lesson_tools.h) in the Tools menu, on keys 1, 2, …,
// which work in the stage view too; the canvas's start banner lists them.
// Panels opened on the stage float over it and close with the next lesson.
void MainWindow::setLessonTools(const QStringList& tools)
{
    // The old tools' actions go: QMenu::clear() keeps those the window also
    // holds, and their keys would clash with the new ones.
    const QList<QAction*> old = m_toolsMenu->actions();
    m_toolsMenu->clear();
    qDeleteAll(old);
    QStringList keys;
    for (qsizetype k = 0; k < tools.size(); ++k) {
        const lessons::ToolInfo* tool = lessons::findTool(tools[k]);
        QDockWidget* dock = toolDock(tools[k]);
        if (!tool || !dock)
            continue;
        QAction* action = m_toolsMenu->addAction(tool->title, this, [this, name = tools[k]] { showTool(name); });
        action->setObjectName(QStringLiteral("toolAction_") + tools[k]);
        addAction(action); // the menu bar is hidden on the stage
        if (k < 9) {
            action->setShortcut(QKeySequence(Qt::Key_1 + static_cast<int>(k)));
            keys << tr("%1 %2").arg(k + 1).arg(tool->title);
        }
    }
    m_toolsMenu->menuAction()->setVisible(!m_toolsMenu->isEmpty());
    m_canvas->setToolKeys(keys);
    if (m_stage->isStaged())
        for (QDockWidget* dock : findChildren<QDockWidget*>())
            if (dock->isFloating())
                dock->hide();
}

QDockWidget* MainWindow::toolDock(const QString& name) const
{
    // lessons::lessonTools()'s names and the panels they open.
    const std::pair<const char*, QDockWidget*> docks[] = {
        {"stopwatch", m_stopwatchDock}, {"predict", m_predictDock}, {"inspector", m_inspectorDock},
        {"plots", m_plotsDock},         {"code", m_codeDock},       {"your_code", m_studentCodeDock},
        {"force_editor", m_forceEditorDock}, {"accuracy", m_accuracyDock}, {"step_apart", m_stepApartDock}};
    for (const auto& [key, dock] : docks)
        if (name == QLatin1String(key))
            return dock;
    return nullptr;
}

void MainWindow::showTool(const QString& name)
{
    QDockWidget* dock = toolDock(name);
    if (!dock)
        return;
    if (!m_stage->isStaged()) {
        dock->show();
        dock->raise();
        focusFirstControl(dock); // the key that opens a tool takes the keyboard into it (Escape: back)
        return;
    }
    // On the stage: a floating panel in the top-right corner, over the box
    // (the class sees the tool and the run at once); the key again closes it.
    if (dock->isVisible() && dock->isFloating()) {
        dock->hide();
        m_canvas->setFocus(Qt::OtherFocusReason);
        return;
    }
    StageToolTitle::attach(dock); // a bar to move and close it by, with or without a window manager
    dock->setFloating(true);
    const QSize size = dock->sizeHint()
                           .expandedTo(QSize(width() * 3 / 10, height() * 2 / 5))
                           .boundedTo(QSize(width() * 9 / 20, height() * 3 / 4));
    dock->resize(size);
    dock->show();
    // Where it fits whole, with the size it took (a panel's least size may be larger).
    const QSize shown = dock->frameGeometry().size();
    const QPoint corner(std::max(0, width() - shown.width() - 12), std::min(12, std::max(0, height() - shown.height())));
    dock->move(mapToGlobal(corner));
    dock->raise();
    focusFirstControl(dock);
}

// The first control of `dock` a Tab would reach (in the order they were
// made, which is the order they are laid out): a typed answer, a button.
void MainWindow::focusFirstControl(QDockWidget* dock)
{
    if (!dock->widget())
        return;
    for (QWidget* w : dock->widget()->findChildren<QWidget*>())
        if ((w->focusPolicy() & Qt::TabFocus) && w->isVisibleTo(dock) && w->isEnabled() &&
            !w->objectName().startsWith(QLatin1String("qt_"))) {
            w->setFocus(Qt::ShortcutFocusReason);
            return;
        }
}

void MainWindow::setTextScale(double scale)
{
    m_textScale = scale;
    applyProjectorFonts(this, m_themeAction->isChecked(), m_textScale);
    applyCanvasLook();
    m_stage->layoutStage(); // the bar's text takes new room
    // The step that would leave the range is off, not cut short.
    m_largerTextAction->setEnabled(m_textScale * kTextScaleStep <= kLargestTextScale + 1e-9);
    m_smallerTextAction->setEnabled(m_textScale / kTextScaleStep >= kSmallestTextScale - 1e-9);
    m_normalTextAction->setEnabled(m_textScale != 1.0);
    QSettings().setValue(kTextScaleKey, m_textScale); // remembered at once, not only on a clean quit
    statusBar()->showMessage(tr("Text at %1% of its usual size (Ctrl+= larger, Ctrl+− smaller, Ctrl+0 usual)")
                                 .arg(std::lround(m_textScale * 100)),
                             4000);
}

void MainWindow::applyCanvasLook()
{
    // The stage view always uses the projector theme.
    const bool stage = m_presentationAction->isChecked();
    m_canvas->setColors(canvasColors(stage || m_themeAction->isChecked()));
    // The canvas's panels and labels follow the teacher's text size (their lines too).
    m_canvas->setLineScale((stage ? 1.6 : m_themeAction->isChecked() ? 1.4 : 1.0) * m_textScale);
}

void MainWindow::updateStatus()
{
    const sim::World& world = m_controller->world();
    const sim::StepStats& last = world.lastStep();
    const double seconds = static_cast<double>(m_statusClock.restart()) * 1e-3;
    const qint64 frames = m_canvas->framesPainted();
    const double fps = seconds > 0.0 ? static_cast<double>(frames - m_lastFrames) / seconds : 0.0;
    m_lastFrames = frames;

    m_timeLabel->setText(tr("t = %1 s").arg(world.time(), 0, 'f', 3));
    m_speedLabel->setText(tr("speed %1×").arg(m_controller->timeScale(), 0, 'g', 3));
    m_fpsLabel->setText(tr("%1 fps · draw %2 ms").arg(fps, 0, 'f', 0).arg(m_canvas->lastPaintMs(), 0, 'f', 2));
    m_costLabel->setText(tr("step %1 µs").arg(last.seconds * 1e6, 0, 'f', 0));
    const int n = world.balls().size();
    m_ballsLabel->setText(n == 1 ? tr("1 ball") : tr("%L1 balls").arg(n));
    m_pairsLabel->setText(tr("pairs tested %L1 · contacts %L2").arg(last.pairsTested).arg(last.contacts));
}

void MainWindow::updatePlayAction(bool playing)
{
    m_playAction->setText(playing ? tr("&Pause") : tr("&Play"));
    m_playAction->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    m_playAction->setStatusTip(playing ? tr("Pause the simulation (Space)") : tr("Run the simulation (Space)"));
}

void MainWindow::setPresentationMode(bool on)
{
    if (on == m_stage->isStaged())
        return;
    if (on) {
        // Everything but the stage goes: docks, menus, toolbars, status bar;
        // lines get thicker. The window takes the whole screen by itself, so
        // it works without a window manager too.
        m_normalGeometry = saveGeometry();
        m_normalDocks = saveState();
        for (QDockWidget* dock : findChildren<QDockWidget*>())
            dock->hide();
        menuBar()->hide();
        m_simulationToolBar->hide();
        m_fileToolBar->hide();
        statusBar()->hide();
        m_stage->setStaged(true);
        applyCanvasLook();
        if (const QScreen* s = screen())
            setGeometry(s->geometry());
        showFullScreen();
    } else {
        m_stage->setStaged(false);
        for (QDockWidget* dock : findChildren<QDockWidget*>())
            StageToolTitle::detach(dock);
        applyCanvasLook();
        menuBar()->show();
        m_simulationToolBar->show();
        m_fileToolBar->show();
        statusBar()->show();
        showNormal();
        restoreState(m_normalDocks);
        restoreGeometry(m_normalGeometry);
    }
    m_stage->layoutStage();
}

void MainWindow::editBall(int index)
{
    if (m_stage->isStaged()) {
        m_stage->showBallTable(index);
        return;
    }
    m_ballsDock->show();
    m_ballsDock->raise();
    m_ballTable->setSelectedBall(index);
    m_ballTable->view()->setFocus();
}

void MainWindow::showError(const QString& message)
{
    statusBar()->showMessage(tr("⚠ %1").arg(message), 8000);
}

void MainWindow::showTimeDropped(double seconds)
{
    m_droppedLabel->setText(tr("behind: %1 ms skipped").arg(seconds * 1e3, 0, 'f', 0));
    m_droppedTimer->start();
}

void MainWindow::about()
{
    QMessageBox::about(this, tr("About ForceLab"),
                       tr("<b>ForceLab</b> %1<br>A workbench for forces and collisions of balls in two dimensions.")
                           .arg(QApplication::applicationVersion()));
}

void MainWindow::describeScene()
{
    m_sceneDescription = forcelab::describeScene(m_controller->world(), m_canvas->selectedBall());
    m_canvas->setAccessibleDescription(m_sceneDescription);
    QAccessibleEvent changed(m_canvas, QAccessible::DescriptionChanged);
    QAccessible::updateAccessibility(&changed);
    statusBar()->showMessage(m_sceneDescription, 20000);
    if (m_stage->isStaged() && m_canvas->isVisible()) // the status bar is hidden there
        QToolTip::showText(m_canvas->mapToGlobal(QPoint(m_canvas->width() / 4, m_canvas->height() * 3 / 4)),
                           m_sceneDescription, m_canvas);
}

bool MainWindow::isStaged() const
{
    return m_stage->isStaged();
}

QByteArray MainWindow::savedGeometry() const
{
    return m_stage->isStaged() ? m_normalGeometry : saveGeometry();
}

QByteArray MainWindow::savedDockState() const
{
    return m_stage->isStaged() ? m_normalDocks : saveState();
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    writeSettings();
    event->accept();
}

void MainWindow::showEvent(QShowEvent* event)
{
    QMainWindow::showEvent(event);
    if (!m_dockLayoutChosen) {
        m_dockLayoutChosen = true;
        if (width() < kCompactWidth)
            useCompactDocks();
    }
    m_controller->setSuspended(isMinimized());
}

void MainWindow::hideEvent(QHideEvent* event)
{
    QMainWindow::hideEvent(event);
    m_controller->setSuspended(true);
}

void MainWindow::changeEvent(QEvent* event)
{
    QMainWindow::changeEvent(event);
    if (event->type() == QEvent::WindowStateChange)
        m_controller->setSuspended(isMinimized() || !isVisible());
}

} // namespace forcelab
