#pragma once
// The speeds of the balls as a histogram (how many balls in each speed bin
// of a round width) with the 2D Maxwell–Boltzmann curve of the same energy
// drawn over it, scaled to counts: N Δv f(v) with
//     f(v) = (m v / kT) exp(−m v² / 2kT),   kT = the balls' mean kinetic energy
// (in 2D a ball has two degrees of freedom, ½kT each, so ⟨½mv²⟩ = kT). Balls
// of different masses each follow their own curve with the same kT; the
// curve is then their sum.
//
// A self-contained widget (the Plots dock shows it for the gas lesson; the
// stage can show it beside the box): it follows its SimulationController and
// redraws at most every kRedrawMs, only while shown.

#include <QChartView>
#include <QList>
#include <QPointF>
#include <QTimer>

class QLineSeries;
class QValueAxis;

namespace forcelab {

namespace sim {
struct BallState;
}

class SimulationController;

class SpeedHistogram : public QChartView {
    Q_OBJECT
public:
    /// `controller` is not owned and must outlive the widget.
    explicit SpeedHistogram(SimulationController* controller, QWidget* parent = nullptr);
    ~SpeedHistogram() override;

    static constexpr int kTargetBins = 20; ///< about this many bins (8 to 50: a round width, 1, 2 or 5 × 10^k px/s)
    static constexpr int kRedrawMs = 100;

    struct Histogram {
        int balls = 0;
        double binWidth = 0.0;  ///< px/s, 1, 2 or 5 × 10^k; bin k is [k Δv, (k+1) Δv)
        QList<double> counts;   ///< balls per bin
        /// Balls per bin the curve expects: N × its integral over the bin (closed form).
        QList<double> expected;
        QList<QPointF> curve;   ///< (speed px/s, N Δv f(v)) on a fine grid over the bins
        double kT = 0.0;        ///< mass·px²/s², the balls' mean kinetic energy per ball
        /// ½ Σ |counts − expected| / N: 0 when the balls follow the curve, 1 when they miss it.
        double totalVariation() const;
    };
    static Histogram compute(const sim::BallState& balls, int targetBins = kTargetBins, int curvePoints = 121);

    /// What the chart shows now (as of the last refresh).
    const Histogram& shown() const { return m_shown; }
    QLineSeries* countSeries() const { return m_counts; }
    QLineSeries* curveSeries() const { return m_curve; }
    QValueAxis* speedAxis() const { return m_speedAxis; }
    QValueAxis* countAxis() const { return m_countAxis; }

public slots:
    void refresh();

protected:
    void showEvent(QShowEvent* event) override;

private:
    SimulationController* m_controller; // not owned
    QTimer m_redraw;
    Histogram m_shown;
    QLineSeries* m_counts = nullptr;
    QLineSeries* m_curve = nullptr;
    QValueAxis* m_speedAxis = nullptr;
    QValueAxis* m_countAxis = nullptr;
};

} // namespace forcelab
