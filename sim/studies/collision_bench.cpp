#include "sim/studies/collision_bench.h"

#include "sim/world/names.h"
#include "sim/studies/peer_scene.h"
#include "sim/world/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <numbers>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>

#include <time.h>

namespace forcelab::sim {
namespace {

using Clock = std::chrono::steady_clock;

// CPU time of this thread: unlike wall-clock time it does not count the time
// the thread waited for the core while other programs ran.
double threadCpuMilliseconds()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

double millisecondsSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v)
{
    if (v.empty())
        return std::nan("");
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}



struct Row {
    std::string table;
    Detection detection;
    int n = 0;
    double detectMs = std::nan("");
    double stepMs = std::nan("");
    double detectCpuMs = std::nan("");
    double stepCpuMs = std::nan("");
    double onePassMs = std::nan("");    // the whole step with collisions.resting off, same warm state
    double onePassCpuMs = std::nan("");
    std::int64_t pairsTested = 0;
    std::int64_t contacts = 0;
};

constexpr Detection kDetections[] = {Detection::Brute, Detection::Halved, Detection::Sweep, Detection::Grid};

// Main table: detection alone and the whole step, per detector and size.
std::vector<Row> runMainTable(const CollisionBenchOptions& o, std::ostream& out)
{
    std::vector<Row> rows;
    out << "Box 30% full, radii 3-5 px, gravity 980 px/s^2, 2d-impulse e = 0.9, dt = 1/60 s, 1 sub-step.\n"
        << "Each world first runs 60 steps (1 s) so the balls are falling and piling up.\n"
        << "detect: CollisionSystem::detect on that state; step: World::step (forces, integration, walls,\n"
        << "detection, response; under gravity 2d-impulse solves resting contacts). 1-pass: the same step\n"
        << "with collisions.resting off (one textbook pass of 2d-impulse), from the same state. Median of " << o.runs
        << " runs.\nbrute and halved only up to N = " << o.bruteLimit
        << " (at 100,000 one brute call is 10^10 tests, about 10 s).\n\n";
    out << std::left << std::setw(8) << "detector" << std::right << std::setw(9) << "N" << std::setw(13)
        << "detect ms" << std::setw(12) << "step ms" << std::setw(11) << "(cpu det" << std::setw(10) << "cpu step)"
        << std::setw(12) << "1-pass cpu" << std::setw(14) << "pairs tested" << std::setw(10) << "contacts" << "\n";
    for (int n : o.sizes) {
        World warm(boxScene(n, 3.0, 5.0, 100.0, 0.9, Detection::Grid, 7));
        for (int k = 0; k < 60; ++k)
            warm.step();
        std::optional<BallState> reference;
        for (Detection d : kDetections) {
            Row row{"main", d, n};
            if ((d == Detection::Brute || d == Detection::Halved) && n > o.bruteLimit) {
                rows.push_back(row);
                continue;
            }
            // Detection alone, on the warm state (the sweep keeps its order between calls).
            CollisionSystem sys;
            std::vector<Contact> pairs;
            std::vector<double> times, cpu;
            const int runs = o.runs;
            for (int k = 0; k < runs + 1; ++k) {
                const double c0 = threadCpuMilliseconds();
                const auto t0 = Clock::now();
                const CollisionStats st = sys.detect(warm.balls(), d, pairs);
                const double ms = millisecondsSince(t0);
                if (k > 0) { // the first call sorts from scratch and allocates
                    times.push_back(ms);
                    cpu.push_back(threadCpuMilliseconds() - c0);
                }
                row.pairsTested = st.pairsTested;
                row.contacts = st.contacts;
            }
            row.detectMs = median(times);
            row.detectCpuMs = median(cpu);
            // Whole steps, from a copy of the warm world: medians of the wall
            // clock and of the thread's CPU time (the first step is dropped).
            auto timeSteps = [&](World& world, double& wallMs, double& cpuMs) {
                times.clear();
                cpu.clear();
                for (int k = 0; k < runs + 1; ++k) {
                    const double c0 = threadCpuMilliseconds();
                    world.step();
                    if (k > 0) {
                        times.push_back(world.lastStep().seconds * 1e3);
                        cpu.push_back(threadCpuMilliseconds() - c0);
                    }
                }
                wallMs = median(times);
                cpuMs = median(cpu);
            };
            World w = warm;
            WorldSettings ws = w.settings();
            ws.collisions.detection = d;
            w.setSettings(ws);
            timeSteps(w, row.stepMs, row.stepCpuMs);
            // The same steps with one pass of 2d-impulse instead of the
            // resting-contact solver, from the same warm state.
            World single = warm;
            ws.collisions.resting = false;
            single.setSettings(ws);
            timeSteps(single, row.onePassMs, row.onePassCpuMs);
            // Every detector finds the same pairs, so the runs (same number of
            // steps from the same state) are identical to the bit.
            if (!reference)
                reference = w.balls();
            else if (reference->position != w.balls().position)
                out << "  warning: " << toString(d) << " gave a different state\n";
            rows.push_back(row);
            out << std::left << std::setw(8) << toString(d) << std::right << std::setw(9) << n << std::fixed
                << std::setprecision(3) << std::setw(13) << row.detectMs << std::setw(12) << row.stepMs
                << std::setw(11) << row.detectCpuMs << std::setw(10) << row.stepCpuMs << std::setw(12)
                << row.onePassCpuMs << std::setw(14) << row.pairsTested << std::setw(10) << row.contacts << "\n"
                << std::flush;
        }
    }
    return rows;
}

// The thread's CPU time where it was measured (the main table): on a shared
// machine the wall clock also counts the time spent waiting for a core.
enum class Timed { Detect, Step, OnePass };

double findMs(const std::vector<Row>& rows, const std::string& table, Detection d, int n, Timed what)
{
    for (const Row& r : rows)
        if (r.table == table && r.detection == d && r.n == n) {
            const auto [cpu, wall] = what == Timed::Detect ? std::pair{r.detectCpuMs, r.detectMs}
                                     : what == Timed::Step ? std::pair{r.stepCpuMs, r.stepMs}
                                                           : std::pair{r.onePassCpuMs, r.onePassMs};
            return std::isnan(cpu) ? wall : cpu;
        }
    return std::nan("");
}

void printTargets(const std::vector<Row>& rows, const CollisionBenchOptions& o, std::ostream& out)
{
    auto ms = [&](Detection d, int n, Timed what) { return findMs(rows, "main", d, n, what); };
    const int small = o.sizes.front(), large = o.sizes.back();
    out << "\nTargets (one core, thread CPU time):\n" << std::fixed << std::setprecision(1);
    for (Detection d : {Detection::Sweep, Detection::Grid}) {
        const double det = ms(d, large, Timed::Detect) / ms(d, small, Timed::Detect);
        const double stp = ms(d, large, Timed::Step) / ms(d, small, Timed::Step);
        out << "  " << toString(d) << ": t(" << large << ")/t(" << small << ") = " << det << " detect, " << stp
            << " step (N ratio " << large / std::max(1, small) << ", target <= 150)\n";
    }
    if (std::find(o.sizes.begin(), o.sizes.end(), 4000) != o.sizes.end()) {
        out << "  sweep vs brute at 4000: "
            << ms(Detection::Brute, 4000, Timed::Detect) / ms(Detection::Sweep, 4000, Timed::Detect) << "x detect, "
            << ms(Detection::Brute, 4000, Timed::Step) / ms(Detection::Sweep, 4000, Timed::Step)
            << "x step (target >= 10x)\n";
    }
    if (std::find(o.sizes.begin(), o.sizes.end(), 100000) != o.sizes.end()) {
        out << std::setprecision(2) << "  whole step at 100000: grid " << ms(Detection::Grid, 100000, Timed::Step)
            << " ms, sweep " << ms(Detection::Sweep, 100000, Timed::Step) << " ms with resting contacts; grid "
            << ms(Detection::Grid, 100000, Timed::OnePass) << " ms, sweep "
            << ms(Detection::Sweep, 100000, Timed::OnePass) << " ms with one pass (target <= 10 ms)\n";
    }
}

// Where one step's time goes, stage by stage, for sweep and grid at the
// largest size: the collision stage's own timers (CollisionSystem::profile)
// and the rest of World::step (forces, integration, walls, the state copy).
void runProfile(const CollisionBenchOptions& o, std::ostream& out)
{
    const int n = o.sizes.back();
    const int steps = std::max(o.runs, 5);
    World warm(boxScene(n, 3.0, 5.0, 100.0, 0.9, Detection::Grid, 7));
    for (int k = 0; k < 60; ++k)
        warm.step();
    out << "\nProfile at N = " << n << ": mean ms per step over " << steps
        << " steps from the warm state (thread CPU time for the whole step).\n\n";
    struct Stage {
        const char* name;
        double CollisionProfile::*field;
    };
    const Stage stages[] = {{"load balls, boxes", &CollisionProfile::load},
                            {"broad phase: sort / cells", &CollisionProfile::broadSort},
                            {"pairs + narrow phase", &CollisionProfile::pairs},
                            {"contact sort (a, b)", &CollisionProfile::contactSort},
                            {"solver: rows, flags", &CollisionProfile::build},
                            {"solver: wall scan", &CollisionProfile::wallScan},
                            {"solver: velocity passes", &CollisionProfile::velocity},
                            {"solver: restitution", &CollisionProfile::restitution},
                            {"solver: position update", &CollisionProfile::position},
                            {"positional correction", &CollisionProfile::correction},
                            {"sleeping", &CollisionProfile::sleep}};
    std::vector<CollisionProfile> profiles;
    std::vector<double> stepMs;
    const Detection dets[] = {Detection::Sweep, Detection::Grid};
    for (Detection d : dets) {
        World w = warm;
        WorldSettings ws = w.settings();
        ws.collisions.detection = d;
        w.setSettings(ws);
        if (o.speculative >= 0.0) {
            ContactSolverSettings cs = w.collisionSystem().solverSettings();
            cs.speculative = o.speculative;
            w.collisionSystem().setSolverSettings(cs);
        }
        w.step(); // first step with this detector: sorts from scratch
        w.collisionSystem().resetProfile();
        w.collisionSystem().setProfiling(true);
        const double c0 = threadCpuMilliseconds();
        for (int k = 0; k < steps; ++k)
            w.step();
        stepMs.push_back((threadCpuMilliseconds() - c0) / steps);
        profiles.push_back(w.collisionSystem().profile());
    }
    out << std::left << std::setw(28) << "stage" << std::right << std::setw(10) << "sweep" << std::setw(10) << "grid"
        << "\n"
        << std::fixed << std::setprecision(3);
    for (const Stage& s : stages) {
        out << std::left << std::setw(28) << s.name << std::right;
        for (const CollisionProfile& p : profiles)
            out << std::setw(10) << p.*s.field * 1e3 / steps;
        out << "\n";
    }
    out << std::left << std::setw(28) << "collision stage, total" << std::right;
    for (const CollisionProfile& p : profiles)
        out << std::setw(10) << p.total() * 1e3 / steps;
    out << "\n" << std::left << std::setw(28) << "rest of World::step" << std::right;
    for (std::size_t k = 0; k < profiles.size(); ++k)
        out << std::setw(10) << stepMs[k] - profiles[k].total() * 1e3 / steps;
    out << "\n" << std::left << std::setw(28) << "whole step (cpu)" << std::right;
    for (double ms : stepMs)
        out << std::setw(10) << ms;
    out << "\n" << std::left << std::setw(28) << "velocity passes per step" << std::right << std::setprecision(1);
    for (const CollisionProfile& p : profiles)
        out << std::setw(10) << static_cast<double>(p.passes) / steps;
    out << "\n" << std::left << std::setw(28) << "solver rows per step" << std::right << std::setprecision(0);
    for (const CollisionProfile& p : profiles)
        out << std::setw(10) << static_cast<double>(p.rows) / steps;
    out << "\n" << std::left << std::setw(28) << "row updates per step" << std::right;
    for (const CollisionProfile& p : profiles)
        out << std::setw(10) << static_cast<double>(p.solves) / steps;
    out << "\n" << std::flush;
}

// The peer scene of the issue: equal circles (r = 5 px) filling 30% of a
// square box on a jittered grid, gravity, restitution 0.9, 600 steps at 60 Hz.
std::vector<Row> runPeerTable(const CollisionBenchOptions& o, std::ostream& out)
{
    std::vector<Row> rows;
    out << "\nPeer scene: N equal circles (r = 5 px) filling 30% of a square box on a jittered grid, at rest,\n"
        << "gravity 980 px/s^2, restitution 0.9 (balls and walls), " << o.peerSteps
        << " steps at 60 Hz, 1 sub-step, one thread.\n"
        << "Mean thread CPU ms per step over the whole run. sweep 1-pass: collisions.resting off, one pass of\n"
        << "2d-impulse per step (piles sink). Other engines on the same scene: forcelab-peer-box2d (built when\n"
        << "libbox2d-dev is installed).\n\n";
    out << std::left << std::setw(8) << "N" << std::right << std::setw(12) << "grid" << std::setw(12) << "sweep"
        << std::setw(14) << "sweep 1-pass" << "\n";
    for (int n : o.peerSizes) {
        // grid and sweep with resting contacts, then sweep with one pass.
        struct Run {
            Detection detection;
            bool resting;
        };
        const Run runs[] = {{Detection::Grid, true}, {Detection::Sweep, true}, {Detection::Sweep, false}};
        double ms[3] = {0, 0, 0};
        for (int k = 0; k < 3; ++k) {
            const Run& run = runs[k];
            const Detection d = run.detection;
            Scene scene = boxScene(n, 5.0, 5.0, 0.0, 0.9, d, 3);
            scene.settings.collisions.resting = run.resting;
            World w(scene);
            const double c0 = threadCpuMilliseconds();
            std::int64_t contacts = 0;
            for (int s = 0; s < o.peerSteps; ++s) {
                w.step();
                contacts += w.lastStep().contacts;
            }
            ms[k] = (threadCpuMilliseconds() - c0) / o.peerSteps;
            if (!run.resting) { // the one-pass run goes beside the sweep's row
                rows.back().onePassMs = rows.back().onePassCpuMs = ms[k];
                continue;
            }
            Row row{"peer", d, n};
            row.stepMs = ms[k];
            row.contacts = contacts;
            row.pairsTested = w.totals().pairsTested;
            rows.push_back(row);
        }
        auto fmt = [](double v) {
            std::ostringstream ss;
            if (std::isnan(v))
                ss << "-";
            else
                ss << std::fixed << std::setprecision(v < 10 ? 2 : 1) << v;
            return ss.str();
        };
        out << std::left << std::setw(8) << n << std::right << std::setw(12) << fmt(ms[0]) << std::setw(12)
            << fmt(ms[1]) << std::setw(14) << fmt(ms[2])
            << "\n"
            << std::flush;
    }
    return rows;
}

// The spawn scene of issue #39: n balls spawned at random (overlapping
// where they land) in a 3500 px box, radii 2-4 px, speeds 0-50 px/s,
// gravity 300 px/s^2, e = 0.9, sweep and prune. A gas that falls into a pile.
Scene spawnScene(int n)
{
    Scene s;
    s.settings.box = BoxSettings{3500.0, 3500.0};
    s.settings.walls = WallSettings{true, true, true, true, WallModel::Clamp, 0.9};
    s.settings.gravity.enabled = true;
    s.settings.gravity.g = Vec2(0.0, 300.0);
    s.settings.collisions.detection = Detection::Sweep;
    s.settings.collisions.response = Response::Impulse2D;
    s.settings.collisions.restitution = 0.9;
    s.settings.time.integrator = IntegratorKind::SemiImplicitEuler;
    s.settings.time.dt = 1.0 / 60.0;
    s.settings.time.substeps = 1;
    s.spawn.count = n;
    s.spawn.minRadius = 2.0;
    s.spawn.maxRadius = 4.0;
    s.spawn.minSpeed = 0.0;
    s.spawn.maxSpeed = 50.0;
    s.spawn.seed = 7;
    return s;
}

// Mean thread-CPU ms per step over the first k steps of the spawn scene, for
// each k of o.spawnSteps, with the resting-contact solver (the default) and
// with one pass (collisions.resting off), and their ratio.
void runSpawnTable(const CollisionBenchOptions& o, std::ostream& out)
{
    const int n = o.spawnSize;
    out << "\nSpawn scene: " << n
        << " balls spawned at random in a 3500 px box (r 2-4 px, speeds 0-50 px/s), gravity 300 px/s^2,\n"
        << "e = 0.9, sweep, dt = 1/60 s, 1 sub-step. Mean thread CPU ms per step over the first K steps;\n"
        << "1-pass: collisions.resting off.\n\n";
    const int last = *std::max_element(o.spawnSteps.begin(), o.spawnSteps.end());
    std::vector<double> perStep[2];
    for (int k = 0; k < 2; ++k) {
        Scene scene = spawnScene(n);
        scene.settings.collisions.resting = k == 0;
        World w(scene);
        for (int s = 0; s < last; ++s) {
            const double c0 = threadCpuMilliseconds();
            w.step();
            perStep[k].push_back(threadCpuMilliseconds() - c0);
        }
    }
    out << std::left << std::setw(10) << "steps" << std::right << std::setw(14) << "default ms" << std::setw(14)
        << "1-pass ms" << std::setw(10) << "ratio" << "\n";
    for (int steps : o.spawnSteps) {
        double mean[2];
        for (int k = 0; k < 2; ++k)
            mean[k] = std::accumulate(perStep[k].begin(), perStep[k].begin() + steps, 0.0) / steps;
        out << std::left << std::setw(10) << steps << std::right << std::fixed << std::setprecision(2)
            << std::setw(14) << mean[0] << std::setw(14) << mean[1] << std::setw(10) << mean[0] / mean[1] << "\n"
            << std::flush;
    }
}

// A streaming copy between two buffers of `bytes`: the rate at which one core
// can read and write memory of that size (bytes read + bytes written per second).
double copyGigabytesPerSecond(std::size_t bytes, int runs)
{
    std::vector<double> a(bytes / sizeof(double), 1.0), b(bytes / sizeof(double), 0.0);
    std::vector<double> times;
    for (int k = 0; k < runs; ++k) {
        const auto t0 = Clock::now();
        std::memcpy(b.data(), a.data(), a.size() * sizeof(double));
        times.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
        a[static_cast<std::size_t>(k) % a.size()] += b[(static_cast<std::size_t>(k) * 7) % b.size()];
    }
    return 2.0 * static_cast<double>(bytes) / median(times) / 1e9;
}

void runBandwidth(const std::vector<Row>& rows, const CollisionBenchOptions& o, std::ostream& out)
{
    const double big = copyGigabytesPerSecond(std::size_t(256) << 20, 5);
    const double mid = copyGigabytesPerSecond(std::size_t(8) << 20, 21);
    out << "\nMemory: streaming copy, one core: " << std::fixed << std::setprecision(1) << big
        << " GB/s (256 MB buffers, main memory), " << mid << " GB/s (8 MB buffers, cache)\n";
    const int n = o.sizes.back();
    // The least a step must move: read and write position and velocity (32 B
    // each way), read radius and inverse mass (16 B): 80 B per ball.
    const double minimum = 80.0 * n;
    for (Detection d : {Detection::Grid, Detection::Sweep}) {
        const double ms = findMs(rows, "main", d, n, Timed::Step);
        if (std::isnan(ms))
            continue;
        out << "  " << toString(d) << " step at N = " << n << ": " << std::setprecision(2) << ms
            << " ms; the 80 B/ball minimum at " << std::setprecision(1) << big << " GB/s takes "
            << std::setprecision(3) << minimum / (big * 1e9) * 1e3 << " ms (" << std::setprecision(0)
            << ms / (minimum / (big * 1e9) * 1e3) << "x); effective traffic at full bandwidth would be "
            << ms * 1e-3 * big * 1e9 / n << " B/ball\n";
    }
}

void writeCsv(const std::vector<Row>& rows, std::ostream& csv)
{
    csv << "table,detector,n,detect_ms,step_ms,detect_cpu_ms,step_cpu_ms,pairs_tested,contacts,one_pass_ms,"
           "one_pass_cpu_ms\n";
    // A time that was not measured (brute force above its limit) is an empty cell.
    auto cell = [&](double ms) -> std::ostream& {
        if (!std::isnan(ms))
            csv << ms;
        return csv;
    };
    for (const Row& r : rows) {
        csv << r.table << "," << toString(r.detection) << "," << r.n << ",";
        cell(r.detectMs) << ",";
        cell(r.stepMs) << ",";
        cell(r.detectCpuMs) << ",";
        cell(r.stepCpuMs) << "," << r.pairsTested << "," << r.contacts << ",";
        cell(r.onePassMs) << ",";
        cell(r.onePassCpuMs) << "\n";
    }
}

} // namespace

void runCollisionBench(const CollisionBenchOptions& o, std::ostream& out, std::ostream* csv)
{
    std::vector<Row> rows;
    if (o.main) {
        rows = runMainTable(o, out);
        printTargets(rows, o, out);
    }
    if (o.profile && o.main)
        runProfile(o, out);
    if (o.bandwidth)
        runBandwidth(rows, o, out);
    if (o.spawnSize > 0)
        runSpawnTable(o, out);
    if (o.peers) {
        const auto peer = runPeerTable(o, out);
        rows.insert(rows.end(), peer.begin(), peer.end());
    }
    if (csv)
        writeCsv(rows, *csv);
}

} // namespace forcelab::sim
