// forcelab-cli soak: a long run of a 1,000-ball box with collisions, to show
// that nothing drifts, leaks or blows up over 10^6 steps. A benchmark, not a
// test: it takes minutes.

#include "cli_commands.h"

#include "cli_args.h"
#include "sim/world/world.h"

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <iomanip>

namespace forcelab::cli {
namespace {

// Peak resident memory of this process so far, MiB (Linux reports KiB).
double peakRssMiB()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

} // namespace

void declareSoak(QCommandLineParser& p)
{
    p.addOptions({{QStringLiteral("steps"), QStringLiteral("Steps to run (default 1000000)."), QStringLiteral("N")},
                  {QStringLiteral("balls"), QStringLiteral("Balls in the box (default 1000)."), QStringLiteral("N")}});
}

int soakCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err)
{
    std::int64_t steps = 1'000'000;
    int balls = 1000;
    for (const char* name : {"steps", "balls"}) {
        if (!parser.isSet(QString::fromLatin1(name)))
            continue;
        const double v = parseFiniteNumber(valueOf(parser, name)).value_or(-1.0);
        const bool isSteps = std::string_view(name) == "steps";
        const double most = isSteps ? 1e10 : double(sim::kMaxBalls);
        if (v < 1 || std::floor(v) != v || v > most) {
            err << "forcelab-cli soak: --" << name << ": expects a whole number from 1 to " << most << "\n";
            return 2;
        }
        if (isSteps)
            steps = static_cast<std::int64_t>(v);
        else
            balls = static_cast<int>(v);
    }

    // A box about 20% full of balls, walls and ball-ball collisions with
    // e = 1 and nothing else: kinetic energy is conserved exactly by the
    // model, so any drift is the program's.
    sim::Scene scene;
    const double side = std::sqrt(balls * 3.14159 * 36.0 / 0.2);
    scene.settings.box = sim::BoxSettings{side, side};
    scene.settings.walls.model = sim::WallModel::Exact;
    scene.settings.collisions = sim::CollisionSettings{sim::Detection::Sweep, sim::Response::Impulse2D, 1.0, false};
    scene.spawn.count = balls;
    scene.spawn.minRadius = 4;
    scene.spawn.maxRadius = 8;
    sim::World world;
    if (auto error = world.reset(scene)) {
        err << "forcelab-cli soak: " << sim::toString(*error) << "\n";
        return 2;
    }
    const double e0 = world.energy().total();
    out << "soak: " << balls << " balls in a " << std::lround(side) << " px box, 2d-impulse e = 1, exact walls, "
        << steps << " steps of " << scene.settings.time.dt << " s\n";
    out << std::setw(12) << "step" << std::setw(16) << "rel. energy" << std::setw(14) << "peak RSS MiB"
        << std::setw(12) << "contacts" << std::setw(12) << "us/step\n";
    const auto started = std::chrono::steady_clock::now();
    auto last = started;
    std::int64_t lastStep = 0;
    double worst = 0.0;
    for (std::int64_t k = 1; k <= steps; ++k) {
        world.step();
        if (world.halted()) {
            err << "forcelab-cli soak: stopped at step " << k << ": " << *world.halted() << "\n";
            return 3;
        }
        const bool report = k == steps || k % (steps / 10 > 0 ? steps / 10 : 1) == 0;
        if (k % 1000 == 0 || report) {
            if (!world.balls().position.allFinite() || !world.balls().velocity.allFinite()) {
                err << "forcelab-cli soak: NaN or Inf at step " << k << "\n";
                return 1;
            }
            worst = std::max(worst, std::abs(world.energy().total() - e0) / e0);
        }
        if (report) {
            const auto now = std::chrono::steady_clock::now();
            const double us = std::chrono::duration<double, std::micro>(now - last).count() / double(k - lastStep);
            out << std::setw(12) << k << std::setw(16) << std::setprecision(3)
                << (world.energy().total() - e0) / e0 << std::setw(14) << std::setprecision(4) << peakRssMiB()
                << std::setw(12) << world.lastStep().contacts << std::setw(12) << std::setprecision(4) << us
                << "\n";
            last = now;
            lastStep = k;
        }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    out << "largest relative energy change (sampled every 1000 steps): " << worst << "\n"
        << "no NaN; peak RSS " << peakRssMiB() << " MiB; " << seconds << " s in all\n";
    return 0;
}

} // namespace forcelab::cli
