// The same lesson and seed give the same bits: two runs of 10,000 steps hash
// to the same value, and so do runs with every collision detector (the
// contact order is made deterministic). Build flags that would break this
// (fused multiply-add contraction) are switched off in the top CMakeLists.

#include "lessons/lesson_loader.h"
#include "sim/collision/resting/row_strips.h"
#include "sim/studies/peer_scene.h"
#include "sim/world/threads.h"
#include "sim/world/world.h"

#include <QTest>

#include <algorithm>
#include <cstring>

using namespace forcelab;
using namespace forcelab::sim;

namespace {

// FNV-1a over the bytes of the state: any difference in any bit shows.
std::uint64_t hashState(const World& w)
{
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&h](const double* data, Eigen::Index n) {
        const auto* bytes = reinterpret_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < static_cast<std::size_t>(n) * sizeof(double); ++i) {
            h ^= bytes[i];
            h *= 1099511628211ull;
        }
    };
    mix(w.balls().position.data(), w.balls().position.size());
    mix(w.balls().velocity.data(), w.balls().velocity.size());
    mix(w.balls().radius.data(), w.balls().radius.size());
    return h;
}

Scene showcase()
{
    const LoadResult r = LessonLoader::load("showcase");
    if (!r.ok())
        qFatal("%s", qPrintable(r.errors().join('\n')));
    return r.lesson->scene;
}

std::uint64_t run(const Scene& scene, int steps)
{
    World w;
    if (auto error = w.reset(scene))
        qFatal("%s", forcelab::sim::toString(*error).c_str());
    // The pointer moves over the scene part of the time, as a student's would.
    for (int k = 0; k < steps; ++k) {
        if (k % 1000 == 200)
            w.setPointer(PointerInput{true, (k / 1000) % 2 == 1, Vec2(150.0 + k % 300, 120.0)});
        if (k % 1000 == 700)
            w.setPointer(PointerInput{});
        w.step();
    }
    return hashState(w);
}

} // namespace

class TestReproducible : public QObject {
    Q_OBJECT
private slots:
    void sameSeedSameBits();
    void everyDetectorSameBits();
    void otherSeedOtherBits();
    void everyThreadCountSameBits();
    void stripListsKeepToTheirStrips();
};

void TestReproducible::sameSeedSameBits()
{
    const Scene scene = showcase();
    QVERIFY(scene.settings.collisions.response != Response::None);
    const std::uint64_t first = run(scene, 10000);
    QCOMPARE(run(scene, 10000), first);
}

void TestReproducible::everyDetectorSameBits()
{
    Scene scene = showcase();
    std::uint64_t reference = 0;
    for (Detection d : {Detection::Brute, Detection::Halved, Detection::Sweep, Detection::Grid}) {
        scene.settings.collisions.detection = d;
        const std::uint64_t h = run(scene, 2000);
        if (d == Detection::Brute)
            reference = h;
        QCOMPARE(h, reference);
    }
}

void TestReproducible::otherSeedOtherBits()
{
    Scene scene = showcase();
    const std::uint64_t a = run(scene, 100);
    scene.spawn.seed += 1;
    QVERIFY(run(scene, 100) != a);
}

// The resting solver's passes run on every core (row_strips.h): a pile of
// 8,000 balls, enough rows for the strips to be shared out, gives the same
// bits on one thread and on two, step for step, and so does the showcase.
void TestReproducible::everyThreadCountSameBits()
{
    const Scene pile = peerScene(8000);
    std::uint64_t pileHash[2] = {0, 0}, showcaseHash[2] = {0, 0};
    for (int threads : {1, 2}) {
        const ThreadLimit limit(threads);
        QVERIFY(availableThreads() >= 1 && availableThreads() <= threads);
        World w(pile);
        w.collisionSystem().setProfiling(true); // counts the rows; the bits do not change
        std::int64_t mostRows = 0;
        for (int k = 0; k < 120; ++k) {
            w.collisionSystem().resetProfile();
            w.step();
            mostRows = std::max(mostRows, w.collisionSystem().profile().rows);
        }
        QVERIFY(w.collisionSystem().lastVelocityPasses() > 1); // the solver ran its passes
        // Some steps had enough rows for the strips to go to both threads.
        QVERIFY2(mostRows >= static_cast<std::int64_t>(RowStrips::kParallelRows),
                 qPrintable(QString::number(mostRows)));
        pileHash[threads - 1] = hashState(w);
        showcaseHash[threads - 1] = run(showcase(), 2000);
    }
    QCOMPARE(pileHash[1], pileHash[0]);
    QCOMPARE(showcaseHash[1], showcaseHash[0]);
}

// RowStrips::runList (a bounce region's passes): a long list, enough for the
// strips to go to both threads, reaches each listed row exactly once, always
// from the strip the row belongs to, so the strips of a colour still share no
// ball; a short list and an empty one too.
void TestReproducible::stripListsKeepToTheirStrips()
{
    // 60,000 rows between neighbours on a line of balls 1 px apart: rows
    // 1 px wide, cut into the most strips.
    const int rows = 60000;
    static_assert(rows / 3 >= static_cast<int>(RowStrips::kParallelRows)); // every third row is shared out
    std::vector<double> x(rows + 1);
    for (int i = 0; i <= rows; ++i)
        x[static_cast<std::size_t>(i)] = static_cast<double>(i);
    RowStrips strips;
    strips.build(x.data(), static_cast<std::size_t>(rows), [](std::size_t k) { return k; },
                 [](std::size_t k) { return k + 1; });
    QVERIFY2(strips.stripCount() >= 60, qPrintable(QString::number(strips.stripCount())));
    // Each strip's positions, from the run over every row (each strip
    // writes only its own entry: the strips of a colour may run at once).
    std::vector<std::pair<int, int>> range(strips.stripCount(), {0, 0});
    strips.run([&](int strip, int begin, int end) { range[static_cast<std::size_t>(strip)] = {begin, end}; });
    std::size_t covered = 0;
    for (const auto& [begin, end] : range)
        covered += static_cast<std::size_t>(end - begin);
    QCOMPARE(covered, static_cast<std::size_t>(rows));
    for (const int every : {1, 3, 50000}) {
        std::vector<int> list;
        for (int k = every / 2; k < rows; k += every)
            list.push_back(k);
        std::vector<int> seen(list.size(), 0), wrongStrip(list.size(), 0);
        const ThreadLimit limit(2);
        strips.runList(list, [&](int strip, int begin, int end) {
            const auto [first, last] = range[static_cast<std::size_t>(strip)];
            for (int i = begin; i < end; ++i) { // each strip writes only its own entries
                ++seen[static_cast<std::size_t>(i)];
                const int k = list[static_cast<std::size_t>(i)];
                wrongStrip[static_cast<std::size_t>(i)] = k < first || k >= last;
            }
        });
        QVERIFY2(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }), qPrintable(QString::number(every)));
        QVERIFY2(std::none_of(wrongStrip.begin(), wrongStrip.end(), [](int w) { return w != 0; }),
                 qPrintable(QString::number(every)));
    }
    bool called = false;
    strips.runList({}, [&](int, int, int) { called = true; });
    QVERIFY(!called);
}

QTEST_GUILESS_MAIN(TestReproducible)
#include "test_reproducible.moc"
