// Plots and readouts a student can read: round ticks (1, 2 or 5 × 10^k), one
// common factor named in an axis title that is never cut, no negative cost
// axis, legends that say p_x and p_y, counts with the right plural, and
// readout numbers without rounding noise.

#include "ui/docks/plots_dock.h"
#include "ui/drawing/world_painter.h"
#include "ui/charts/energy_bars.h"
#include "ui/charts/quantity_graph.h"
#include "ui/charts/speed_histogram.h"
#include "lessons/lesson_loader.h"
#include "sim/world/world.h"
#include "ui/controls/readable_numbers.h"
#include "ui/canvas/simulation_controller.h"

#include "sim/world/scene.h"

#include <QBarCategoryAxis>
#include <QBarSet>
#include <QComboBox>
#include <QChart>
#include <QRegularExpression>
#include <QChartView>
#include <QLineSeries>
#include <QTabWidget>
#include <QTest>
#include <QValueAxis>

#include <cmath>

using namespace forcelab;

namespace {

// The step's mantissa: 1, 2 or 5 (times a power of ten) for a round tick.
bool isRoundStep(double step)
{
    const double m = step / std::pow(10.0, std::floor(std::log10(step) + 1e-12));
    return std::abs(m - 1.0) < 1e-9 || std::abs(m - 2.0) < 1e-9 || std::abs(m - 5.0) < 1e-9;
}

QValueAxis* yAxisOf(QLineSeries* series)
{
    for (QAbstractAxis* a : series->attachedAxes())
        if (a->orientation() == Qt::Vertical)
            return qobject_cast<QValueAxis*>(a);
    return nullptr;
}

} // namespace

class GuiPlotsTest : public QObject {
    Q_OBJECT
private slots:
    void niceAxisHasRoundTicksAndOneFactor_data();
    void niceAxisHasRoundTicksAndOneFactor();
    void roundedDropsNoiseBelowTheScale();
    void panelsWriteNumbersAsAStudentDoes();
    void countsHaveTheRightPlural();
    void bigEnergiesAreReadable();
    void energyBarsAreTheClosedFormEnergies();
    void energyBarsBookWhatDragTakes();
    void graphFollowsTheFallUntilTheBounce();
    void graphOfTotalsKeepsEnergyWhereNothingDissipates();
    void speedHistogramOfAMaxwellBoltzmannSample();
    void gasLessonSettlesOnTheCurve();
};

void GuiPlotsTest::niceAxisHasRoundTicksAndOneFactor_data()
{
    QTest::addColumn<double>("lo");
    QTest::addColumn<double>("hi");
    QTest::addColumn<int>("exponent");
    QTest::newRow("the issue's energies") << -1.02e10 << 8.87e10 << 9;
    QTest::newRow("small and positive") << 0.013 << 0.047 << 0;
    QTest::newRow("tiny") << 1.2e-7 << 3.9e-7 << -9;
    QTest::newRow("a few hundred") << -250.0 << 730.0 << 0;
    QTest::newRow("flat line") << 4.2e6 << 4.2e6 << 6;
    QTest::newRow("flat zero") << 0.0 << 0.0 << 0;
    QTest::newRow("thousands stay plain") << 1200.0 << 7900.0 << 0;
    QTest::newRow("ten thousand takes a factor") << 1200.0 << 9900.0 << 3;
}

// Ticks at 1, 2 or 5 × 10^k that cover the data with 3 to 7 intervals; the
// factor is a power of 1000, so labels show at most four digits before the
// point; the decimals tell two neighbouring ticks apart.
void GuiPlotsTest::niceAxisHasRoundTicksAndOneFactor()
{
    QFETCH(double, lo);
    QFETCH(double, hi);
    QFETCH(int, exponent);
    const NiceAxis a = niceAxis(lo, hi);
    QVERIFY2(isRoundStep(a.step), qPrintable(QString::number(a.step)));
    QVERIFY(a.min <= lo && a.max >= hi);
    const double intervals = (a.max - a.min) / a.step;
    QVERIFY2(intervals >= 2.5 && intervals <= 7.5, qPrintable(QString::number(intervals)));
    QCOMPARE(std::remainder(a.min, a.step), 0.0);
    QCOMPARE(a.exponent, exponent);
    const double biggestLabel = std::max(std::abs(a.min), std::abs(a.max)) / a.factor();
    QVERIFY2(biggestLabel < 1e4, qPrintable(QString::number(biggestLabel)));
    const QString first = QString::number(a.min / a.factor(), 'f', a.decimals);
    const QString second = QString::number((a.min + a.step) / a.factor(), 'f', a.decimals);
    QVERIFY2(first != second, qPrintable(first));
    QVERIFY(!first.contains(QLatin1Char('e')));
}

void GuiPlotsTest::roundedDropsNoiseBelowTheScale()
{
    QCOMPARE(rounded(1.39698e-09, 1000.0), QStringLiteral("0"));
    QCOMPARE(rounded(-12.34567, 1000.0), QStringLiteral("−12")); // four digits of 1000: whole numbers
    QCOMPARE(rounded(-12.34567, 100.0), QStringLiteral("−12.3"));
    QCOMPARE(rounded(-1.4e-12, 0.0), QStringLiteral("−1.4 × 10⁻¹²")); // alone, a small value keeps its digits
    QCOMPARE(rounded(-1e-13, 1.0), QStringLiteral("0.000"));      // no "-0.000"
    QCOMPARE(rounded(2.5e7, 2.5e7), QStringLiteral("2.5 × 10⁷"));
    QCOMPARE(rounded(-1.164e-10, 1.6e8), QStringLiteral("0")); // a total momentum's noise
    QCOMPARE(oneDecimal(-1.5e6), QStringLiteral("−1.5 × 10⁶"));
    QCOMPARE(oneDecimal(-0.04), QStringLiteral("0.0"));
    QCOMPARE(oneDecimal(-12.34), QStringLiteral("−12.3"));
    QCOMPARE(rounded(std::nan(""), 1.0), QStringLiteral("—"));
}

// Every shipped lesson's readout and totals, in every shape, at the start
// and after 3 s: no computer notation ("1.601e+08"), no hyphen for a minus,
// and a unit on each line that holds a number (a line of energies or a
// momentum names its unit once, after "energy" or at the end).
void GuiPlotsTest::panelsWriteNumbersAsAStudentDoes()
{
    const QRegularExpression computer(QStringLiteral(R"(\de[+-]?\d|-\d)"));
    const QRegularExpression digit(QStringLiteral(R"(\d)"));
    const QStringList units{QStringLiteral("px"), QStringLiteral(" s"), QStringLiteral("mass·")};
    int checked = 0;
    for (const QString& file : forcelab::LessonLoader::builtInFiles()) {
        const forcelab::LoadResult loaded = forcelab::LessonLoader::load(file);
        QVERIFY2(loaded.ok(), qPrintable(file));
        forcelab::sim::World world(loaded.lesson->scene);
        for (int pass = 0; pass < 2; ++pass) {
            if (pass == 1)
                for (int k = 0; k < 180 && !world.halted(); ++k)
                    world.step();
            if (world.balls().empty())
                continue;
            const forcelab::sim::Matrix2X a = world.accelerations();
            QStringList lines;
            for (auto shape : {WorldPainter::ReadoutShape::Panel, WorldPainter::ReadoutShape::Wide,
                               WorldPainter::ReadoutShape::Short})
                lines << WorldPainter::readoutText(world, 0, &a, shape);
            const double scale = WorldPainter::momentumScale(world);
            lines << WorldPainter::totalsText(world, false) << WorldPainter::totalsText(world, true)
                  << WorldPainter::stageTotalsText(world.energy(), world.momentum(), true, scale)
                  << WorldPainter::stageTotalsText(world.energy(), world.momentum(), false, scale);
            for (const QString& line : lines) {
                const QString where = file + QStringLiteral(": ") + line;
                QVERIFY2(!computer.match(line).hasMatch(), qPrintable(where));
                // Lines of energies under a head line "energy (unit)" and the
                // column's momentum x and y carry the unit of their head line.
                const bool underHead = line.startsWith(QStringLiteral("  "));
                if (digit.match(line).hasMatch() && !line.startsWith(QStringLiteral("ball ")) && !underHead) {
                    bool hasUnit = false;
                    for (const QString& u : units)
                        hasUnit = hasUnit || line.contains(u);
                    QVERIFY2(hasUnit, qPrintable(where));
                }
                ++checked;
            }
        }
    }
    QVERIFY(checked > 1000);
    // Lesson 19's orbit: kinetic 2.025 × 10⁶, and its total momentum, zero
    // up to rounding, reads 0.
    const forcelab::LoadResult orbit = forcelab::LessonLoader::load(QStringLiteral("two-bodies-in-orbit"));
    QVERIFY(orbit.ok());
    const forcelab::sim::World world(orbit.lesson->scene);
    const QString totals = WorldPainter::totalsText(world, true).join(QLatin1Char('\n'));
    QVERIFY2(totals.contains(QStringLiteral("kinetic 2.025 × 10⁶")), qPrintable(totals));
    QVERIFY2(totals.contains(QStringLiteral("momentum (0, 0) mass·px/s")), qPrintable(totals));
}

void GuiPlotsTest::countsHaveTheRightPlural()
{
    QCOMPARE(countText(1, QStringLiteral("evaluation"), QStringLiteral("evaluations")), QStringLiteral("1 evaluation"));
    QCOMPARE(countText(0, QStringLiteral("evaluation"), QStringLiteral("evaluations")), QStringLiteral("0 evaluations"));
    QCOMPARE(countText(4, QStringLiteral("ball"), QStringLiteral("balls")), QStringLiteral("4 balls"));
}

// A heavy ball falling fast: energies near 1e10 as in the issue. The axis
// shows small round numbers and names ×10⁹ once; the legends say p_x and
// p_y; the cost axis starts at 0; each y-axis title fits beside its plot.
void GuiPlotsTest::bigEnergiesAreReadable()
{
    sim::Scene scene;
    scene.settings.box = {600.0, 400.0};
    scene.settings.gravity.enabled = true;
    sim::Ball heavy;
    heavy.position = {300.0, 100.0};
    heavy.velocity = {500.0, 0.0};
    heavy.radius = 60.0; // mass 4/3 π 60³ ≈ 9.0e5
    scene.balls = {heavy};
    SimulationController controller;
    QVERIFY(!controller.setScene(scene));
    PlotsDock dock(&controller);
    for (int k = 0; k < 30; ++k)
        controller.advance(controller.world().settings().time.dt);
    dock.resize(dock.minimumSizeHint().width() + 40, 400);
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));
    dock.refreshCharts();

    const double kinetic = controller.world().energy().kinetic;
    QVERIFY2(kinetic > 1e10, qPrintable(QString::number(kinetic)));
    QValueAxis* energy = yAxisOf(dock.series(PlotsDock::Series::Kinetic));
    QVERIFY(energy);
    QCOMPARE(dock.shownFactor(PlotsDock::Series::Kinetic), 1e9);
    const QString title = dock.series(PlotsDock::Series::Kinetic)->chart()->title();
    QVERIFY2(title == QStringLiteral("Energy (×10⁹ mass·px²/s²)"), qPrintable(title));
    QVERIFY(isRoundStep(energy->tickInterval()));
    QCOMPARE(energy->tickType(), QValueAxis::TicksDynamic);
    QVERIFY2(!energy->labelFormat().contains(QLatin1Char('e')) && !energy->labelFormat().contains(QLatin1Char('g')),
             qPrintable(energy->labelFormat()));

    QCOMPARE(dock.series(PlotsDock::Series::MomentumX)->name(), QStringLiteral("p_x"));
    QCOMPARE(dock.series(PlotsDock::Series::MomentumY)->name(), QStringLiteral("p_y"));
    QValueAxis* cost = yAxisOf(dock.series(PlotsDock::Series::StepCost));
    QVERIFY(cost && cost->min() >= 0.0);

    // Each chart, at the size the dock gives it, shows its title (quantity,
    // factor, unit) and its x-axis title whole.
    for (auto* view : dock.findChildren<QChartView*>()) {
        if (!view->isVisible())
            continue;
        const QChart* chart = view->chart();
        const double title = QFontMetricsF(chart->titleFont()).horizontalAdvance(chart->title());
        QVERIFY2(title <= view->width() - 16,
                 qPrintable(QStringLiteral("%1: %2 px wide in a %3 px chart").arg(chart->title()).arg(title).arg(view->width())));
        for (QAbstractAxis* a : chart->axes(Qt::Horizontal)) {
            const double xTitle = QFontMetricsF(a->titleFont()).horizontalAdvance(a->titleText());
            QVERIFY2(xTitle <= chart->plotArea().width(), qPrintable(a->titleText()));
        }
    }
}

// One ball thrown up under gravity, no walls, no drag, rk4 (exact for a
// constant acceleration, up to rounding): after t the bars are
//     kinetic   ½ m (vx₀² + (vy₀ + g t)²)
//     potential m g h with h = −y (y down, 0 at the top), y = y₀ + vy₀ t + ½ g t²
//     lost      0
//     total     the starting ½ m v₀² − m g y₀, the same all the time
// to 1e-9 of the energy scale.
void GuiPlotsTest::energyBarsAreTheClosedFormEnergies()
{
    const double g = 980.0, y0 = 300.0, vx0 = 50.0, vy0 = -400.0;
    sim::Scene scene = sim::openScene({sim::ballAt(200.0, y0, vx0, vy0, 10.0)});
    scene.settings.gravity.enabled = true;
    scene.settings.time.integrator = sim::IntegratorKind::Rk4;
    SimulationController controller;
    QVERIFY(!controller.setScene(scene));
    PlotsDock dock(&controller);
    dock.tabs()->setCurrentWidget(dock.energyBars());
    dock.resize(420, 360);
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));
    EnergyBars* bars = dock.energyBars();
    QVERIFY(bars->isVisible());
    QVERIFY(controller.world().accounting()); // shown bars keep the books

    const double m = controller.world().balls().mass[0];
    const double start = 0.5 * m * (vx0 * vx0 + vy0 * vy0) - m * g * y0;
    const double scale = 0.5 * m * (vx0 * vx0 + vy0 * vy0) + m * g * y0;
    for (int k = 0; k < 45; ++k) {
        controller.advance(controller.world().settings().time.dt);
        bars->refresh();
        const double t = controller.world().time();
        const double vy = vy0 + g * t, y = y0 + vy0 * t + 0.5 * g * t * t;
        const EnergyBars::Account& a = bars->shown();
        QVERIFY2(std::abs(a.kinetic - 0.5 * m * (vx0 * vx0 + vy * vy)) < 1e-9 * scale, qPrintable(QString::number(t)));
        QVERIFY2(std::abs(a.potential - m * g * (-y)) < 1e-9 * scale, qPrintable(QString::number(t)));
        QVERIFY(a.lostKnown);
        QVERIFY(std::abs(a.lost) < 1e-9 * scale);
        QVERIFY2(std::abs(a.total - start) < 1e-9 * scale, qPrintable(QString::number(a.total - start)));
    }
    QCOMPARE(controller.world().stepCount(), 45);
    QVERIFY(controller.world().balls().velocity(1, 0) > 0.0); // past the top: on its way down again

    // The bars are those values over the factor the axis title names, with
    // the unit; each category says its value in those units, in human notation.
    for (EnergyBars::Bar bar : {EnergyBars::Bar::Kinetic, EnergyBars::Bar::Potential, EnergyBars::Bar::Lost,
                                EnergyBars::Bar::Total}) {
        const int k = static_cast<int>(bar);
        QCOMPARE(bars->barSet(bar)->at(k) * bars->shownFactor(), bars->shown().value(bar));
        QVERIFY(bars->categoryAxis()->categories().at(k).endsWith(
            humanNumber(bars->shown().value(bar) / bars->shownFactor(), 3)));
    }
    // Energies of about 10⁹ (mass ≈ 4189): one factor, a power of 1000, named with the unit.
    const double exponent = std::log10(bars->shownFactor());
    QVERIFY2(exponent >= 6 && std::fmod(exponent, 3.0) == 0.0, qPrintable(QString::number(exponent)));
    QCOMPARE(bars->valueAxis()->titleText(),
             QStringLiteral("energy (×10%1 mass·px²/s²)").arg(exponent == 6 ? QStringLiteral("⁶") : QStringLiteral("⁹")));
    QVERIFY(std::max(std::abs(bars->valueAxis()->min()), std::abs(bars->valueAxis()->max())) < 1e4);
    QVERIFY(isRoundStep(bars->valueAxis()->tickInterval()));
    QVERIFY(!bars->valueAxis()->labelFormat().contains(QLatin1Char('e')));

    // Hidden, the bars let the books go (nobody else holds them).
    dock.tabs()->setCurrentIndex(0);
    QTRY_VERIFY(!bars->isVisible());
    QVERIFY(!controller.world().accounting());
}

// Linear drag takes energy away: the lost bar grows by what the books say
// drag took, and the total stays where it started to the error of the
// books' trapezoid rule, second order in the step: below 2 (k dt)² = 3.6e-4
// of the starting energy (k = 0.8/s, dt = 1/60 s, rk4; measured 8.3e-5 over 2 s).
void GuiPlotsTest::energyBarsBookWhatDragTakes()
{
    sim::Scene scene = sim::openScene({sim::ballAt(200.0, 300.0, 300.0, -200.0, 10.0)});
    scene.settings.gravity.enabled = true;
    scene.settings.drag = sim::DragSettings{true, sim::DragLaw::Linear, 0.8};
    scene.settings.time.integrator = sim::IntegratorKind::Rk4;
    SimulationController controller;
    QVERIFY(!controller.setScene(scene));
    EnergyBars bars(&controller);
    bars.resize(360, 300);
    bars.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bars));
    const double start = controller.world().energy().total();
    for (int k = 0; k < 120; ++k)
        controller.advance(controller.world().settings().time.dt);
    QTRY_VERIFY(bars.shown().lost > 0.0); // the timer redraws
    bars.refresh();
    const EnergyBars::Account& a = bars.shown();
    QCOMPARE(a.lost, -controller.world().bookedEnergy());
    QVERIFY2(a.lost > 0.1 * a.kinetic, qPrintable(QString::number(a.lost)));
    const double k = 0.8, dt = controller.world().settings().time.dt;
    QVERIFY2(std::abs(a.total - start) < 2.0 * k * k * dt * dt * std::abs(start), qPrintable(QString::number((a.total - start) / start)));
}

// Lesson 07: the orange ball (ball 3) thrown up from y₀ = 300 px at
// v₀ = −400 px/s under g = 980 px/s², picked from the combo boxes. Until it
// reaches the floor (y = 390 px, t = 1.0 s in closed form; a little earlier
// for the integrator) its graphed y is the theory y₀ + v₀t + ½gt² plus
// semi-implicit Euler's own offset ½g·dt·t (at most 8.2 px at 1 s), to
// 1e-8 px; vy is v₀ + gt to 1e-9 px/s; with the exact integrator y is the
// theory itself to 1e-8 px. The theory curve stops at the bounce.
void GuiPlotsTest::graphFollowsTheFallUntilTheBounce()
{
    const LoadResult r = LessonLoader::load(QStringLiteral("gravity"));
    QVERIFY2(r.ok(), qPrintable(r.errors().join(" | ")));
    for (const sim::IntegratorKind integrator : {sim::IntegratorKind::SemiImplicitEuler, sim::IntegratorKind::Exact}) {
        sim::Scene scene = r.lesson->scene;
        scene.settings.time.integrator = integrator;
        SimulationController controller;
        QVERIFY(!controller.setScene(scene));
        PlotsDock dock(&controller);
        QuantityGraph* graph = dock.quantityGraph();
        dock.tabs()->setCurrentWidget(graph);
        dock.resize(480, 400);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        // Numbered from 0, as in the readout, the table and the lesson texts.
        graph->ballBox()->setCurrentIndex(graph->ballBox()->findText(QStringLiteral("ball 3")));
        QCOMPARE(graph->ball(), 3);
        graph->quantityBox()->setCurrentIndex(graph->quantityBox()->findText(QStringLiteral("y position")));
        QCOMPARE(graph->quantity(), QuantityGraph::Quantity::Y);
        // y grows downwards in the box and on the graph's axis.
        const QList<QAbstractAxis*> vertical = graph->findChild<QChartView*>()->chart()->axes(Qt::Vertical);
        QCOMPARE(vertical.size(), 1);
        QVERIFY(qobject_cast<QValueAxis*>(vertical[0])->isReverse());
        QCOMPARE(graph->theoryName(), QStringLiteral("theory: y₀ + v₀t + ½gt²"));

        const double dt = controller.world().settings().time.dt, g = 980.0, y0 = 300.0, v0 = -400.0;
        while (controller.world().time() < 1.5)
            controller.advance(dt);
        // Its own bounce ends the theory (the red, blue and green balls reach the floor earlier).
        QVERIFY2(graph->theoryEnd() > 0.95 && graph->theoryEnd() <= 1.0, qPrintable(QString::number(graph->theoryEnd())));
        int compared = 0;
        for (const QPointF& p : graph->samples()) {
            const std::optional<double> theory = graph->theoryAt(p.x());
            if (p.x() > graph->theoryEnd()) {
                QVERIFY(!theory);
                continue;
            }
            QVERIFY(theory);
            const double t = p.x();
            QVERIFY(std::abs(*theory - (y0 + v0 * t + 0.5 * g * t * t)) < 1e-9);
            const double offset = integrator == sim::IntegratorKind::Exact ? 0.0 : 0.5 * g * dt * t;
            QVERIFY2(std::abs(p.y() - *theory - offset) < 1e-8,
                     qPrintable(QStringLiteral("t %1: y %2, theory %3").arg(t).arg(p.y()).arg(*theory)));
            ++compared;
        }
        QVERIFY(compared >= 57); // 0 … 0.95 s at 60 samples a second

        // On screen: the theory dashed, named, and only up to the bounce.
        graph->refresh();
        QLineSeries* theory = graph->theorySeries();
        QVERIFY(theory->isVisible());
        QCOMPARE(theory->pen().style(), Qt::DashLine);
        QCOMPARE(theory->name(), QStringLiteral("theory: y₀ + v₀t + ½gt²"));
        QVERIFY(theory->count() > 100);
        QCOMPARE(theory->at(theory->count() - 1).x(), graph->theoryEnd());
        QVERIFY(graph->measuredSeries()->at(graph->measuredSeries()->count() - 1).x() > graph->theoryEnd());

        // vy: v₀ + gt, exact for every integrator, from a fresh start now (after the bounce).
        graph->quantityBox()->setCurrentIndex(graph->quantityBox()->findText(QStringLiteral("velocity v_y")));
        QCOMPARE(graph->theoryName(), QStringLiteral("theory: v₀ + gt"));
        const double t0 = controller.world().time();
        const double vy0 = controller.world().balls().velocity(1, 3);
        for (int k = 0; k < 10; ++k)
            controller.advance(dt);
        QCOMPARE(graph->samples().size(), std::size_t{11});
        for (const QPointF& p : graph->samples())
            if (p.x() <= graph->theoryEnd())
                QVERIFY(std::abs(p.y() - (vy0 + g * (p.x() - t0))) < 1e-9);
    }
}

// All balls of a box without walls under gravity and a spring: nothing
// takes energy away, so the theory is the starting total, and the total
// energy graphed stays on it to rk4's error (1e-6 of the energy scale over
// 1 s at dt = 1/60 s). With drag there is no theory curve.
void GuiPlotsTest::graphOfTotalsKeepsEnergyWhereNothingDissipates()
{
    sim::Scene scene = sim::openScene({sim::ballAt(100, 100, 120, 0), sim::ballAt(300, 50, -60, 30, 15)});
    scene.settings.gravity.enabled = true;
    scene.settings.spring.enabled = true;
    scene.settings.spring.k = 4.0;
    scene.settings.spring.anchor = {200.0, 100.0};
    scene.settings.time.integrator = sim::IntegratorKind::Rk4;
    SimulationController controller;
    QVERIFY(!controller.setScene(scene));
    QuantityGraph graph(&controller);
    graph.setBall(QuantityGraph::kAllBalls);
    graph.setQuantity(QuantityGraph::Quantity::Total);
    QCOMPARE(graph.theoryName(), QStringLiteral("theory: E₀, nothing takes energy away"));
    const double e0 = controller.world().energy().total();
    const double scale = controller.world().energy().kinetic + std::abs(controller.world().energy().potential);
    for (int k = 0; k < 60; ++k)
        controller.advance(controller.world().settings().time.dt);
    QCOMPARE(graph.samples().size(), std::size_t{61});
    for (const QPointF& p : graph.samples()) {
        QCOMPARE(*graph.theoryAt(p.x()), e0);
        QVERIFY2(std::abs(p.y() - e0) < 1e-6 * scale, qPrintable(QString::number((p.y() - e0) / scale)));
    }
    scene.settings.drag.enabled = true;
    QVERIFY(controller.setSettings(scene.settings));
    QVERIFY(graph.theoryName().isEmpty());
    QVERIFY(!graph.theoryAt(controller.world().time()));
}

// 4000 equal balls with speeds at the quantiles of the 2D Maxwell–Boltzmann
// law of kT/m = σ² = 100² (px/s)²: speed σ √(−2 ln U). Bins of a round
// width; the counts add up to N; kT is the balls' mean kinetic energy; the
// curve, N Δv f(v), has that same mean energy: over [0, V] the trapezoid sum
// of ½mv² f(v) is the closed form kT (1 − e^(−x)(1 + x)), x = mV²/2kT, to
// 1e-6 kT; and the balls follow the curve, total variation below 0.02.
void GuiPlotsTest::speedHistogramOfAMaxwellBoltzmannSample()
{
    std::vector<sim::Ball> list;
    const double sigma = 100.0;
    const int n = 4000;
    for (int i = 0; i < n; ++i) {
        const double u = (i + 0.5) / n; // quantiles: no random numbers needed
        const double speed = sigma * std::sqrt(-2.0 * std::log(u));
        const double angle = 2.399963 * i;
        list.push_back(sim::ballAt(0, 0, speed * std::cos(angle), speed * std::sin(angle), 5));
    }
    sim::BallState balls;
    balls.assign(list);
    const SpeedHistogram::Histogram h = SpeedHistogram::compute(balls, 20, 4001);
    QVERIFY(isRoundStep(h.binWidth));
    QVERIFY(h.counts.size() >= 10 && h.counts.size() <= 40);
    double counted = 0.0;
    for (double c : h.counts)
        counted += c;
    QCOMPARE(counted, double(n));
    const double m = balls.mass[0];
    double kinetic = 0.0;
    for (int i = 0; i < n; ++i)
        kinetic += 0.5 * m * balls.velocity.col(i).squaredNorm();
    QVERIFY(std::abs(h.kT / (kinetic / n) - 1.0) < 1e-12);
    QVERIFY(std::abs(h.kT / (m * sigma * sigma) - 1.0) < 0.01); // the sample's own kT/m is σ² to 1%

    double energy = 0.0; // ∫ ½mv² f(v) dv over the curve's range
    for (qsizetype k = 1; k < h.curve.size(); ++k) {
        const QPointF a = h.curve[k - 1], b = h.curve[k];
        const double fa = a.y() / (n * h.binWidth), fb = b.y() / (n * h.binWidth);
        energy += 0.5 * (0.5 * m * a.x() * a.x() * fa + 0.5 * m * b.x() * b.x() * fb) * (b.x() - a.x());
    }
    const double x = m * h.curve.back().x() * h.curve.back().x() / (2.0 * h.kT);
    const double closedForm = h.kT * (1.0 - std::exp(-x) * (1.0 + x));
    QVERIFY2(std::abs(energy - closedForm) < 1e-6 * h.kT, qPrintable(QString::number((energy - closedForm) / h.kT)));
    QVERIFY(std::abs(closedForm - h.kT) < 1e-3 * h.kT); // the range holds all but the far tail
    QVERIFY2(h.totalVariation() < 0.02, qPrintable(QString::number(h.totalVariation())));
}

// Lesson 32: 400 equal balls all at 200 px/s spread into the curve through
// their collisions. At the start the histogram is one spike far from it
// (total variation above 0.5; measured 0.93); after 5 s below 0.2 (measured
// 0.09 with 25 bins of 20 px/s). The dock shows the tab.
void GuiPlotsTest::gasLessonSettlesOnTheCurve()
{
    const LoadResult r = LessonLoader::load(QStringLiteral("gas-in-a-box"));
    QVERIFY2(r.ok(), qPrintable(r.errors().join(" | ")));
    SimulationController controller;
    QVERIFY(!controller.setScene(r.lesson->scene));
    const sim::BallState& balls = controller.world().balls();
    QCOMPARE(balls.size(), 400);
    QCOMPARE(balls.mass.minCoeff(), balls.mass.maxCoeff()); // equal masses: one curve
    PlotsDock dock(&controller);
    QVERIFY(!dock.tabs()->isAncestorOf(dock.speedHistogram()));
    dock.setHistogramShown(true);
    QCOMPARE(dock.tabs()->currentWidget(), dock.speedHistogram());
    dock.resize(480, 400);
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));
    SpeedHistogram* histogram = dock.speedHistogram();
    histogram->refresh();
    const double start = histogram->shown().totalVariation();
    QVERIFY2(start > 0.5, qPrintable(QString::number(start)));
    QCOMPARE(histogram->shown().kT, controller.world().energy().kinetic / 400);
    while (controller.world().time() < 5.0)
        controller.advance(controller.world().settings().time.dt);
    histogram->refresh();
    const SpeedHistogram::Histogram& h = histogram->shown();
    QVERIFY(std::abs(h.kT / (controller.world().energy().kinetic / 400) - 1.0) < 1e-12);
    qInfo("gas: total variation %.3f at 0 s, %.3f at 5 s (%lld bins of %g px/s)", start, h.totalVariation(),
          static_cast<long long>(h.counts.size()), h.binWidth);
    QVERIFY2(h.totalVariation() < 0.2, qPrintable(QString::number(h.totalVariation())));
    QCOMPARE(histogram->countSeries()->count(), 2 * h.counts.size() + 2);
    QVERIFY(histogram->curveSeries()->count() > 100);
    QVERIFY(histogram->countAxis()->titleText().startsWith(QStringLiteral("balls per ")));
}

QTEST_MAIN(GuiPlotsTest)
#include "test_gui_plots.moc"
