#include "sim/forces/wind.h"

#include "sim/forces/force_model.h"

#include <algorithm>

namespace forcelab::sim {

WindGenerator::WindGenerator(std::uint64_t seed)
    : m_rng(seed)
    , m_noise(seed)
{
}

void WindGenerator::advance(WindMode mode, const WindSettings& w, const PointerInput& pointer, double boxWidth)
{
    // A uniform value in [-1, 1) from the top 53 bits: the standard fixes the
    // output of mt19937_64 but not of std::uniform_real_distribution.
    auto symmetric = [this] { return static_cast<double>(m_rng() >> 11) * 0x1.0p-52 - 1.0; };
    switch (mode) {
    case WindMode::Off:
    case WindMode::Noise:
        m_value = 0.0;
        break;
    case WindMode::Random: // a fresh value every step, centred on zero: jerky
        m_value = w.strength * symmetric();
        break;
    case WindMode::Smoothed: // a bounded random walk: each step changes it only a little
        m_value = std::clamp(m_value + w.smoothedStep * w.strength * symmetric(), -w.strength, w.strength);
        break;
    case WindMode::Pointer: { // blows away from the pointer's side, harder the further out
        const double half = 0.5 * boxWidth;
        m_value = pointer.inside ? -w.strength * std::clamp((pointer.position.x() - half) / half, -1.0, 1.0) : 0.0;
        break;
    }
    }
}

double WindGenerator::at(WindMode mode, const WindSettings& w, double t) const
{
    if (mode == WindMode::Noise)
        return w.strength * m_noise(t * w.noiseFrequency);
    return m_value;
}

} // namespace forcelab::sim
