#pragma once
// Round numbers for scales a student reads: grid spacings and scale bars are
// 1, 2 or 5 times a power of ten, so their labels are short and add up.

#include <cmath>

namespace forcelab {

/// The smallest of 1, 2, 5 × 10^k that is at least `atLeast` (> 0; 1 otherwise).
inline double roundStep(double atLeast)
{
    if (!(atLeast > 0.0) || !std::isfinite(atLeast))
        return 1.0;
    const double power = std::pow(10.0, std::floor(std::log10(atLeast)));
    for (double mantissa : {1.0, 2.0, 5.0, 10.0})
        if (mantissa * power >= atLeast * (1.0 - 1e-12))
            return mantissa * power;
    return 10.0 * power;
}

/// Decimals that write every multiple of a round step exactly (0 for steps of 1 and more).
inline int roundStepDecimals(double step)
{
    return step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
}

} // namespace forcelab
