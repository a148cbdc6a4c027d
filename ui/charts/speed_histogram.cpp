#include "ui/charts/speed_histogram.h"
#include "ui/charts/chart_setup.h"

#include "ui/canvas/simulation_controller.h"
#include "ui/controls/readable_numbers.h"
#include "ui/drawing/display_units.h"

#include "sim/world/ball_state.h"

#include <QChart>
#include <QLineSeries>
#include <QPainter>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace forcelab {

namespace {

// The 1, 2 or 5 × 10^k nearest to `x` (> 0) on a log scale.
double roundStepNear(double x)
{
    const double decade = std::pow(10.0, std::floor(std::log10(x)));
    double best = decade;
    for (double m : {2.0, 5.0, 10.0})
        if (std::abs(std::log(m * decade / x)) < std::abs(std::log(best / x)))
            best = m * decade;
    return best;
}

} // namespace

double SpeedHistogram::Histogram::totalVariation() const
{
    if (balls == 0)
        return 0.0;
    double sum = 0.0;
    for (qsizetype k = 0; k < counts.size(); ++k)
        sum += std::abs(counts[k] - expected[k]);
    // What the curve expects beyond the last bin is missed by every ball.
    double inside = 0.0;
    for (double e : expected)
        inside += e;
    sum += std::max(0.0, balls - inside);
    return 0.5 * sum / balls;
}

SpeedHistogram::Histogram SpeedHistogram::compute(const sim::BallState& balls, int targetBins, int curvePoints)
{
    Histogram h;
    const int n = balls.size();
    h.balls = n;
    if (n == 0 || targetBins < 1)
        return h;
    const Eigen::VectorXd speed = balls.velocity.colwise().norm().transpose();
    const double top = speed.maxCoeff();
    if (!(top > 0.0) || !std::isfinite(top))
        return h;
    h.binWidth = roundStepNear(top / targetBins);
    const int bins = static_cast<int>(std::floor(top / h.binWidth)) + 1; // the fastest ball is in the last bin
    h.counts = QList<double>(bins, 0.0);
    for (int i = 0; i < n; ++i)
        h.counts[std::min(bins - 1, static_cast<int>(speed[i] / h.binWidth))] += 1.0;

    h.kT = 0.5 * balls.mass.dot(speed.cwiseAbs2()) / n;
    if (!(h.kT > 0.0))
        return h;
    // Balls of one mass m follow f_m; many distinct masses (random radii) are
    // described by 256 mass quantiles of equal weight, so a point costs at
    // most 256 terms.
    std::map<double, int> masses;
    for (int i = 0; i < n; ++i)
        ++masses[balls.mass[i]];
    std::vector<std::pair<double, double>> groups; // (mass, balls)
    if (masses.size() <= 256) {
        for (const auto& [m, count] : masses)
            groups.emplace_back(m, static_cast<double>(count));
    } else {
        std::vector<double> sorted(balls.mass.data(), balls.mass.data() + n);
        std::sort(sorted.begin(), sorted.end());
        for (int q = 0; q < 256; ++q)
            groups.emplace_back(sorted[static_cast<std::size_t>((2 * q + 1) * n / 512)], n / 256.0);
    }
    // ∫ f_m over [lo, hi] = exp(−m lo² / 2kT) − exp(−m hi² / 2kT).
    h.expected = QList<double>(bins, 0.0);
    for (int k = 0; k < bins; ++k) {
        const double lo = k * h.binWidth, hi = lo + h.binWidth;
        for (const auto& [m, count] : groups)
            h.expected[k] += count * (std::exp(-m * lo * lo / (2.0 * h.kT)) - std::exp(-m * hi * hi / (2.0 * h.kT)));
    }
    const int points = std::max(2, curvePoints);
    const double range = bins * h.binWidth;
    h.curve.reserve(points);
    for (int k = 0; k < points; ++k) {
        const double v = range * k / (points - 1);
        double f = 0.0;
        for (const auto& [m, count] : groups)
            f += count * (m * v / h.kT) * std::exp(-m * v * v / (2.0 * h.kT));
        h.curve.append(QPointF(v, f * h.binWidth));
    }
    return h;
}

SpeedHistogram::SpeedHistogram(SimulationController* controller, QWidget* parent)
    : QChartView(parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("speedHistogram"));
    setAccessibleName(tr("Histogram of the balls' speeds with the Maxwell–Boltzmann curve"));
    setRenderHint(QPainter::Antialiasing);
    m_counts = new QLineSeries(this);
    m_counts->setName(tr("balls"));
    m_counts->setPen(QPen(QColor(0x2a, 0x6f, 0xdb), 2.0));
    m_curve = new QLineSeries(this);
    m_curve->setName(tr("Maxwell–Boltzmann (2D), same energy"));
    m_curve->setPen(QPen(QColor(0xd9, 0x48, 0x0f), 2.0));
    const LineChart chart = makeLineChart({m_counts, m_curve}, tr("speed (px/s)"));
    m_speedAxis = chart.x;
    m_countAxis = chart.y;
    setOwnChart(this, chart.chart);
    setMinimumSize(260, 180);

    m_redraw.setSingleShot(true);
    m_redraw.setInterval(kRedrawMs);
    connect(&m_redraw, &QTimer::timeout, this, &SpeedHistogram::refresh);
    for (auto signal : {&SimulationController::stepped, &SimulationController::sceneChanged})
        connect(m_controller, signal, this, [this] {
            if (isVisible() && !m_redraw.isActive())
                m_redraw.start();
        });
    refresh();
}

SpeedHistogram::~SpeedHistogram() = default;

void SpeedHistogram::showEvent(QShowEvent* event)
{
    QChartView::showEvent(event);
    refresh();
}

void SpeedHistogram::refresh()
{
    m_redraw.stop();
    m_shown = compute(m_controller->world().balls());
    const Histogram& h = m_shown;
    // Speeds in the view's units (ui/drawing/display_units.h): m/s in SI.
    const ShownUnit unit = shownUnit(QStringLiteral("px/s"), displayUnits());
    const double f = unit.factor();
    // The counts as a step outline: up the left edge of each bin, across, down.
    QList<QPointF> steps;
    steps.reserve(2 * h.counts.size() + 2);
    steps.append(QPointF(0.0, 0.0));
    double most = 0.0;
    for (qsizetype k = 0; k < h.counts.size(); ++k) {
        steps.append(QPointF(k * h.binWidth * f, h.counts[k]));
        steps.append(QPointF((k + 1) * h.binWidth * f, h.counts[k]));
        most = std::max(most, h.counts[k]);
    }
    if (!h.counts.isEmpty())
        steps.append(QPointF(h.counts.size() * h.binWidth * f, 0.0));
    for (const QPointF& p : h.curve)
        most = std::max(most, p.y());
    m_counts->replace(steps);
    QList<QPointF> curve = h.curve;
    for (QPointF& p : curve)
        p.setX(p.x() * f);
    m_curve->replace(curve);
    m_speedAxis->setTitleText(tr("speed (%1)").arg(unit.text));
    const double top = h.counts.size() * h.binWidth * f;
    applyNiceAxis(m_speedAxis, niceAxis(0.0, top > 0.0 ? top : 1.0));
    m_speedAxis->setRange(0.0, top > 0.0 ? top : 1.0);
    const int ticks = std::clamp(static_cast<int>(chart()->plotArea().height() / 45.0), 2, 6);
    NiceAxis counts = niceAxis(0.0, std::max(most, 1.0), ticks);
    counts.min = 0.0;
    // Counts are whole numbers: no factor on the axis for a few thousand balls.
    applyNiceAxis(m_countAxis, counts);
    if (counts.factor() != 1.0) {
        for (QLineSeries* s : {m_counts, m_curve}) {
            QList<QPointF> shown = s->points();
            for (QPointF& p : shown)
                p.setY(p.y() / counts.factor());
            s->replace(shown);
        }
    }
    m_countAxis->setTitleText(
        tr("%1balls per %2 %3").arg(counts.factorText(), humanNumber(unit.toShown(h.binWidth)), unit.text));
    chart()->setTitle(tr("Speeds of %1").arg(countText(h.balls, tr("ball"), tr("balls"))));
}

} // namespace forcelab
