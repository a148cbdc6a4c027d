#include "ui/charts/energy_bars.h"
#include "ui/charts/chart_setup.h"

#include "ui/canvas/simulation_controller.h"
#include "ui/controls/readable_numbers.h"
#include "ui/drawing/display_units.h"

#include "sim/world/world.h"

#include <QBarCategoryAxis>
#include <QBarSet>
#include <QChart>
#include <QStackedBarSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace forcelab {

namespace {

constexpr int kBars = 4;

QString barName(EnergyBars::Bar bar)
{
    switch (bar) {
    case EnergyBars::Bar::Kinetic: return EnergyBars::tr("kinetic");
    case EnergyBars::Bar::Potential: return EnergyBars::tr("potential");
    case EnergyBars::Bar::Lost: return EnergyBars::tr("lost");
    case EnergyBars::Bar::Total: return EnergyBars::tr("total");
    }
    return {};
}

} // namespace

double EnergyBars::Account::value(Bar bar) const
{
    switch (bar) {
    case Bar::Kinetic: return kinetic;
    case Bar::Potential: return potential;
    case Bar::Lost: return lost;
    case Bar::Total: return total;
    }
    return 0.0;
}

EnergyBars::Account EnergyBars::accountOf(const sim::World& world)
{
    Account a;
    const sim::Energy e = world.energy();
    a.kinetic = e.kinetic;
    a.potential = e.potential;
    a.lostKnown = world.accounting();
    a.lost = a.lostKnown ? -world.bookedEnergy() : 0.0;
    a.total = a.kinetic + a.potential + a.lost;
    return a;
}

EnergyBars::EnergyBars(SimulationController* controller, QWidget* parent)
    : QChartView(parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("energyBars"));
    setAccessibleName(tr("Energy bars: kinetic, potential, lost and total energy now"));
    setRenderHint(QPainter::Antialiasing);

    auto* chart = new QChart();
    chart->setTitle(tr("Energy now"));
    applyChartStyle(chart);
    chart->legend()->hide(); // the categories name the bars
    // One set per bar, each with a value only in its own category, stacked:
    // every bar its own colour, full width.
    auto* series = new QStackedBarSeries(chart);
    const QColor colours[kBars] = {QColor(0x2a, 0x6f, 0xdb), QColor(0x2e, 0x9d, 0x4f), QColor(0xd9, 0x48, 0x0f),
                                   QColor(0x1d, 0x22, 0x2c)};
    QStringList categories;
    for (int k = 0; k < kBars; ++k) {
        const Bar bar = static_cast<Bar>(k);
        m_sets[k] = new QBarSet(barName(bar), series);
        for (int j = 0; j < kBars; ++j)
            m_sets[k]->append(0.0);
        m_sets[k]->setColor(colours[k]);
        m_sets[k]->setBorderColor(colours[k]);
        series->append(m_sets[k]);
        categories << barName(bar);
    }
    series->setBarWidth(0.7);
    chart->addSeries(series);
    m_categoryAxis = new QBarCategoryAxis(chart);
    m_categoryAxis->setCategories(categories);
    m_valueAxis = new QValueAxis(chart);
    chart->addAxis(m_categoryAxis, Qt::AlignBottom);
    chart->addAxis(m_valueAxis, Qt::AlignLeft);
    series->attachAxis(m_categoryAxis);
    series->attachAxis(m_valueAxis);
    setOwnChart(this, chart);
    setMinimumSize(240, 180);
    setToolTip(tr("Lost: energy taken out by drag, bumpy collisions and walls since the bars were shown or the "
                  "lesson restarted. Energy put in (wind, your hand, an edit) counts as negative lost energy, "
                  "so the total stays the same unless the computer's steps are inaccurate."));

    m_redraw.setSingleShot(true);
    m_redraw.setInterval(kRedrawMs);
    connect(&m_redraw, &QTimer::timeout, this, &EnergyBars::refresh);
    for (auto signal : {&SimulationController::stepped, &SimulationController::sceneChanged,
                        &SimulationController::settingsChanged, &SimulationController::seeked})
        connect(m_controller, signal, this, &EnergyBars::scheduleRefresh);
    refresh();
}

EnergyBars::~EnergyBars()
{
    if (m_controller) // gone first when the window closes
        m_controller->holdAccounting(this, false);
}

QBarSet* EnergyBars::barSet(Bar bar) const
{
    return m_sets[static_cast<int>(bar)];
}

void EnergyBars::showEvent(QShowEvent* event)
{
    QChartView::showEvent(event);
    m_controller->holdAccounting(this, true);
    refresh();
}

void EnergyBars::hideEvent(QHideEvent* event)
{
    QChartView::hideEvent(event);
    if (m_controller)
        m_controller->holdAccounting(this, false);
}

void EnergyBars::scheduleRefresh()
{
    if (isVisible() && !m_redraw.isActive())
        m_redraw.start();
}

void EnergyBars::refresh()
{
    m_redraw.stop();
    m_shown = accountOf(m_controller->world());
    // In the view's units (ui/drawing/display_units.h): J in SI.
    const ShownUnit unit = shownUnit(QStringLiteral("mass·px²/s²"), displayUnits());
    double lo = 0.0, hi = 0.0; // bars stand on 0
    for (int k = 0; k < kBars; ++k) {
        const double v = unit.toShown(m_shown.value(static_cast<Bar>(k)));
        if (std::isfinite(v))
            lo = std::min(lo, v), hi = std::max(hi, v);
    }
    const int ticks = std::clamp(static_cast<int>(chart()->plotArea().height() / 45.0), 2, 6);
    const NiceAxis nice = niceAxis(lo, hi, ticks);
    applyNiceAxis(m_valueAxis, nice);
    m_factor = nice.factor();
    m_valueAxis->setTitleText(tr("energy (%1%2)").arg(nice.factorText(), unit.text));
    // Each category says its value under its name, in the axis's units (the
    // factor is named once, in the axis title) so it fits under its bar.
    QStringList categories;
    for (int k = 0; k < kBars; ++k) {
        const Bar bar = static_cast<Bar>(k);
        const double v = unit.toShown(m_shown.value(bar));
        m_sets[k]->replace(k, v / m_factor);
        const QString value = bar == Bar::Lost && !m_shown.lostKnown ? tr("not counted") : humanNumber(v / m_factor, 3);
        categories << QStringLiteral("%1<br>%2").arg(barName(bar), value);
    }
    m_categoryAxis->setCategories(categories);
}

} // namespace forcelab
