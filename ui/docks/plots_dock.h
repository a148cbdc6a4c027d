#pragma once
// The Plots dock: energy (kinetic, potential, total), momentum (|p|, px, py)
// and the cost of a step over the last kWindowSeconds of simulated time, the
// energies now as bars (ui/charts/energy_bars.h), any quantity of a ball or
// of all balls against time with its theory (ui/charts/quantity_graph.h), and
// for the gas lesson the histogram of speeds with the 2D Maxwell–Boltzmann
// curve of the same mean energy (ui/charts/speed_histogram.h).
//
// One sample per controller frame in which the world's time moved on, so a
// paused simulation adds nothing and the plots stand still. Samples are kept
// in a ring; the charts are redrawn at most every kRedrawMs and only while the
// dock is visible, each series with at most kMaxPoints points (decimated).

#include <QDockWidget>
#include <QList>
#include <QPointF>
#include <QTimer>

#include <deque>

class QTabWidget;
class QChartView;
class QLineSeries;
class QValueAxis;

namespace forcelab {

class EnergyBars;
class QuantityGraph;
class SpeedHistogram;
class SimulationController;

class PlotsDock : public QDockWidget {
    Q_OBJECT
public:
    /// `controller` is not owned and must outlive the dock.
    explicit PlotsDock(SimulationController* controller, QWidget* parent = nullptr);
    ~PlotsDock() override;

    struct Sample {
        double t = 0.0;         ///< s, simulated
        double kinetic = 0.0;   ///< energy units (mass px²/s²)
        double potential = 0.0;
        double total = 0.0;
        double px = 0.0, py = 0.0, p = 0.0; ///< mass px/s
        double stepMicros = 0.0; ///< µs, wall-clock cost of the last step of the frame
    };

    static constexpr double kWindowSeconds = 10.0; ///< s of simulated time shown
    static constexpr std::size_t kMaxSamples = 20000; ///< ring bound (very slow motion shortens the window)
    static constexpr int kMaxPoints = 1000;        ///< points per series on screen
    static constexpr int kRedrawMs = 100;

    const std::deque<Sample>& samples() const { return m_samples; }

    /// The "Energy bars" tab: the energies now as bars (ui/charts/energy_bars.h).
    EnergyBars* energyBars() const { return m_energyBars; }
    /// The "Graph" tab: any quantity against time with its theory (ui/charts/quantity_graph.h).
    QuantityGraph* quantityGraph() const { return m_quantityGraph; }
    /// The tabs (tests pick one to show).
    QTabWidget* tabs() const { return m_tabs; }

    /// Shows the speed-histogram tab (a lesson whose overlays name "histogram").
    void setHistogramShown(bool shown);
    bool isHistogramShown() const { return m_histogramShown; }

    enum class Series { Kinetic, Potential, Total, MomentumMagnitude, MomentumX, MomentumY, StepCost };
    /// The chart series (for tests and screenshots). Their points are the
    /// values divided by shownFactor(), the common factor the axis names.
    QLineSeries* series(Series which) const;
    double shownFactor(Series which) const;

    /// The "Speeds" tab (shown by setHistogramShown).
    SpeedHistogram* speedHistogram() const { return m_speedHistogram; }

public slots:
    /// Redraws the charts from the samples now (the timer calls it).
    void refreshCharts();
    void clearSamples();

private:
    void onStepped();
    void scheduleRefresh();
    QChartView* makeChart(const QString& title, const QList<QLineSeries*>& series, QValueAxis** xAxis,
                          QValueAxis** yAxis);

    SimulationController* m_controller; // not owned
    std::deque<Sample> m_samples;
    double m_lastTime = -1.0;
    bool m_histogramShown = false;
    QTimer m_redraw;
    // The common factor divided out of each chart's points.
    double m_energyFactor = 1.0, m_momentumFactor = 1.0, m_costFactor = 1.0;

    QTabWidget* m_tabs = nullptr;
    EnergyBars* m_energyBars = nullptr;
    QuantityGraph* m_quantityGraph = nullptr;
    QLineSeries* m_kinetic = nullptr;
    QLineSeries* m_potential = nullptr;
    QLineSeries* m_total = nullptr;
    QLineSeries* m_p = nullptr;
    QLineSeries* m_px = nullptr;
    QLineSeries* m_py = nullptr;
    QLineSeries* m_cost = nullptr;
    QValueAxis* m_energyX = nullptr;
    QValueAxis* m_energyY = nullptr;
    QValueAxis* m_momentumX = nullptr;
    QValueAxis* m_momentumY = nullptr;
    QValueAxis* m_costX = nullptr;
    QValueAxis* m_costY = nullptr;
    SpeedHistogram* m_speedHistogram = nullptr;
};

} // namespace forcelab
