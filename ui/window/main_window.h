#pragma once
// The workbench window: the stage (stage_view.h: the canvas, and in the stage
// view the bar a class reads) in the middle and the docks around it (Lessons,
// Parameters, Plots, Inspector, Predict, Stopwatch, Force editor, Accuracy,
// Code), one QAction per command shared by menu and toolbar, a status bar
// with the step's numbers, and layout plus last lesson kept in QSettings.

#include "lessons/lesson.h"
#include "lessons/lesson_derive.h"
#include "ui/drawing/display_units.h"
#include "ui/drawing/world_painter.h"

#include <QElapsedTimer>
#include <QFont>
#include <QMainWindow>
#include <QString>

#include <optional>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QTimer;
class QToolBar;

namespace forcelab {

class AccuracyDock;
class CodeDock;
class StudentCodeDock;
class StepApartDock;
class SettingsEditor;
class StageView;
class OverlayActions;
class Canvas;
class BallTable;
class InspectorDock;
class LessonsDock;
class ParameterPanel;
class PlotsDock;
class PredictDock;
class StopwatchDock;
class ForceEditorDock;
class SimulationController;
class TrajectoryExport;
class TraceCheck;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    /// Opens `lesson` (a file path or a built-in id) when given; otherwise
    /// the last lesson from the settings, otherwise the first built-in one.
    explicit MainWindow(const QString& lesson = {}, QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Loads and starts a lesson. On errors shows them in a dialog, keeps the
    /// running lesson and returns false.
    bool openLesson(const QString& pathOrId);
    /// Starts a lesson already in memory. Returns false (with the error in the
    /// status bar) when its scene is refused.
    bool setLesson(const Lesson& lesson);
    const Lesson& lesson() const { return m_lesson; }

    /// The running scene as a lesson: the lesson's text with the live
    /// settings, every current ball listed and no random spawning.
    Lesson currentSceneAsLesson() const;
    /// Saves the running scene to `path` as a new lesson made from the one on
    /// screen (lessons::deriveLesson: the new title and text, only the claims
    /// and questions that still hold; the file's name as its id when valid).
    /// The status bar says what was dropped. On failure shows the error in
    /// the status bar and returns false. Without choices: the Save dialog's
    /// starting ones (lessons::defaultDeriveChoices).
    bool saveLessonTo(const QString& path, const lessons::DeriveChoices& choices);
    bool saveLessonTo(const QString& path);
    /// Writes a picture of the stage to `path` (PNG): laid out as large as
    /// the screen would show it, at the screen's device pixel ratio times `scale`.
    bool saveScreenshotTo(const QString& path, double scale = 1.0);
    /// Logical size of that picture: the canvas grown to fill the screen.
    QSize pictureSize() const;
    /// Where the Open dialog starts: the installed lessons, or the source tree's.
    static QString lessonsFolder();
    /// The projector theme (View menu; always on in the stage view).
    void setProjectorTheme(bool on);
    /// The teacher's text size, a factor of the usual one
    /// (kSmallestTextScale to kLargestTextScale): every panel, the stage bar
    /// and the canvas's labels; remembered.
    void setTextScale(double scale);
    /// Shows the lesson tool `name` (lesson_tools.h): its panel, or on the
    /// stage a panel floating over it; on the stage again, hides it.
    void showTool(const QString& name);
    double textScale() const { return m_textScale; }
    /// The units every panel, readout and table shows (View → Units): pixels,
    /// or SI at a scale; a lesson's `units` set them when it opens.
    void setUnits(const DisplayUnits& units);

    /// Shows the Balls table (the dock, or under the box in the stage view)
    /// with ball `index` selected (−1: none), its keyboard focus in the table.
    void editBall(int index);

    /// Whether the stage view is on.
    bool isStaged() const;
    /// The window's geometry and the docks' layout as the normal (not the
    /// stage) view has them: what a rebuilt window restores.
    QByteArray savedGeometry() const;
    QByteArray savedDockState() const;

    SimulationController* controller() const { return m_controller; }
    /// Says what is on the stage (Simulation → Describe the Scene, D; and
    /// after every pause): the canvas's accessible description, announced to
    /// a screen reader, and the status bar (on the stage, a note over it).
    void describeScene();
    QString sceneDescription() const { return m_sceneDescription; }

signals:
    /// View → Language: the user picked `code` (language.h); the window host
    /// applies it and rebuilds the window in it.
    void languageChosen(const QString& code);

public:
    Canvas* canvas() const { return m_canvas; }
    ParameterPanel* parameterPanel() const { return m_parameters; }
    LessonsDock* lessonsDock() const { return m_lessonsDock; }
    InspectorDock* inspectorDock() const { return m_inspectorDock; }
    PlotsDock* plotsDock() const { return m_plotsDock; }
    AccuracyDock* accuracyDock() const { return m_accuracyDock; }
    CodeDock* codeDock() const { return m_codeDock; }
    StudentCodeDock* studentCodeDock() const { return m_studentCodeDock; }
    StepApartDock* stepApartDock() const { return m_stepApartDock; }
    TraceCheck* traceCheck() const { return m_traceCheck; }

protected:
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;
    void changeEvent(QEvent* event) override;

public:
    /// Tells why a lesson could not be opened: the first problems in the
    /// dialog, all of them under "Show Details…" (a scrolling list), so a
    /// file with a hundred problems never makes a dialog taller than the screen.
    void showLoadErrors(const QStringList& errors);

private slots:
    void openLessonFile();
    void saveLessonFile();
    void saveScreenshot(double scale);
    void exportTrajectory();
    void exportHandbook();
    void chooseLesson(const QString& source);
    void previousLesson();
    void nextLesson();
    void resetLesson();
    void slower();
    void faster();
    void updateStatus();
    void updatePlayAction(bool playing);
    void showError(const QString& message);
    void showTimeDropped(double seconds);
    void setPresentationMode(bool on);
    void applyCanvasLook();
    void setLessonTools(const QStringList& tools);
    QDockWidget* toolDock(const QString& name) const;
    void useCompactDocks();
    void focusFirstControl(QDockWidget* dock);
    void about();

private:
    void createSimulationActions();
    /// Add, delete, duplicate, copy and paste a ball (the canvas does them).
    void createBallActions();
    void createTimeActions();
    void createCameraActions();
    void createFileActions();
    /// View → Units: Pixels, SI and the SI scale.
    void createUnitActions();
    /// Asks for the SI scale (px per m, kg per mass unit) and applies it in SI.
    void askUnitScale();
    void createMenus();
    void createToolBars();
    void createDocks();
    void createStatusBar();
    void readSettings();
    void writeSettings() const;
    void openInitialLesson(const QString& requested);
    /// The loader's one-line errors in a dialog.
    /// Multiplies the time scale by `factor` within the controller's limits (an undo step).
    void scaleTime(double factor);
    QString suggestedFileName(const QString& extension) const;

    SimulationController* m_controller = nullptr;
    Canvas* m_canvas = nullptr;
    ParameterPanel* m_parameters = nullptr;
    LessonsDock* m_lessonsDock = nullptr;
    InspectorDock* m_inspectorDock = nullptr;
    QDockWidget* m_ballsDock = nullptr;
    BallTable* m_ballTable = nullptr;
    QDockWidget* m_parametersDock = nullptr;
    PlotsDock* m_plotsDock = nullptr;
    PredictDock* m_predictDock = nullptr;
    StopwatchDock* m_stopwatchDock = nullptr;
    ForceEditorDock* m_forceEditorDock = nullptr;
    AccuracyDock* m_accuracyDock = nullptr;
    CodeDock* m_codeDock = nullptr;
    StudentCodeDock* m_studentCodeDock = nullptr;
    StepApartDock* m_stepApartDock = nullptr;
    SettingsEditor* m_editor = nullptr; // every control edits through it; owns the undo stack
    StageView* m_stage = nullptr;       // the central widget: the canvas and the stage view's bar
    OverlayActions* m_overlayActions = nullptr;
    QByteArray m_normalGeometry; // before the stage view
    QByteArray m_normalDocks;
    QAction* m_handbookAction = nullptr;
    TrajectoryExport* m_trajectory = nullptr;
    TraceCheck* m_traceCheck = nullptr; // File → Check a Student's Trace
    Lesson m_lesson;

    QAction* m_playAction = nullptr;
    QAction* m_stepAction = nullptr;
    QAction* m_stepBackAction = nullptr;
    QAction* m_resetAction = nullptr;
    QAction* m_slowerAction = nullptr;
    QAction* m_fasterAction = nullptr;
    QAction* m_undoAction = nullptr;
    // Ball edits on the canvas (createBallActions).
    QAction* m_addBallAction = nullptr;
    QAction* m_deleteBallAction = nullptr;
    QAction* m_duplicateBallAction = nullptr;
    QAction* m_copyBallAction = nullptr;
    QAction* m_pasteBallAction = nullptr;
    QAction* m_redoAction = nullptr;
    // The view's zoom and follow (createCameraActions).
    QAction* m_zoomInAction = nullptr;
    QAction* m_zoomOutAction = nullptr;
    QAction* m_fitBoxAction = nullptr;
    QAction* m_fitBallsAction = nullptr;
    QAction* m_followAction = nullptr;
    QAction* m_openAction = nullptr;
    QAction* m_saveAction = nullptr;
    QAction* m_screenshotAction = nullptr;
    QAction* m_recordAction = nullptr;
    QAction* m_exportAction = nullptr;
    QAction* m_previousAction = nullptr;
    QAction* m_nextAction = nullptr;
    QAction* m_quitAction = nullptr;
    QAction* m_presentationAction = nullptr;
    QAction* m_describeAction = nullptr;
    QString m_sceneDescription;
    QAction* m_themeAction = nullptr;
    QAction* m_pixelUnitsAction = nullptr; // View → Units, one of the two checked
    QAction* m_siUnitsAction = nullptr;
    QAction* m_unitScaleAction = nullptr;
    QMenu* m_unitsMenu = nullptr;
    QMenu* m_languageMenu = nullptr;
    QMenu* m_toolsMenu = nullptr; // the lesson's tools, keys 1, 2, …
    QAction* m_largerTextAction = nullptr;
    QAction* m_smallerTextAction = nullptr;
    QAction* m_normalTextAction = nullptr;
    double m_textScale = 1.0;
    /// Below this window width (px) the first layout puts the lesson in a tab beside the Parameters.
    static constexpr int kCompactWidth = 1400;
    bool m_dockLayoutChosen = false; // a saved layout was restored, or the first show chose one
    QAction* m_screenshotDoubleAction = nullptr;
    QAction* m_aboutAction = nullptr;
    QMenu* m_viewMenu = nullptr;
    QMenu* m_accuracyMenu = nullptr; // filled by createDocks with the Accuracy dock's actions
    QToolBar* m_simulationToolBar = nullptr;
    QToolBar* m_fileToolBar = nullptr;

    QLabel* m_timeLabel = nullptr;
    QLabel* m_speedLabel = nullptr;
    QLabel* m_fpsLabel = nullptr;
    QLabel* m_costLabel = nullptr;
    QLabel* m_ballsLabel = nullptr;
    QLabel* m_pairsLabel = nullptr;
    QLabel* m_droppedLabel = nullptr;
    QTimer* m_statusTimer = nullptr;
    QTimer* m_droppedTimer = nullptr;
    QElapsedTimer m_statusClock;
    qint64 m_lastFrames = 0;
    QString m_lastLesson;    // from the settings
    QStringList m_settingsProblems; // values in the settings file that were refused, for the status bar
    QString m_lastDirectory; // of Open / Save lesson, screenshots and exports
};

} // namespace forcelab
