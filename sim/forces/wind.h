#pragma once
// The wind: a horizontal acceleration that changes over time, in one of four
// ways. Random and smoothed draw a value once per step (so every stage of an
// integrator sees the same wind); noise is a smooth function of time; pointer
// follows the pointer's horizontal offset from the centre of the box.

#include "sim/forces/noise.h"
#include "sim/world/types.h"
#include "sim/world/world_settings.h"

#include <cstdint>
#include <random>

namespace forcelab::sim {

struct PointerInput;

class WindGenerator {
public:
    WindGenerator() : WindGenerator(1) {}
    explicit WindGenerator(std::uint64_t seed);

    /// Moves to the next step: draws the random and smoothed values, reads the pointer.
    void advance(WindMode mode, const WindSettings& settings, const PointerInput& pointer, double boxWidth);

    /// Wind on a reference ball at time t, px/s² (+ blows to the right).
    double at(WindMode mode, const WindSettings& settings, double t) const;

    /// The generator's state and this step's value, for a copy of the run
    /// written elsewhere (the course's JavaScript) to go on from here.
    const std::mt19937_64& generator() const { return m_rng; }
    double value() const { return m_value; } ///< px/s²

private:
    std::mt19937_64 m_rng;
    GradientNoise1D m_noise;
    double m_value = 0.0; // px/s², this step's value for random, smoothed and pointer
};

} // namespace forcelab::sim
