#pragma once
// The Accuracy dock: how far the integrator is from the truth, live and
// measured.
//
// - Drift since the last reset: the total energy's change with everything
//   done on purpose (drag, wind, walls, collisions, the pointer, edits) booked
//   apart by the world's accounting, so what is left is the integrator's own
//   error; the same for momentum; force evaluations per simulated second and
//   the cost of a step. The dock switches the accounting on while it is shown.
// - The ghost: the same scene run beside the live one by another integrator or
//   step (default: the reference, ias15), or a "sensitivity twin" nudged by
//   1e-10 px; the canvas draws it as outlines, the dock plots the separation.
// - "Measure the trade-off": the work-precision study of the current scene in
//   the background (error against cost, log-log, one line per integrator), and
//   the convergence check (dt, dt/2, dt/4, dt/8 and the fitted order).

#include "sim/studies/work_precision.h"

#include <QDockWidget>
#include <QFuture>
#include <QFutureWatcher>

#include <atomic>
#include <limits>
#include <vector>

class QAction;
class QChart;
class QChartView;
class QCheckBox;
class QComboBox;
class QLabel;
class QLineSeries;
class QLogValueAxis;
class QProgressBar;
class QPushButton;
class QValueAxis;

namespace forcelab {

class Canvas;
class SimulationController;

class AccuracyDock : public QDockWidget {
    Q_OBJECT
public:
    /// `controller` and `canvas` are not owned and must outlive the dock.
    AccuracyDock(SimulationController* controller, Canvas* canvas, QWidget* parent = nullptr);
    ~AccuracyDock() override;

    /// The action that starts the trade-off study (for the menu).
    QAction* tradeOffAction() const { return m_tradeOffAction; }
    QAction* convergenceAction() const { return m_convergenceAction; }

    /// Simulated time each run of a study covers, s (rounded up to whole steps).
    void setStudyDuration(double seconds) { m_studyDuration = seconds; }
    double studyDuration() const { return m_studyDuration; }
    /// The integrators of the trade-off chart, one line each.
    static const std::vector<sim::IntegratorKind>& tradeOffIntegrators();

    /// From the start of a study until its result is shown.
    bool isMeasuring() const { return m_measuring; }
    /// The running (or last) study, for tests to wait on.
    QFuture<sim::WorkPrecisionResult> studyFuture() const { return m_watcher.future(); }
    /// The last finished study (empty runs when none or cancelled before any).
    const sim::WorkPrecisionResult& lastStudy() const { return m_lastStudy; }
    /// The fitted order of the last convergence check (NaN before one).
    double lastOrder() const { return m_lastOrder; }
    /// The "draw the ghost" switch (the canvas's ghost overlay).
    bool isGhostDrawn() const;
    QChart* tradeOffChart() const { return m_tradeOffChart; }
    QChart* separationChart() const { return m_separationChart; }

public slots:
    void measureTradeOff();
    void measureConvergence();
    void cancelMeasurement();
    /// Restarts the books of the accounting at the current state.
    void restartDrift();

private:
    QWidget* createGhostTab();
    QWidget* createTradeOffTab();
    enum class Study { TradeOff, Convergence };
    void createDriftGroup(QWidget* page);
    void updateNumbers();
    void applyGhost();
    void onGhostChanged();
    void recordSeparation();
    void startStudy(Study kind);
    void studyFinished();
    void showTradeOff(const sim::WorkPrecisionResult& result);
    sim::Scene currentScene() const;

    SimulationController* m_controller; // not owned
    Canvas* m_canvas;                    // not owned
    QLabel* m_energyDrift = nullptr;
    QLabel* m_booked = nullptr;
    QLabel* m_momentumDrift = nullptr;
    QLabel* m_evaluationsPerSecond = nullptr;
    QLabel* m_stepCost = nullptr;
    QComboBox* m_ghostMode = nullptr;
    QComboBox* m_ghostIntegrator = nullptr;
    QComboBox* m_ghostDivider = nullptr;
    QCheckBox* m_ghostShown = nullptr;
    QLabel* m_separation = nullptr;
    QChart* m_separationChart = nullptr;
    QLineSeries* m_separationSeries = nullptr;
    QValueAxis* m_separationTime = nullptr;
    QLogValueAxis* m_separationAxis = nullptr;
    QAction* m_tradeOffAction = nullptr;
    QAction* m_convergenceAction = nullptr;
    QPushButton* m_cancel = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_studyStatus = nullptr;
    QChart* m_tradeOffChart = nullptr;
    QChartView* m_tradeOffView = nullptr;

    QFutureWatcher<sim::WorkPrecisionResult> m_watcher;
    std::atomic<bool> m_cancelFlag{false};
    Study m_study = Study::TradeOff;
    bool m_measuring = false;
    sim::IntegratorKind m_convergenceIntegrator = sim::IntegratorKind::Euler;
    sim::WorkPrecisionResult m_lastStudy;
    double m_lastOrder = std::numeric_limits<double>::quiet_NaN();
    double m_studyDuration = 2.0; // s
};

} // namespace forcelab
