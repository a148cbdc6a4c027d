#include "sim/world/scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace forcelab::sim {

const std::vector<Rgb>& defaultPalette()
{
    static const std::vector<Rgb> palette{0xe05050, 0xe0a030, 0x50b050, 0x3090d0, 0x8060d0, 0xd060a0};
    return palette;
}

Vec2 paletteHome(int k, int count, const BoxSettings& box)
{
    const Vec2 centre(0.5 * box.width, 0.5 * box.height);
    if (count <= 1)
        return centre;
    const double radius = 0.3 * std::min(box.width, box.height);
    const double angle = 2.0 * std::numbers::pi * k / count;
    return centre + radius * Vec2(std::cos(angle), std::sin(angle));
}

namespace {

// A uniform value in [lo, hi) from the top 53 bits of the generator: the
// standard fixes mt19937_64's output but not std::uniform_real_distribution's.
double uniform(std::mt19937_64& rng, double lo, double hi)
{
    const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;
    return lo + (hi - lo) * u;
}

} // namespace

Ball randomBall(const SpawnSettings& spawn, const BoxSettings& box, std::mt19937_64& rng)
{
    const std::vector<Rgb>& palette = spawn.palette.empty() ? defaultPalette() : spawn.palette;
    const int colours = static_cast<int>(palette.size());
    Ball b;
    b.radius = uniform(rng, spawn.minRadius, spawn.maxRadius);
    // Fully inside the box when asked and when it fits (a ball wider than the
    // box sits in the middle); otherwise the centre is anywhere in the box.
    const double mx = spawn.fullyInside ? std::min(b.radius, 0.5 * box.width) : 0.0;
    const double my = spawn.fullyInside ? std::min(b.radius, 0.5 * box.height) : 0.0;
    // Drawn one at a time, y first: two draws as the arguments of one call
    // happen in an order the compiler chooses (GCC right to left), so the
    // same seed gave other balls with another compiler. y first keeps every
    // lesson's balls as GCC has always made them, and is the order the
    // course's JavaScript (lessons/code/spawn.js) draws them in.
    const double y = uniform(rng, my, box.height - my);
    const double x = uniform(rng, mx, box.width - mx);
    b.position = Vec2(x, y);
    const double speed = uniform(rng, spawn.minSpeed, spawn.maxSpeed);
    const double angle = uniform(rng, 0.0, 2.0 * std::numbers::pi);
    b.velocity = spawn.horizontal ? Vec2(std::cos(angle) < 0.0 ? -speed : speed, 0.0)
                                  : Vec2(speed * std::cos(angle), speed * std::sin(angle));
    const int k = std::min(colours - 1, static_cast<int>(uniform(rng, 0.0, colours)));
    b.color = palette[static_cast<std::size_t>(k)];
    b.home = paletteHome(k, colours, box);
    return b;
}

BallState buildBalls(const Scene& scene)
{
    const BoxSettings& box = scene.settings.box;
    const SpawnSettings& spawn = scene.spawn;
    const std::vector<Rgb>& palette = spawn.palette.empty() ? defaultPalette() : spawn.palette;
    const int colours = static_cast<int>(palette.size());
    auto homeOf = [&](Rgb c) {
        const auto it = std::find(palette.begin(), palette.end(), c);
        return it == palette.end() ? Vec2(0.5 * box.width, 0.5 * box.height)
                                   : paletteHome(static_cast<int>(it - palette.begin()), colours, box);
    };

    const int listed = static_cast<int>(scene.balls.size());
    BallState state;
    state.resize(listed + std::max(0, spawn.count));
    for (int i = 0; i < listed; ++i) {
        Ball b = scene.balls[static_cast<std::size_t>(i)];
        b.home = homeOf(b.color);
        state.set(i, b);
    }
    std::mt19937_64 rng(spawn.seed);
    for (int i = 0; i < spawn.count; ++i)
        state.set(listed + i, randomBall(spawn, box, rng));
    return state;
}

Ball ballAt(double x, double y, double vx, double vy, double r, double mass)
{
    Ball b;
    b.position = Vec2(x, y);
    b.velocity = Vec2(vx, vy);
    b.radius = r;
    b.mass = mass;
    return b;
}

Scene openScene(std::vector<Ball> balls)
{
    Scene s;
    s.settings.walls = WallSettings{false, false, false, false, WallModel::Clamp, 1.0};
    s.balls = std::move(balls);
    return s;
}

} // namespace forcelab::sim
