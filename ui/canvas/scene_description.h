#pragma once
// The stage in one or two sentences, for a screen reader and for anyone who
// cannot see the projector well: how many balls, what the selected ball (or
// ball 0) does, when it reaches a wall, and the total energy, in the units
// shown. "Four balls. The red ball moves right and down at 1.2 m/s and
// will hit the floor in 0.41 s. Total energy 1.2 × 10⁴ J." A wall time is
// exact for a ball under gravity alone (said plainly) and the continuation
// of the present motion otherwise (said "about").
#include "sim/world/world.h"

#include <QString>

namespace forcelab {

QString describeScene(const sim::World& world, int ball);

} // namespace forcelab
