// The four detectors (brute, halved, sweep, grid) must report exactly the same
// set of touching pairs on any scene. Brute force is the reference; it is
// itself checked against the definition (distance < r_a + r_b) written out here.

#include "sim/collision/collision_system.h"

#include "sim_check.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include <string>
#include <vector>

using forcelab::test::Text;

using namespace forcelab::sim;

namespace {

constexpr Detection kMethods[] = {Detection::Brute, Detection::Halved, Detection::Sweep, Detection::Grid};

const char* nameOf(Detection d)
{
    switch (d) {
    case Detection::Brute: return "brute";
    case Detection::Halved: return "halved";
    case Detection::Sweep: return "sweep";
    case Detection::Grid: return "grid";
    }
    return "?";
}

BallState makeBalls(const std::vector<Vec2>& p, const std::vector<double>& r)
{
    BallState s;
    s.resize(static_cast<int>(p.size()));
    for (int i = 0; i < s.size(); ++i) {
        Ball b;
        b.position = p[static_cast<std::size_t>(i)];
        b.radius = r[static_cast<std::size_t>(i)];
        s.set(i, b);
    }
    return s;
}

// The definition, independent of the library's code paths.
std::vector<Contact> byDefinition(const BallState& s)
{
    std::vector<Contact> out;
    for (int a = 0; a < s.size(); ++a)
        for (int b = a + 1; b < s.size(); ++b) {
            const double dx = s.position(0, b) - s.position(0, a);
            const double dy = s.position(1, b) - s.position(1, a);
            const double sum = s.radius[a] + s.radius[b];
            if (dx * dx + dy * dy < sum * sum)
                out.push_back({a, b});
        }
    return out;
}

std::string describe(const std::vector<Contact>& want, const std::vector<Contact>& got)
{
    std::size_t i = 0;
    while (i < want.size() && i < got.size() && want[i] == got[i])
        ++i;
    std::string s = "sizes " + std::to_string(want.size()) + " vs " + std::to_string(got.size());
    if (i < want.size())
        s += ", want (" + std::to_string(want[i].a) + "," + std::to_string(want[i].b) + ")";
    if (i < got.size())
        s += ", got (" + std::to_string(got[i].a) + "," + std::to_string(got[i].b) + ")";
    return s;
}

// Runs every detector on `balls` with a fresh system and with a long-lived one
// (whose sweep keeps an order from earlier scenes) and compares with brute.
void checkAgreement(const BallState& balls, CollisionSystem& kept, const char* what, bool checkDefinition = true)
{
    std::vector<Contact> reference;
    CollisionSystem fresh;
    const CollisionStats refStats = fresh.detect(balls, Detection::Brute, reference);
    const auto n = static_cast<std::int64_t>(balls.size());
    REQUIRE_SAME(refStats.pairsTested, n * (n > 0 ? n - 1 : 0));
    REQUIRE_SAME(refStats.contacts, static_cast<std::int64_t>(reference.size()));
    if (checkDefinition) {
        const auto def = byDefinition(balls);
        VERIFY2(def == reference, (std::string(what) + ": brute vs definition: " + describe(def, reference)).c_str());
    }
    for (Detection m : kMethods) {
        for (CollisionSystem* sys : {&fresh, &kept}) {
            std::vector<Contact> got;
            const CollisionStats st = sys->detect(balls, m, got);
            VERIFY2(got == reference, (std::string(what) + ": " + nameOf(m) + ": " + describe(reference, got)).c_str());
            REQUIRE_SAME(st.contacts, static_cast<std::int64_t>(got.size()));
            VERIFY(st.pairsTested >= st.contacts);
            if (m == Detection::Halved)
                REQUIRE_SAME(st.pairsTested, n * (n > 0 ? n - 1 : 0) / 2);
            if (m == Detection::Sweep || m == Detection::Grid)
                VERIFY(st.pairsTested <= std::max<std::int64_t>(n * (n - 1) / 2, 0));
        }
    }
}

// Random balls in a 600×400 box, a share of them outside the walls, radii
// log-uniform over [rMin, rMin·ratio].
BallState randomScene(std::mt19937_64& rng, int n, double rMin, double ratio, double fill)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Vec2> p(static_cast<std::size_t>(n));
    std::vector<double> r(static_cast<std::size_t>(n));
    // Box side so that the balls cover about `fill` of it.
    double area = 0.0;
    for (auto& ri : r) {
        ri = rMin * std::pow(ratio, u(rng));
        area += std::numbers::pi * ri * ri;
    }
    const double side = std::sqrt(area / fill) + 1.0;
    for (auto& pi : p) {
        // 10% outside the walls, some far away.
        const double spread = u(rng) < 0.1 ? 3.0 : 1.0;
        pi = Vec2((u(rng) * spread - 0.5 * (spread - 1.0)) * side, (u(rng) * spread - 0.5 * (spread - 1.0)) * side);
    }
    return makeBalls(p, r);
}

} // namespace


TEST_CASE("TestCollisionDetectors::emptyAndTiny")
{
    CollisionSystem kept;
    checkAgreement(BallState{}, kept, "empty");
    checkAgreement(makeBalls({Vec2(1, 2)}, {3.0}), kept, "one ball");
    checkAgreement(makeBalls({Vec2(0, 0), Vec2(5, 0)}, {3.0, 3.0}), kept, "two touching");
    checkAgreement(makeBalls({Vec2(0, 0), Vec2(6, 0)}, {3.0, 3.0}), kept, "two exactly touching");
    std::vector<Contact> c;
    CollisionSystem sys;
    sys.detect(makeBalls({Vec2(0, 0), Vec2(5, 0)}, {3.0, 3.0}), Detection::Grid, c);
    REQUIRE_SAME(c.size(), std::size_t(1));
    sys.detect(makeBalls({Vec2(0, 0), Vec2(6, 0)}, {3.0, 3.0}), Detection::Sweep, c);
    REQUIRE_SAME(c.size(), std::size_t(0)); // touching edges are not a contact
}

TEST_CASE("TestCollisionDetectors::randomScenes")
{
    CollisionSystem kept;
    std::mt19937_64 rng(12345);
    const int sizes[] = {2, 3, 5, 10, 30, 100, 300, 1000, 2000};
    int scenes = 0;
    for (int n : sizes) {
        const int seeds = n <= 100 ? 40 : (n <= 1000 ? 8 : 3);
        for (int s = 0; s < seeds; ++s) {
            const double fill = (s % 3 == 0) ? 0.3 : (s % 3 == 1 ? 0.6 : 0.05);
            const double ratio = (s % 2 == 0) ? 1.0 : 4.0;
            checkAgreement(randomScene(rng, n, 2.0, ratio, fill), kept, ("random n=" + std::to_string(n)).c_str(),
                           n <= 1000);
            ++scenes;
        }
    }
    VERIFY(scenes > 200);
}

TEST_CASE("TestCollisionDetectors::tenThousandBalls")
{
    CollisionSystem kept;
    std::mt19937_64 rng(777);
    checkAgreement(randomScene(rng, 10000, 3.0, 1.0, 0.3), kept, "10k equal", false);
    checkAgreement(randomScene(rng, 10000, 1.0, 100.0, 0.3), kept, "10k ratio 100", false);
}

TEST_CASE("TestCollisionDetectors::mixedRadiiRatio100")
{
    CollisionSystem kept;
    std::mt19937_64 rng(99);
    for (int s = 0; s < 10; ++s)
        checkAgreement(randomScene(rng, 500, 1.0, 100.0, 0.4), kept, "log-uniform ratio 100");
    // Mostly tiny balls with a few giants among them.
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int s = 0; s < 5; ++s) {
        std::vector<Vec2> p;
        std::vector<double> r;
        for (int i = 0; i < 1500; ++i) {
            p.emplace_back(u(rng) * 800.0, u(rng) * 800.0);
            r.push_back(i % 100 == 0 ? 100.0 : 1.0);
        }
        checkAgreement(makeBalls(p, r), kept, "giants among dust");
    }
}

// Pairs whose distance equals the sum of radii exactly (3-4-5 triangles and
// integer rows), and the same pairs one ulp closer or farther.
TEST_CASE("TestCollisionDetectors::exactlyTouching")
{
    CollisionSystem kept;
    std::vector<Vec2> p;
    std::vector<double> r;
    for (int i = 0; i < 20; ++i) { // a row of touching balls: distance 10 = 5 + 5
        p.emplace_back(10.0 * i, 0.0);
        r.push_back(5.0);
    }
    for (int i = 0; i < 20; ++i) { // 3-4-5: radii 2 and 3 at distance exactly 5
        p.emplace_back(20.0 * i, 100.0);
        r.push_back(2.0);
        p.emplace_back(20.0 * i + 3.0, 104.0);
        r.push_back(3.0);
    }
    const BallState exact = makeBalls(p, r);
    std::vector<Contact> c;
    for (Detection m : kMethods) {
        kept.detect(exact, m, c);
        VERIFY2(c.empty(), nameOf(m));
    }
    checkAgreement(exact, kept, "exactly touching");

    // Nudge every other ball by one ulp towards or away from its neighbour.
    for (int sign : {-1, 1}) {
        auto q = p;
        for (std::size_t i = 1; i < q.size(); i += 2)
            q[i].x() = std::nextafter(q[i].x(), sign < 0 ? -1e300 : 1e300);
        checkAgreement(makeBalls(q, r), kept, sign < 0 ? "one ulp closer" : "one ulp farther");
    }
    std::vector<Contact> closer;
    auto q = p;
    for (std::size_t i = 1; i < q.size(); i += 2)
        q[i].x() = std::nextafter(q[i].x(), -1e300);
    kept.detect(makeBalls(q, r), Detection::Grid, closer);
    VERIFY(!closer.empty());
}

// Balls centred on cell borders of the grid (cell = mean box size = 2r) and
// on an exact lattice where every neighbour pair touches exactly.
TEST_CASE("TestCollisionDetectors::cellBordersAndLattice")
{
    CollisionSystem kept;
    for (double spacing : {1.0, 2.0, 0.999999999999, 1.5}) {
        std::vector<Vec2> p;
        std::vector<double> r;
        for (int i = 0; i < 30; ++i)
            for (int j = 0; j < 30; ++j) {
                p.emplace_back(spacing * i, spacing * j);
                r.push_back(0.5);
            }
        checkAgreement(makeBalls(p, r), kept, ("lattice spacing " + std::to_string(spacing)).c_str());
    }
    // Random balls snapped to multiples of the cell size and half of it.
    std::mt19937_64 rng(5);
    std::uniform_int_distribution<int> k(-10, 60);
    for (int s = 0; s < 10; ++s) {
        std::vector<Vec2> p;
        std::vector<double> r;
        for (int i = 0; i < 800; ++i) {
            p.emplace_back(0.5 * k(rng) * 8.0, 0.5 * k(rng) * 8.0);
            r.push_back(i % 2 ? 4.0 : 2.0);
        }
        checkAgreement(makeBalls(p, r), kept, "snapped to cell borders");
    }
}

TEST_CASE("TestCollisionDetectors::outsideWallsAndFarAway")
{
    CollisionSystem kept;
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (double far : {1e3, 1e6, 1e9, 1e12}) {
        std::vector<Vec2> p;
        std::vector<double> r;
        for (int i = 0; i < 600; ++i) {
            if (i % 50 == 0) { // a small cluster far away, touching among itself
                p.emplace_back(far + 5.0 * u(rng), -far + 5.0 * u(rng));
                r.push_back(3.0);
            } else {
                p.emplace_back(300.0 + 300.0 * u(rng), 200.0 + 200.0 * u(rng));
                r.push_back(4.0 + 3.0 * u(rng));
            }
        }
        checkAgreement(makeBalls(p, r), kept, ("far away " + std::to_string(far)).c_str());
    }
    // A whole scene translated far from the origin: rounding at large coordinates.
    for (double offset : {1e7, -3e9}) {
        BallState s = randomScene(rng, 700, 2.0, 5.0, 0.5);
        s.position.array() += offset;
        checkAgreement(s, kept, "translated");
    }
}

TEST_CASE("TestCollisionDetectors::onePointAndNonFinite")
{
    CollisionSystem kept;
    std::vector<Vec2> p(100, Vec2(300.0, 200.0));
    std::vector<double> r(100, 10.0);
    std::vector<Contact> c;
    checkAgreement(makeBalls(p, r), kept, "100 on one point");
    kept.detect(makeBalls(p, r), Detection::Grid, c);
    REQUIRE_SAME(c.size(), std::size_t(100 * 99 / 2));
    // Broken balls take part in no pair, whatever the detector.
    p[3] = Vec2(std::numeric_limits<double>::quiet_NaN(), 200.0);
    p[7] = Vec2(std::numeric_limits<double>::infinity(), 200.0);
    p[8] = Vec2(300.0, -std::numeric_limits<double>::infinity());
    checkAgreement(makeBalls(p, r), kept, "with NaN and inf");
    kept.detect(makeBalls(p, r), Detection::Sweep, c);
    REQUIRE_SAME(c.size(), std::size_t(97 * 96 / 2));
}

// The sweep keeps its order between calls: drift a scene for many steps
// (small moves, then a big shuffle) and compare every step.
TEST_CASE("TestCollisionDetectors::movingScenesKeepOrder")
{
    std::mt19937_64 rng(2024);
    std::normal_distribution<double> g(0.0, 1.0);
    BallState s = randomScene(rng, 1500, 2.0, 3.0, 0.4);
    CollisionSystem kept;
    for (int step = 0; step < 60; ++step) {
        const double jiggle = (step % 20 == 19) ? 200.0 : 1.5; // now and then everything jumps
        for (int i = 0; i < s.size(); ++i)
            s.position.col(i) += jiggle * Vec2(g(rng), g(rng));
        checkAgreement(s, kept, ("drift step " + std::to_string(step)).c_str(), false);
    }
}

TEST_CASE("TestCollisionDetectors::continuousDetectionAgrees")
{
    std::mt19937_64 rng(77);
    std::normal_distribution<double> g(0.0, 1.0);
    CollisionSystem kept;
    for (int s = 0; s < 12; ++s) {
        const int n = s < 10 ? 400 : 3000;
        BallState end = randomScene(rng, n, 2.0, s % 2 ? 20.0 : 1.0, 0.2);
        Matrix2X start = end.position;
        const double speed = (s % 3 == 0) ? 40.0 : 3.0; // some balls move many radii
        for (int i = 0; i < n; ++i)
            start.col(i) -= speed * Vec2(g(rng), g(rng));
        std::vector<Contact> reference, got;
        CollisionSystem fresh;
        fresh.detectMoving(end, start, Detection::Brute, reference);
        std::vector<Contact> staticPairs;
        fresh.detect(end, Detection::Brute, staticPairs);
        VERIFY(reference.size() > staticPairs.size()); // paths that crossed add pairs
        VERIFY(std::includes(reference.begin(), reference.end(), staticPairs.begin(), staticPairs.end(),
                              [](const Contact& x, const Contact& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); }));
        for (Detection m : kMethods) {
            kept.detectMoving(end, start, m, got);
            VERIFY2(got == reference, (std::string("continuous ") + nameOf(m) + ": " + describe(reference, got)).c_str());
        }
    }
}

