#pragma once
// A scene: the settings of a world plus the balls it starts with. The lesson
// loader produces one; World::reset consumes one.

#include "ball_state.h"
#include "world_settings.h"

#include <cstdint>
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
};

struct Scene {
    WorldSettings settings;
    std::vector<Ball> balls;    ///< listed balls, placed first
    SpawnSettings spawn;
};

/// The default palette of spawned balls (six colours, readable on a projector).
const std::vector<Rgb>& defaultPalette();

/// Home of colour k of a palette of `count` colours: points on a circle around
/// the box centre (radius 0.3 × the shorter side), colour 0 at the right.
Vec2 paletteHome(int k, int count, const BoxSettings& box);

/// The starting balls of a scene: the listed ones, then `spawn.count` random
/// ones placed fully inside the box. Every ball gets the home of its colour
/// when its colour is in the palette, and the box centre otherwise.
/// Deterministic: depends only on the scene.
BallState buildBalls(const Scene& scene);

} // namespace forcelab::sim
