#include "ui/charts/quantity_graph.h"
#include "ui/charts/chart_setup.h"

#include "ui/drawing/display_units.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/controls/readable_numbers.h"

#include "sim/forces/force_models.h"
#include "sim/world/world.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineSeries>
#include <QPainter>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace forcelab {

namespace {

using Quantity = QuantityGraph::Quantity;

QString quantityName(Quantity q)
{
    switch (q) {
    case Quantity::X: return QuantityGraph::tr("x position");
    case Quantity::Y: return QuantityGraph::tr("y position");
    case Quantity::Vx: return QuantityGraph::tr("velocity v_x");
    case Quantity::Vy: return QuantityGraph::tr("velocity v_y");
    case Quantity::Speed: return QuantityGraph::tr("speed");
    case Quantity::Kinetic: return QuantityGraph::tr("kinetic energy");
    case Quantity::Potential: return QuantityGraph::tr("potential energy");
    case Quantity::Total: return QuantityGraph::tr("total energy");
    case Quantity::MomentumX: return QuantityGraph::tr("momentum p_x");
    case Quantity::MomentumY: return QuantityGraph::tr("momentum p_y");
    }
    return {};
}

QString unitOf(Quantity q)
{
    switch (q) {
    case Quantity::X:
    case Quantity::Y: return QStringLiteral("px");
    case Quantity::Vx:
    case Quantity::Vy:
    case Quantity::Speed: return QStringLiteral("px/s");
    case Quantity::Kinetic:
    case Quantity::Potential:
    case Quantity::Total: return QStringLiteral("mass·px²/s²");
    case Quantity::MomentumX:
    case Quantity::MomentumY: return QStringLiteral("mass·px/s");
    }
    return {};
}

// The bounces so far: ball–wall and ball–ball.
long long bounces(const sim::World& world)
{
    return static_cast<long long>(world.totals().wallHits + world.totals().contacts);
}

} // namespace

namespace {

// What the graph can show of one ball or of all of them: a position, a
// velocity, the energies and a momentum.
struct State {
    sim::Vec2 x{0, 0}, v{0, 0}, p{0, 0}; // px, px/s, mass·px/s
    double kinetic = 0.0, potential = 0.0; // mass·px²/s²
};

double pick(const State& s, QuantityGraph::Quantity q)
{
    using Quantity = QuantityGraph::Quantity;
    switch (q) {
    case Quantity::X: return s.x.x();
    case Quantity::Y: return s.x.y();
    case Quantity::Vx: return s.v.x();
    case Quantity::Vy: return s.v.y();
    case Quantity::Speed: return s.v.norm();
    case Quantity::Kinetic: return s.kinetic;
    case Quantity::Potential: return s.potential;
    case Quantity::Total: return s.kinetic + s.potential;
    case Quantity::MomentumX: return s.p.x();
    case Quantity::MomentumY: return s.p.y();
    }
    return 0.0;
}

} // namespace

double QuantityGraph::valueOf(const sim::World& world, Quantity q, int ball)
{
    const sim::BallState& b = world.balls();
    State s;
    if (ball == kAllBalls) {
        // The potential energy can cost a sum over all pairs: only when asked.
        const bool energy = q == Quantity::Kinetic || q == Quantity::Potential || q == Quantity::Total;
        const sim::Energy e = energy ? world.energy() : sim::Energy{};
        s.p = world.momentum();
        // The totals' position and velocity are those of the centre of mass.
        const double m = b.mass.sum();
        if (b.size() > 0 && m > 0.0) {
            s.x = (b.position * b.mass) / m;
            s.v = s.p / m;
        }
        s.kinetic = e.kinetic;
        s.potential = e.potential;
        return pick(s, q);
    }
    if (ball < 0 || ball >= b.size())
        return std::numeric_limits<double>::quiet_NaN();
    s.x = b.position.col(ball);
    s.v = b.velocity.col(ball);
    const double m = b.mass[ball];
    s.p = m * s.v;
    // A ball's potential energy is gravity's alone (m g h).
    const sim::Vec2 g = world.settings().gravity.acting();
    s.kinetic = 0.5 * m * s.v.squaredNorm();
    s.potential = -m * g.dot(s.x);
    return pick(s, q);
}

QuantityGraph::QuantityGraph(SimulationController* controller, QWidget* parent)
    : QWidget(parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("quantityGraph"));
    m_quantityBox = new QComboBox;
    m_quantityBox->setObjectName(QStringLiteral("graphQuantity"));
    m_quantityBox->setAccessibleName(tr("Quantity to graph"));
    for (int k = 0; k < kQuantities; ++k)
        m_quantityBox->addItem(quantityName(static_cast<Quantity>(k)), k);
    m_quantityBox->setCurrentIndex(static_cast<int>(m_quantity));
    m_ballBox = new QComboBox;
    m_ballBox->setObjectName(QStringLiteral("graphBall"));
    m_ballBox->setAccessibleName(tr("Ball to graph"));

    auto* choice = new QHBoxLayout;
    choice->addWidget(m_quantityBox, 1);
    choice->addWidget(new QLabel(tr("of")));
    choice->addWidget(m_ballBox, 1);

    m_measured = new QLineSeries(this);
    m_measured->setName(tr("measured"));
    m_theory = new QLineSeries(this);
    QPen dashed(QColor(0xd9, 0x48, 0x0f), 2.0, Qt::DashLine);
    m_theory->setPen(dashed);
    m_measured->setPen(QPen(QColor(0x2a, 0x6f, 0xdb), 2.0));
    const LineChart chart = makeLineChart({m_measured, m_theory}, tr("time (s)"));
    m_timeAxis = chart.x;
    m_valueAxis = chart.y;
    m_view = new QChartView(chart.chart);
    m_view->setRenderHint(QPainter::Antialiasing);
    m_view->setMinimumSize(260, 180);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(choice);
    layout->addWidget(m_view, 1);

    m_redraw.setSingleShot(true);
    m_redraw.setInterval(kRedrawMs);
    connect(&m_redraw, &QTimer::timeout, this, &QuantityGraph::refresh);
    connect(m_quantityBox, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (index >= 0)
            setQuantity(static_cast<Quantity>(m_quantityBox->itemData(index).toInt()));
    });
    connect(m_ballBox, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (index >= 0)
            setBall(m_ballBox->itemData(index).toInt());
    });
    connect(m_controller, &SimulationController::stepped, this, &QuantityGraph::onStepped);
    for (auto signal : {&SimulationController::sceneChanged, &SimulationController::settingsChanged,
                        &SimulationController::seeked})
        connect(m_controller, signal, this, [this] {
            fillBallBox();
            restart();
        });
    fillBallBox();
    restart();
}

QuantityGraph::~QuantityGraph() = default;

void QuantityGraph::fillBallBox()
{
    const int n = m_controller->world().balls().size();
    if (m_ballBox->count() == n + 1)
        return;
    const QSignalBlocker block(m_ballBox);
    m_ballBox->clear();
    m_ballBox->addItem(tr("all balls"), kAllBalls);
    for (int i = 0; i < n; ++i)
        m_ballBox->addItem(tr("ball %1").arg(i), i);
    if (m_ball >= n)
        m_ball = n > 0 ? 0 : kAllBalls;
    m_ballBox->setCurrentIndex(m_ballBox->findData(m_ball));
}

void QuantityGraph::setQuantity(Quantity quantity)
{
    if (quantity == m_quantity)
        return;
    m_quantity = quantity;
    const QSignalBlocker block(m_quantityBox);
    m_quantityBox->setCurrentIndex(m_quantityBox->findData(static_cast<int>(quantity)));
    restart();
}

void QuantityGraph::setBall(int index)
{
    if (index < kAllBalls || index >= m_controller->world().balls().size() || index == m_ball)
        return;
    m_ball = index;
    const QSignalBlocker block(m_ballBox);
    m_ballBox->setCurrentIndex(m_ballBox->findData(index));
    restart();
}

void QuantityGraph::restart()
{
    m_samples.clear();
    m_lastTime = -1.0;
    startTheory();
    onStepped();
    refresh();
}

void QuantityGraph::startTheory()
{
    const sim::World& world = m_controller->world();
    m_theoryKind = Theory::None;
    m_t0 = world.time();
    m_theoryEnd = std::numeric_limits<double>::infinity();
    m_bouncesAtStart = bounces(world);
    if (m_ball == kAllBalls) {
        // Nothing takes energy away: every force that acts has a potential.
        if (m_quantity != Quantity::Total)
            return;
        for (const sim::ForceModelInfo& model : sim::forceModels())
            if (model.on(world.settings()) && (!model.potential || model.conservativePart))
                return;
        m_theoryKind = Theory::ConstantEnergy;
        m_energy0 = world.energy().total();
        return;
    }
    const sim::BallState& b = world.balls();
    if (m_ball < 0 || m_ball >= b.size() || b.pinned[static_cast<std::size_t>(m_ball)])
        return;
    // Constant gravity alone, or no force at all.
    for (const sim::World::SourceAcceleration& source : world.accelerationBySource(m_ball))
        if (source.model != "gravity")
            return;
    const sim::Vec2 g = world.settings().gravity.acting();
    m_theoryKind = Theory::ConstantAcceleration;
    m_mass = b.mass[m_ball];
    for (int k = 0; k < 2; ++k) {
        m_x0[k] = b.position(k, m_ball);
        m_v0[k] = b.velocity(k, m_ball);
        m_g[k] = g[k];
    }
}

std::optional<double> QuantityGraph::theoryAt(double t) const
{
    if (m_theoryKind == Theory::None || t < m_t0 || t > m_theoryEnd)
        return std::nullopt;
    if (m_theoryKind == Theory::ConstantEnergy)
        return m_energy0;
    const double tau = t - m_t0;
    const double x = m_x0[0] + m_v0[0] * tau + 0.5 * m_g[0] * tau * tau;
    const double y = m_x0[1] + m_v0[1] * tau + 0.5 * m_g[1] * tau * tau;
    const double vx = m_v0[0] + m_g[0] * tau, vy = m_v0[1] + m_g[1] * tau;
    const double kinetic = 0.5 * m_mass * (vx * vx + vy * vy);
    const double potential = -m_mass * (m_g[0] * x + m_g[1] * y);
    switch (m_quantity) {
    case Quantity::X: return x;
    case Quantity::Y: return y;
    case Quantity::Vx: return vx;
    case Quantity::Vy: return vy;
    case Quantity::Speed: return std::hypot(vx, vy);
    case Quantity::Kinetic: return kinetic;
    case Quantity::Potential: return potential;
    case Quantity::Total: return kinetic + potential;
    case Quantity::MomentumX: return m_mass * vx;
    case Quantity::MomentumY: return m_mass * vy;
    }
    return std::nullopt;
}

QString QuantityGraph::theoryName() const
{
    if (m_theoryKind == Theory::None)
        return {};
    if (m_theoryKind == Theory::ConstantEnergy)
        return tr("theory: E₀, nothing takes energy away");
    const bool gx = m_g[0] != 0.0, gy = m_g[1] != 0.0, any = gx || gy;
    switch (m_quantity) {
    case Quantity::X: return gx ? tr("theory: x₀ + v₀t + ½gt²") : tr("theory: x₀ + v₀t");
    case Quantity::Y: return gy ? tr("theory: y₀ + v₀t + ½gt²") : tr("theory: y₀ + v₀t");
    case Quantity::Vx: return gx ? tr("theory: v₀ + gt") : tr("theory: v₀, constant");
    case Quantity::Vy: return gy ? tr("theory: v₀ + gt") : tr("theory: v₀, constant");
    case Quantity::Speed: return any ? tr("theory: |v₀ + gt|") : tr("theory: |v₀|, constant");
    case Quantity::Kinetic: return any ? tr("theory: ½m|v₀ + gt|²") : tr("theory: ½m|v₀|², constant");
    case Quantity::Potential: return any ? tr("theory: mgh, h of the flight") : tr("theory: 0, no gravity");
    case Quantity::Total: return tr("theory: E₀, constant");
    case Quantity::MomentumX: return gx ? tr("theory: m(v₀ + gt)") : tr("theory: mv₀, constant");
    case Quantity::MomentumY: return gy ? tr("theory: m(v₀ + gt)") : tr("theory: mv₀, constant");
    }
    return {};
}

// All balls: no bounce anywhere since the start (an impact may take energy
// away). One ball: its velocity is still v₀ + gt, which every integrator
// keeps to rounding under a constant acceleration (its position may be off
// by the integrator's error, its velocity not), so the ball's own first
// bounce ends the theory and other balls' bounces do not.
bool QuantityGraph::theoryStillHolds(const sim::World& world) const
{
    switch (m_theoryKind) {
    case Theory::None: return true;
    case Theory::ConstantEnergy: return bounces(world) == m_bouncesAtStart;
    case Theory::ConstantAcceleration: break;
    }
    const sim::BallState& b = world.balls();
    if (m_ball < 0 || m_ball >= b.size())
        return false;
    const double tau = world.time() - m_t0;
    const double scale = std::hypot(m_v0[0], m_v0[1]) + std::hypot(m_g[0], m_g[1]) * tau + 1.0;
    for (int k = 0; k < 2; ++k)
        if (!(std::abs(b.velocity(k, m_ball) - (m_v0[k] + m_g[k] * tau)) <= 1e-6 * scale))
            return false;
    return true;
}

void QuantityGraph::onStepped()
{
    const sim::World& world = m_controller->world();
    if (!(world.time() > m_lastTime))
        return;
    // The theory held up to the last sample before the frame that broke it.
    if (std::isinf(m_theoryEnd) && !theoryStillHolds(world))
        m_theoryEnd = m_lastTime;
    m_lastTime = world.time();
    m_samples.emplace_back(world.time(), valueOf(world, m_quantity, m_ball));
    if (m_samples.size() > kMaxSamples)
        m_samples.erase(m_samples.begin(), m_samples.begin() + static_cast<std::ptrdiff_t>(m_samples.size() - kMaxSamples));
    if (isVisible() && !m_redraw.isActive())
        m_redraw.start();
}

void QuantityGraph::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    refresh();
}

void QuantityGraph::refresh()
{
    m_redraw.stop();
    const std::size_t n = m_samples.size();
    const std::size_t stride = std::max<std::size_t>(1, (n + kMaxPoints - 1) / kMaxPoints);
    QList<QPointF> measured, theory;
    for (std::size_t k = 0; k < n; k += stride)
        measured.append(m_samples[k]);
    if (n > 0 && (n - 1) % stride != 0)
        measured.append(m_samples.back());
    const double start = n > 0 ? m_samples.front().x() : m_controller->world().time();
    const double end = n > 0 ? m_samples.back().x() : start;
    // The theory on its own grid up to where it holds (at most the last sample).
    const double theoryEnd = std::min(end, m_theoryEnd);
    if (m_theoryKind != Theory::None && theoryEnd > m_t0) {
        constexpr int kTheoryPoints = 200;
        for (int k = 0; k <= kTheoryPoints; ++k) {
            const double t = m_t0 + (theoryEnd - m_t0) * k / kTheoryPoints;
            if (const std::optional<double> v = theoryAt(t))
                theory.append(QPointF(t, *v));
        }
    }
    // In the view's units (ui/drawing/display_units.h): m, m/s, J in SI.
    const ShownUnit unit = shownUnit(unitOf(m_quantity), displayUnits());
    if (unit.px != 0 || unit.mass != 0)
        for (QList<QPointF>* points : {&measured, &theory})
            for (QPointF& p : *points)
                p.setY(unit.toShown(p.y()));
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const QList<QPointF>* points : {&measured, &theory})
        for (const QPointF& p : *points)
            if (std::isfinite(p.y()))
                lo = std::min(lo, p.y()), hi = std::max(hi, p.y());
    if (!(lo <= hi))
        lo = hi = 0.0;
    const int ticks = std::clamp(static_cast<int>(m_view->chart()->plotArea().height() / 45.0), 2, 6);
    const NiceAxis nice = niceAxis(lo, hi, ticks);
    applyNiceAxis(m_valueAxis, nice);
    // y grows downwards in the box: its axis does too, so a ball's highest
    // point is a peak on the graph as on the screen, not a dip.
    m_valueAxis->setReverse(m_quantity == Quantity::Y || m_quantity == Quantity::Vy ||
                            m_quantity == Quantity::MomentumY);
    m_factor = nice.factor();
    for (QList<QPointF>* points : {&measured, &theory})
        for (QPointF& p : *points)
            p.setY(p.y() / m_factor);
    m_measured->replace(measured);
    m_theory->replace(theory);
    m_theory->setName(theoryName());
    m_theory->setVisible(!theory.isEmpty());
    const double span = std::max(end - start, 1.0);
    applyNiceAxis(m_timeAxis, niceAxis(start, start + span));
    m_timeAxis->setRange(start, start + span);
    const QString of = m_ball == kAllBalls ? tr("all balls") : tr("ball %1").arg(m_ball);
    m_view->chart()->setTitle(
        tr("%1 of %2 (%3%4)").arg(quantityName(m_quantity), of, nice.factorText(), unit.text));
}

} // namespace forcelab
