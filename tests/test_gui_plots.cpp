// Plots and readouts a student can read: round ticks (1, 2 or 5 × 10^k), one
// common factor named in an axis title that is never cut, no negative cost
// axis, legends that say p_x and p_y, counts with the right plural, and
// readout numbers without rounding noise.

#include "ui/docks/plots_dock.h"
#include "ui/drawing/world_painter.h"
#include "lessons/lesson_loader.h"
#include "sim/world/world.h"
#include "ui/controls/readable_numbers.h"
#include "ui/canvas/simulation_controller.h"

#include "sim/world/scene.h"

#include <QChart>
#include <QRegularExpression>
#include <QChartView>
#include <QLineSeries>
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

QTEST_MAIN(GuiPlotsTest)
#include "test_gui_plots.moc"
