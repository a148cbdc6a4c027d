#include "ui/window/main_window.h"

#include "lessons/atomic_file.h"
#include "lessons/lesson_markup.h"
#include "ui/drawing/png_file.h"

#include "ui/docks/accuracy_dock.h"
#include "ui/canvas/canvas.h"
#include "ui/window/overlay_actions.h"
#include "ui/stage/stage_bar.h"
#include "ui/stage/stage_sliders.h"
#include "ui/drawing/handbook.h"
#include "ui/docks/code_dock.h"
#include "ui/controls/parameter_commands.h"
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

namespace {
const QString kGeometryKey = QStringLiteral("mainWindow/geometry");
const QString kStateKey = QStringLiteral("mainWindow/layout2"); // the docks since the plots moved to the right
const QString kLastLessonKey = QStringLiteral("lesson/last");
const QString kDirectoryKey = QStringLiteral("lesson/directory");
const QString kThemeKey = QStringLiteral("view/projectorTheme");

// The tabs of docks stacked in one place keep their whole names and scroll
// when the column is too narrow for all of them. Qt's own tab bars for docks
// shorten every name instead: at 1024x768 the right column's six tabs read
// "Ins…", "P…", "P…", "Stop…", "Force …", "C…", and nobody can tell Plots
// from Predict. The main window makes those bars itself, when docks are
// stacked (at start, on a saved layout, when the user drags one), so each
// is set up here when it is first polished.
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
            }
        return QObject::eventFilter(watched, event);
    }
};

// A red dot: the usual sign for recording.
QIcon recordIcon()
{
    QPixmap pixmap(32, 32);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(QPen(QColor(0x80, 0x10, 0x10), 1.5));
    p.setBrush(QColor(0xd0, 0x20, 0x20));
    p.drawEllipse(QRectF(6, 6, 20, 20));
    return QIcon(pixmap);
}
} // namespace

MainWindow::MainWindow(const QString& lesson, QWidget* parent)
    : QMainWindow(parent)
{
    m_controller = new SimulationController(this);
    m_controller->setSuspended(true); // until the window is shown
    m_canvas = new Canvas(m_controller, this);
    // The banner says, above the canvas, why the simulation stopped itself.
    m_haltBanner = new QLabel(this);
    m_haltBanner->setObjectName(QStringLiteral("haltBanner"));
    m_haltBanner->setWordWrap(true);
    m_haltBanner->setStyleSheet(QStringLiteral("QLabel { background: #fde2e1; color: #7a1410; "
                                               "border-bottom: 2px solid #c0392b; padding: 8px; }"));
    m_haltBanner->hide();
    // The stage: the halt banner over the canvas, and, in the stage view, the
    // bar of large controls beside or under it.
    auto* central = new QWidget(this);
    m_stageLayout = new QBoxLayout(QBoxLayout::LeftToRight, central);
    m_stageLayout->setContentsMargins(0, 0, 0, 0);
    m_stageLayout->setSpacing(0);
    auto* column = new QVBoxLayout;
    column->setSpacing(0);
    column->addWidget(m_haltBanner);
    column->addWidget(m_canvas, 1);
    m_stageLayout->addLayout(column, 1);
    setCentralWidget(central);
    m_trajectory = new TrajectoryExport(m_controller, this);

    createActions();
    m_overlayActions = new OverlayActions(m_canvas, this);
    m_stageBar = new StageBar(
        {m_playAction, m_stepAction, m_resetAction, m_slowerAction, m_fasterAction, m_stageSlidersAction}, central);
    m_stageLayout->addWidget(m_stageBar);
    m_stageBar->hide();
    connect(m_controller, &SimulationController::stepped, this, &MainWindow::updateStageReadout);
    connect(m_stageBar, &StageBar::readoutRoomChanged, this, &MainWindow::updateStageReadout, Qt::QueuedConnection);
    // Escape leaves the stage view.
    auto* leave = new QShortcut(QKeySequence(Qt::Key_Escape), this);
    connect(leave, &QShortcut::activated, this, [this] { m_presentationAction->setChecked(false); });
    createMenus();
    createToolBars();
    installEventFilter(new ReadableDockTabs(this));
    createDocks();
    // The lesson's sliders on the stage share the Parameters panel's undo stack.
    m_stageSliders = new StageSliders(m_controller, m_parameters->undoStack(), m_stageBar);
    m_stageBar->setSliders(m_stageSliders);
    createStatusBar();
    readSettings();
    openInitialLesson(lesson);
    if (!m_settingsProblems.isEmpty())
        showError(m_settingsProblems.join(QStringLiteral(" · ")));
    m_canvas->setFocus();
}

MainWindow::~MainWindow() = default;

void MainWindow::createActions()
{
    m_playAction = new QAction(this);
    m_playAction->setObjectName(QStringLiteral("playAction"));
    m_playAction->setShortcut(Qt::Key_Space);
    connect(m_playAction, &QAction::triggered, m_controller, &SimulationController::togglePlay);
    connect(m_controller, &SimulationController::playingChanged, this, &MainWindow::updatePlayAction);
    updatePlayAction(m_controller->isPlaying());

    m_stepAction = new QAction(style()->standardIcon(QStyle::SP_MediaSkipForward), tr("&Step"), this);
    m_stepAction->setObjectName(QStringLiteral("stepAction"));
    m_stepAction->setShortcuts({QKeySequence(Qt::Key_Right), QKeySequence(Qt::Key_Period)});
    m_stepAction->setStatusTip(tr("Pause and advance by one time step dt (→ or .)"));
    connect(m_stepAction, &QAction::triggered, m_controller, &SimulationController::stepOnce);

    m_resetAction = new QAction(style()->standardIcon(QStyle::SP_BrowserReload), tr("&Reset"), this);
    m_resetAction->setObjectName(QStringLiteral("resetAction"));
    m_resetAction->setShortcut(Qt::Key_R);
    m_resetAction->setStatusTip(tr("Start the lesson again with its own values (R)"));
    connect(m_resetAction, &QAction::triggered, this, &MainWindow::resetLesson);

    m_slowerAction = new QAction(style()->standardIcon(QStyle::SP_MediaSeekBackward), tr("S&lower"), this);
    m_slowerAction->setObjectName(QStringLiteral("slowerAction"));
    m_slowerAction->setShortcut(Qt::Key_BracketLeft);
    m_slowerAction->setStatusTip(tr("Half the speed: slow motion down to 1/16× ([)"));
    connect(m_slowerAction, &QAction::triggered, this, &MainWindow::slower);

    m_fasterAction = new QAction(style()->standardIcon(QStyle::SP_MediaSeekForward), tr("&Faster"), this);
    m_fasterAction->setObjectName(QStringLiteral("fasterAction"));
    m_fasterAction->setShortcut(Qt::Key_BracketRight);
    m_fasterAction->setStatusTip(tr("Double the speed, up to %1× (])").arg(SimulationController::kMaxTimeScale));
    connect(m_fasterAction, &QAction::triggered, this, &MainWindow::faster);

    // The stage view's row bar under the box has room for the lesson's
    // sliders only on a wide screen; on a 4:3 projector this button makes
    // the bar taller to show them (the box shrinks while they are shown).
    m_stageSlidersAction = new QAction(style()->standardIcon(QStyle::SP_FileDialogDetailedView), tr("Sliders"), this);
    m_stageSlidersAction->setObjectName(QStringLiteral("stageSlidersAction"));
    m_stageSlidersAction->setCheckable(true);
    m_stageSlidersAction->setShortcut(Qt::Key_S);
    m_stageSlidersAction->setStatusTip(tr("Show the lesson's sliders under the box in the stage view (S)"));
    m_stageSlidersAction->setVisible(false);
    connect(m_stageSlidersAction, &QAction::toggled, this, &MainWindow::layoutStage);

    m_openAction = new QAction(style()->standardIcon(QStyle::SP_DialogOpenButton), tr("&Open Lesson…"), this);
    m_openAction->setObjectName(QStringLiteral("openAction"));
    m_openAction->setShortcut(QKeySequence::Open);
    m_openAction->setIconText(tr("Open"));
    m_openAction->setStatusTip(tr("Open a lesson file from disk"));
    connect(m_openAction, &QAction::triggered, this, &MainWindow::openLessonFile);

    m_saveAction = new QAction(style()->standardIcon(QStyle::SP_DialogSaveButton), tr("&Save Scene as Lesson…"), this);
    m_saveAction->setObjectName(QStringLiteral("saveAction"));
    m_saveAction->setShortcut(QKeySequence::Save);
    m_saveAction->setIconText(tr("Save"));
    m_saveAction->setStatusTip(tr("Save the balls as they are now and the live settings as a lesson file"));
    connect(m_saveAction, &QAction::triggered, this, &MainWindow::saveLessonFile);

    m_screenshotAction = new QAction(style()->standardIcon(QStyle::SP_DesktopIcon), tr("Screens&hot…"), this);
    m_screenshotAction->setIconText(tr("Picture"));
    m_screenshotAction->setObjectName(QStringLiteral("screenshotAction"));
    m_screenshotAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_P));
    m_screenshotAction->setStatusTip(tr("Save a picture of the canvas as PNG"));
    connect(m_screenshotAction, &QAction::triggered, this, [this] { saveScreenshot(1.0); });

    m_recordAction = new QAction(recordIcon(), tr("Re&cord Trajectory"), this);
    m_recordAction->setIconText(tr("Record"));
    m_recordAction->setObjectName(QStringLiteral("recordAction"));
    m_recordAction->setCheckable(true);
    m_recordAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    m_recordAction->setStatusTip(tr("Record the path of the selected ball (or of all balls when none is selected)"));
    connect(m_recordAction, &QAction::toggled, this, [this](bool on) {
        if (on == m_trajectory->isRecording())
            return;
        if (on) {
            m_trajectory->start(m_controller->world(), m_canvas->selectedBall());
            statusBar()->showMessage(m_canvas->selectedBall() >= 0
                                         ? tr("Recording ball #%1").arg(m_canvas->selectedBall())
                                         : tr("Recording every ball"), 4000);
        } else {
            m_trajectory->stop();
        }
    });
    connect(m_trajectory, &TrajectoryExport::recordingChanged, m_recordAction, &QAction::setChecked);

    m_exportAction = new QAction(style()->standardIcon(QStyle::SP_FileDialogDetailedView), tr("&Export Trajectory…"),
                                 this);
    m_exportAction->setIconText(tr("CSV"));
    m_exportAction->setObjectName(QStringLiteral("exportAction"));
    m_exportAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    m_exportAction->setStatusTip(tr("Write the recorded trajectory as CSV (time, ball, position, velocity)"));
    connect(m_exportAction, &QAction::triggered, this, &MainWindow::exportTrajectory);

    m_handbookAction = new QAction(tr("Export Teacher &Handbook…"), this);
    m_handbookAction->setObjectName(QStringLiteral("handbookAction"));
    m_handbookAction->setStatusTip(tr("Write every lesson with its teacher notes as one printable HTML page"));
    connect(m_handbookAction, &QAction::triggered, this, &MainWindow::exportHandbook);

    m_previousAction = new QAction(style()->standardIcon(QStyle::SP_ArrowBack), tr("&Previous Lesson"), this);
    m_previousAction->setObjectName(QStringLiteral("previousLessonAction"));
    m_previousAction->setShortcut(QKeySequence(Qt::ALT | Qt::Key_Left));
    connect(m_previousAction, &QAction::triggered, this, &MainWindow::previousLesson);
    m_nextAction = new QAction(style()->standardIcon(QStyle::SP_ArrowForward), tr("&Next Lesson"), this);
    m_nextAction->setObjectName(QStringLiteral("nextLessonAction"));
    m_nextAction->setShortcut(QKeySequence(Qt::ALT | Qt::Key_Right));
    connect(m_nextAction, &QAction::triggered, this, &MainWindow::nextLesson);

    m_quitAction = new QAction(tr("&Quit"), this);
    m_quitAction->setObjectName(QStringLiteral("quitAction"));
    m_quitAction->setShortcut(QKeySequence::Quit);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);

    m_presentationAction = new QAction(tr("&Stage View (Projector)"), this);
    m_presentationAction->setObjectName(QStringLiteral("presentationAction"));
    m_presentationAction->setCheckable(true);
    m_presentationAction->setShortcut(QKeySequence::FullScreen);
    m_presentationAction->setStatusTip(
        tr("The simulation fills the screen with large controls beside it, for a projector (F11; Escape leaves)"));
    m_presentationAction->setIconText(tr("Stage"));
    m_presentationAction->setIcon(style()->standardIcon(QStyle::SP_TitleBarMaxButton));
    connect(m_presentationAction, &QAction::toggled, this, &MainWindow::setPresentationMode);

    m_themeAction = new QAction(tr("P&rojector Theme"), this);
    m_themeAction->setObjectName(QStringLiteral("themeAction"));
    m_themeAction->setCheckable(true);
    m_themeAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_T));
    m_themeAction->setStatusTip(tr("White box, dark thick outlines, colour-blind-safe balls and larger text "
                                   "everywhere (always on in the stage view)"));
    connect(m_themeAction, &QAction::toggled, this, &MainWindow::setProjectorTheme);

    m_screenshotDoubleAction = new QAction(tr("Picture at &Double Size…"), this);
    m_screenshotDoubleAction->setObjectName(QStringLiteral("screenshotDoubleAction"));
    m_screenshotDoubleAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
    m_screenshotDoubleAction->setStatusTip(tr("Save the stage at twice the screen's resolution, for print"));
    connect(m_screenshotDoubleAction, &QAction::triggered, this, [this] { saveScreenshot(2.0); });

    m_aboutAction = new QAction(tr("&About ForceLab"), this);
    connect(m_aboutAction, &QAction::triggered, this, &MainWindow::about);
}

void MainWindow::createMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(m_openAction);
    file->addAction(m_saveAction);
    file->addSeparator();
    file->addAction(m_screenshotAction);
    file->addAction(m_screenshotDoubleAction);
    file->addAction(m_recordAction);
    file->addAction(m_exportAction);
    file->addAction(m_handbookAction);
    file->addSeparator();
    file->addAction(m_quitAction);

    // Undo / Redo come from the Parameters panel's stack (createDocks).
    menuBar()->addMenu(tr("&Edit"))->setObjectName(QStringLiteral("editMenu"));

    QMenu* simulation = menuBar()->addMenu(tr("&Simulation"));
    simulation->addAction(m_playAction);
    simulation->addAction(m_stepAction);
    simulation->addAction(m_resetAction);
    simulation->addSeparator();
    simulation->addAction(m_slowerAction);
    simulation->addAction(m_fasterAction);

    QMenu* lessons = menuBar()->addMenu(tr("&Lesson"));
    lessons->addAction(m_previousAction);
    lessons->addAction(m_nextAction);

    m_accuracyMenu = menuBar()->addMenu(tr("&Accuracy"));
    m_accuracyMenu->setObjectName(QStringLiteral("accuracyMenu"));

    // Also filled by createToolBars and createDocks with their toggle actions.
    m_viewMenu = menuBar()->addMenu(tr("&View"));
    m_viewMenu->addAction(m_presentationAction);
    m_viewMenu->addAction(m_themeAction);
    m_viewMenu->addMenu(m_overlayActions->menu());
    m_viewMenu->addSeparator();

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(m_aboutAction);
}

void MainWindow::createToolBars()
{
    m_simulationToolBar = addToolBar(tr("Simulation"));
    m_simulationToolBar->setObjectName(QStringLiteral("simulationToolBar"));
    m_simulationToolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_simulationToolBar->addAction(m_playAction);
    m_simulationToolBar->addAction(m_stepAction);
    m_simulationToolBar->addAction(m_resetAction);
    m_simulationToolBar->addSeparator();
    m_simulationToolBar->addAction(m_slowerAction);
    m_simulationToolBar->addAction(m_fasterAction);
    m_simulationToolBar->addAction(m_presentationAction);
    {
        // The drawing aids, one click away: a button with the View menu's "Show" menu.
        auto* show = new QToolButton(m_simulationToolBar);
        show->setObjectName(QStringLiteral("showButton"));
        show->setText(tr("Show"));
        show->setIcon(style()->standardIcon(QStyle::SP_FileDialogContentsView));
        show->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
        show->setPopupMode(QToolButton::InstantPopup);
        show->setMenu(m_overlayActions->menu());
        show->setAccessibleName(tr("Show: what the stage draws"));
        m_simulationToolBar->addWidget(show);
    }

    m_fileToolBar = addToolBar(tr("File"));
    m_fileToolBar->setObjectName(QStringLiteral("fileToolBar"));
    m_fileToolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_fileToolBar->addAction(m_openAction);
    m_fileToolBar->addAction(m_saveAction);
    m_fileToolBar->addAction(m_screenshotAction);
    m_fileToolBar->addAction(m_recordAction);
    m_fileToolBar->addAction(m_exportAction);

    m_viewMenu->addAction(m_simulationToolBar->toggleViewAction());
    m_viewMenu->addAction(m_fileToolBar->toggleViewAction());
    m_viewMenu->addSeparator();
}

void MainWindow::createDocks()
{
    m_lessonsDock = new LessonsDock(this);
    m_lessonsDock->setCourse(LessonsDock::builtInCourse());
    m_lessonsDock->setNavigationActions(m_previousAction, m_nextAction);
    connect(m_lessonsDock, &LessonsDock::lessonChosen, this, &MainWindow::chooseLesson);
    addDockWidget(Qt::LeftDockWidgetArea, m_lessonsDock);

    m_parameters = new ParameterPanel(m_controller);
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
    m_plotsDock = new PlotsDock(m_controller, this);
    m_accuracyDock = new AccuracyDock(m_controller, m_canvas, this); // closed at first: its books cost evaluations
    m_codeDock = new CodeDock(m_controller, this);
    m_predictDock = new PredictDock(m_controller, this);
    m_stopwatchDock = new StopwatchDock(m_controller, this);
    m_forceEditorDock = new ForceEditorDock(m_controller, m_parameters->undoStack(), this);
    connect(m_canvas, &Canvas::selectedBallChanged, m_stopwatchDock, &StopwatchDock::setBall);
    for (QDockWidget* dock : {static_cast<QDockWidget*>(m_plotsDock), static_cast<QDockWidget*>(m_predictDock),
                              static_cast<QDockWidget*>(m_stopwatchDock), static_cast<QDockWidget*>(m_forceEditorDock),
                              static_cast<QDockWidget*>(m_codeDock),
                              static_cast<QDockWidget*>(m_accuracyDock)}) {
        addDockWidget(Qt::RightDockWidgetArea, dock);
        tabifyDockWidget(m_inspectorDock, dock);
    }
    m_plotsDock->raise();
    m_accuracyDock->hide();
    m_accuracyMenu->addAction(m_accuracyDock->tradeOffAction());
    m_accuracyMenu->addAction(m_accuracyDock->convergenceAction());
    m_accuracyMenu->addSeparator();
    m_accuracyMenu->addAction(m_accuracyDock->toggleViewAction());

    m_undoAction = m_parameters->undoStack()->createUndoAction(this, tr("&Undo"));
    m_undoAction->setObjectName(QStringLiteral("undoAction"));
    m_undoAction->setShortcut(QKeySequence::Undo);
    m_undoAction->setIcon(style()->standardIcon(QStyle::SP_ArrowLeft));
    m_redoAction = m_parameters->undoStack()->createRedoAction(this, tr("&Redo"));
    m_redoAction->setObjectName(QStringLiteral("redoAction"));
    m_redoAction->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    m_redoAction->setIcon(style()->standardIcon(QStyle::SP_ArrowRight));
    if (QMenu* edit = menuBar()->findChild<QMenu*>(QStringLiteral("editMenu"))) {
        edit->addAction(m_undoAction);
        edit->addAction(m_redoAction);
    }
    m_simulationToolBar->addSeparator();
    m_simulationToolBar->addAction(m_undoAction);
    m_simulationToolBar->addAction(m_redoAction);

    m_viewMenu->addAction(m_lessonsDock->toggleViewAction());
    m_viewMenu->addAction(m_parametersDock->toggleViewAction());
    m_viewMenu->addAction(m_plotsDock->toggleViewAction());
    m_viewMenu->addAction(m_inspectorDock->toggleViewAction());
    m_viewMenu->addAction(m_accuracyDock->toggleViewAction());
    m_viewMenu->addAction(m_codeDock->toggleViewAction());
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
    connect(m_controller, &SimulationController::haltedChanged, this, &MainWindow::showHalted);
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
}

void MainWindow::writeSettings() const
{
    QSettings settings;
    // Quitting from the stage view keeps the normal layout for next time.
    const bool staged = m_stageBar && m_stageBar->isVisible();
    settings.setValue(kGeometryKey, staged ? m_normalGeometry : saveGeometry());
    settings.setValue(kStateKey, staged ? m_normalDocks : saveState());
    if (!m_lesson.source.isEmpty())
        settings.setValue(kLastLessonKey, m_lesson.source);
    settings.setValue(kDirectoryKey, m_lastDirectory);
    settings.setValue(kThemeKey, m_themeAction->isChecked());
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

bool MainWindow::setLesson(const Lesson& lesson)
{
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
    m_canvas->setOverlays(m_stageBar->isVisible() ? readoutsToStageBar(overlays) : overlays);
    m_overlayActions->sync(); // the lesson's choice is the default; the Show menu follows it
    m_canvas->setSelectedBall(-1);
    m_canvas->setTrailScope(TrailRecorder::Scope::All);
    m_inspectorDock->setSelectedBall(-1);
    m_plotsDock->setHistogramShown(lesson.overlays.contains(QStringLiteral("histogram")));
    m_codeDock->setLessonControls(lesson.controls);
    m_predictDock->setLesson(lesson);
    if (m_predictDock->hasQuestions())
        m_predictDock->raise(); // the lesson asks first
    else if (lesson.scene.settings.custom.enabled)
        m_forceEditorDock->raise(); // the lesson is about writing a law
    else if (!m_plotsDock->isHidden())
        m_plotsDock->raise();
    updateStageCaption();
    updateStageReadout();
    m_stageSliders->setLessonControls(lesson.controls);
    layoutStage(); // the box's shape decides where the stage bar goes
    setWindowTitle(lesson.title.isEmpty() ? tr("ForceLab")
                                          : tr("%1 — ForceLab").arg(lessons::markupToPlainText(lesson.title)));
    m_lessonsDock->setCurrentLesson(lesson);
    m_parameters->setLessonControls(lesson.controls);
    // Undo steps belong to the lesson they were made in.
    m_parameters->undoStack()->clear();
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
    m_parameters->undoStack()->clear();
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
    m_controller->setTimeScale(wanted);
    m_parameters->undoStack()->push(new TimeScaleCommand(m_controller, now, wanted));
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
    Lesson lesson = currentSceneAsLesson();
    // The file's name as its id, when it makes a valid one.
    static const QRegularExpression validId(QStringLiteral("^[A-Za-z0-9_-]{1,64}$"));
    if (const QString stem = QFileInfo(path).completeBaseName(); validId.match(stem).hasMatch())
        lesson.id = stem;
    QString why;
    if (!lessons::writeFileAtomically(path, saveLesson(lesson), &why)) {
        showError(tr("Lesson not saved: %1").arg(why));
        return false;
    }
    statusBar()->showMessage(tr("Saved %n ball(s) and the settings to %1", nullptr, int(lesson.scene.balls.size()))
                                 .arg(QDir::toNativeSeparators(path)), 5000);
    return true;
}

void MainWindow::saveLessonFile()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Save Scene as Lesson"), suggestedFileName("json"),
                                                      tr("Lesson files (*.json)"));
    if (path.isEmpty())
        return;
    m_lastDirectory = QFileInfo(path).absolutePath();
    saveLessonTo(path);
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

void MainWindow::setProjectorTheme(bool on)
{
    if (m_themeAction->isChecked() != on)
        m_themeAction->setChecked(on); // comes back here through toggled
    applyProjectorFonts(this, on);
    applyCanvasLook();
}

void MainWindow::applyCanvasLook()
{
    // The stage view always uses the projector theme.
    const bool stage = m_presentationAction->isChecked();
    m_canvas->setColors(canvasColors(stage || m_themeAction->isChecked()));
    m_canvas->setLineScale(stage ? 1.6 : m_themeAction->isChecked() ? 1.4 : 1.0);
}

void MainWindow::exportHandbook()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Teacher Handbook"),
                                                      QStringLiteral("forcelab-handbook.html"), tr("HTML (*.html)"));
    if (path.isEmpty())
        return;
    QString why;
    if (!lessons::writeFileAtomically(path, builtInHandbookHtml().toUtf8(), &why)) {
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
    if (on == m_stageBar->isVisible())
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
        m_canvas->setBoxMargin(4.0);
        m_canvas->setOverlays(readoutsToStageBar(m_canvas->overlays()));
        updateStageCaption();
        m_stageBar->show();
        applyCanvasLook();
        updateStageReadout(); // shown now, so it fills in
        if (const QScreen* s = screen())
            setGeometry(s->geometry());
        showFullScreen();
    } else {
        m_stageBar->hide();
        applyCanvasLook();
        m_canvas->setBoxMargin(10.0);
        Overlays back = m_canvas->overlays();
        back.readout = m_stageOverlays.readout;
        back.totals = m_stageOverlays.totals;
        m_canvas->setOverlays(back);
        menuBar()->show();
        m_simulationToolBar->show();
        m_fileToolBar->show();
        statusBar()->show();
        showNormal();
        restoreState(m_normalDocks);
        restoreGeometry(m_normalGeometry);
    }
    layoutStage();
}

// The stage view shows the readout and the totals in its bar, not on the
// canvas: remembers which of them the canvas had, and returns the canvas's
// overlays without them.
Overlays MainWindow::readoutsToStageBar(Overlays overlays)
{
    m_stageOverlays = overlays;
    overlays.readout = overlays.totals = false;
    return overlays;
}

void MainWindow::updateStageReadout()
{
    if (!m_stageBar->isVisible())
        return;
    // Long lines in a row, short ones in a column, and in a row too when
    // the long ones would have to shrink out of reading size.
    const StageReadout text = stageReadoutText();
    const bool wide = !m_stageBar->isVertical() && m_stageBar->readoutFits(text.wide);
    m_stageBar->setReadout(wide ? text.wide : text.narrow);
}

// Both forms from one evaluation of the accelerations and the energy (each
// a pass over every pair of balls when they attract).
MainWindow::StageReadout MainWindow::stageReadoutText() const
{
    const sim::World& world = m_controller->world();
    QStringList wide, narrow;
    if (m_stageOverlays.readout && !world.balls().empty()) {
        const sim::Matrix2X a = world.accelerations();
        wide << WorldPainter::readoutText(world, m_canvas->selectedBall(), &a, true);
        // Short lines, x and y side by side.
        const int n = world.balls().size(), selected = m_canvas->selectedBall();
        const int i = selected >= 0 && selected < n ? selected : 0;
        const sim::Vec2 x = world.balls().position.col(i), v = world.balls().velocity.col(i);
        // One decimal, or four significant digits from 100,000 on (a stiff
        // spring's −1e+06 px/s², not −1000000.0).
        auto num = [](double value) {
            return std::abs(value) < 1e5 ? QString::number(value, 'f', 1) : QString::number(value, 'g', 4);
        };
        narrow << tr("ball %1   t = %2 s").arg(i).arg(world.time(), 0, 'f', 3)
               << QStringLiteral("x %1  y %2 px").arg(num(x.x()), num(x.y()))
               << QStringLiteral("v (%1, %2) px/s").arg(num(v.x()), num(v.y()))
               << QStringLiteral("a (%1, %2) px/s²").arg(num(a(0, i)), num(a(1, i)))
               << tr("speed %1 px/s").arg(v.norm(), 0, 'f', 1);
    }
    if (m_stageOverlays.totals) {
        const sim::Energy e = world.energy();
        const sim::Vec2 p = world.momentum();
        wide << WorldPainter::totalsText(e, p, true);
        // A column is narrow: there "energy" and "momentum" head lines of
        // their own and the momentum's x and y take one line each, so no
        // line is much wider than one number's; a row's short form needs
        // the lines this saves.
        const bool column = m_stageBar->isVertical();
        const QString kinetic = QString::number(e.kinetic, 'g', 4);
        if (column)
            narrow << tr("energy") << tr("  kinetic %1").arg(kinetic);
        else
            narrow << tr("energy: kinetic %1").arg(kinetic);
        narrow << tr("  potential %1").arg(e.potential, 0, 'g', 4) << tr("  total %1").arg(e.total(), 0, 'g', 4);
        if (column)
            narrow << tr("momentum") << tr("  x %1").arg(p.x(), 0, 'g', 4) << tr("  y %1").arg(p.y(), 0, 'g', 4);
        else
            narrow << tr("momentum (%1, %2)").arg(p.x(), 0, 'g', 4).arg(p.y(), 0, 'g', 4);
    }
    return {wide.join(QLatin1Char('\n')), narrow.join(QLatin1Char('\n'))};
}

void MainWindow::updateStageCaption()
{
    m_stageBar->setCaption(lessons::markupToPlainText(m_lesson.title),
                           lessons::markupToPlainText(m_lesson.challenges.value(0)));
}

void MainWindow::resizeEvent(QResizeEvent* event)
{
    QMainWindow::resizeEvent(event);
    layoutStage();
}

// In the stage view the bar takes the strip the box leaves: a column beside
// it when the window is wider than the box (16:9 screens and a 3:2 box), a
// row under it otherwise, so the box is as large as the window allows.
void MainWindow::layoutStage()
{
    if (!m_stageBar->isVisible())
        return;
    const sim::BoxSettings& box = m_controller->world().settings().box;
    const double aspect = box.width > 0 && box.height > 0 ? box.width / box.height : 1.5;
    const QSize area = centralWidget()->size();
    const double side = area.width() - aspect * area.height();      // px left beside a full-height box
    const double below = area.height() - area.width() / aspect;      // px left under a full-width box
    const bool vertical = side >= below;
    const bool wasVertical = m_stageBar->isVertical();
    m_stageBar->setVertical(vertical);
    m_stageLayout->setDirection(vertical ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom);
    // A row is as tall as its caption, readout and sliders need, up to a
    // seventh of the screen (the box keeps over 80% of it); the sliders
    // stay in the Parameters panel when they would not fit under that.
    // Two sliders side by side in a column at least 320 px wide (one in a
    // narrower one, so a label such as "Ball restitution" is not cut); in a
    // row as many as fit its width.
    const int columnWidth = std::max(200, static_cast<int>(side));
    m_stageSliders->setColumns(vertical ? (columnWidth >= 320 ? 2 : 1)
                                        : std::clamp(area.width() / 240, 1, std::max(1, m_stageSliders->count())));
    int minimum = 200;
    if (!vertical) {
        // Sliders that do not fit under the cap wait for the Sliders button,
        // which lets the bar take up to 2/5 of the screen to show them.
        const int cap = std::max(96, area.height() / 7);
        const bool sliders = m_stageSliders->count() > 0;
        m_stageBar->unfitChallenge(); // its size hint at its own font, whatever room it had before
        m_stageBar->setSlidersShown(sliders);
        const bool fit = m_stageBar->sizeHint().height() <= cap;
        m_stageSlidersAction->setVisible(sliders && !fit);
        const bool asked = sliders && !fit && m_stageSlidersAction->isChecked();
        m_stageBar->setSlidersShown(sliders && (fit || asked));
        minimum = std::clamp(m_stageBar->sizeHint().height(), 96, cap);
        if (asked) // the bar as without them, plus the rows of sliders
            minimum = std::min(cap + m_stageSliders->sizeHint().height() + 8, area.height() * 2 / 5);
    } else {
        m_stageSlidersAction->setVisible(false);
        m_stageBar->setSlidersShown(m_stageSliders->count() > 0);
    }
    const int strip = std::max(minimum, static_cast<int>(vertical ? side : below));
    if (vertical) {
        m_stageBar->setFixedWidth(strip);
        m_stageBar->setMinimumHeight(0);
        m_stageBar->setMaximumHeight(QWIDGETSIZE_MAX);
    } else {
        m_stageBar->setFixedHeight(strip);
        m_stageBar->setMinimumWidth(0);
        m_stageBar->setMaximumWidth(QWIDGETSIZE_MAX);
    }
    if (vertical != wasVertical)
        updateStageReadout(); // short lines in a column, long ones in a row
}

void MainWindow::showError(const QString& message)
{
    statusBar()->showMessage(tr("⚠ %1").arg(message), 8000);
}

void MainWindow::showHalted(const QString& reason)
{
    m_haltBanner->setText(tr("<b>Stopped:</b> %1").arg(reason.toHtmlEscaped()));
    m_haltBanner->setVisible(!reason.isEmpty());
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
