#include "ui/docks/plots_dock.h"
#include "ui/charts/chart_setup.h"

#include "ui/drawing/display_units.h"
#include "ui/charts/energy_bars.h"
#include "ui/charts/quantity_graph.h"
#include "ui/charts/speed_histogram.h"

#include "ui/controls/readable_numbers.h"
#include "ui/canvas/simulation_controller.h"

#include <QChart>
#include <QChartView>
#include <QLineSeries>
#include <QPainter>
#include <QTabWidget>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <limits>

namespace forcelab {

namespace {

// The points of samples [first, end) as (t, value), at most `maxPoints` of
// them: every k-th sample and always the newest, so a long window stays cheap
// to draw and the right edge is exact.
template <class Value>
QList<QPointF> decimated(const std::deque<PlotsDock::Sample>& samples, std::size_t first, int maxPoints, Value value)
{
    QList<QPointF> points;
    const std::size_t n = samples.size() - first;
    if (n == 0)
        return points;
    const std::size_t stride = std::max<std::size_t>(1, (n + static_cast<std::size_t>(maxPoints) - 1) /
                                                            static_cast<std::size_t>(maxPoints));
    points.reserve(static_cast<qsizetype>(n / stride + 2));
    for (std::size_t k = first; k < samples.size(); k += stride)
        points.append(QPointF(samples[k].t, value(samples[k])));
    if ((samples.size() - 1 - first) % stride != 0)
        points.append(QPointF(samples.back().t, value(samples.back())));
    return points;
}

// The y axis over the points of some series: round ticks, the common factor
// divided out of the points and named once, with the unit, in the chart's
// title above the plot ("Energy (×10⁶ mass·px²/s²)"), which has the width to
// show it whole where a title along the axis would be cut in a short dock.
// `fromZero` keeps the axis at or above 0 (costs, counts). Returns the factor.
double showOnAxis(QValueAxis* axis, const QString& quantity, const QString& unit,
                  const QList<std::pair<QLineSeries*, QList<QPointF>>>& data, bool fromZero, int ticks)
{
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& [series, points] : data)
        for (const QPointF& p : points)
            if (std::isfinite(p.y())) {
                lo = std::min(lo, p.y());
                hi = std::max(hi, p.y());
            }
    if (!(lo <= hi))
        lo = hi = 0.0;
    if (fromZero)
        lo = std::max(0.0, lo), hi = std::max(hi, lo);
    NiceAxis nice = niceAxis(lo, hi, ticks);
    if (fromZero)
        nice.min = std::max(0.0, nice.min);
    applyNiceAxis(axis, nice);
    if (QChart* chart = data.isEmpty() ? nullptr : data.first().first->chart())
        chart->setTitle(QStringLiteral("%1 (%2%3)").arg(quantity, nice.factorText(), unit));
    const double f = nice.factor();
    for (const auto& [series, points] : data) {
        if (f == 1.0) {
            series->replace(points);
            continue;
        }
        QList<QPointF> shown = points;
        for (QPointF& p : shown)
            p.setY(p.y() / f);
        series->replace(shown);
    }
    return f;
}

// About one tick per 45 px of plot height (2 to 6), so the labels never
// crowd together and turn into "…" in a short dock.
int ticksFor(const QLineSeries* series)
{
    const QChart* chart = series->chart();
    const double height = chart ? chart->plotArea().height() : 0.0;
    return std::clamp(static_cast<int>(height / 45.0), 2, 6);
}

} // namespace

PlotsDock::PlotsDock(SimulationController* controller, QWidget* parent)
    : QDockWidget(tr("Plots"), parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("plotsDock"));
    m_kinetic = new QLineSeries(this);
    m_kinetic->setName(tr("kinetic"));
    m_potential = new QLineSeries(this);
    m_potential->setName(tr("potential"));
    m_total = new QLineSeries(this);
    m_total->setName(tr("total"));
    m_p = new QLineSeries(this);
    m_p->setName(tr("|p|"));
    m_px = new QLineSeries(this);
    m_px->setName(tr("p_x"));
    m_py = new QLineSeries(this);
    m_py->setName(tr("p_y"));
    m_cost = new QLineSeries(this);
    m_cost->setName(tr("one step"));

    m_tabs = new QTabWidget(this);
    m_tabs->setAccessibleName(tr("Plots of energy, momentum and step cost"));
    m_tabs->setDocumentMode(true);
    m_tabs->addTab(makeChart(tr("Energy"), {m_kinetic, m_potential, m_total}, &m_energyX, &m_energyY), tr("Energy"));
    m_energyBars = new EnergyBars(m_controller);
    m_tabs->addTab(m_energyBars, tr("Energy bars"));
    m_quantityGraph = new QuantityGraph(m_controller);
    m_tabs->addTab(m_quantityGraph, tr("Graph"));
    m_tabs->addTab(makeChart(tr("Momentum"), {m_p, m_px, m_py}, &m_momentumX, &m_momentumY), tr("Momentum"));
    m_tabs->addTab(makeChart(tr("Cost of a step"), {m_cost}, &m_costX, &m_costY), tr("Step cost"));
    m_speedHistogram = new SpeedHistogram(m_controller, this);
    m_speedHistogram->hide();
    setWidget(m_tabs);

    // The same colours as the canvas where they mean the same thing.
    m_total->setPen(QPen(QColor(0x1d, 0x22, 0x2c), 2.0));

    m_redraw.setSingleShot(true);
    m_redraw.setInterval(kRedrawMs);
    connect(&m_redraw, &QTimer::timeout, this, &PlotsDock::refreshCharts);
    connect(this, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible)
            refreshCharts();
    });
    connect(m_controller, &SimulationController::stepped, this, &PlotsDock::onStepped);
    connect(m_controller, &SimulationController::sceneChanged, this, &PlotsDock::clearSamples);
    onStepped();
}

PlotsDock::~PlotsDock() = default;

QChartView* PlotsDock::makeChart(const QString& title, const QList<QLineSeries*>& series, QValueAxis** xAxis,
                                 QValueAxis** yAxis)
{
    for (QLineSeries* s : series)
        s->setUseOpenGL(false);
    const LineChart made = makeLineChart(series, tr("time (s)"));
    QChart* chart = made.chart;
    chart->setTitle(title);
    *xAxis = made.x;
    *yAxis = made.y;
    auto* view = new QChartView(chart);
    view->setRenderHint(QPainter::Antialiasing);
    // Wide enough for the longest chart title ("Momentum (×10¹² mass·px/s)").
    const QFontMetrics titleFont(chart->titleFont());
    view->setMinimumSize(titleFont.horizontalAdvance(tr("Momentum (×10¹² mass·px²/s²)")) + 24, 180);
    return view;
}

double PlotsDock::shownFactor(Series which) const
{
    switch (which) {
    case Series::Kinetic:
    case Series::Potential:
    case Series::Total: return m_energyFactor;
    case Series::MomentumMagnitude:
    case Series::MomentumX:
    case Series::MomentumY: return m_momentumFactor;
    case Series::StepCost: return m_costFactor;
    }
    return 1.0;
}

QLineSeries* PlotsDock::series(Series which) const
{
    switch (which) {
    case Series::Kinetic: return m_kinetic;
    case Series::Potential: return m_potential;
    case Series::Total: return m_total;
    case Series::MomentumMagnitude: return m_p;
    case Series::MomentumX: return m_px;
    case Series::MomentumY: return m_py;
    case Series::StepCost: return m_cost;
    }
    return nullptr;
}

void PlotsDock::setHistogramShown(bool shown)
{
    if (shown == m_histogramShown)
        return;
    m_histogramShown = shown;
    if (shown) {
        m_tabs->addTab(m_speedHistogram, tr("Speeds"));
        m_tabs->setCurrentWidget(m_speedHistogram);
    } else {
        m_tabs->removeTab(m_tabs->indexOf(m_speedHistogram));
        m_speedHistogram->setParent(this);
        m_speedHistogram->hide();
    }
}

void PlotsDock::clearSamples()
{
    m_samples.clear();
    m_lastTime = -1.0;
    scheduleRefresh();
}

void PlotsDock::onStepped()
{
    const sim::World& world = m_controller->world();
    // Only a frame that moved time on is a sample: redraws and edits while
    // paused add nothing.
    if (!(world.time() > m_lastTime))
        return;
    m_lastTime = world.time();
    Sample s;
    s.t = world.time();
    const sim::Energy e = world.energy();
    s.kinetic = e.kinetic;
    s.potential = e.potential;
    s.total = e.total();
    const sim::Vec2 p = world.momentum();
    s.px = p.x();
    s.py = p.y();
    s.p = p.norm();
    s.stepMicros = world.lastStep().seconds * 1e6;
    m_samples.push_back(s);
    // A sample exactly the window's length old stays, whatever the last bit
    // of the two times (each is the sum of its steps, rounded once).
    const double oldest = s.t - kWindowSeconds - 1e-12 * std::max(1.0, std::abs(s.t));
    while (!m_samples.empty() && (m_samples.size() > kMaxSamples || m_samples.front().t < oldest))
        m_samples.pop_front();
    scheduleRefresh();
}

void PlotsDock::scheduleRefresh()
{
    if (isVisible() && !m_redraw.isActive())
        m_redraw.start();
}

void PlotsDock::refreshCharts()
{
    m_redraw.stop();
    const double end = m_samples.empty() ? 0.0 : m_samples.back().t;
    const double start = std::max(0.0, end - kWindowSeconds);
    const NiceAxis time = niceAxis(start, std::max(start + kWindowSeconds, end));
    for (QValueAxis* x : {m_energyX, m_momentumX, m_costX}) {
        applyNiceAxis(x, time);
        x->setRange(start, std::max(start + kWindowSeconds, end)); // the window itself, ticks at round times
    }

    auto points = [this](auto value) { return decimated(m_samples, 0, kMaxPoints, value); };
    // In the view's units (ui/drawing/display_units.h): J and kg·m/s in SI.
    const ShownUnit energyUnit = shownUnit(QStringLiteral("mass·px²/s²"), displayUnits());
    const ShownUnit momentumUnit = shownUnit(QStringLiteral("mass·px/s"), displayUnits());
    auto shown = [](const ShownUnit& unit, QList<QPointF> list) {
        if (unit.px != 0 || unit.mass != 0)
            for (QPointF& q : list)
                q.setY(unit.toShown(q.y()));
        return list;
    };
    const QList<QPointF> kinetic = shown(energyUnit, points([](const Sample& s) { return s.kinetic; }));
    const QList<QPointF> potential = shown(energyUnit, points([](const Sample& s) { return s.potential; }));
    const QList<QPointF> total = shown(energyUnit, points([](const Sample& s) { return s.total; }));
    m_energyFactor = showOnAxis(m_energyY, tr("Energy"), energyUnit.text,
                                            {{m_kinetic, kinetic}, {m_potential, potential}, {m_total, total}}, false,
                                ticksFor(m_kinetic));

    const QList<QPointF> p = shown(momentumUnit, points([](const Sample& s) { return s.p; }));
    const QList<QPointF> px = shown(momentumUnit, points([](const Sample& s) { return s.px; }));
    const QList<QPointF> py = shown(momentumUnit, points([](const Sample& s) { return s.py; }));
    m_momentumFactor = showOnAxis(m_momentumY, tr("Momentum"), momentumUnit.text, {{m_p, p}, {m_px, px}, {m_py, py}},
                                  false, ticksFor(m_p));

    const QList<QPointF> cost = points([](const Sample& s) { return s.stepMicros; });
    m_costFactor = showOnAxis(m_costY, tr("Computer time per step"), tr("µs"), {{m_cost, cost}}, true, ticksFor(m_cost));
}

} // namespace forcelab
