#include "scene.h"

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

    // std::mt19937_64 is specified bit for bit by the standard; the
    // distributions are not, so uniform values come from our own mapping.
    std::mt19937_64 rng(spawn.seed);
    auto uniform = [&](double lo, double hi) {
        const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53; // [0, 1)
        return lo + (hi - lo) * u;
    };
    for (int i = 0; i < spawn.count; ++i) {
        Ball b;
        b.radius = uniform(spawn.minRadius, spawn.maxRadius);
        // Fully inside the box when it fits; a ball wider than the box sits in the middle.
        const double x0 = std::min(b.radius, 0.5 * box.width), x1 = std::max(box.width - b.radius, x0);
        const double y0 = std::min(b.radius, 0.5 * box.height), y1 = std::max(box.height - b.radius, y0);
        b.position = Vec2(uniform(x0, x1), uniform(y0, y1));
        const double speed = uniform(spawn.minSpeed, spawn.maxSpeed);
        const double angle = uniform(0.0, 2.0 * std::numbers::pi);
        b.velocity = speed * Vec2(std::cos(angle), std::sin(angle));
        const int k = std::min(colours - 1, static_cast<int>(uniform(0.0, colours)));
        b.color = palette[static_cast<std::size_t>(k)];
        b.home = paletteHome(k, colours, box);
        state.set(listed + i, b);
    }
    return state;
}

} // namespace forcelab::sim
