// Building and changing a scene in front of the class, through the real
// widgets: the right-click menu, mouse drags of a ball and of its velocity
// arrow, the ball table and the keys. Each edit is one undo step that brings
// every field back bit for bit, and each challenge of the shipped lessons
// that asks for a changed ball is done through the editor and checked
// against what physics says must then happen.

#include "gui_workbench.h"
#include "ui/canvas/canvas.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/controls/ball_clipboard.h"
#include "ui/controls/ball_table.h"
#include "ui/controls/ball_table_model.h"
#include "ui/controls/readable_numbers.h"
#include "ui/controls/settings_editor.h"
#include "ui/window/main_window.h"

#include "lessons/lesson_loader.h"

#include "sim/world/ball_placement.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStyle>
#include <QStyleOptionViewItem>
#include <QTableView>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <numbers>

using namespace forcelab;
using forcelab::test::sendMouse;

namespace {

// Every field of every ball, compared bit for bit.
bool sameBalls(const sim::BallState& a, const sim::BallState& b)
{
    return a.size() == b.size() && a.position == b.position && a.velocity == b.velocity && a.radius == b.radius &&
           a.mass == b.mass && a.inverseMass == b.inverseMass && a.charge == b.charge && a.color == b.color &&
           a.home == b.home && a.pinned == b.pinned && a.restitution == b.restitution;
}

// A press, a few moves and a release after the hand has stood still for
// longer than the throw window (a drop, not a throw).
void drag(QWidget* w, QPointF from, QPointF to, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    sendMouse(w, QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton, modifiers);
    for (int k = 1; k <= 5; ++k)
        sendMouse(w, QEvent::MouseMove, from + (to - from) * (k / 5.0), Qt::NoButton, Qt::LeftButton, modifiers);
    sendMouse(w, QEvent::MouseMove, to, Qt::NoButton, Qt::LeftButton, modifiers, 2 * int(Canvas::kThrowWindowMs));
    sendMouse(w, QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton, modifiers, 2 * int(Canvas::kThrowWindowMs));
}

QAction* menuAction(QMenu& menu, const QString& text)
{
    for (QAction* a : menu.actions())
        if (a->text() == text)
            return a;
    return nullptr;
}

struct Workbench : test::Workbench {
    using test::Workbench::Workbench;
    QUndoStack* undo() { return window.findChild<QUndoStack*>(QStringLiteral("parameterUndoStack")); }
    QTableView* table()
    {
        auto* dock = window.findChild<QDockWidget*>(QStringLiteral("ballsDock"));
        dock->show();
        dock->raise();
        return dock->findChild<QTableView*>(QStringLiteral("ballTableView"));
    }
    BallTable* ballTable() { return window.findChild<QDockWidget*>(QStringLiteral("ballsDock"))->findChild<BallTable*>(); }
    // Types `text` into the table's cell of `ball` and `column`, as a student
    // does: the cell's editor opens, the text replaces its content, Return.
    bool type(int ball, int column, const QString& text)
    {
        QTableView* view = table();
        if (!QTest::qWaitForWindowExposed(view->window()) || !QTest::qWaitFor([view] { return view->isVisible(); }))
            return false;
        const int row = ballTable()->rowOf(ball);
        const QModelIndex at = view->model()->index(row, column);
        view->setCurrentIndex(at);
        view->edit(at);
        QLineEdit* editor = nullptr;
        if (!QTest::qWaitFor([&] {
                editor = qobject_cast<QLineEdit*>(QApplication::focusWidget());
                return editor != nullptr && view->isAncestorOf(editor);
            })) {
            return false;
        }
        editor->selectAll();
        if (text.isEmpty())
            QTest::keyClick(editor, Qt::Key_Backspace); // an empty cell
        else
            QTest::keyClicks(editor, text);
        QTest::keyClick(editor, Qt::Key_Return);
        // The delegate commits the text in a queued call, then closes the editor.
        return QTest::qWaitFor([view] {
            for (const QLineEdit* open : view->findChildren<QLineEdit*>())
                if (open->isVisible())
                    return false;
            return true;
        });
    }
    void run(double seconds)
    {
        sim::World& world = controller()->mutableWorld();
        const auto steps = static_cast<int>(std::lround(seconds / world.settings().time.dt));
        for (int k = 0; k < steps; ++k)
            world.step();
    }
};

} // namespace

class GuiEditingTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void addDragArrowDeleteAndUndo();
    void aBallDroppedOnAnotherIsMovedToTouching();
    void typedValuesAreCheckedAndNamedTheirRange();
    void copyAndPasteABall();
    void humanNumbers();
    void lesson19FasterMoonFliesAnEllipse();
    void lesson19MoonAsHeavyAsTheEarth();
    void lesson27EqualMassesSwapVelocities();
    void lesson27HeavyAgainstLight();
    void lesson29TwiceAsBig();
    void lesson30TwoBallsIn();
    void lesson31DoubleSpeedAndHeavier();
    void aLessonMayGiveADensity();
    void anEditInThePastIsANewFutureUndoneToTheOld();
    void pinFromTheTableHoldsTheBallWhilePlaying();
    void pinFromTheMenuIsOneUndoStep();
    void restitutionIsTypedAndClearedInTheTable();
};

// The whole round: a ball added with the right-click menu, dragged with the
// mouse, its velocity set by dragging its arrow (Ctrl snaps to tens of px/s),
// deleted with the Delete key; then every step undone, back to the lesson's
// balls bit for bit, and redone.
void GuiEditingTest::addDragArrowDeleteAndUndo()
{
    Workbench w(QStringLiteral("the-line-of-impact"));
    QVERIFY(w.ready());
    Canvas* canvas = w.window.canvas();
    const sim::BallState start = w.balls();
    QCOMPARE(start.size(), 2);

    // Add a ball on empty space.
    const QPointF empty = canvas->worldToWidget(sim::Vec2(450, 100));
    QMenu menu;
    canvas->fillContextMenu(menu, empty);
    QAction* add = menuAction(menu, QStringLiteral("Add a ball here"));
    QVERIFY(add && add->isEnabled());
    add->trigger();
    QCOMPARE(w.balls().size(), 3);
    QCOMPARE(canvas->selectedBall(), 2);
    QVERIFY((sim::Vec2(w.balls().position.col(2)) - sim::Vec2(450, 100)).norm() < 1e-9);
    QCOMPARE(w.balls().mass[2], sim::sphereMass(w.balls().radius[2]));
    const sim::BallState added = w.balls();

    // Drag it 80 px (widget) to the left.
    const QPointF from = canvas->worldToWidget(sim::Vec2(450, 100));
    const QPointF to = from + QPointF(-80, 40);
    drag(canvas, from, to);
    const sim::Vec2 dropped = w.balls().position.col(2);
    QVERIFY2((dropped - canvas->widgetToWorld(to)).norm() < 1e-6, qPrintable(QString::number(dropped.x())));
    QCOMPARE(w.balls().velocity(0, 2), 0.0); // dropped, not thrown: the hand stood still at the end

    // Drag the tip of its velocity arrow with Ctrl: velocity in whole tens.
    canvas->setSelectedBall(2);
    const QPointF centre = canvas->worldToWidget(dropped);
    const QPointF target = centre + QPointF(63, -17);
    drag(canvas, centre, target, Qt::AltModifier | Qt::ControlModifier);
    const sim::Vec2 v = w.balls().velocity.col(2);
    QVERIFY2(v.norm() > 0.0, "the arrow set no velocity");
    QCOMPARE(std::fmod(v.x(), Canvas::kVelocitySnap), 0.0);
    QCOMPARE(std::fmod(v.y(), Canvas::kVelocitySnap), 0.0);
    QVERIFY(v.x() > 0.0 && v.y() < 0.0); // right and up, as dragged
    QCOMPARE(w.balls().position.col(2), dropped); // the arrow moves no ball
    const sim::BallState aimed = w.balls();

    // Delete it with the key.
    QSignalSpy recount(canvas->editor(), &SettingsEditor::ballCountChanged);
    canvas->setFocus();
    QTest::keyClick(canvas, Qt::Key_Delete);
    QCOMPARE(w.balls().size(), 2);
    QVERIFY(sameBalls(w.balls(), start));
    QCOMPARE(recount.count(), 1); // the paths kept by index start over

    // Four steps, each undone bit for bit, then redone.
    QCOMPARE(w.undo()->count(), 4);
    w.undo()->undo();
    QVERIFY(sameBalls(w.balls(), aimed));
    QCOMPARE(recount.count(), 2); // its undo too
    w.undo()->undo();
    QCOMPARE(sim::Vec2(w.balls().position.col(2)), dropped);
    QCOMPARE(w.balls().velocity(0, 2), 0.0);
    w.undo()->undo();
    QVERIFY(sameBalls(w.balls(), added));
    w.undo()->undo();
    QVERIFY(sameBalls(w.balls(), start));
    for (int k = 0; k < 3; ++k)
        w.undo()->redo();
    QVERIFY(sameBalls(w.balls(), aimed));
}

// A ball dragged onto another lands touching it (the sum of the radii apart,
// to the touching gap), never inside it; dropped over a wall, it is inside.
void GuiEditingTest::aBallDroppedOnAnotherIsMovedToTouching()
{
    Workbench w(QStringLiteral("the-line-of-impact"));
    QVERIFY(w.ready());
    Canvas* canvas = w.window.canvas();
    const sim::Vec2 red = w.balls().position.col(0);
    const sim::Vec2 blue = w.balls().position.col(1);
    drag(canvas, canvas->worldToWidget(red), canvas->worldToWidget(sim::Vec2(blue + sim::Vec2(-5, 3))));
    const double distance = (sim::Vec2(w.balls().position.col(0)) - blue).norm();
    const double touching = w.balls().radius[0] + w.balls().radius[1];
    QVERIFY2(distance >= touching && distance <= touching * (1.0 + 2.0 * sim::kTouchingGap),
             qPrintable(QString::number(distance, 'g', 17)));
    auto* note = w.ballTable()->findChild<QLabel*>(QStringLiteral("ballTableNote"));
    QVERIFY2(note->text().contains(QStringLiteral("touching")), qPrintable(note->text()));

    // Past the right wall: inside, touching it.
    const double width = w.controller()->world().settings().box.width;
    drag(canvas, canvas->worldToWidget(blue), canvas->worldToWidget(sim::Vec2(width + 30, 200)));
    QCOMPARE(w.balls().position(0, 1), width - w.balls().radius[1]);
}

// A typed value out of its range is refused with the range named; the world
// and the undo history are unchanged. A new radius keeps the density.
void GuiEditingTest::typedValuesAreCheckedAndNamedTheirRange()
{
    Workbench w(QStringLiteral("the-line-of-impact"));
    QVERIFY(w.ready());
    const sim::BallState start = w.balls();
    QVERIFY(w.type(0, BallTableModel::Radius, QStringLiteral("0")));
    QVERIFY(sameBalls(w.balls(), start));
    QCOMPARE(w.undo()->count(), 0);
    auto* note = w.ballTable()->findChild<QLabel*>(QStringLiteral("ballTableNote"));
    QVERIFY2(note->text().contains(QStringLiteral("[1e-06, 10000]")), qPrintable(note->text()));

    QVERIFY(w.type(0, BallTableModel::Mass, QStringLiteral("-4")));
    QVERIFY(sameBalls(w.balls(), start));
    QVERIFY2(note->text().contains(QStringLiteral("[1e-12, 1e+15]")), qPrintable(note->text()));

    QVERIFY(w.type(0, BallTableModel::Vx, QStringLiteral("fast")));
    QVERIFY(sameBalls(w.balls(), start));
    QVERIFY2(note->text().contains(QStringLiteral("not a number")), qPrintable(note->text()));

    // Mass and size apart: a small heavy ball.
    QVERIFY(w.type(1, BallTableModel::Mass, QStringLiteral("1e6")));
    QCOMPARE(w.balls().mass[1], 1e6);
    QCOMPARE(w.balls().inverseMass[1], 1.0 / 1e6);
    QCOMPARE(w.balls().radius[1], start.radius[1]);
    QVERIFY(w.type(1, BallTableModel::Radius, QStringLiteral("10")));
    QCOMPARE(w.balls().radius[1], 10.0);
    QVERIFY(std::abs(w.balls().mass[1] - 1e6 / 8.0) <= 1e-9 * 1e6); // same density, half the size: 1/8 the mass
    QCOMPARE(w.undo()->count(), 2);
}

void GuiEditingTest::copyAndPasteABall()
{
    Workbench w(QStringLiteral("the-line-of-impact"));
    QVERIFY(w.ready());
    Canvas* canvas = w.window.canvas();
    canvas->setSelectedBall(0);
    canvas->copySelectedBall();
    const std::optional<sim::Ball> copied = ballFromText(QApplication::clipboard()->text());
    QVERIFY(copied);
    const sim::Ball red = w.balls().ball(0);
    QCOMPARE(copied->velocity, red.velocity);
    QCOMPARE(copied->mass, red.mass);
    QCOMPARE(copied->color, red.color);
    QMenu menu;
    const QPointF at = canvas->worldToWidget(sim::Vec2(450, 320));
    canvas->fillContextMenu(menu, at);
    QAction* paste = menuAction(menu, QStringLiteral("Paste the copied ball here"));
    QVERIFY(paste && paste->isEnabled());
    paste->trigger();
    QCOMPARE(w.balls().size(), 3);
    QCOMPARE(w.balls().velocity.col(2), red.velocity);
    QCOMPARE(w.balls().mass[2], red.mass);
    QString why;
    QVERIFY(!ballFromText(QStringLiteral("{\"x\": 1, \"y\": 2, \"r\": 3, \"spin\": 4}"), &why));
    QVERIFY2(why.contains(QStringLiteral("spin")), qPrintable(why));
    QVERIFY(!ballFromText(QString(5000, QLatin1Char(' ')), &why));
}

void GuiEditingTest::humanNumbers()
{
    QCOMPARE(humanNumber(12.3456, 4), QStringLiteral("12.35"));
    QCOMPARE(humanNumber(-3.0, 4), QStringLiteral("−3"));
    QCOMPARE(humanNumber(4.2e9, 4), QStringLiteral("4.2 × 10⁹"));
    QCOMPARE(humanNumber(1.5e-5, 3), QStringLiteral("1.5 × 10⁻⁵"));
    QCOMPARE(humanNumber(9.99996e6, 4), QStringLiteral("1 × 10⁷"));
    QCOMPARE(humanNumber(0.0042, 4), QStringLiteral("0.0042"));
    QCOMPARE(humanNumber(-1e-20, 4), QStringLiteral("−1 × 10⁻²⁰"));
    QCOMPARE(humanNumber(std::nan(""), 4), QStringLiteral("—"));
}

// Lesson 19, "give the Moon 20% more speed (change its vy)": the orbit
// becomes an ellipse whose far point is where the energy and the angular
// momentum of the two-body problem put it, r_far = 2a − r₀ with
// a = −μ / (2ε), ε = v²/2 − μ/r₀, μ = G (M + m) (the start is the near point:
// the velocity is at right angles to the line between them). To 1%.
void GuiEditingTest::lesson19FasterMoonFliesAnEllipse()
{
    Workbench w(QStringLiteral("two-bodies-in-orbit"));
    QVERIFY(w.ready());
    const double vy = w.balls().velocity(1, 1);
    QVERIFY(w.type(1, BallTableModel::Vy, QString::number(1.2 * vy, 'g', 17)));
    QCOMPARE(w.balls().velocity(1, 1), 1.2 * vy);
    const sim::BallState& b = w.balls();
    const double mu = w.controller()->world().settings().mutualGravity.G * (b.mass[0] + b.mass[1]);
    const sim::Vec2 r0 = sim::Vec2(b.position.col(1)) - sim::Vec2(b.position.col(0));
    const sim::Vec2 v0 = sim::Vec2(b.velocity.col(1)) - sim::Vec2(b.velocity.col(0));
    const double energy = 0.5 * v0.squaredNorm() - mu / r0.norm();
    QVERIFY(energy < 0.0);
    const double a = -mu / (2.0 * energy);
    const double far = 2.0 * a - r0.norm();
    const double period = 2.0 * std::numbers::pi * std::sqrt(a * a * a / mu);
    double farthest = 0.0;
    sim::World& world = w.controller()->mutableWorld();
    while (world.time() < period) {
        world.step();
        farthest = std::max(farthest, (sim::Vec2(b.position.col(1)) - sim::Vec2(b.position.col(0))).norm());
    }
    qInfo("far point %.2f px, expected %.2f px (circle: %.0f px)", farthest, far, r0.norm());
    QVERIFY2(std::abs(farthest - far) <= 0.01 * far, qPrintable(QString::number(farthest)));
}

// Lesson 19, "make the Moon as heavy as the Earth (and keep the total
// momentum zero)": typed mass 8100 and vy = −(M v_E)/m. The centre of mass
// then stands still and the two circle it at equal distances (to 1e-9).
void GuiEditingTest::lesson19MoonAsHeavyAsTheEarth()
{
    Workbench w(QStringLiteral("two-bodies-in-orbit"));
    QVERIFY(w.ready());
    const double earth = w.balls().mass[0];
    QVERIFY(w.type(1, BallTableModel::Mass, QString::number(earth, 'g', 17)));
    const double vy = -w.balls().velocity(1, 0) * earth / w.balls().mass[1];
    QVERIFY(w.type(1, BallTableModel::Vy, QString::number(vy, 'g', 17)));
    QCOMPARE(w.balls().mass[1], earth);
    const sim::Vec2 p = w.controller()->world().momentum();
    QVERIFY2(p.norm() <= 1e-9 * earth, qPrintable(QString::number(p.norm())));
    const sim::Vec2 centre = 0.5 * (sim::Vec2(w.balls().position.col(0)) + sim::Vec2(w.balls().position.col(1)));
    w.run(3.0);
    const sim::Vec2 e = w.balls().position.col(0), m = w.balls().position.col(1);
    QVERIFY((0.5 * (e + m) - centre).norm() <= 1e-9 * centre.norm());
    QVERIFY(std::abs((e - centre).norm() - (m - centre).norm()) <= 1e-9 * (e - centre).norm());
}

// Lesson 27, "check the formula with equal masses": balls 0 and 1 given one
// mass swap their velocities in the first hit, to 1e-12.
void GuiEditingTest::lesson27EqualMassesSwapVelocities()
{
    Workbench w(QStringLiteral("elastic-collisions-in-1d"));
    QVERIFY(w.ready());
    QVERIFY(w.type(0, BallTableModel::Mass, QStringLiteral("5000")));
    QVERIFY(w.type(1, BallTableModel::Mass, QStringLiteral("5000")));
    const double v0 = w.balls().velocity(0, 0), v1 = w.balls().velocity(0, 1);
    sim::World& world = w.controller()->mutableWorld();
    while (w.balls().velocity(0, 0) == v0 && world.time() < 5.0)
        world.step();
    QVERIFY2(std::abs(w.balls().velocity(0, 0) - v1) <= 1e-12 * std::abs(v0),
             qPrintable(QString::number(w.balls().velocity(0, 0), 'g', 17)));
    QVERIFY2(std::abs(w.balls().velocity(0, 1) - v0) <= 1e-12 * std::abs(v0),
             qPrintable(QString::number(w.balls().velocity(0, 1), 'g', 17)));
}

// Lesson 27, "a very heavy ball against a very light one at rest": the light
// one leaves at v' = 2M/(M + m) v, nearly twice the heavy one's speed.
void GuiEditingTest::lesson27HeavyAgainstLight()
{
    Workbench w(QStringLiteral("elastic-collisions-in-1d"));
    QVERIFY(w.ready());
    QVERIFY(w.type(0, BallTableModel::Mass, QStringLiteral("1e9")));
    QVERIFY(w.type(1, BallTableModel::Mass, QStringLiteral("1")));
    QVERIFY(w.type(1, BallTableModel::Vx, QStringLiteral("0")));
    const double v = w.balls().velocity(0, 0);
    sim::World& world = w.controller()->mutableWorld();
    while (w.balls().velocity(0, 1) == 0.0 && world.time() < 5.0)
        world.step();
    const double expected = 2.0 * 1e9 / (1e9 + 1.0) * v;
    QVERIFY2(std::abs(w.balls().velocity(0, 1) - expected) <= 1e-12 * expected,
             qPrintable(QString::number(w.balls().velocity(0, 1), 'g', 17)));
}

// Lesson 29, "make the red ball twice as big": a new radius keeps the
// density, so 8 times the mass, and the two no longer leave at 90°. Along
// the line of impact n (between the centres at the step of the hit) the
// impulse gives v_blue = 2M/(M + m) (v·n) n and v_red = v − 2m/(M + m) (v·n) n,
// to 1e-9.
void GuiEditingTest::lesson29TwiceAsBig()
{
    Workbench w(QStringLiteral("the-line-of-impact"));
    QVERIFY(w.ready());
    const double m0 = w.balls().mass[0];
    QVERIFY(w.type(0, BallTableModel::Radius, QStringLiteral("40")));
    QCOMPARE(w.balls().radius[0], 40.0);
    QVERIFY(std::abs(w.balls().mass[0] - 8.0 * m0) <= 1e-12 * 8.0 * m0);
    const sim::Vec2 v = w.balls().velocity.col(0);
    const double M = w.balls().mass[0], m = w.balls().mass[1];
    sim::World& world = w.controller()->mutableWorld();
    while (w.balls().velocity.col(1).isZero() && world.time() < 10.0)
        world.step();
    // The line of impact as the step found it: between the centres at the contact.
    const sim::Vec2 n = (sim::Vec2(w.balls().position.col(1)) - sim::Vec2(w.balls().position.col(0))).normalized();
    const sim::Vec2 blue = w.balls().velocity.col(1), red = w.balls().velocity.col(0);
    const sim::Vec2 blueExpected = 2.0 * M / (M + m) * v.dot(n) * n;
    const sim::Vec2 redExpected = v - 2.0 * m / (M + m) * v.dot(n) * n;
    qInfo("blue (%.9g, %.9g) expected (%.9g, %.9g)", blue.x(), blue.y(), blueExpected.x(), blueExpected.y());
    QVERIFY2((blue - blueExpected).norm() <= 1e-9 * v.norm(), qPrintable(QString::number(blue.x(), 'g', 12)));
    QVERIFY2((red - redExpected).norm() <= 1e-9 * v.norm(), qPrintable(QString::number(red.x(), 'g', 12)));
    const double angle = std::acos(blue.normalized().dot(red.normalized())) * 180.0 / std::numbers::pi;
    qInfo("angle between the paths after the hit: %.1f degrees", angle);
    QVERIFY(angle < 80.0);
}

// Lesson 30, "move the first grey ball next to the red one (x = 190) and give
// it the red ball's velocity": x = 190 touches the red ball, so it is moved
// to touching (by the gap); two balls come in, and two leave at the far end
// with the speed they came in with (momentum and energy of equal masses).
void GuiEditingTest::lesson30TwoBallsIn()
{
    Workbench w(QStringLiteral("newtons-cradle"));
    QVERIFY(w.ready());
    QVERIFY(w.type(1, BallTableModel::X, QStringLiteral("190")));
    QVERIFY(std::abs(w.balls().position(0, 1) - 190.0) <= 1e-6);
    QVERIFY(w.type(1, BallTableModel::Vx, QString::number(w.balls().velocity(0, 0), 'g', 17)));
    const double v = w.balls().velocity(0, 0);
    sim::World& world = w.controller()->mutableWorld();
    const int n = w.balls().size();
    // Until the last ball first reaches the right wall's neighbourhood.
    while (w.balls().position(0, n - 1) < 700.0 && world.time() < 5.0)
        world.step();
    int moving = 0;
    for (int i = 0; i < n; ++i)
        if (std::abs(w.balls().velocity(0, i)) > 0.5 * v)
            ++moving;
    QCOMPARE(moving, 2);
    QVERIFY(std::abs(w.balls().velocity(0, n - 1) - v) <= 1e-6 * v);
    QVERIFY(std::abs(w.balls().velocity(0, n - 2) - v) <= 1e-6 * v);
}

// Lesson 31, "double the cue ball's speed" and "make it heavy": the typed
// values are the world's exactly, the energy before the break is 4 times,
// and a heavier ball keeps its size.
void GuiEditingTest::lesson31DoubleSpeedAndHeavier()
{
    Workbench w(QStringLiteral("break-shot"));
    QVERIFY(w.ready());
    const double energy = w.controller()->world().energy().kinetic;
    const double vx = w.balls().velocity(0, 0);
    QVERIFY(w.type(0, BallTableModel::Vx, QString::number(2.0 * vx, 'g', 17)));
    QCOMPARE(w.balls().velocity(0, 0), 2.0 * vx);
    QVERIFY(std::abs(w.controller()->world().energy().kinetic - 4.0 * energy) <= 1e-12 * 4.0 * energy);
    const double m = w.balls().mass[0];
    QVERIFY(w.type(0, BallTableModel::Mass, QString::number(10.0 * m, 'g', 17)));
    QCOMPARE(w.balls().mass[0], 10.0 * m);
    QCOMPARE(w.balls().radius[0], 10.0); // heavier, not bigger
    QCOMPARE(w.undo()->count(), 2);
}

// A lesson file may give a density instead of a mass (not both), and the
// table's density column sets the mass the same way.
void GuiEditingTest::aLessonMayGiveADensity()
{
    const QByteArray file = R"({"format": 1, "id": "dense", "title": "Dense", "world": {"width": 400, "height": 300},
        "balls": [{"x": 100, "y": 100, "r": 10, "density": 7.9}, {"x": 300, "y": 100, "r": 10}]})";
    const LoadResult dense = LessonLoader::loadBytes(file, QStringLiteral("dense.json"));
    QVERIFY2(dense.ok(), qPrintable(dense.errors().join(QLatin1Char('\n'))));
    QCOMPARE(dense.lesson->scene.balls[0].mass, 7.9 * sim::sphereMass(10.0));
    QCOMPARE(dense.lesson->scene.balls[1].mass, 0.0); // by its size, as before
    QByteArray both = file;
    both.replace("\"density\": 7.9", "\"density\": 7.9, \"mass\": 3");
    const LoadResult refused = LessonLoader::loadBytes(both, QStringLiteral("both.json"));
    QVERIFY(!refused.ok());
    QVERIFY2(refused.errors().join(QString()).contains(QStringLiteral("balls.0.density")),
             qPrintable(refused.errors().join(QLatin1Char('\n'))));

    Workbench w(QStringLiteral("the-line-of-impact"));
    QVERIFY(w.ready());
    QVERIFY(w.type(0, BallTableModel::Density, QStringLiteral("19.3")));
    QVERIFY(std::abs(w.balls().mass[0] - 19.3 * sim::sphereMass(20.0)) <= 1e-12 * w.balls().mass[0]);
    const QModelIndex density = w.table()->model()->index(w.ballTable()->rowOf(0), BallTableModel::Density);
    QCOMPARE(density.data().toString(), QStringLiteral("19.3"));
}

// Rewound to step 30 of 90, a typed speed starts a new future (the record
// ends at step 30); Undo brings back the old one: the world at step 30 and,
// sought again, at step 90 are bit for bit those of the run never edited.
void GuiEditingTest::anEditInThePastIsANewFutureUndoneToTheOld()
{
    Workbench w(QStringLiteral("the-line-of-impact"));
    QVERIFY(w.ready());
    SimulationController* c = w.controller();
    for (int k = 0; k < 90; ++k)
        c->stepOnce();
    const sim::BallState at90 = w.balls();
    QVERIFY(c->seekStep(30));
    const sim::BallState at30 = w.balls();
    QCOMPARE(c->latestStep(), std::int64_t(90));
    QVERIFY(w.type(0, BallTableModel::Vx, QStringLiteral("-15")));
    QCOMPARE(w.balls().velocity(0, 0), -15.0);
    QCOMPARE(c->latestStep(), std::int64_t(30));
    w.undo()->undo();
    QVERIFY(sameBalls(w.balls(), at30));
    QCOMPARE(c->latestStep(), std::int64_t(90));
    QVERIFY(c->seekStep(90));
    QVERIFY(sameBalls(w.balls(), at90));
}

QTEST_MAIN(GuiEditingTest)
// Issue #35: the pinned check box of the table pins a ball under gravity
// (one undo step that also stops it); played for a second it stays where it
// was to the bit while the others fall; undone, it is free again with the
// velocity it had, and falls.
void GuiEditingTest::pinFromTheTableHoldsTheBallWhilePlaying()
{
    Workbench w(QStringLiteral("gravity"));
    QVERIFY(w.ready());
    QVERIFY(w.controller()->world().settings().gravity.enabled);
    QVERIFY(w.balls().size() >= 2);
    w.run(0.1); // moving, so that pinning has a velocity to take away
    const sim::Ball before = w.balls().ball(0);
    QVERIFY(before.velocity.norm() > 0.0);
    QVERIFY(!before.pinned);
    const int edits = w.undo()->count();

    // The check box, clicked as a student clicks it (Space is Play here).
    QTableView* view = w.table();
    QTRY_VERIFY(view->isVisible());
    const QModelIndex cell = view->model()->index(w.ballTable()->rowOf(0), BallTableModel::Pinned);
    QCOMPARE(view->model()->data(cell, Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
    view->scrollTo(cell);
    QStyleOptionViewItem option;
    option.initFrom(view);
    option.rect = view->visualRect(cell);
    option.features = QStyleOptionViewItem::HasCheckIndicator;
    const QRect box = view->style()->subElementRect(QStyle::SE_ItemViewItemCheckIndicator, &option, view);
    QVERIFY(box.isValid());
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, box.center());
    QTRY_VERIFY(w.balls().pinned[0] != 0);
    QCOMPARE(w.undo()->count(), edits + 1);
    QCOMPARE(view->model()->data(cell, Qt::CheckStateRole).toInt(), int(Qt::Checked));
    QCOMPARE(w.balls().inverseMass[0], 0.0);
    QVERIFY(w.balls().velocity.col(0).isZero(0.0));

    // Played: the pinned ball stays, the others fall.
    const sim::Vec2 at = w.balls().position.col(0);
    const sim::Vec2 other = w.balls().position.col(1);
    const std::int64_t from = w.controller()->world().stepCount();
    w.controller()->play();
    QTRY_VERIFY_WITH_TIMEOUT(w.controller()->world().stepCount() >= from + 60, 20000);
    w.controller()->pause();
    QCOMPARE(sim::Vec2(w.balls().position.col(0)), at); // bit for bit
    QVERIFY(w.balls().velocity.col(0).isZero(0.0));
    QVERIFY((sim::Vec2(w.balls().position.col(1)) - other).norm() > 1.0);

    // Undone: free, with the velocity and inverse mass it had, and it falls.
    w.undo()->undo();
    QCOMPARE(w.balls().pinned[0], static_cast<unsigned char>(0));
    QCOMPARE(sim::Vec2(w.balls().velocity.col(0)), before.velocity);
    QCOMPARE(w.balls().inverseMass[0], 1.0 / before.mass);
    QCOMPARE(view->model()->data(cell, Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
    w.run(0.1);
    QVERIFY((sim::Vec2(w.balls().position.col(0)) - at).norm() > 1.0);
}

// The right-click menu's checkable Pin: checked for a pinned ball, each
// toggle one undo step, undone bit for bit.
void GuiEditingTest::pinFromTheMenuIsOneUndoStep()
{
    Workbench w(QStringLiteral("the-line-of-impact"));
    QVERIFY(w.ready());
    Canvas* canvas = w.window.canvas();
    const sim::BallState start = w.balls();
    const QPointF on = canvas->worldToWidget(sim::Vec2(w.balls().position.col(1)));
    {
        QMenu menu;
        canvas->fillContextMenu(menu, on);
        QAction* pin = menuAction(menu, QStringLiteral("Pin"));
        QVERIFY(pin && pin->isCheckable() && pin->isEnabled() && !pin->isChecked());
        pin->trigger();
    }
    QCOMPARE(w.balls().pinned[1], static_cast<unsigned char>(1));
    QCOMPARE(w.undo()->count(), 1);
    const sim::BallState pinned = w.balls();
    // The class sees it: a dark nail head on the ball's centre.
    {
        const QImage picture = canvas->renderImage();
        const QPointF centre = canvas->worldToWidget(sim::Vec2(w.balls().position.col(1)));
        const QColor nail = picture.pixelColor((centre * picture.devicePixelRatio()).toPoint());
        QVERIFY2(nail.lightness() < 90, qPrintable(nail.name()));
        QVERIFY(nail.rgb() != w.balls().color[1]);
    }
    {
        QMenu menu;
        canvas->fillContextMenu(menu, on);
        QAction* pin = menuAction(menu, QStringLiteral("Pin"));
        QVERIFY(pin && pin->isChecked());
        pin->trigger(); // unchecks: free again
    }
    QCOMPARE(w.balls().pinned[1], static_cast<unsigned char>(0));
    QCOMPARE(w.undo()->count(), 2);
    w.undo()->undo();
    QVERIFY(sameBalls(w.balls(), pinned));
    w.undo()->undo();
    QVERIFY(sameBalls(w.balls(), start));

    // Copied and pasted, a pinned ball with its own restitution stays both.
    sim::Ball ball = start.ball(0);
    ball.pinned = true;
    ball.restitution = 0.25;
    const std::optional<sim::Ball> back = ballFromText(ballToText(ball));
    QVERIFY(back && back->pinned && back->restitution == 0.25);
    const std::optional<sim::Ball> plain = ballFromText(ballToText(start.ball(0)));
    QVERIFY(plain && !plain->pinned && plain->restitution == sim::kWorldRestitution);
    QVERIFY(!ballToText(start.ball(0)).contains(QStringLiteral("restitution")));
}

// The restitution column: "world" until a value is typed; a typed value is
// the ball's own, an empty cell gives it the world's again, a value outside
// [0, 1] is refused with its range; each edit undone bit for bit.
void GuiEditingTest::restitutionIsTypedAndClearedInTheTable()
{
    Workbench w(QStringLiteral("the-line-of-impact"));
    QVERIFY(w.ready());
    const sim::BallState start = w.balls();
    QTableView* view = w.table();
    const QModelIndex cell = view->model()->index(w.ballTable()->rowOf(0), BallTableModel::Restitution);
    QCOMPARE(view->model()->data(cell, Qt::DisplayRole).toString(), QStringLiteral("world"));
    QVERIFY(w.type(0, BallTableModel::Restitution, QStringLiteral("0.5")));
    QCOMPARE(w.balls().restitution[0], 0.5);
    const sim::BallState own = w.balls();
    QVERIFY(w.type(0, BallTableModel::Restitution, QStringLiteral("1.5")));
    QCOMPARE(w.balls().restitution[0], 0.5); // refused
    auto* note = w.ballTable()->findChild<QLabel*>(QStringLiteral("ballTableNote"));
    QVERIFY2(note->text().contains(QStringLiteral("restitution")) && note->text().contains(QStringLiteral("[0, 1]")),
             qPrintable(note->text()));
    QVERIFY(w.type(0, BallTableModel::Restitution, QString()));
    QCOMPARE(w.balls().restitution[0], sim::kWorldRestitution);
    QCOMPARE(view->model()->data(cell, Qt::DisplayRole).toString(), QStringLiteral("world"));
    QCOMPARE(w.undo()->count(), 2);
    w.undo()->undo();
    QVERIFY(sameBalls(w.balls(), own));
    w.undo()->undo();
    QVERIFY(sameBalls(w.balls(), start));
}

#include "test_gui_editing.moc"
