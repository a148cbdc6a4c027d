// Going back in time through the real widgets: the timeline bar's step back
// and step forward buttons, its scrubber dragged by the mouse, and the main
// window's Step Back action. Every world they show is compared bit for bit
// with a world stepped the same way that never went back.

#include "ui/canvas/simulation_controller.h"
#include "ui/controls/settings_editor.h"
#include "ui/controls/timeline_bar.h"
#include "ui/window/main_window.h"

#include "sim/world/scene.h"
#include "sim/world/world.h"

#include <QAction>
#include <QLabel>
#include <QSlider>
#include <QStandardPaths>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QMenu>
#include <QTest>
#include <QUndoStack>
#include <QToolButton>

#include <cstring>
#include <vector>

using namespace forcelab;

namespace {

struct Snapshot {
    sim::Matrix2X position; // px
    sim::Matrix2X velocity; // px/s
    double time = 0.0;      // s
    std::int64_t steps = 0;
};

Snapshot snap(const sim::World& w)
{
    return {w.balls().position, w.balls().velocity, w.time(), w.stepCount()};
}

bool sameBits(const sim::Matrix2X& a, const sim::Matrix2X& b)
{
    return a.cols() == b.cols() &&
           std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

// Every number of `w` equals the snapshot's, bit for bit.
bool sameWorld(const sim::World& w, const Snapshot& s)
{
    const double t = w.time();
    return w.stepCount() == s.steps && std::memcmp(&t, &s.time, sizeof t) == 0 &&
           sameBits(w.balls().position, s.position) && sameBits(w.balls().velocity, s.velocity);
}

// Balls that collide with each other and the walls under gravity, with drag
// and the pointer's pull: every kind of state a step keeps.
sim::Scene scene()
{
    sim::Scene s = sim::openScene({sim::ballAt(100, 100, 220, -50, 12), sim::ballAt(300, 120, -180, 30, 10),
                                   sim::ballAt(200, 300, 60, -240, 14), sim::ballAt(450, 250, -90, 120, 9)});
    s.settings.gravity.enabled = true;
    s.settings.drag.enabled = true;
    s.settings.pointer.enabled = true;
    s.settings.time.integrator = sim::IntegratorKind::Ias15;
    s.settings.collisions.response = sim::Response::Impulse2D;
    return s;
}

// The pointer before step k (the same for the controller and the reference).
std::optional<sim::PointerInput> pointerAt(std::int64_t k)
{
    if (k % 13 == 5)
        return sim::PointerInput{true, k % 26 == 5, sim::Vec2(50.0 + 4.0 * static_cast<double>(k), 200.0)};
    return std::nullopt;
}

// The world that never goes back: `steps` + 1 snapshots.
std::vector<Snapshot> reference(const sim::Scene& s, std::int64_t steps)
{
    sim::World w(s);
    std::vector<Snapshot> out{snap(w)};
    while (w.stepCount() < steps) {
        if (auto p = pointerAt(w.stepCount()))
            w.setPointer(*p);
        w.step();
        out.push_back(snap(w));
    }
    return out;
}

// Steps the controller as the window does (its timer's advance), one step a frame.
void stepLive(SimulationController& c, std::int64_t to)
{
    c.setMaxStepsPerFrame(1);
    while (c.world().stepCount() < to) {
        if (auto p = pointerAt(c.world().stepCount()))
            c.setPointer(*p);
        c.advance(c.world().settings().time.dt);
    }
}

QPoint handleCentre(QSlider* slider)
{
    QStyleOptionSlider option;
    option.initFrom(slider);
    option.orientation = slider->orientation();
    option.minimum = slider->minimum();
    option.maximum = slider->maximum();
    option.sliderPosition = slider->sliderPosition();
    option.sliderValue = slider->value();
    option.subControls = QStyle::SC_All;
    return slider->style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider).center();
}

} // namespace

class GuiRewindTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void barStepsBackAndForwardBitForBit();
    void draggingTheScrubberShowsTheRecordedWorld();
    void anEditInThePastIsUndoneWithItsFuture();
    void undoOfASettingsEditBringsTheFutureBack();
    void aBallHeldWhilePlayingIsReplayed();
    void undoOfARespawnBringsTheRunBack();
    void stepBackActionOfTheWindow();
};

void GuiRewindTest::barStepsBackAndForwardBitForBit()
{
    const std::vector<Snapshot> never = reference(scene(), 160);
    SimulationController c;
    QVERIFY(!c.setScene(scene()));
    c.setGhost(SimulationController::GhostMode::Twin);
    TimelineBar bar(&c);
    bar.resize(600, 40);
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    stepLive(c, 120);
    QCOMPARE(c.latestStep(), std::int64_t{120});
    QCOMPARE(bar.slider()->maximum(), 120);
    QCOMPARE(bar.slider()->value(), 120);

    for (int k = 0; k < 5; ++k)
        QTest::mouseClick(bar.stepBackButton(), Qt::LeftButton);
    QCOMPARE(c.world().stepCount(), std::int64_t{115});
    QVERIFY(sameWorld(c.world(), never[115]));
    QCOMPARE(bar.slider()->value(), 115);
    QCOMPARE(bar.timeLabel()->text(), TimelineBar::timeText(never[115].time, never[120].time));
    QVERIFY(bar.timeLabel()->text().startsWith(QStringLiteral("t = 1.92 s of 2.00 s")));
    // The twin ghost starts again from the world shown.
    QVERIFY(c.ghost());
    QCOMPARE(c.ghost()->time(), 0.0);
    QVERIFY(c.ghostSeparation() <= 2 * SimulationController::kTwinOffset);

    // Forward: the recorded steps again, then new ones.
    for (int k = 0; k < 5; ++k)
        QTest::mouseClick(bar.stepForwardButton(), Qt::LeftButton);
    QVERIFY(sameWorld(c.world(), never[120]));
    QCOMPARE(c.latestStep(), std::int64_t{120});
    QTest::mouseClick(bar.stepBackButton(), Qt::LeftButton);
    stepLive(c, 160); // plays through the record, then on
    QVERIFY(sameWorld(c.world(), never[160]));
    QCOMPARE(c.latestStep(), std::int64_t{160});
}

void GuiRewindTest::draggingTheScrubberShowsTheRecordedWorld()
{
    const std::vector<Snapshot> never = reference(scene(), 200);
    SimulationController c;
    QVERIFY(!c.setScene(scene()));
    TimelineBar bar(&c);
    bar.resize(800, 40);
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    stepLive(c, 200);
    QSlider* slider = bar.slider();
    QCOMPARE(slider->value(), 200);

    // Drag the handle a third of the groove to the left.
    const QPoint from = handleCentre(slider);
    const QPoint to(from.x() - slider->width() / 3, from.y());
    QTest::mousePress(slider, Qt::LeftButton, Qt::NoModifier, from);
    for (int i = 1; i <= 10; ++i)
        QTest::mouseMove(slider, from + (to - from) * i / 10);
    QTest::mouseRelease(slider, Qt::LeftButton, Qt::NoModifier, to);
    QTRY_VERIFY(c.world().stepCount() < 160);
    const std::int64_t shown = c.world().stepCount();
    QVERIFY(shown > 0);
    QCOMPARE(slider->value(), static_cast<int>(shown));
    QVERIFY(sameWorld(c.world(), never[static_cast<std::size_t>(shown)]));
    QVERIFY(!c.isPlaying());

    // Back to the right end: the latest world, as it was.
    QTest::mousePress(slider, Qt::LeftButton, Qt::NoModifier, handleCentre(slider));
    QTest::mouseMove(slider, QPoint(slider->width() + 20, from.y()));
    QTest::mouseRelease(slider, Qt::LeftButton, Qt::NoModifier, QPoint(slider->width() + 20, from.y()));
    QTRY_COMPARE(c.world().stepCount(), std::int64_t{200});
    QVERIFY(sameWorld(c.world(), never[200]));
}

void GuiRewindTest::anEditInThePastIsUndoneWithItsFuture()
{
    const std::vector<Snapshot> never = reference(scene(), 100);
    SimulationController c;
    QVERIFY(!c.setScene(scene()));
    stepLive(c, 100);
    QVERIFY(c.seekStep(40));
    QVERIFY(sameWorld(c.world(), never[40]));
    const sim::WorldSettings before = c.world().settings();
    sim::WorldSettings after = before;
    after.gravity.g = sim::Vec2(0.0, -300.0);
    QVERIFY(c.setSettings(after));
    const int cut = c.lastCut();
    QVERIFY(cut >= 0);
    QCOMPARE(c.latestStep(), std::int64_t{40});
    stepLive(c, 60);
    QVERIFY(!sameWorld(c.world(), never[60]));
    // Undo: the settings back, then the future.
    QVERIFY(c.setSettings(before));
    QVERIFY(c.restoreFuture(cut));
    QVERIFY(sameWorld(c.world(), never[40]));
    QCOMPARE(c.latestStep(), std::int64_t{100});
    QVERIFY(c.seekStep(100));
    QVERIFY(sameWorld(c.world(), never[100]));
}

void GuiRewindTest::undoOfASettingsEditBringsTheFutureBack()
{
    const std::vector<Snapshot> never = reference(scene(), 90);
    SimulationController c;
    SettingsEditor editor(&c);
    QVERIFY(!c.setScene(scene()));
    stepLive(c, 90);
    QVERIFY(c.seekStep(30));
    QVERIFY(editor.editSettings(QStringLiteral("gravity up"),
                                [](sim::WorldSettings& s) { s.gravity.g = sim::Vec2(0.0, -300.0); }));
    QCOMPARE(c.latestStep(), std::int64_t{30});
    stepLive(c, 50);
    const Snapshot edited = snap(c.world());
    editor.undoStack()->undo();
    QVERIFY(sameWorld(c.world(), never[30]));
    QCOMPARE(c.world().settings().gravity.g.y(), 980.0);
    QCOMPARE(c.latestStep(), std::int64_t{90});
    QVERIFY(c.seekStep(90));
    QVERIFY(sameWorld(c.world(), never[90]));
    editor.undoStack()->redo();
    QCOMPARE(c.world().settings().gravity.g.y(), -300.0);
    QCOMPARE(c.latestStep(), std::int64_t{50});
    QVERIFY(c.seekStep(50));
    QCOMPARE(snap(c.world()).steps, edited.steps);
    QVERIFY(sameBits(c.world().balls().position, edited.position));
}

// The canvas holds a dragged ball after every frame of a playing world
// (Canvas::onStepped) with no undo step, only noteHandMoved: the record must
// still re-run to what was shown.
void GuiRewindTest::aBallHeldWhilePlayingIsReplayed()
{
    SimulationController c;
    QVERIFY(!c.setScene(scene()));
    stepLive(c, 20);
    std::vector<Snapshot> shown;
    for (int k = 0; k < 15; ++k) {
        stepLive(c, c.world().stepCount() + 1);
        sim::BallState& balls = c.mutableWorld().mutableBalls();
        balls.position.col(1) = sim::Vec2(300.0 + 5.0 * k, 200.0);
        balls.velocity.col(1).setZero();
        c.noteHandMoved();
        shown.push_back(snap(c.world()));
    }
    stepLive(c, 40);
    const Snapshot latest = snap(c.world());
    QVERIFY(c.seekStep(10));
    for (const Snapshot& s : shown) {
        QVERIFY(c.seekStep(s.steps));
        QVERIFY(sameWorld(c.world(), s));
    }
    QVERIFY(c.seekStep(40));
    QVERIFY(sameWorld(c.world(), latest));
}

void GuiRewindTest::undoOfARespawnBringsTheRunBack()
{
    const std::vector<Snapshot> never = reference(scene(), 60);
    SimulationController c;
    SettingsEditor editor(&c);
    QVERIFY(!c.setScene(scene()));
    stepLive(c, 60);
    sim::SpawnSettings more;
    more.count = 3;
    QVERIFY(editor.editSpawn(QStringLiteral("3 balls"), more));
    QCOMPARE(c.world().balls().size(), 7);
    QCOMPARE(c.world().stepCount(), std::int64_t{0});
    stepLive(c, 20);
    const Snapshot respawned = snap(c.world());
    editor.undoStack()->undo();
    QVERIFY(sameWorld(c.world(), never[0]));
    QCOMPARE(c.latestStep(), std::int64_t{60});
    QVERIFY(c.seekStep(60));
    QVERIFY(sameWorld(c.world(), never[60]));
    editor.undoStack()->redo();
    QCOMPARE(c.world().balls().size(), 7);
    QCOMPARE(c.latestStep(), std::int64_t{20});
    QVERIFY(c.seekStep(20));
    QVERIFY(sameWorld(c.world(), respawned));
}

void GuiRewindTest::stepBackActionOfTheWindow()
{
    MainWindow window(QString{});
    window.resize(1200, 800);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto* c = window.findChild<SimulationController*>();
    QVERIFY(c);
    QVERIFY(!c->setScene(scene()));
    const std::vector<Snapshot> never = reference(scene(), 40);
    auto* step = window.findChild<QAction*>(QStringLiteral("stepAction"));
    auto* back = window.findChild<QAction*>(QStringLiteral("stepBackAction"));
    QVERIFY(step && back);
    QVERIFY(back->shortcuts().contains(QKeySequence(Qt::Key_Left)));
    // In the Simulation menu, right after Step.
    auto* menu = window.findChild<QMenu*>(QStringLiteral("simulationMenu"));
    QVERIFY(menu);
    const QList<QAction*> items = menu->actions();
    QCOMPARE(items.indexOf(back), items.indexOf(step) + 1);
    // The Step action, with the pointer moves of the reference.
    const auto stepTo = [&](std::int64_t to) {
        while (c->world().stepCount() < to) {
            if (auto p = pointerAt(c->world().stepCount()))
                c->setPointer(*p);
            step->trigger();
        }
    };
    stepTo(30);
    QVERIFY(sameWorld(c->world(), never[30]));
    for (int k = 0; k < 4; ++k)
        back->trigger();
    QVERIFY(sameWorld(c->world(), never[26]));
    auto* bar = window.findChild<TimelineBar*>();
    QVERIFY(bar && bar->isVisible());
    QCOMPARE(bar->slider()->value(), 26);
    stepTo(40); // 4 recorded steps again, then 10 new ones
    QVERIFY(sameWorld(c->world(), never[40]));
}

QTEST_MAIN(GuiRewindTest)
#include "test_gui_rewind.moc"
