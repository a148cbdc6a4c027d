// Collisions inside a whole world: walls and balls together, energy and
// momentum over long runs, and the same run whichever detector is chosen.

#include "sim/world.h"

#include <QTest>

#include <cmath>

using namespace forcelab::sim;

namespace {

Scene boxOfBalls(int count, double width, double height, Detection detection, double restitution)
{
    Scene s;
    s.settings.box = BoxSettings{width, height};
    s.settings.walls = WallSettings{true, true, true, true, WallModel::Clamp, 1.0};
    s.settings.collisions.detection = detection;
    s.settings.collisions.response = Response::Impulse2D;
    s.settings.collisions.restitution = restitution;
    s.spawn.count = count;
    s.spawn.minRadius = 3.0;
    s.spawn.maxRadius = 6.0;
    s.spawn.minSpeed = 50.0;
    s.spawn.maxSpeed = 300.0;
    s.spawn.seed = 42;
    return s;
}

} // namespace

class TestCollisionWorld : public QObject {
    Q_OBJECT
private slots:
    void boxKeepsKineticEnergy();
    void openSpaceKeepsMomentum();
    void detectorsGiveTheSameRun();
    void flagLeavesMotionAlone();
    void continuousWithExactWalls();
};

// 2,000 balls in a box, 2d-impulse with e = 1, walls with e = 1, no gravity or
// drag: kinetic energy within 1e-9 relative over 10,000 steps.
void TestCollisionWorld::boxKeepsKineticEnergy()
{
    World w(boxOfBalls(2000, 1000.0, 800.0, Detection::Grid, 1.0));
    QCOMPARE(w.balls().size(), 2000);
    const double ke0 = w.energy().kinetic;
    QVERIFY(ke0 > 0.0);
    double worst = 0.0;
    std::int64_t contacts = 0;
    for (int step = 0; step < 10000; ++step) {
        w.step();
        contacts += w.lastStep().contacts;
        if (step % 100 == 99)
            worst = std::max(worst, std::abs(w.energy().kinetic - ke0) / ke0);
    }
    worst = std::max(worst, std::abs(w.energy().kinetic - ke0) / ke0);
    qInfo("largest relative change of kinetic energy: %.3g", worst);
    QVERIFY2(worst <= 1e-9, qPrintable(QString("relative KE change %1").arg(worst)));
    QVERIFY(contacts > 100000); // the balls really collided
    QVERIFY(w.balls().position.allFinite());
}

// No walls, e = 0.8: every collision loses energy but none changes momentum.
void TestCollisionWorld::openSpaceKeepsMomentum()
{
    Scene s = boxOfBalls(800, 500.0, 500.0, Detection::Sweep, 0.8);
    s.settings.walls = WallSettings{false, false, false, false, WallModel::Clamp, 1.0};
    World w(s);
    const Vec2 p0 = w.momentum();
    const double scale = (w.balls().velocity.colwise().norm().transpose().array() * w.balls().mass.array()).sum();
    const double ke0 = w.energy().kinetic;
    std::int64_t contacts = 0;
    for (int step = 0; step < 300; ++step) {
        w.step();
        contacts += w.lastStep().contacts;
    }
    QVERIFY(contacts > 1000);
    QVERIFY((w.momentum() - p0).norm() <= 1e-12 * scale);
    QVERIFY(w.energy().kinetic < ke0);
}

void TestCollisionWorld::detectorsGiveTheSameRun()
{
    std::vector<BallState> finals;
    std::vector<std::int64_t> contacts, tested;
    for (Detection d : {Detection::Brute, Detection::Halved, Detection::Sweep, Detection::Grid}) {
        Scene s = boxOfBalls(600, 400.0, 300.0, d, 0.9);
        s.settings.gravity.enabled = true;
        World w(s);
        for (int step = 0; step < 200; ++step)
            w.step();
        finals.push_back(w.balls());
        contacts.push_back(w.totals().contacts);
        tested.push_back(w.totals().pairsTested);
    }
    for (std::size_t k = 1; k < finals.size(); ++k) {
        QCOMPARE(finals[k].position, finals[0].position);
        QCOMPARE(finals[k].velocity, finals[0].velocity);
        QCOMPARE(contacts[k], contacts[0]);
    }
    // Why the workbench shows the counters: brute tests twice what halved does,
    // and sweep and grid a tiny share of it.
    QCOMPARE(tested[0], 2 * tested[1]);
    QVERIFY(tested[2] * 20 < tested[1]);
    QVERIFY(tested[3] * 20 < tested[1]);
}

void TestCollisionWorld::flagLeavesMotionAlone()
{
    Scene s = boxOfBalls(500, 400.0, 300.0, Detection::Sweep, 1.0);
    s.settings.gravity.enabled = true;
    Scene none = s;
    none.settings.collisions.response = Response::None;
    s.settings.collisions.response = Response::Flag;
    World flagged(s), plain(none);
    int marked = 0;
    for (int step = 0; step < 100; ++step) {
        flagged.step();
        plain.step();
    }
    for (auto f : flagged.balls().colliding)
        marked += f;
    QVERIFY(marked > 0);
    QVERIFY(flagged.lastStep().contacts > 0);
    QCOMPARE(flagged.balls().position, plain.balls().position);
    QCOMPARE(flagged.balls().velocity, plain.balls().velocity);
}

// A ball moving 100 radii per step towards a resting ball near the right wall
// (exact wall model): it hits the ball and neither passes through the other
// or the wall.
void TestCollisionWorld::continuousWithExactWalls()
{
    Scene s;
    s.settings.box = BoxSettings{3000.0, 400.0};
    s.settings.walls = WallSettings{true, true, true, true, WallModel::Exact, 1.0};
    s.settings.collisions.response = Response::Impulse2D;
    s.settings.collisions.continuous = true;
    s.settings.collisions.detection = Detection::Grid;
    Ball fast, still;
    fast.radius = still.radius = 10.0;
    fast.position = Vec2(100.0, 200.0);
    fast.velocity = Vec2(1000.0 / s.settings.time.dt, 0.0); // 100 radii per step
    still.position = Vec2(1550.0, 200.0);
    s.balls = {fast, still};
    World w(s);
    for (int step = 0; step < 20; ++step) {
        w.step();
        const auto& x = w.balls().position;
        QVERIFY2(x(0, 0) < x(0, 1), qPrintable(QString("step %1: %2 %3").arg(step).arg(x(0, 0)).arg(x(0, 1))));
        QVERIFY(x(0, 0) >= 10.0 && x(0, 1) <= 2990.0);
    }
    QVERIFY(std::abs(w.energy().kinetic - 0.5 * w.balls().mass[0] * std::pow(1000.0 / s.settings.time.dt, 2)) <=
            1e-9 * w.energy().kinetic);
}

QTEST_APPLESS_MAIN(TestCollisionWorld)
#include "test_collision_world.moc"
