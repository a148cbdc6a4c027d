#pragma once
// Where the view looks: how far it is zoomed in and which world point is at
// the middle of the stage. The default camera shows the whole box, as large
// as it fits; the canvas changes it with the wheel, the zoom keys, a pan drag
// and "follow the selected ball".

#include "sim/world/types.h"

#include <optional>

namespace forcelab {

struct Camera {
    /// Zoom limits: a 800 px box is 8 px wide at the smallest, and 1 px of
    /// the world (lesson 19's Earth wobbles 2.4 px) is 1000 px at the largest.
    static constexpr double kMinZoom = 0.01;
    static constexpr double kMaxZoom = 1000.0;

    double zoom = 1.0;               ///< 1: the box just fits the stage; 2: everything twice as large
    std::optional<sim::Vec2> centre; ///< world px at the middle of the stage; none: the box's centre

    /// The view that shows the whole box: nothing zoomed or moved.
    bool fitted() const { return zoom == 1.0 && !centre; }
    friend bool operator==(const Camera&, const Camera&) = default;
};

} // namespace forcelab
