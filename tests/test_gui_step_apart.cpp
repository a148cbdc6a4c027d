// The One Step Apart panel on the real workbench: the stages of one step in
// the order the JavaScript runs them, their numbers at full precision, and
// the last row against the engine's own next step, bit for bit.

#include "gui_workbench.h"
#include "ui/canvas/canvas.h"
#include "ui/docks/step_apart_dock.h"
#include "ui/script/script_pieces.h"

#include "lessons/lesson_loader.h"

#include "sim/world/world.h"

#include <QPushButton>
#include <QTest>

#include <cstring>

using namespace forcelab;
using Kind = StepApartRow::Kind;

namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

int indexOf(const QList<StepApartRow>& rows, Kind kind)
{
    for (int i = 0; i < rows.size(); ++i)
        if (rows[i].kind == kind)
            return i;
    return -1;
}

// The dock raised over its tab group, visible and filled.
StepApartDock* showDock(test::Workbench& bench)
{
    StepApartDock* dock = bench.window.stepApartDock();
    dock->show();
    dock->raise();
    return dock;
}

} // namespace

class GuiStepApartTest : public QObject {
    Q_OBJECT
private slots:
    void gravityStepInOrderAndBitForBit();
    void collisionNamesThePairAndItsResponse();
    void stepBackShowsTheStepBefore();
    void lessonWithoutJavaScriptSaysSo();
    void playingAsksToPause();
    void everyCoveredLessonMatchesTheEngine();
    void eachSubStepHasItsRows();
};

// Lesson 07, semi-implicit Euler with gravity: forces, acceleration,
// velocity, then position; vy after the velocity row is vy0 + h·g exactly,
// and the check row is the engine's next step.
void GuiStepApartTest::gravityStepInOrderAndBitForBit()
{
    test::Workbench bench(QStringLiteral("07-gravity"));
    QVERIFY(bench.ready());
    bench.controller()->pause();
    bench.window.canvas()->setSelectedBall(0);
    StepApartDock* dock = showDock(bench);
    QTRY_VERIFY(dock->isVisible() && !dock->rows().isEmpty());
    QVERIFY2(dock->message().isEmpty(), qPrintable(dock->message()));

    const sim::World& world = bench.controller()->world();
    const QList<StepApartRow>& rows = dock->rows();
    const int force = indexOf(rows, Kind::Force);
    const int acceleration = indexOf(rows, Kind::Acceleration);
    const int velocity = indexOf(rows, Kind::Velocity);
    const int position = indexOf(rows, Kind::Position);
    const int walls = indexOf(rows, Kind::Rule);
    QVERIFY(force >= 0 && force < acceleration && acceleration < velocity && velocity < position && position < walls);
    QVERIFY2(rows[force].stage.contains(QStringLiteral("gravity")), qPrintable(rows[force].stage));
    QVERIFY2(rows[velocity].code.join(QLatin1Char('\n')).contains(QStringLiteral("step_semi_implicit_euler.js:")),
             qPrintable(rows[velocity].code.join(QLatin1Char('\n'))));
    QVERIFY(rows[velocity].code.join(QLatin1Char('\n')).contains(QStringLiteral("b.vy = b.vy + h * acc[i].y;")));
    QVERIFY(rows[position].code.join(QLatin1Char('\n')).contains(QStringLiteral("b.y = b.y + h * b.vy;")));
    QVERIFY2(rows[walls].note.contains(QStringLiteral("no wall touched")), qPrintable(rows[walls].note));

    const sim::WorldSettings& s = world.settings();
    const double h = s.time.dt / s.time.substeps;
    const double vy0 = world.balls().velocity(1, 0);
    QCOMPARE(rows[force].ay, s.gravity.g.y());
    QVERIFY(sameBits(rows[velocity].vy, vy0 + h * s.gravity.g.y()));
    QVERIFY(sameBits(rows[velocity].y, world.balls().position(1, 0))); // the position has not moved yet

    sim::World copy = world;
    copy.step();
    const StepApartRow& check = rows.last();
    QCOMPARE(check.kind, Kind::Check);
    QVERIFY2(check.ok, qPrintable(check.note));
    QVERIFY(sameBits(check.x, copy.balls().position(0, 0)) && sameBits(check.y, copy.balls().position(1, 0)));
    QVERIFY(sameBits(check.vx, copy.balls().velocity(0, 0)) && sameBits(check.vy, copy.balls().velocity(1, 0)));
    QVERIFY(dock->shownText().contains(QStringLiteral("matches the engine bit for bit")));
}

// Lesson 29, run to the step just before a contact: the detection row names
// the pair, and the response row's velocity is the engine's after the step.
void GuiStepApartTest::collisionNamesThePairAndItsResponse()
{
    test::Workbench bench(QStringLiteral("29-the-line-of-impact"));
    QVERIFY(bench.ready());
    SimulationController* controller = bench.controller();
    controller->pause();
    sim::World next = controller->world();
    int steps = 0;
    for (next.step(); next.contacts().empty() && steps < 2000; next.step()) {
        controller->stepOnce();
        ++steps;
    }
    QVERIFY2(!next.contacts().empty(), "no contact in 2000 steps");
    QCOMPARE(controller->world().stepCount() + 1, next.stepCount());
    const sim::Contact contact = next.contacts().front();
    bench.window.canvas()->setSelectedBall(contact.a);
    StepApartDock* dock = showDock(bench);
    QTRY_VERIFY(dock->isVisible() && dock->ball() == contact.a && !dock->rows().isEmpty());

    const QList<StepApartRow>& rows = dock->rows();
    const int detection = indexOf(rows, Kind::Detection);
    const int response = indexOf(rows, Kind::Response);
    QVERIFY(detection >= 0 && response > detection);
    QVERIFY(rows[detection].pairs.contains(qMakePair(contact.a, contact.b)));
    QVERIFY2(rows[detection].note.contains(QStringLiteral("ball %1 and ball %2").arg(contact.a).arg(contact.b)),
             qPrintable(rows[detection].note));
    QCOMPARE(rows[response].other, contact.b);
    // No force in this lesson: the acceleration row says so.
    const int acceleration = indexOf(rows, Kind::Acceleration);
    QVERIFY(acceleration >= 0 && indexOf(rows, Kind::Force) < 0);
    QVERIFY2(rows[acceleration].note.contains(QStringLiteral("no force")), qPrintable(rows[acceleration].note));
    // Nothing after the response changes a velocity in this lesson (the
    // push-apart moves positions only), so its velocity is the engine's.
    QVERIFY(sameBits(rows[response].vx, next.balls().velocity(0, contact.a)));
    QVERIFY(sameBits(rows[response].vy, next.balls().velocity(1, contact.a)));
    QVERIFY2(rows.last().ok, qPrintable(rows.last().note));
}

// "◀ Step back" takes the world one step back and the panel then shows the
// step from there.
void GuiStepApartTest::stepBackShowsTheStepBefore()
{
    test::Workbench bench(QStringLiteral("07-gravity"));
    QVERIFY(bench.ready());
    SimulationController* controller = bench.controller();
    controller->pause();
    StepApartDock* dock = showDock(bench);
    auto* step = dock->findChild<QPushButton*>(QStringLiteral("stepApartStep"));
    auto* back = dock->findChild<QPushButton*>(QStringLiteral("stepApartBack"));
    QVERIFY(step && back);
    QTRY_VERIFY(dock->isVisible());
    const qint64 start = controller->world().stepCount();
    QTest::mouseClick(step, Qt::LeftButton);
    QTest::mouseClick(step, Qt::LeftButton);
    QTRY_COMPARE(controller->world().stepCount(), start + 2);
    const double vyAfterTwo = dock->rows().last().vy;
    QTest::mouseClick(back, Qt::LeftButton);
    QTRY_COMPARE(controller->world().stepCount(), start + 1);
    sim::World copy = controller->world();
    copy.step();
    QVERIFY(sameBits(dock->rows().last().vy, copy.balls().velocity(1, 0)));
    QVERIFY(!sameBits(dock->rows().last().vy, vyAfterTwo));
    QVERIFY2(dock->rows().last().ok, qPrintable(dock->rows().last().note));
}

// Lesson 41 runs a force the course has no JavaScript for: the panel says
// so and shows nothing else.
void GuiStepApartTest::lessonWithoutJavaScriptSaysSo()
{
    test::Workbench bench(QStringLiteral("41-write-your-own-force"));
    QVERIFY(bench.ready());
    bench.controller()->pause();
    StepApartDock* dock = showDock(bench);
    QTRY_VERIFY(dock->isVisible() && !dock->message().isEmpty());
    QVERIFY2(dock->message().contains(QStringLiteral("no JavaScript yet")), qPrintable(dock->message()));
    QVERIFY(dock->rows().isEmpty());
}

// While the world plays the panel runs no JavaScript and asks for a pause;
// paused, it takes the step apart again.
void GuiStepApartTest::playingAsksToPause()
{
    test::Workbench bench(QStringLiteral("07-gravity"));
    QVERIFY(bench.ready());
    SimulationController* controller = bench.controller();
    controller->pause();
    StepApartDock* dock = showDock(bench);
    QTRY_VERIFY(dock->isVisible() && !dock->rows().isEmpty());
    controller->play();
    QTRY_VERIFY(dock->rows().isEmpty() && dock->message().startsWith(QStringLiteral("Pause")));
    controller->pause();
    QTRY_VERIFY(!dock->rows().isEmpty() && dock->message().isEmpty());
    QVERIFY2(dock->rows().last().ok, qPrintable(dock->rows().last().note));
}

// The wrappers only watch: in every lesson the JavaScript covers, the step
// taken apart is still the engine's, at the start and 90 steps in, for the
// first ball and the last.
void GuiStepApartTest::everyCoveredLessonMatchesTheEngine()
{
    int covered = 0;
    for (const QString& file : LessonLoader::builtInFiles()) {
        const LoadResult loaded = LessonLoader::load(file);
        QVERIFY2(loaded.ok(), qPrintable(file));
        SimulationController controller;
        if (controller.setScene(loaded.lesson->scene))
            continue;
        if (!scriptPiecesFor(controller.world().settings(), controller.world().spawn()).missing.isEmpty())
            continue;
        StepApartDock dock(&controller);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        for (int run = 0; run < 2; ++run) {
            const int last = controller.world().balls().size() - 1;
            for (int ball : {0, last}) {
                if (last < 0)
                    break; // no ball yet (they appear as it runs)
                dock.setSelectedBall(ball);
                const QString what =
                    QStringLiteral("%1 step %2 ball %3").arg(file).arg(controller.world().stepCount()).arg(ball);
                QVERIFY2(dock.message().isEmpty(), qPrintable(what + QStringLiteral(": ") + dock.message()));
                QVERIFY2(!dock.rows().isEmpty() && dock.rows().last().ok,
                         qPrintable(what + QStringLiteral(": ") + dock.rows().value(dock.rows().size() - 1).note));
            }
            dock.hide(); // hidden, the panel does not follow the 90 steps
            for (int k = 0; k < 90; ++k)
                controller.stepOnce();
            dock.show();
        }
        ++covered;
    }
    QVERIFY2(covered >= 25, qPrintable(QString::number(covered)));
}

// With 8 sub-steps each has its own rows, h = dt / 8; the panel shows one at
// a time, and the rows still end on the engine's step.
void GuiStepApartTest::eachSubStepHasItsRows()
{
    const LoadResult loaded = LessonLoader::load(QStringLiteral("07-gravity"));
    QVERIFY(loaded.ok());
    SimulationController controller;
    QVERIFY(!controller.setScene(loaded.lesson->scene));
    sim::WorldSettings s = controller.world().settings();
    s.time.substeps = 8;
    QVERIFY(controller.setSettings(s));
    StepApartDock dock(&controller);
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));
    QTRY_VERIFY(!dock.rows().isEmpty());
    QList<int> velocityRows;
    for (const StepApartRow& row : dock.rows())
        if (row.kind == Kind::Velocity)
            velocityRows << row.subStep;
    QCOMPARE(velocityRows, (QList<int>{0, 1, 2, 3, 4, 5, 6, 7}));
    const double h = s.time.dt / 8;
    const double vy0 = controller.world().balls().velocity(1, 0);
    QVERIFY(sameBits(dock.rows()[indexOf(dock.rows(), Kind::Velocity)].vy, vy0 + h * s.gravity.g.y()));
    QCOMPARE(dock.shownSubStep(), 1);
    QVERIFY(dock.shownText().contains(QStringLiteral("Sub-step 1 of 8")));
    QVERIFY(!dock.shownText().contains(QStringLiteral("Sub-step 2 of 8")));
    dock.showSubStep(8);
    QVERIFY(dock.shownText().contains(QStringLiteral("Sub-step 8 of 8")));
    QVERIFY(dock.shownText().contains(QStringLiteral("matches the engine bit for bit")));
    QVERIFY2(dock.rows().last().ok, qPrintable(dock.rows().last().note));
}

QTEST_MAIN(GuiStepApartTest)
#include "test_gui_step_apart.moc"
