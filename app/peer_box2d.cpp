// forcelab-peer-box2d: the peer scene run by ForceLab and by Box2D from the
// same initial state, with the same end-state measures. Built only when CMake
// finds a Box2D: Debian's 2.4 (libbox2d-dev; peer_box2d_v2.cpp) or a Box2D 3
// installed by hand and named with -DCMAKE_PREFIX_PATH (peer_box2d_v3.cpp).
//
//   forcelab-peer-box2d [--profile] [N ...]   (default 5000 20000; 600 steps at 60 Hz)
//
// --profile adds, per N, where ForceLab's step spends its time (one more run
// on one thread with the collision stage's clocks on).

#include "peer_box2d.h"

#include "sim/world/threads.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace forcelab::peer {

double nowMilliseconds()
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void print(const char* engine, int n, const StepTimes& ms, const sim::PileMeasures& m)
{
    std::printf("%-10s %7d %10.2f %10.4f %10.3f %10.4f %10.2f %10.1f %10.2f %10d\n", engine, n, ms.all, ms.lastHalf,
                m.deepestOverlap, m.meanOverlap, m.rmsSpeed, m.meanHeight, m.pileRmsSpeed, m.inFlight);
}

// ForceLab on `threads` threads: the wall-clock time per step (with one
// thread the same as its CPU time), and the same end state for any count.
void runForceLab(const sim::Scene& scene, int threads)
{
    using namespace forcelab::sim;
    const ThreadLimit limit(threads);
    World w(scene);
    const StepTimes ms = timeSteps([&] { w.step(); });
    char name[32];
    std::snprintf(name, sizeof name, "ForceLab/%d", availableThreads());
    print(name, w.balls().size(), ms, measurePile(w));
}

// ForceLab on one thread again, with the collision stage's clocks on
// (collision_profile.h): where a step's time goes, in ms per step over the
// whole run. What the collision stage does not count (integrating, the
// walls, the world's checks) is the step's time less the stages'.
void profileForceLab(const sim::Scene& scene)
{
    using namespace forcelab::sim;
    const ThreadLimit limit(1);
    World w(scene);
    CollisionSystem& collisions = w.collisionSystem();
    collisions.setProfiling(true);
    const StepTimes ms = timeSteps([&] { w.step(); });
    const CollisionProfile& p = collisions.profile();
    const double perStep = 1000.0 / kSteps; // s over the run to ms a step
    const double broad = p.load + p.broadSort + p.pairs + p.contactSort;
    const double passes = p.velocity + p.restitution + p.position;
    std::printf("  profile %d: %.2f ms a step = broad phase %.2f + rows %.2f + passes %.2f + correction %.2f + "
                "sleeping %.2f + the rest of the step %.2f; %lld rows and %lld passes a step\n",
                w.balls().size(), ms.all, broad * perStep, (p.build + p.wallScan) * perStep, passes * perStep,
                p.correction * perStep, p.sleep * perStep, ms.all - p.total() * perStep,
                static_cast<long long>(p.rows / kSteps), static_cast<long long>(p.passes / kSteps));
}

} // namespace forcelab::peer

int main(int argc, char** argv)
{
    using namespace forcelab::peer;
    std::setvbuf(stdout, nullptr, _IOLBF, 0); // each row as soon as it is measured
    std::vector<int> sizes;
    bool profile = false;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--profile") {
            profile = true;
            continue;
        }
        char* end = nullptr;
        const long n = std::strtol(argv[i], &end, 10);
        if (*end != '\0' || n < 1 || n > 1000000) {
            std::fprintf(stderr, "forcelab-peer-box2d: ball count '%s' is not a whole number in [1, 1000000]\n", argv[i]);
            return 2;
        }
        sizes.push_back(static_cast<int>(n));
    }
    if (sizes.empty())
        sizes = {5000, 20000};
    std::printf("Peer scene, %d steps at 60 Hz; ms per step (wall clock; ForceLab/T: T threads, %s one) over "
                "all steps and over the last %d; end state after 10 s\n",
                kSteps, box2dName(), kSteps - kSteps / 2);
    std::printf("%-10s %7s %10s %10s %10s %10s %10s %10s %10s %10s\n", "engine", "N", "ms/step", "last half",
                "deepest r", "mean r", "rms px/s", "height px", "pile px/s", "in flight");
    for (int n : sizes) {
        const forcelab::sim::Scene scene = forcelab::sim::peerScene(n);
        runForceLab(scene, 1);
        runForceLab(scene, 2);
        runBox2D(scene);
        if (profile)
            profileForceLab(scene);
    }
    return 0;
}
