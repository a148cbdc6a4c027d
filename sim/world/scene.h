#pragma once
// A scene: the settings of a world plus the balls it starts with. The lesson
// loader produces one; World::reset consumes one.

#include "sim/world/ball_state.h"
#include "sim/world/world_settings.h"

#include <cstdint>
#include <random>
#include <vector>

namespace forcelab::sim {

/// Balls placed at random when a scene starts (in addition to the listed ones).
struct SpawnSettings {
    int count = 0;              ///< balls
    double minRadius = 4.0;     ///< px
    double maxRadius = 12.0;    ///< px
    double minSpeed = 0.0;      ///< px/s
    double maxSpeed = 300.0;    ///< px/s
    std::uint64_t seed = 7;     ///< the same seed places the same balls
    std::vector<Rgb> palette;   ///< colours to choose from; empty: the default palette
    bool horizontal = false;    ///< velocities along x only, to the left or right (stages 2–5)
    bool fullyInside = true;    ///< false: a centre may be anywhere in the box, so a ball can start partly outside
    double perStep = 0.0;       ///< 1, chance each step that one more ball appears while running, [0, 1]
    int maxCount = 200;         ///< balls, spawning over time stops at this many balls in the world
};

struct Scene {
    WorldSettings settings;
    std::vector<Ball> balls;    ///< listed balls, placed first
    SpawnSettings spawn;
};

/// A ball at (x, y) px with velocity (vx, vy) px/s, radius r px and mass m
/// (0: the density-1 sphere of its radius): for tests, tools and reference
/// problems that build scenes in code.
Ball ballAt(double x, double y, double vx = 0.0, double vy = 0.0, double r = 10.0, double mass = 0.0);

/// A scene with these balls, no walls and no models.
Scene openScene(std::vector<Ball> balls);

/// The default palette of spawned balls (six colours, readable on a projector).
const std::vector<Rgb>& defaultPalette();

/// Home of colour k of a palette of `count` colours: points on a circle around
/// the box centre (radius 0.3 × the shorter side), colour 0 at the right.
Vec2 paletteHome(int k, int count, const BoxSettings& box);

/// One random ball as the spawn settings describe (radius, position, speed,
/// colour and home), drawn from `rng`.
Ball randomBall(const SpawnSettings& spawn, const BoxSettings& box, std::mt19937_64& rng);

/// The starting balls of a scene: the listed ones, then `spawn.count` random
/// ones placed fully inside the box. Every ball gets the home of its colour
/// when its colour is in the palette, and the box centre otherwise.
/// Deterministic: depends only on the scene.
BallState buildBalls(const Scene& scene);

} // namespace forcelab::sim
