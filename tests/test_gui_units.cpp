// The SI mode (issue #36, part 4): the world works in px, px/s and mass
// units; with SI on, every number a student reads or types is in m, m/s,
// m/s², kg, N or J at the lesson's (or the teacher's) scale. Checked here:
// the conversion in closed forms, that every unit of the parameter table is
// understood, the lesson field, and through the real window that a value
// typed in SI reaches the world in px and shows back in SI.

#include "gui_workbench.h"

#include "ui/controls/ball_table.h"
#include "ui/controls/ball_table_model.h"
#include "ui/controls/number_control.h"
#include "ui/controls/parameter_panel.h"
#include "ui/charts/quantity_graph.h"
#include "ui/charts/speed_histogram.h"
#include "ui/docks/inspector_dock.h"
#include "ui/docks/plots_dock.h"
#include "ui/drawing/display_units.h"
#include "ui/drawing/human_number.h"
#include "ui/canvas/canvas.h"
#include "ui/drawing/world_painter.h"
#include "ui/window/main_window.h"

#include "lessons/lesson_loader.h"
#include "sim/world/parameters.h"

#include <QAbstractAxis>
#include <QAction>
#include <QDialog>
#include <QDoubleSpinBox>
#include <QTimer>
#include <QChart>
#include <QChartView>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPushButton>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTest>

using namespace forcelab;

namespace {

QString qs(std::string_view s)
{
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

// A minimal lesson with `units` as given (JSON text).
QByteArray lessonWithUnits(const QByteArray& units)
{
    return R"({"format": 1, "id": "si", "balls": [{"x": 100, "y": 50, "vx": 200, "vy": 0, "r": 10}], "units": )" +
           units + "}";
}

} // namespace

class GuiUnitsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void cleanup() { setDisplayUnits({}); }

    void conversionClosedForms();
    void everyParameterUnitIsUnderstood();
    void lessonUnitsLoadAndSave();
    void lessonUnitsRefused();
    void typedSiReachesTheWorld();
    void readoutsTableInspectorSpeakSi();
    void scaleDialogSetsTheScale();
    void toolsSpeakSiToo();
};

void GuiUnitsTest::conversionClosedForms()
{
    const DisplayUnits si{.si = true, .pxPerMetre = 100, .kgPerMass = 1};
    const ShownUnit g = shownUnit(QStringLiteral("px/s²"), si);
    QCOMPARE(g.text, QStringLiteral("m/s²"));
    QCOMPARE(g.toShown(980.0), 9.8);   // the same double as the literal 9.8
    QCOMPARE(g.fromShown(9.8), 980.0); // and back, to the bit
    QCOMPARE(g.fromShown(1.62), 162.0);

    // 10⁴ mass·px²/s² at 100 px/m and 2 kg per mass unit: 10⁴ × 2 / 100² = 2 J.
    const DisplayUnits heavy{.si = true, .pxPerMetre = 100, .kgPerMass = 2};
    const ShownUnit e = shownUnit(WorldPainter::kEnergyUnit, heavy);
    QCOMPARE(e.text, QStringLiteral("J"));
    QCOMPARE(e.toShown(1e4), 2.0);
    QCOMPARE(e.fromShown(2.0), 1e4);
    QCOMPARE(shownUnit(QStringLiteral("mass·px/s²"), heavy).text, QStringLiteral("N"));
    QCOMPARE(shownUnit(QStringLiteral("mass·px/s²"), heavy).toShown(50.0), 1.0); // 50 × 2 / 100
    QCOMPARE(shownUnit(WorldPainter::kMomentumUnit, heavy).text, QStringLiteral("kg·m/s"));
    QCOMPARE(shownUnit(QStringLiteral("mass"), heavy).text, QStringLiteral("kg"));
    QCOMPARE(shownUnit(QStringLiteral("mass"), heavy).toShown(3.0), 6.0);
    QCOMPARE(shownUnit(QStringLiteral("px³/(mass·s²)"), heavy).text, QStringLiteral("m³/(kg·s²)"));
    QCOMPARE(shownUnit(QStringLiteral("px³/(mass·s²)"), heavy).toShown(2e6), 1.0); // 2×10⁶ / 100³ / 2
    QCOMPARE(shownUnit(QStringLiteral("1/px"), si).text, QStringLiteral("1/m"));
    QCOMPARE(shownUnit(QStringLiteral("1/px"), si).toShown(0.01), 1.0);
    QCOMPARE(shownUnit(QStringLiteral("px"), si).text, QStringLiteral("m"));

    // Without px or mass, or in pixel mode, or unreadable: unchanged.
    for (const char* unit : {"s", "1/s", "1/s²", "Hz", "rad/s", ""}) {
        const ShownUnit u = shownUnit(QString::fromUtf8(unit), si);
        QCOMPARE(u.text, QString::fromUtf8(unit));
        QCOMPARE(u.toShown(7.5), 7.5);
    }
    QCOMPARE(shownUnit(QStringLiteral("px/s²"), DisplayUnits{}).text, QStringLiteral("px/s²"));

    // A shown number reads back (the tests and the tools read what a student reads).
    for (double v : {-1.5e-5, 4.2e9, 12.35, 0.0042, -3.0, 0.0, 123456.0}) {
        const QString text = humanNumber(v, 4);
        const std::optional<double> back = humanNumberValue(text + QStringLiteral(" m/s"));
        QVERIFY2(back && std::abs(*back - v) <= 1e-12 * std::abs(v), qPrintable(text));
    }
    QVERIFY(!humanNumberValue(QStringLiteral("m/s")));
    QVERIFY(!humanNumberValue(QStringLiteral("4.2 × 10")));
    QCOMPARE(humanNumberValue(QStringLiteral("3.2 m")).value_or(0), 3.2);
    QCOMPARE(shownUnit(QStringLiteral("px/s²"), DisplayUnits{}).toShown(980.0), 980.0);
    QVERIFY(!parseUnit(QStringLiteral("mass units")));
    QCOMPARE(shownUnit(QStringLiteral("mass units"), si).text, QStringLiteral("mass units"));
}

void GuiUnitsTest::everyParameterUnitIsUnderstood()
{
    // No unit of the table silently stays in px: each one reads, except the
    // drag constant's, whose unit follows the law and which the Parameters
    // panel converts as "1/s" or "1/px" (ParameterPanel::addParameterWidget).
    for (const sim::Parameter& p : sim::parameters()) {
        const QString unit = qs(p.unit);
        if (p.key == "models.drag.k") {
            QVERIFY(!parseUnit(unit));
            QVERIFY(parseUnit(QStringLiteral("1/s")) && parseUnit(QStringLiteral("1/px")));
            continue;
        }
        QVERIFY2(parseUnit(unit).has_value(), qPrintable(qs(p.key) + QStringLiteral(": ") + unit));
        const DisplayUnits si{.si = true};
        QVERIFY2(!shownUnit(unit, si).text.contains(QStringLiteral("px")), qPrintable(unit));
        QVERIFY2(!shownUnit(unit, si).text.contains(QStringLiteral("mass")), qPrintable(unit));
    }
    // The readouts' own units.
    for (const QString& unit : {WorldPainter::kEnergyUnit, WorldPainter::kMomentumUnit})
        QVERIFY(parseUnit(unit).has_value());
}

void GuiUnitsTest::lessonUnitsLoadAndSave()
{
    const LoadResult gravity = LessonLoader::load(QStringLiteral("gravity"));
    QVERIFY2(gravity.ok(), qPrintable(gravity.errors().join(QLatin1Char('\n'))));
    QVERIFY(gravity.lesson->units.has_value());
    QCOMPARE(gravity.lesson->units->pxPerMetre, 100.0);
    QCOMPARE(gravity.lesson->units->kgPerMass, 1.0);

    const LoadResult pixels = LessonLoader::load(QStringLiteral("balls-on-a-canvas"));
    QVERIFY(pixels.ok());
    QVERIFY(!pixels.lesson->units.has_value());

    const LoadResult r = LessonLoader::loadBytes(lessonWithUnits(R"({"px_per_metre": 50, "kg_per_mass": 0.5})"),
                                                 QStringLiteral("si.json"));
    QVERIFY2(r.ok(), qPrintable(r.errors().join(QLatin1Char('\n'))));
    QCOMPARE(r.lesson->units->pxPerMetre, 50.0);
    QCOMPARE(r.lesson->units->kgPerMass, 0.5);
    // Written back and read again: the same scale.
    const LoadResult again = LessonLoader::loadBytes(saveLesson(*r.lesson), QStringLiteral("saved.json"));
    QVERIFY2(again.ok(), qPrintable(again.errors().join(QLatin1Char('\n'))));
    QVERIFY(again.lesson->units == r.lesson->units);
    // A pixel lesson saves without the key.
    QVERIFY(!saveLesson(*pixels.lesson).contains("\"units\""));
}

void GuiUnitsTest::lessonUnitsRefused()
{
    struct Bad {
        QByteArray units;
        QString field;
    };
    const Bad cases[] = {{R"({"px_per_metre": 0})", QStringLiteral("units.px_per_metre")},
                         {R"({"px_per_metre": -100})", QStringLiteral("units.px_per_metre")},
                         {R"({"kg_per_mass": 1e300})", QStringLiteral("units.kg_per_mass")},
                         {R"({"px_per_metre": "100"})", QStringLiteral("units.px_per_metre")},
                         {R"({"px_per_meter": 100})", QStringLiteral("units")},
                         {R"(100)", QStringLiteral("units")}};
    for (const Bad& bad : cases) {
        const LoadResult r = LessonLoader::loadBytes(lessonWithUnits(bad.units), QStringLiteral("bad.json"));
        QVERIFY2(!r.ok(), bad.units.constData());
        const QStringList errors = r.errors();
        QCOMPARE(errors.size(), 1);
        // One line naming the file and the field.
        QVERIFY2(errors.front().contains(QStringLiteral("bad.json")) && errors.front().contains(bad.field),
                 qPrintable(errors.front()));
        QVERIFY(!errors.front().contains(QLatin1Char('\n')));
    }
}

void GuiUnitsTest::typedSiReachesTheWorld()
{
    // Lesson 07 speaks SI at 100 px = 1 m.
    test::Workbench w(QStringLiteral("gravity"));
    QVERIFY(w.ready());
    auto* si = w.window.findChild<QAction*>(QStringLiteral("siUnitsAction"));
    auto* pixels = w.window.findChild<QAction*>(QStringLiteral("pixelUnitsAction"));
    QVERIFY(si && pixels);
    QVERIFY(si->isChecked());
    QVERIFY(displayUnits().si);

    auto* spin = w.window.parameterPanel()->findChild<NumberSpinBox*>(QStringLiteral("gravityYSpin"));
    QVERIFY(spin);
    QCOMPARE(spin->suffix(), QStringLiteral(" m/s²"));
    QCOMPARE(spin->value(), 9.8); // the world's 980 px/s²
    QCOMPARE(w.controller()->world().settings().gravity.g.y(), 980.0);

    // Typed in SI: the Moon's 1.62 m/s² reaches the world as 162 px/s².
    auto type = [spin](const QString& text) {
        spin->setFocus();
        spin->selectAll();
        QTest::keyClicks(spin, text);
        QTest::keyClick(spin, Qt::Key_Return);
    };
    type(QStringLiteral("1.62"));
    QTRY_COMPARE(w.controller()->world().settings().gravity.g.y(), 162.0);
    QCOMPARE(spin->value(), 1.62);
    type(QStringLiteral("9.8"));
    QTRY_COMPARE(w.controller()->world().settings().gravity.g.y(), 980.0);
    QCOMPARE(spin->value(), 9.8);

    // Back to pixels: the same world value in px/s².
    pixels->trigger();
    QVERIFY(!displayUnits().si);
    QCOMPARE(spin->suffix(), QStringLiteral(" px/s²"));
    QCOMPARE(spin->value(), 980.0);
    type(QStringLiteral("1234.5"));
    QTRY_COMPARE(w.controller()->world().settings().gravity.g.y(), 1234.5);
    // Fixed decimals again, as before SI (not SI's four significant digits: "1235").
    QCOMPARE(spin->text(), QStringLiteral("1234.5 px/s²"));

    // The teacher's switch on again, at another scale: 50 px = 1 m.
    w.window.setUnits({.si = true, .pxPerMetre = 50, .kgPerMass = 1});
    QVERIFY(si->isChecked());
    QCOMPARE(spin->value(), 24.69); // 1234.5 px/s² / 50 px per m
    type(QStringLiteral("4"));
    QTRY_COMPARE(w.controller()->world().settings().gravity.g.y(), 200.0);
}

void GuiUnitsTest::readoutsTableInspectorSpeakSi()
{
    test::Workbench w(QStringLiteral("gravity"));
    QVERIFY(w.ready());
    QVERIFY(displayUnits().si);
    const sim::World& world = w.controller()->world();

    const QString readout = WorldPainter::readoutText(world, 0, nullptr).join(QLatin1Char('\n'));
    QVERIFY2(readout.contains(QStringLiteral("m/s")) && !readout.contains(QStringLiteral("px")), qPrintable(readout));
    const QString wide = WorldPainter::readoutText(world, 0, nullptr, true).join(QLatin1Char('\n'));
    QVERIFY2(wide.contains(QStringLiteral("m/s²")) && !wide.contains(QStringLiteral("px")), qPrintable(wide));
    const QString totals = WorldPainter::totalsText(world).join(QLatin1Char('\n'));
    QVERIFY2(totals.contains(QStringLiteral("J")) && totals.contains(QStringLiteral("kg·m/s")) &&
                 !totals.contains(QStringLiteral("px")) && !totals.contains(QStringLiteral("mass")),
             qPrintable(totals));
    // Ball 0 at x = 120 px is 1.2 m.
    QVERIFY2(readout.contains(QStringLiteral("1.2")), qPrintable(readout));

    // The grid's labels speak metres down the left as well as across the
    // top (they said 100, 200, 300 beside 1 m, 2, 3).
    Overlays withGrid = w.window.canvas()->overlays();
    withGrid.grid = true;
    w.window.canvas()->setOverlays(withGrid);
    w.window.canvas()->repaint();
    const PaintedFrame& frame = w.window.canvas()->painter().lastFrame();
    QVERIFY(frame.gridStep > 0.0 && !frame.gridLabelsX.isEmpty() && !frame.gridLabelsY.isEmpty());
    QVERIFY2(frame.gridLabelsX.front().endsWith(QStringLiteral(" m")), qPrintable(frame.gridLabelsX.front()));
    double last = -1.0;
    for (const QString& label : frame.gridLabelsY) {
        // Each label is a whole number of grid steps, in m at 100 px = 1 m,
        // inside the 4 m tall box, one step below the last.
        const double metres = humanNumberValue(label).value_or(-1.0);
        const double steps = metres * 100.0 / frame.gridStep;
        QVERIFY2(metres >= 0.0 && metres <= 4.0 && std::abs(steps - std::round(steps)) < 1e-6 &&
                     (last < 0.0 || std::abs((metres - last) * 100.0 - frame.gridStep) < 1e-6),
                 qPrintable(frame.gridLabelsY.join(QLatin1Char(' '))));
        last = metres;
    }

    // The ball table: headers in m and m/s, numbers in m, a typed 2.5 m is 250 px.
    BallTableModel* model = w.window.findChild<BallTable*>()->model();
    QCOMPARE(model->headerData(BallTableModel::X, Qt::Horizontal).toString(), QStringLiteral("x (m)"));
    QCOMPARE(model->headerData(BallTableModel::Vy, Qt::Horizontal).toString(), QStringLiteral("vy (m/s)"));
    QCOMPARE(model->headerData(BallTableModel::Mass, Qt::Horizontal).toString(), QStringLiteral("mass (kg)"));
    for (int c = 0; c < BallTableModel::ColumnCount; ++c)
        QVERIFY(!model->headerData(c, Qt::Horizontal).toString().contains(QStringLiteral("px")));
    QCOMPARE(model->data(model->index(0, BallTableModel::X), BallTableModel::kSortRole).toDouble(), 1.2);
    QVERIFY(model->setData(model->index(0, BallTableModel::X), QStringLiteral("2.5")));
    QTRY_COMPARE(world.balls().position(0, 0), 250.0);

    // The Inspector on ball 0.
    InspectorDock* inspector = w.window.inspectorDock();
    inspector->show();
    inspector->raise();
    inspector->setSelectedBall(0);
    inspector->refresh();
    for (const char* name : {"inspectorPosition", "inspectorVelocity", "inspectorAcceleration", "inspectorMass"}) {
        auto* label = inspector->findChild<QLabel*>(QString::fromLatin1(name));
        QVERIFY(label);
        QVERIFY2(!label->text().contains(QStringLiteral("px")), qPrintable(label->text()));
    }
    QVERIFY(inspector->findChild<QLabel*>(QStringLiteral("inspectorVelocity"))->text().contains(QStringLiteral("m/s")));
    QVERIFY(inspector->findChild<QLabel*>(QStringLiteral("inspectorPosition"))->text().contains(QStringLiteral("2.5")));
    QVERIFY(inspector->findChild<QLabel*>(QStringLiteral("inspectorMass"))->text().contains(QStringLiteral("kg")));

    // The graphs' titles name the SI units.
    PlotsDock* plots = w.window.plotsDock();
    plots->refreshCharts();
    plots->quantityGraph()->refresh();
    QStringList titles;
    for (QChartView* view : plots->findChildren<QChartView*>())
        titles << view->chart()->title();
    const QString all = titles.join(QStringLiteral(" | "));
    QVERIFY2(all.contains(QStringLiteral("J)")) && all.contains(QStringLiteral("kg·m/s)")), qPrintable(all));
    QVERIFY2(!all.contains(QStringLiteral("px")) && !all.contains(QStringLiteral("mass")), qPrintable(all));

    plots->speedHistogram()->refresh();
    QStringList axes;
    for (QAbstractAxis* axis : plots->speedHistogram()->chart()->axes())
        axes << axis->titleText();
    QVERIFY2(axes.contains(QStringLiteral("speed (m/s)")), qPrintable(axes.join(QStringLiteral(" | "))));
    QVERIFY2(!axes.join(QString()).contains(QStringLiteral("px")), qPrintable(axes.join(QStringLiteral(" | "))));

    // The stopwatch's line: its 300 px shown as 3 m.
    auto* line = w.window.findChild<QDoubleSpinBox*>(QStringLiteral("stopwatchLine"));
    QVERIFY(line);
    QCOMPARE(line->suffix(), QStringLiteral(" m"));
    QCOMPARE(line->value(), 3.0);

    // Pixels again: the same texts speak px.
    w.window.findChild<QAction*>(QStringLiteral("pixelUnitsAction"))->trigger();
    QVERIFY(WorldPainter::readoutText(world, 0, nullptr).join(QLatin1Char('\n')).contains(QStringLiteral("px/s")));
    QCOMPARE(model->headerData(BallTableModel::X, Qt::Horizontal).toString(), QStringLiteral("x (px)"));
    QVERIFY(inspector->findChild<QLabel*>(QStringLiteral("inspectorVelocity"))->text().contains(QStringLiteral("px/s")));
    QCOMPARE(line->suffix(), QStringLiteral(" px"));
    QCOMPARE(line->value(), 300.0);
}

void GuiUnitsTest::scaleDialogSetsTheScale()
{
    // A lesson without units opens in pixels; the teacher sets 50 px = 1 m
    // and 2 kg per mass unit in the View → Units dialog, which switches SI on.
    test::Workbench w(QStringLiteral("balls-on-a-canvas"));
    QVERIFY(w.ready());
    QVERIFY(!displayUnits().si);
    QVERIFY(w.window.findChild<QAction*>(QStringLiteral("pixelUnitsAction"))->isChecked());
    bool answered = false;
    QTimer::singleShot(0, &w.window, [&] {
        auto* dialog = w.window.findChild<QDialog*>(QStringLiteral("unitScaleDialog"));
        if (!dialog)
            return;
        dialog->findChild<QDoubleSpinBox*>(QStringLiteral("pxPerMetreSpin"))->setValue(50.0);
        dialog->findChild<QDoubleSpinBox*>(QStringLiteral("kgPerMassSpin"))->setValue(2.0);
        answered = true;
        dialog->accept();
    });
    QAction* scale = w.window.findChild<QAction*>(QStringLiteral("unitScaleAction"));
    QVERIFY(scale);
    scale->trigger(); // returns when the dialog is closed
    QVERIFY(answered);
    QVERIFY(displayUnits().si);
    QCOMPARE(displayUnits().pxPerMetre, 50.0);
    QCOMPARE(displayUnits().kgPerMass, 2.0);
    QVERIFY(w.window.findChild<QAction*>(QStringLiteral("siUnitsAction"))->isChecked());
    QVERIFY2(scale->text().contains(QStringLiteral("50 px = 1 m")), qPrintable(scale->text()));
    // The ball table's mass column now in kg: twice the mass units.
    BallTableModel* model = w.window.findChild<BallTable*>()->model();
    QCOMPARE(model->data(model->index(0, BallTableModel::Mass), BallTableModel::kSortRole).toDouble(),
             2.0 * w.balls().mass[0]);
}


// The ruler, the Predict panel and the spawn-speed rows speak SI too: what
// a student reads and types is in m and m/s, and reaches the world in px.
void GuiUnitsTest::toolsSpeakSiToo()
{
    {
        // Lesson 02 lists the spawn speeds; the teacher switches to SI at 100 px = 1 m.
        test::Workbench w(QStringLiteral("animation"));
        QVERIFY(w.ready());
        w.window.setUnits({.si = true, .pxPerMetre = 100, .kgPerMass = 1});
        auto* spin = w.window.parameterPanel()->findChild<NumberSpinBox*>(QStringLiteral("spawnMaxSpeedSpin"));
        QVERIFY(spin);
        QCOMPARE(spin->suffix(), QStringLiteral(" m/s"));
        QCOMPARE(spin->value(), w.controller()->spawn().maxSpeed / 100.0);
        spin->setFocus();
        spin->selectAll();
        QTest::keyClicks(spin, QStringLiteral("3.5"));
        QTest::keyClick(spin, Qt::Key_Return);
        QTRY_COMPARE(w.controller()->spawn().maxSpeed, 350.0);

        // The ruler: 300 by 400 px is 5 m, at 53.13° (y down, measured as seen).
        Canvas* canvas = w.window.canvas();
        const QPoint a = canvas->worldToWidget(sim::Vec2(100, 450)).toPoint();
        const QPoint b = canvas->worldToWidget(sim::Vec2(400, 50)).toPoint();
        QTest::mousePress(canvas, Qt::LeftButton, Qt::ShiftModifier, a);
        QMouseEvent move(QEvent::MouseMove, QPointF(b), canvas->mapToGlobal(QPointF(b)), Qt::NoButton, Qt::LeftButton,
                         Qt::ShiftModifier);
        QCoreApplication::sendEvent(canvas, &move);
        QTest::mouseRelease(canvas, Qt::LeftButton, Qt::ShiftModifier, b);
        QVERIFY(canvas->ruler().shown);
        const QString text = canvas->rulerTexts().value(0);
        QVERIFY2(text.contains(QStringLiteral(" m at ")), qPrintable(text));
        const double metres = humanNumberValue(text).value_or(0.0);
        QVERIFY2(std::abs(metres - canvas->ruler().length() / 100.0) <= 5e-4 * metres, qPrintable(text));
        w.window.setUnits({});
        QVERIFY2(canvas->rulerTexts().value(0).contains(QStringLiteral(" px at ")), qPrintable(canvas->rulerTexts().value(0)));
    }
    {
        // Lesson 08 asks how high the red ball rises (its claim is in px).
        test::Workbench w(QStringLiteral("losing-energy"));
        QVERIFY(w.ready());
        w.window.setUnits({.si = true, .pxPerMetre = 100, .kgPerMass = 1});
        auto* dock = w.window.findChild<QWidget*>(QStringLiteral("predictDock"));
        QVERIFY(dock);
        QCOMPARE(dock->findChild<QLabel*>(QStringLiteral("predictUnit"))->text(), QStringLiteral("m"));
        auto* number = dock->findChild<QLineEdit*>(QStringLiteral("predictNumber"));
        number->setText(QStringLiteral("2"));
        dock->findChild<QPushButton*>(QStringLiteral("predictRun"))->click();
        auto* show = dock->findChild<QPushButton*>(QStringLiteral("predictShow"));
        QTRY_VERIFY_WITH_TIMEOUT(show->isEnabled(), 30000);
        show->click();
        const QString result = dock->findChild<QLabel*>(QStringLiteral("predictResult"))->text();
        QVERIFY2(result.contains(QStringLiteral("You said <b>2 m</b>")), qPrintable(result));
        // The measured rise, 211.2 px ± 5% in the lesson's claim, read in m.
        const QRegularExpression measured(QStringLiteral("Measured: <b>([0-9.]+) m</b>"));
        const QRegularExpressionMatch m = measured.match(result);
        QVERIFY2(m.hasMatch(), qPrintable(result));
        QVERIFY2(std::abs(m.captured(1).toDouble() - 2.112) <= 0.05 * 2.112, qPrintable(result));
    }
}

QTEST_MAIN(GuiUnitsTest)
#include "test_gui_units.moc"
