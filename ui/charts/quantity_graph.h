#pragma once
// A graph of one quantity against time — position, velocity, speed,
// energy or momentum of one ball or of all balls together, chosen from two
// combo boxes — with the lesson's theory drawn over it, dashed, where the
// theory holds:
//   * one ball under constant gravity alone (or no force at all):
//     x = x₀ + v₀t + ½gt², v = v₀ + gt and the energies and momenta of that
//     motion, until the ball's velocity leaves v₀ + gt (its own first
//     bounce off a wall or another ball);
//   * all balls, total energy, when every force that acts has a potential
//     (nothing takes energy away), until the first bounce anywhere in the
//     box (an impact may take energy away): constant E₀.
// The theory starts where the recording starts (a new choice, a new scene, a
// reset or a seek start both again). Samples: one per controller frame in
// which the world's time moved on, at most kMaxSamples; redrawn at most
// every kRedrawMs and only while shown.

#include <QPointF>
#include <QString>
#include <QTimer>
#include <QWidget>

#include <optional>
#include <vector>

class QChartView;
class QComboBox;
class QLineSeries;
class QValueAxis;

namespace forcelab {

namespace sim {
class World;
}

class SimulationController;

class QuantityGraph : public QWidget {
    Q_OBJECT
public:
    enum class Quantity { X, Y, Vx, Vy, Speed, Kinetic, Potential, Total, MomentumX, MomentumY };
    static constexpr int kQuantities = 10;
    static constexpr int kAllBalls = -1; ///< ball(): the totals of all balls
    static constexpr std::size_t kMaxSamples = 20000;
    static constexpr int kMaxPoints = 1000; ///< points per series on screen
    static constexpr int kRedrawMs = 100;

    /// `controller` is not owned and must outlive the widget.
    explicit QuantityGraph(SimulationController* controller, QWidget* parent = nullptr);
    ~QuantityGraph() override;

    void setQuantity(Quantity quantity);
    Quantity quantity() const { return m_quantity; }
    /// The ball graphed (index into the world's balls), or kAllBalls. The
    /// stage can follow its selection with it.
    void setBall(int index);
    int ball() const { return m_ball; }

    /// The value of `quantity` for ball `ball` (or kAllBalls) of `world`, in
    /// px, px/s, mass·px²/s² or mass·px/s. A ball's potential energy is its
    /// gravity energy m g h (h = −y, y down); the totals' is the world's.
    static double valueOf(const sim::World& world, Quantity quantity, int ball);

    /// The recorded (t, value) samples since the recording started.
    const std::vector<QPointF>& samples() const { return m_samples; }
    /// The theory's value at t, where it holds (from the first sample to the
    /// first bounce); nullopt elsewhere or when there is none.
    std::optional<double> theoryAt(double t) const;
    /// The theory in words as the legend says it ("theory: y₀ + v₀t + ½gt²"),
    /// empty when there is none.
    QString theoryName() const;
    /// s, the last sample where the theory held (before the first bounce), or +∞.
    double theoryEnd() const { return m_theoryEnd; }

    /// The chart series (tests, screenshots): points are values / shownFactor().
    QLineSeries* measuredSeries() const { return m_measured; }
    QLineSeries* theorySeries() const { return m_theory; }
    double shownFactor() const { return m_factor; }
    QComboBox* quantityBox() const { return m_quantityBox; }
    QComboBox* ballBox() const { return m_ballBox; }

public slots:
    /// Redraws the chart now (the timer calls it).
    void refresh();
    /// Starts the recording (and the theory) again from the world now.
    void restart();

protected:
    void showEvent(QShowEvent* event) override;

private:
    void onStepped();
    void fillBallBox();
    void startTheory();
    bool theoryStillHolds(const sim::World& world) const;

    SimulationController* m_controller; // not owned
    Quantity m_quantity = Quantity::Y;
    int m_ball = 0;
    std::vector<QPointF> m_samples;
    double m_lastTime = -1.0;
    QTimer m_redraw;
    double m_factor = 1.0;

    // The theory: constant acceleration g of one ball from (x₀, v₀) at t₀,
    // or constant total energy E₀ of all balls.
    enum class Theory { None, ConstantAcceleration, ConstantEnergy };
    Theory m_theoryKind = Theory::None;
    double m_t0 = 0.0, m_mass = 0.0, m_energy0 = 0.0;
    double m_x0[2] = {}, m_v0[2] = {}, m_g[2] = {};
    double m_theoryEnd = 0.0;
    long long m_bouncesAtStart = 0;

    QComboBox* m_quantityBox = nullptr;
    QComboBox* m_ballBox = nullptr;
    QChartView* m_view = nullptr;
    QLineSeries* m_measured = nullptr;
    QLineSeries* m_theory = nullptr;
    QValueAxis* m_timeAxis = nullptr;
    QValueAxis* m_valueAxis = nullptr;
};

} // namespace forcelab
