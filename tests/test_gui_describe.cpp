// Describe the Scene (D, and after every pause): the stage in words, built
// from the world's own numbers, given to the canvas's accessible description
// and the status bar. The wall time is checked against the run itself.

#include "gui_workbench.h"

#include "sim/studies/wall_arrival.h"
#include "ui/canvas/canvas.h"
#include "ui/drawing/display_units.h"
#include "ui/drawing/human_number.h"
#include "ui/drawing/world_painter.h"

#include <QAccessible>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTest>

using namespace forcelab;

class GuiDescribeTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void theKeyDescribesTheWorldsNumbers();
    void aPauseDescribesTheNewMoment();
};

// Lesson 07 at step 20: ball 0 falls under gravity alone. The sentence names
// the count, the ball's speed in the shown units, the floor and the time to
// it (which the run itself meets within one step), and the total energy.
void GuiDescribeTest::theKeyDescribesTheWorldsNumbers()
{
    test::Workbench w(QStringLiteral("gravity"));
    QVERIFY(w.ready());
    QVERIFY(w.controller()->runToStep(20));
    w.window.canvas()->setSelectedBall(0);
    QTest::keyClick(w.window.canvas(), Qt::Key_D);
    const QString said = w.window.sceneDescription();
    QVERIFY(!said.isEmpty());
    const sim::World& world = w.controller()->world();
    const sim::BallState& b = world.balls();
    QVERIFY2(said.startsWith(QStringLiteral("%1 balls.").arg(b.size())), qPrintable(said));
    QVERIFY2(said.contains(quantityText(b.velocity.col(0).norm(), QStringLiteral("px/s"), 2)), qPrintable(said));
    QVERIFY2(said.contains(QStringLiteral("Total energy %1.").arg(quantityText(world.energy().total(), WorldPainter::kEnergyUnit, 2))),
             qPrintable(said));

    const auto arrival = sim::nextWallArrival(world.settings().box, world.settings().walls, b.position.col(0),
                                              b.velocity.col(0), world.accelerations().col(0), b.radius[0]);
    QVERIFY(arrival && arrival->side == sim::WallSide::Bottom);
    QVERIFY2(said.contains(QStringLiteral("will hit the floor in %1 s").arg(humanNumber(arrival->seconds, 2))),
             qPrintable(said));
    // The run meets the floor within one step of that time: the step whose end has ball 0 bounced.
    sim::World run = world;
    const double start = run.time();
    while (run.balls().velocity(1, 0) > 0.0 && run.time() - start < 10.0)
        run.step();
    const double dt = world.settings().time.dt;
    QVERIFY2(std::abs((run.time() - start) - arrival->seconds) <= dt,
             qPrintable(QStringLiteral("bounced after %1 s, said %2 s").arg(run.time() - start).arg(arrival->seconds)));

    // A screen reader reads the same words from the canvas.
    QAccessibleInterface* canvas = QAccessible::queryAccessibleInterface(w.window.canvas());
    QVERIFY(canvas);
    QCOMPARE(canvas->text(QAccessible::Description), said);
    QCOMPARE(w.window.statusBar()->currentMessage(), said);
}

void GuiDescribeTest::aPauseDescribesTheNewMoment()
{
    test::Workbench w(QStringLiteral("gravity"));
    QVERIFY(w.ready());
    QTest::keyClick(w.window.canvas(), Qt::Key_D);
    const QString atStart = w.window.sceneDescription();
    w.controller()->play();
    QTRY_VERIFY(w.controller()->world().time() > 0.2);
    w.controller()->pause();
    QTRY_VERIFY(w.window.sceneDescription() != atStart);
    QCOMPARE(w.window.canvas()->accessibleDescription(), w.window.sceneDescription());
}

QTEST_MAIN(GuiDescribeTest)
#include "test_gui_describe.moc"
