#pragma once
// The workbench window: the canvas in the middle, docks around it (Lesson,
// Parameters), one QAction per command shared by menu and toolbar, a status
// bar with the step's numbers, and layout plus last lesson kept in QSettings.

#include "lessons/lesson.h"

#include <QElapsedTimer>
#include <QFont>
#include <QMainWindow>
#include <QString>

#include <optional>

class QAction;
class QComboBox;
class QDockWidget;
class QLabel;
class QMenu;
class QTextBrowser;
class QTimer;
class QToolBar;

namespace forcelab {

class Canvas;
class ParameterPanel;
class SimulationController;

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

    SimulationController* controller() const { return m_controller; }
    Canvas* canvas() const { return m_canvas; }
    ParameterPanel* parameterPanel() const { return m_parameters; }

protected:
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;
    void changeEvent(QEvent* event) override;

private slots:
    void openLessonFile();
    void chooseLesson(int index);
    void updateStatus();
    void updatePlayAction(bool playing);
    void showError(const QString& message);
    void showTimeDropped(double seconds);
    void setPresentationMode(bool on);
    void about();

private:
    void createActions();
    void createMenus();
    void createToolBar();
    void createDocks();
    void createStatusBar();
    void readSettings();
    void writeSettings() const;
    void openInitialLesson(const QString& requested);
    void fillLessonChooser();
    void showLessonText();
    /// The loader's one-line errors in a dialog.
    void showLoadErrors(const QStringList& errors);

    SimulationController* m_controller = nullptr;
    Canvas* m_canvas = nullptr;
    ParameterPanel* m_parameters = nullptr;
    Lesson m_lesson;

    QAction* m_playAction = nullptr;
    QAction* m_stepAction = nullptr;
    QAction* m_resetAction = nullptr;
    QAction* m_openAction = nullptr;
    QAction* m_quitAction = nullptr;
    QAction* m_presentationAction = nullptr;
    QAction* m_aboutAction = nullptr;
    QMenu* m_viewMenu = nullptr;
    QToolBar* m_toolBar = nullptr;
    QComboBox* m_lessonChooser = nullptr;
    QDockWidget* m_lessonDock = nullptr;
    QDockWidget* m_parametersDock = nullptr;
    QTextBrowser* m_lessonText = nullptr;

    QLabel* m_timeLabel = nullptr;
    QLabel* m_fpsLabel = nullptr;
    QLabel* m_costLabel = nullptr;
    QLabel* m_ballsLabel = nullptr;
    QLabel* m_pairsLabel = nullptr;
    QLabel* m_droppedLabel = nullptr;
    QTimer* m_statusTimer = nullptr;
    QTimer* m_droppedTimer = nullptr;
    QElapsedTimer m_statusClock;
    qint64 m_lastFrames = 0;
    std::optional<QFont> m_normalFont; // before presentation mode
    QString m_lastLesson;    // from the settings
    QString m_lastDirectory; // of Open lesson…
};

} // namespace forcelab
