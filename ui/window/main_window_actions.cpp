// The main window's commands: one QAction per command, made and set up in
// one place, then placed in the menus and on the toolbars. Part of
// MainWindow (main_window.h).
#include "ui/window/main_window.h"
#include "ui/window/language.h"
#include "ui/window/trace_check.h"

#include "lessons/atomic_file.h"
#include "lessons/lesson_markup.h"
#include "ui/drawing/png_file.h"

#include "ui/docks/accuracy_dock.h"
#include "ui/canvas/canvas.h"
#include "ui/window/overlay_actions.h"
#include "ui/stage/stage_view.h"
#include "ui/drawing/handbook.h"
#include "ui/docks/code_dock.h"
#include "ui/controls/settings_editor.h"
#include "ui/docks/inspector_dock.h"
#include "ui/docks/lessons_dock.h"
#include "ui/controls/parameter_panel.h"
#include "ui/docks/plots_dock.h"
#include "ui/charts/energy_bars.h"
#include "ui/charts/quantity_graph.h"
#include "ui/charts/speed_histogram.h"
#include "ui/docks/predict_dock.h"
#include "ui/docks/stopwatch_dock.h"
#include "ui/docks/force_editor_dock.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/window/theme.h"
#include "ui/controls/timeline_bar.h"
#include "ui/controls/ball_table.h"
#include "ui/controls/ball_table_model.h"
#include "ui/drawing/human_number.h"
#include "ui/stage/stage_sliders.h"
#include "ui/docks/trajectory_export.h"

#include "lessons/lesson_loader.h"

#include <QAction>
#include <QActionGroup>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
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
#include <QActionGroup>
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

// Going back in time: Step Back (← or , mirroring Step's → and .) and the
// timeline bar (step back, the scrubber over the recorded past, step) in a
// toolbar of its own, on the row of the others: a row of its own would take
// the box's height.
void MainWindow::createTimeActions()
{
    m_stepBackAction = new QAction(style()->standardIcon(QStyle::SP_MediaSkipBackward), tr("Step &Back"), this);
    m_stepBackAction->setObjectName(QStringLiteral("stepBackAction"));
    m_stepBackAction->setShortcuts({QKeySequence(Qt::Key_Left), QKeySequence(Qt::Key_Comma)});
    m_stepBackAction->setStatusTip(tr("Pause and go back by one time step dt, to the world as it was (← or ,)"));
    connect(m_stepBackAction, &QAction::triggered, m_controller, &SimulationController::stepBack);
    addAction(m_stepBackAction);
    if (auto* simulation = menuBar()->findChild<QMenu*>(QStringLiteral("simulationMenu")))
        simulation->insertAction(m_resetAction, m_stepBackAction); // after Step
    auto* timeBar = new QToolBar(tr("Timeline"), this);
    timeBar->setObjectName(QStringLiteral("timelineToolBar"));
    timeBar->addWidget(new TimelineBar(m_controller, timeBar));
    addToolBar(Qt::TopToolBarArea, timeBar);
    // The stage view shows the stage alone (leaving it restores the bar with the layout).
    connect(m_presentationAction, &QAction::toggled, timeBar, [timeBar](bool staged) {
        if (staged)
            timeBar->hide();
    });
}

void MainWindow::createSimulationActions()
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

    // The stage in words (scene_description.h): on the key, and by itself after every pause.
    m_describeAction = new QAction(tr("&Describe the Scene"), this);
    m_describeAction->setObjectName(QStringLiteral("describeAction"));
    m_describeAction->setShortcut(Qt::Key_D);
    m_describeAction->setStatusTip(tr("Say in words what is on the stage: the balls, the selected one's motion, "
                                      "when it reaches a wall, the energy (D)"));
    connect(m_describeAction, &QAction::triggered, this, &MainWindow::describeScene);
    connect(m_controller, &SimulationController::playingChanged, this, [this](bool playing) {
        if (!playing)
            describeScene();
    });

    m_resetAction = new QAction(style()->standardIcon(QStyle::SP_BrowserReload), tr("&Reset"), this);
    m_resetAction->setObjectName(QStringLiteral("resetAction"));
    m_resetAction->setIconText(tr("Reset", "the word under the button's icon: short, it has 72 px on the stage"));
    m_resetAction->setShortcut(Qt::Key_R);
    m_resetAction->setStatusTip(tr("Start the lesson again with its own values (R)"));
    connect(m_resetAction, &QAction::triggered, this, &MainWindow::resetLesson);

    m_slowerAction = new QAction(style()->standardIcon(QStyle::SP_MediaSeekBackward), tr("S&lower"), this);
    m_slowerAction->setIconText(tr("Slower", "the word under the button's icon: short, it has 72 px on the stage"));
    m_slowerAction->setObjectName(QStringLiteral("slowerAction"));
    m_slowerAction->setShortcut(Qt::Key_BracketLeft);
    m_slowerAction->setStatusTip(tr("Half the speed: slow motion down to 1/16× ([)"));
    connect(m_slowerAction, &QAction::triggered, this, &MainWindow::slower);

    m_fasterAction = new QAction(style()->standardIcon(QStyle::SP_MediaSeekForward), tr("&Faster"), this);
    m_fasterAction->setIconText(tr("Faster", "the word under the button's icon: short, it has 72 px on the stage"));
    m_fasterAction->setObjectName(QStringLiteral("fasterAction"));
    m_fasterAction->setShortcut(Qt::Key_BracketRight);
    m_fasterAction->setStatusTip(tr("Double the speed, up to %1× (])").arg(SimulationController::kMaxTimeScale));
    connect(m_fasterAction, &QAction::triggered, this, &MainWindow::faster);
}

namespace {

// A ball with a plus: the Add Ball icon (no standard icon means "new ball").
QIcon addBallIcon()
{
    QPixmap pixmap(64, 64);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(QPen(QColor(0x2d3340), 3));
    p.setBrush(QColor(0x3090d0));
    p.drawEllipse(QRectF(6, 6, 52, 52));
    p.setPen(QPen(Qt::white, 7, Qt::SolidLine, Qt::RoundCap));
    p.drawLine(QPointF(32, 19), QPointF(32, 45));
    p.drawLine(QPointF(19, 32), QPointF(45, 32));
    return QIcon(pixmap);
}

} // namespace

void MainWindow::createBallActions()
{
    m_addBallAction = new QAction(addBallIcon(), tr("&Add Ball"), this);
    m_addBallAction->setObjectName(QStringLiteral("addBallAction"));
    m_addBallAction->setShortcuts({QKeySequence(Qt::Key_Insert), QKeySequence(Qt::Key_B)});
    m_addBallAction->setToolTip(tr("Add a ball in the middle of the box (B). Right-click the stage to add one "
                                   "where you click."));
    connect(m_addBallAction, &QAction::triggered, m_canvas, &Canvas::addBall);

    m_deleteBallAction = new QAction(tr("&Delete Ball"), this);
    m_deleteBallAction->setObjectName(QStringLiteral("deleteBallAction"));
    m_deleteBallAction->setShortcut(QKeySequence::Delete);
    connect(m_deleteBallAction, &QAction::triggered, m_canvas, &Canvas::deleteSelectedBall);

    m_duplicateBallAction = new QAction(tr("D&uplicate Ball"), this);
    m_duplicateBallAction->setObjectName(QStringLiteral("duplicateBallAction"));
    m_duplicateBallAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    connect(m_duplicateBallAction, &QAction::triggered, m_canvas, &Canvas::duplicateSelectedBall);

    m_copyBallAction = new QAction(tr("&Copy Ball"), this);
    m_copyBallAction->setObjectName(QStringLiteral("copyBallAction"));
    m_copyBallAction->setShortcut(QKeySequence::Copy);
    connect(m_copyBallAction, &QAction::triggered, m_canvas, &Canvas::copySelectedBall);

    m_pasteBallAction = new QAction(tr("&Paste Ball"), this);
    m_pasteBallAction->setObjectName(QStringLiteral("pasteBallAction"));
    m_pasteBallAction->setShortcut(QKeySequence::Paste);
    connect(m_pasteBallAction, &QAction::triggered, m_canvas, &Canvas::pasteBall);

    // The actions on the selected ball wait for a selection.
    auto sync = [this](int selected) {
        for (QAction* action : {m_deleteBallAction, m_duplicateBallAction, m_copyBallAction})
            action->setEnabled(selected >= 0);
    };
    connect(m_canvas, &Canvas::selectedBallChanged, this, sync);
    sync(m_canvas->selectedBall());
    for (QAction* action : {m_addBallAction, m_deleteBallAction, m_duplicateBallAction, m_copyBallAction,
                            m_pasteBallAction})
        addAction(action); // their keys work on the stage too, where the menus are hidden
}

void MainWindow::createCameraActions()
{
    m_zoomInAction = new QAction(tr("Zoom &In"), this);
    m_zoomInAction->setObjectName(QStringLiteral("zoomInAction"));
    // Plain keys, one press in front of the class; Ctrl with + and − is left
    // for the text size.
    m_zoomInAction->setShortcuts({QKeySequence(Qt::Key_Plus), QKeySequence(Qt::Key_Equal)});
    m_zoomInAction->setToolTip(tr("Zoom in on the middle (+); the mouse wheel zooms in on the pointer"));
    connect(m_zoomInAction, &QAction::triggered, m_canvas, &Canvas::zoomIn);

    m_zoomOutAction = new QAction(tr("Zoom &Out"), this);
    m_zoomOutAction->setObjectName(QStringLiteral("zoomOutAction"));
    m_zoomOutAction->setShortcut(QKeySequence(Qt::Key_Minus));
    m_zoomOutAction->setToolTip(tr("Zoom out (−), to see balls that left the box"));
    connect(m_zoomOutAction, &QAction::triggered, m_canvas, &Canvas::zoomOut);

    m_fitBoxAction = new QAction(tr("Fit the &Box"), this);
    m_fitBoxAction->setObjectName(QStringLiteral("fitBoxAction"));
    m_fitBoxAction->setShortcut(QKeySequence(Qt::Key_0));
    m_fitBoxAction->setToolTip(tr("Show the whole box, as large as it fits (0)"));
    connect(m_fitBoxAction, &QAction::triggered, m_canvas, &Canvas::fitBox);

    m_fitBallsAction = new QAction(tr("Fit &All Balls"), this);
    m_fitBallsAction->setObjectName(QStringLiteral("fitBallsAction"));
    m_fitBallsAction->setShortcut(QKeySequence(Qt::Key_A));
    m_fitBallsAction->setToolTip(tr("Zoom so that every ball is seen, in the box or out of it (A)"));
    connect(m_fitBallsAction, &QAction::triggered, m_canvas, &Canvas::fitAllBalls);

    m_followAction = new QAction(tr("&Follow the Selected Ball"), this);
    m_followAction->setObjectName(QStringLiteral("followAction"));
    m_followAction->setCheckable(true);
    m_followAction->setShortcut(QKeySequence(Qt::Key_F));
    m_followAction->setToolTip(tr("Keep the selected ball in the middle of the view as it moves (F)"));
    connect(m_followAction, &QAction::toggled, m_canvas, &Canvas::setFollowing);

    for (QAction* action : {m_zoomInAction, m_zoomOutAction, m_fitBoxAction, m_fitBallsAction, m_followAction})
        addAction(action); // their keys work on the stage too, where the menus are hidden
    // The actions follow the canvas: a pan or a fit stops following, the
    // zoom keys grey at the limits, and following needs a ball to follow.
    auto sync = [this] {
        m_followAction->setChecked(m_canvas->isFollowing());
        m_followAction->setEnabled(m_canvas->selectedBall() >= 0 || m_canvas->isFollowing());
        const double zoom = m_canvas->camera().zoom;
        m_zoomInAction->setEnabled(zoom < Camera::kMaxZoom);
        m_zoomOutAction->setEnabled(zoom > Camera::kMinZoom);
    };
    connect(m_canvas, &Canvas::cameraChanged, this, sync);
    connect(m_canvas, &Canvas::selectedBallChanged, this, sync);
    sync();
}

void MainWindow::createFileActions()
{
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

    m_traceCheck = new TraceCheck(m_controller, m_canvas, this);
    connect(m_traceCheck, &TraceCheck::error, this, &MainWindow::showError);

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
    // F11 everywhere: the platform's own full-screen key (QKeySequence::FullScreen)
    // is none at all under a bare X server, which left the stage view with no key.
    QList<QKeySequence> stageKeys{QKeySequence(Qt::Key_F11)};
    for (const QKeySequence& key : QKeySequence::keyBindings(QKeySequence::FullScreen))
        if (!stageKeys.contains(key))
            stageKeys << key;
    m_presentationAction->setShortcuts(stageKeys);
    m_presentationAction->setStatusTip(
        tr("The simulation fills the screen with large controls beside it, for a projector (F11; Escape leaves)"));
    m_presentationAction->setIconText(tr("Stage"));
    m_presentationAction->setIcon(style()->standardIcon(QStyle::SP_TitleBarMaxButton));
    connect(m_presentationAction, &QAction::toggled, this, &MainWindow::setPresentationMode);
    // The keys of the menus and toolbars the stage view hides work there too.
    addActions({m_presentationAction, m_previousAction, m_nextAction, m_playAction, m_stepAction, m_resetAction,
                m_slowerAction, m_fasterAction, m_quitAction, m_describeAction});

    // Text size: Ctrl with = (or +) and −, as in a web browser; the plain
    // keys zoom the stage (createCameraActions).
    m_largerTextAction = new QAction(tr("&Larger Text"), this);
    m_largerTextAction->setObjectName(QStringLiteral("largerTextAction"));
    m_largerTextAction->setShortcuts({QKeySequence(Qt::CTRL | Qt::Key_Equal), QKeySequence(Qt::CTRL | Qt::Key_Plus)});
    m_largerTextAction->setStatusTip(tr("Larger text in every panel and on the stage (Ctrl+=)"));
    connect(m_largerTextAction, &QAction::triggered, this, [this] { setTextScale(m_textScale * kTextScaleStep); });
    m_smallerTextAction = new QAction(tr("S&maller Text"), this);
    m_smallerTextAction->setObjectName(QStringLiteral("smallerTextAction"));
    m_smallerTextAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Minus));
    m_smallerTextAction->setStatusTip(tr("Smaller text in every panel and on the stage (Ctrl+−)"));
    connect(m_smallerTextAction, &QAction::triggered, this, [this] { setTextScale(m_textScale / kTextScaleStep); });
    m_normalTextAction = new QAction(tr("&Usual Text Size"), this);
    m_normalTextAction->setObjectName(QStringLiteral("normalTextAction"));
    m_normalTextAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_0));
    m_normalTextAction->setEnabled(false);
    connect(m_normalTextAction, &QAction::triggered, this, [this] { setTextScale(1.0); });
    addActions({m_largerTextAction, m_smallerTextAction, m_normalTextAction}); // on the stage too

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

void MainWindow::createUnitActions()
{
    // Pixels for the programming stages; SI (m, m/s, kg, N, J) for physics,
    // at a scale a lesson or the teacher sets. Only what is shown changes.
    auto* group = new QActionGroup(this);
    m_pixelUnitsAction = new QAction(tr("&Pixels"), group);
    m_pixelUnitsAction->setObjectName(QStringLiteral("pixelUnitsAction"));
    m_pixelUnitsAction->setCheckable(true);
    m_pixelUnitsAction->setChecked(true);
    m_pixelUnitsAction->setStatusTip(tr("Show px, px/s and mass units, as the program computes them"));
    m_siUnitsAction = new QAction(tr("&SI (m, kg, N, J)"), group);
    m_siUnitsAction->setObjectName(QStringLiteral("siUnitsAction"));
    m_siUnitsAction->setCheckable(true);
    m_siUnitsAction->setStatusTip(tr("Show metres, kilograms, newtons and joules at the scale set below"));
    connect(m_pixelUnitsAction, &QAction::triggered, this, [this] {
        DisplayUnits units = displayUnits();
        units.si = false;
        setUnits(units);
    });
    connect(m_siUnitsAction, &QAction::triggered, this, [this] {
        DisplayUnits units = displayUnits();
        units.si = true;
        setUnits(units);
    });
    m_unitScaleAction = new QAction(this);
    m_unitScaleAction->setObjectName(QStringLiteral("unitScaleAction"));
    m_unitScaleAction->setStatusTip(tr("How many pixels make a metre, and how many kilograms a mass unit"));
    connect(m_unitScaleAction, &QAction::triggered, this, &MainWindow::askUnitScale);
}

void MainWindow::askUnitScale()
{
    QDialog dialog(this);
    dialog.setObjectName(QStringLiteral("unitScaleDialog"));
    dialog.setWindowTitle(tr("SI Scale"));
    auto* form = new QFormLayout(&dialog);
    auto spin = [&dialog](const QString& name, double value, const QString& suffix) {
        auto* box = new QDoubleSpinBox(&dialog);
        box->setObjectName(name);
        box->setRange(DisplayUnits::kMinScale, DisplayUnits::kMaxScale);
        box->setDecimals(6);
        box->setValue(value);
        box->setSuffix(suffix);
        return box;
    };
    const DisplayUnits now = displayUnits();
    QDoubleSpinBox* px = spin(QStringLiteral("pxPerMetreSpin"), now.pxPerMetre, tr(" px"));
    QDoubleSpinBox* kg = spin(QStringLiteral("kgPerMassSpin"), now.kgPerMass, tr(" kg"));
    form->addRow(tr("1 m is"), px);
    form->addRow(tr("1 mass unit is"), kg);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    form->addRow(buttons);
    if (dialog.exec() != QDialog::Accepted)
        return;
    setUnits({.si = true, .pxPerMetre = px->value(), .kgPerMass = kg->value()});
}

void MainWindow::setUnits(const DisplayUnits& units)
{
    forcelab::setDisplayUnits(units);
    m_pixelUnitsAction->setChecked(!units.si);
    m_siUnitsAction->setChecked(units.si);
    m_unitScaleAction->setText(tr("SI &Scale: %1 px = 1 m, 1 mass unit = %2 kg…")
                                   .arg(humanNumber(units.pxPerMetre), humanNumber(units.kgPerMass)));
    // Everything that shows a number with a unit reads it again.
    if (m_parameters)
        m_parameters->refresh();
    if (m_ballTable)
        m_ballTable->model()->unitsChanged();
    if (m_inspectorDock)
        m_inspectorDock->refresh();
    if (m_plotsDock) {
        m_plotsDock->refreshCharts();
        if (m_plotsDock->energyBars()->isVisible()) // hidden, it keeps no account; it refreshes when shown
            m_plotsDock->energyBars()->refresh();
        m_plotsDock->quantityGraph()->refresh();
        if (m_plotsDock->speedHistogram() && m_plotsDock->speedHistogram()->isVisible())
            m_plotsDock->speedHistogram()->refresh();
    }
    if (m_stopwatchDock)
        m_stopwatchDock->unitsChanged();
    if (m_predictDock)
        m_predictDock->unitsChanged();
    for (StageSliders* sliders : findChildren<StageSliders*>())
        sliders->refresh();
    m_canvas->update();
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
    file->addAction(m_traceCheck->action());
    file->addSeparator();
    file->addAction(m_quitAction);

    // Undo / Redo come from the editor's stack (createDocks), above these.
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->setObjectName(QStringLiteral("editMenu"));
    edit->addSeparator();
    for (QAction* action : {m_addBallAction, m_duplicateBallAction, m_deleteBallAction, m_copyBallAction,
                            m_pasteBallAction})
        edit->addAction(action);

    QMenu* simulation = menuBar()->addMenu(tr("&Simulation"));
    simulation->setObjectName(QStringLiteral("simulationMenu"));
    simulation->addAction(m_playAction);
    simulation->addAction(m_stepAction);
    simulation->addAction(m_resetAction);
    simulation->addSeparator();
    simulation->addAction(m_slowerAction);
    simulation->addAction(m_fasterAction);
    simulation->addSeparator();
    simulation->addAction(m_describeAction);

    QMenu* lessons = menuBar()->addMenu(tr("&Lesson"));
    lessons->addAction(m_previousAction);
    lessons->addAction(m_nextAction);

    // Filled by setLessonTools with the panels the lesson's text uses; its
    // keys work on the stage too (the actions are the window's).
    m_toolsMenu = menuBar()->addMenu(tr("&Tools"));
    m_toolsMenu->setObjectName(QStringLiteral("toolsMenu"));

    m_accuracyMenu = menuBar()->addMenu(tr("&Accuracy"));
    m_accuracyMenu->setObjectName(QStringLiteral("accuracyMenu"));

    // Also filled by createToolBars and createDocks with their toggle actions.
    m_viewMenu = menuBar()->addMenu(tr("&View"));
    m_viewMenu->addAction(m_presentationAction);
    m_viewMenu->addAction(m_themeAction);
    m_viewMenu->addAction(m_largerTextAction);
    m_viewMenu->addAction(m_smallerTextAction);
    m_viewMenu->addAction(m_normalTextAction);
    m_viewMenu->addSeparator();
    for (QAction* action : {m_zoomInAction, m_zoomOutAction, m_fitBoxAction, m_fitBallsAction, m_followAction})
        m_viewMenu->addAction(action);
    m_viewMenu->addSeparator();
    m_unitsMenu = m_viewMenu->addMenu(tr("&Units"));
    m_unitsMenu->setObjectName(QStringLiteral("unitsMenu"));
    m_unitsMenu->addAction(m_pixelUnitsAction);
    m_unitsMenu->addAction(m_siUnitsAction);
    m_unitsMenu->addSeparator();
    m_unitsMenu->addAction(m_unitScaleAction);
    m_viewMenu->addMenu(m_overlayActions->menu());
    // Each language in its own words, so whoever cannot read the current one finds theirs.
    m_languageMenu = m_viewMenu->addMenu(tr("&Language"));
    m_languageMenu->setObjectName(QStringLiteral("languageMenu"));
    auto* languages = new QActionGroup(m_languageMenu);
    for (const Language& language : shippedLanguages()) {
        QAction* action = m_languageMenu->addAction(language.name);
        action->setObjectName(QStringLiteral("language_%1").arg(language.code));
        action->setCheckable(true);
        action->setChecked(language.code == currentLanguage());
        languages->addAction(action);
        connect(action, &QAction::triggered, this, [this, code = language.code] {
            if (code != currentLanguage())
                emit languageChosen(code);
        });
    }
    // The stage view hides the menu bar: its right-click menu ends with the
    // lesson's tools and what the stage shows.
    m_canvas->setContextMenus({m_toolsMenu, m_overlayActions->menu()});
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
    m_simulationToolBar->addAction(m_addBallAction);
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

} // namespace forcelab
