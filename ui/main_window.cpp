#include "main_window.h"

#include "canvas.h"
#include "parameter_panel.h"
#include "simulation_controller.h"

#include "lessons/lesson_loader.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QScrollArea>
#include <QScreen>
#include <QSettings>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QStyle>
#include <QTextBrowser>
#include <QTextDocument>
#include <QTimer>
#include <QToolBar>

namespace forcelab {

namespace {
const QString kGeometryKey = QStringLiteral("mainWindow/geometry");
const QString kStateKey = QStringLiteral("mainWindow/state");
const QString kLastLessonKey = QStringLiteral("lesson/last");
const QString kDirectoryKey = QStringLiteral("lesson/directory");
} // namespace

MainWindow::MainWindow(const QString& lesson, QWidget* parent)
    : QMainWindow(parent)
{
    m_controller = new SimulationController(this);
    m_controller->setSuspended(true); // until the window is shown
    m_canvas = new Canvas(m_controller, this);
    setCentralWidget(m_canvas);

    createActions();
    createMenus();
    createToolBar();
    createDocks();
    createStatusBar();
    readSettings();
    openInitialLesson(lesson);
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
    m_stepAction->setStatusTip(tr("Pause and advance by one time step dt"));
    connect(m_stepAction, &QAction::triggered, m_controller, &SimulationController::stepOnce);

    m_resetAction = new QAction(style()->standardIcon(QStyle::SP_BrowserReload), tr("&Reset"), this);
    m_resetAction->setObjectName(QStringLiteral("resetAction"));
    m_resetAction->setShortcut(Qt::Key_R);
    m_resetAction->setStatusTip(tr("Start the lesson again with its own values"));
    connect(m_resetAction, &QAction::triggered, m_controller, &SimulationController::reset);

    m_openAction = new QAction(style()->standardIcon(QStyle::SP_DialogOpenButton), tr("&Open Lesson…"), this);
    m_openAction->setObjectName(QStringLiteral("openAction"));
    m_openAction->setShortcut(QKeySequence::Open);
    m_openAction->setStatusTip(tr("Open a lesson file from disk"));
    connect(m_openAction, &QAction::triggered, this, &MainWindow::openLessonFile);

    m_quitAction = new QAction(tr("&Quit"), this);
    m_quitAction->setObjectName(QStringLiteral("quitAction"));
    m_quitAction->setShortcut(QKeySequence::Quit);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);

    m_presentationAction = new QAction(tr("&Presentation Mode"), this);
    m_presentationAction->setObjectName(QStringLiteral("presentationAction"));
    m_presentationAction->setCheckable(true);
    m_presentationAction->setShortcut(QKeySequence::FullScreen);
    m_presentationAction->setStatusTip(tr("Full screen with larger text and thicker lines, for a projector"));
    connect(m_presentationAction, &QAction::toggled, this, &MainWindow::setPresentationMode);

    m_aboutAction = new QAction(tr("&About ForceLab"), this);
    connect(m_aboutAction, &QAction::triggered, this, &MainWindow::about);
}

void MainWindow::createMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(m_openAction);
    file->addSeparator();
    file->addAction(m_quitAction);

    QMenu* simulation = menuBar()->addMenu(tr("&Simulation"));
    simulation->addAction(m_playAction);
    simulation->addAction(m_stepAction);
    simulation->addAction(m_resetAction);

    // Also filled by createDocks and createToolBar with their toggle actions.
    m_viewMenu = menuBar()->addMenu(tr("&View"));
    m_viewMenu->addAction(m_presentationAction);
    m_viewMenu->addSeparator();

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(m_aboutAction);
}

void MainWindow::createToolBar()
{
    m_toolBar = addToolBar(tr("Simulation"));
    m_toolBar->setObjectName(QStringLiteral("simulationToolBar"));
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_toolBar->addAction(m_playAction);
    m_toolBar->addAction(m_stepAction);
    m_toolBar->addAction(m_resetAction);
    m_toolBar->addSeparator();
    m_toolBar->addWidget(new QLabel(tr(" Lesson: "), m_toolBar));
    m_lessonChooser = new QComboBox(m_toolBar);
    m_lessonChooser->setObjectName(QStringLiteral("lessonChooser"));
    m_lessonChooser->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_lessonChooser->setFocusPolicy(Qt::ClickFocus);
    fillLessonChooser();
    connect(m_lessonChooser, &QComboBox::activated, this, &MainWindow::chooseLesson);
    m_toolBar->addWidget(m_lessonChooser);
    m_toolBar->addAction(m_openAction);
    m_viewMenu->addAction(m_toolBar->toggleViewAction());
}

void MainWindow::createDocks()
{
    m_lessonText = new QTextBrowser;
    m_lessonText->setObjectName(QStringLiteral("lessonText"));
    m_lessonText->setOpenExternalLinks(true);
    m_lessonDock = new QDockWidget(tr("Lesson"), this);
    m_lessonDock->setObjectName(QStringLiteral("lessonDock"));
    m_lessonDock->setWidget(m_lessonText);
    addDockWidget(Qt::LeftDockWidgetArea, m_lessonDock);

    m_parameters = new ParameterPanel(m_controller);
    auto* scroll = new QScrollArea;
    scroll->setWidget(m_parameters);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_parametersDock = new QDockWidget(tr("Parameters"), this);
    m_parametersDock->setObjectName(QStringLiteral("parametersDock"));
    m_parametersDock->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, m_parametersDock);

    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_lessonDock->toggleViewAction());
    m_viewMenu->addAction(m_parametersDock->toggleViewAction());
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
    m_fpsLabel = label(QStringLiteral("fpsLabel"), tr("Frames drawn per second, and the time to draw one"));
    m_costLabel = label(QStringLiteral("costLabel"), tr("Wall-clock time of the last simulation step"));
    m_ballsLabel = label(QStringLiteral("ballsLabel"), tr("Number of balls"));
    m_pairsLabel = label(QStringLiteral("pairsLabel"),
                         tr("Ball pairs tested for contact in the last step, and the contacts found"));

    connect(m_controller, &SimulationController::errorOccurred, this, &MainWindow::showError);
    connect(m_controller, &SimulationController::timeDropped, this, &MainWindow::showTimeDropped);

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
    const QSettings settings;
    const QByteArray geometry = settings.value(kGeometryKey).toByteArray();
    if (geometry.isEmpty() || !restoreGeometry(geometry)) {
        const QRect available = screen() ? screen()->availableGeometry() : QRect(0, 0, 1400, 900);
        resize(std::min(1400, available.width() * 9 / 10), std::min(900, available.height() * 9 / 10));
    }
    restoreState(settings.value(kStateKey).toByteArray());
    m_lastLesson = settings.value(kLastLessonKey).toString();
    m_lastDirectory = settings.value(kDirectoryKey).toString();
}

void MainWindow::writeSettings() const
{
    QSettings settings;
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kStateKey, saveState());
    if (!m_lesson.source.isEmpty())
        settings.setValue(kLastLessonKey, m_lesson.source);
    settings.setValue(kDirectoryKey, m_lastDirectory);
}

void MainWindow::openInitialLesson(const QString& requested)
{
    if (!requested.isEmpty() && openLesson(requested))
        return;
    // The last lesson quietly: a file that has gone away is no reason for a dialog.
    if (requested.isEmpty() && !m_lastLesson.isEmpty()) {
        LoadResult last = LessonLoader::load(m_lastLesson);
        if (last.ok() && setLesson(*last.lesson))
            return;
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
        showError(first.errors.value(0));
}

bool MainWindow::openLesson(const QString& pathOrId)
{
    LoadResult result = LessonLoader::load(pathOrId);
    if (!result.ok()) {
        showLoadErrors(result.errors);
        return false;
    }
    return setLesson(*result.lesson);
}

bool MainWindow::setLesson(const Lesson& lesson)
{
    if (m_controller->setScene(lesson.scene))
        return false; // the controller has signalled the error
    m_lesson = lesson;
    m_canvas->setOverlays(Overlays::fromNames(lesson.overlays));
    m_canvas->setSelectedBall(-1);
    setWindowTitle(lesson.title.isEmpty() ? tr("ForceLab") : tr("%1 — ForceLab").arg(lesson.title));
    showLessonText();
    {
        const QSignalBlocker block(m_lessonChooser);
        m_lessonChooser->setCurrentIndex(m_lessonChooser->findData(lesson.source));
    }
    m_controller->play();
    return true;
}

void MainWindow::fillLessonChooser()
{
    m_lessonChooser->clear();
    for (const QString& file : LessonLoader::builtInFiles()) {
        const LoadResult result = LessonLoader::load(file);
        const QString name = QFileInfo(file).completeBaseName();
        const QString text = result.ok()
            ? QStringLiteral("%1  %2").arg(result.lesson->stage, 2, 10, QLatin1Char('0')).arg(result.lesson->title)
            : name;
        m_lessonChooser->addItem(text, result.ok() ? result.lesson->source : file);
    }
}

void MainWindow::chooseLesson(int index)
{
    const QString source = m_lessonChooser->itemData(index).toString();
    if (source.isEmpty() || source == m_lesson.source)
        return;
    if (!openLesson(source)) {
        const QSignalBlocker block(m_lessonChooser);
        m_lessonChooser->setCurrentIndex(m_lessonChooser->findData(m_lesson.source));
    }
}

void MainWindow::showLessonText()
{
    QString html = QStringLiteral("<h2>%1</h2>").arg(m_lesson.title.toHtmlEscaped());
    if (m_lesson.stage > 0)
        html += QStringLiteral("<p style='color:#5a6270'>%1</p>").arg(tr("Stage %1").arg(m_lesson.stage));
    if (Qt::mightBeRichText(m_lesson.text)) {
        html += m_lesson.text;
    } else {
        for (const QString& paragraph : m_lesson.text.split(QStringLiteral("\n\n"), Qt::SkipEmptyParts))
            html += QStringLiteral("<p>%1</p>").arg(paragraph.toHtmlEscaped());
    }
    if (!m_lesson.challenges.isEmpty()) {
        html += QStringLiteral("<h3>%1</h3><ul>").arg(tr("Try this"));
        for (const QString& challenge : m_lesson.challenges)
            html += QStringLiteral("<li style='margin-bottom:6px'>%1</li>").arg(challenge.toHtmlEscaped());
        html += QStringLiteral("</ul>");
    }
    m_lessonText->setHtml(html);
}

void MainWindow::showLoadErrors(const QStringList& errors)
{
    QMessageBox box(QMessageBox::Warning, tr("Cannot open lesson"),
                    tr("The lesson could not be opened; the running lesson goes on."), QMessageBox::Ok, this);
    box.setInformativeText(errors.join(QLatin1Char('\n')));
    box.exec();
}

void MainWindow::openLessonFile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Lesson"), m_lastDirectory,
                                                      tr("Lesson files (*.json);;All files (*)"));
    if (path.isEmpty())
        return;
    m_lastDirectory = QFileInfo(path).absolutePath();
    const LoadResult result = LessonLoader::loadFile(path);
    if (!result.ok()) {
        showLoadErrors(result.errors);
        return;
    }
    setLesson(*result.lesson);
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
    m_playAction->setStatusTip(playing ? tr("Pause the simulation") : tr("Run the simulation"));
}

void MainWindow::setPresentationMode(bool on)
{
    // Larger text everywhere and thicker lines on the canvas: readable from
    // the back of a classroom.
    if (on && !m_normalFont)
        m_normalFont = font();
    QFont f = m_normalFont.value_or(font());
    if (on)
        f.setPointSizeF(f.pointSizeF() * 1.4);
    setFont(f);
    m_canvas->setLineScale(on ? 1.6 : 1.0);
    if (on)
        showFullScreen();
    else
        showNormal();
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

void MainWindow::closeEvent(QCloseEvent* event)
{
    writeSettings();
    event->accept();
}

void MainWindow::showEvent(QShowEvent* event)
{
    QMainWindow::showEvent(event);
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
