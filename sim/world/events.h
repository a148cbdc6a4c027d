#pragma once
// Events a stopwatch can start or stop on: a ball bouncing (its vertical
// velocity turns from down to up), reaching its highest point (up to down),
// crossing a line x = c or y = c, or completing a full turn round a centre.
// An EventWatch is fed the state after every step and reports the time the
// event happened inside that step (interpolated where the motion is smooth).

#include "sim/world/ball_state.h"

#include <optional>

namespace forcelab::sim {

enum class EventKind {
    Bounce, ///< vy turns from down (+) to up (−): a bounce off the floor or a ball below
    Apex,   ///< vy turns from up (−) to down (+): the top of a flight
    CrossX, ///< the centre crosses the line x = value, either way
    CrossY, ///< the centre crosses the line y = value, either way
    Orbit,  ///< the angle round `centre` has grown by a whole turn (2π), either way round
};

struct EventSpec {
    EventKind kind = EventKind::Bounce;
    int ball = 0;               ///< the ball watched
    double value = 0.0;         ///< px: the line of CrossX / CrossY
    Vec2 centre{0.0, 0.0};      ///< px: the centre of Orbit
};

class EventWatch {
public:
    /// Starts watching from `balls` at time `time` (s).
    void start(const EventSpec& spec, const BallState& balls, double time);
    /// The state after a step that ended at `time`: the time of the event if
    /// it happened during the step (between the last state and this one).
    std::optional<double> update(const BallState& balls, double time);
    const EventSpec& spec() const { return m_spec; }
    bool watching() const { return m_watching; }

private:
    EventSpec m_spec;
    bool m_watching = false;
    Vec2 m_x{0.0, 0.0}, m_v{0.0, 0.0}; // the ball's last position and velocity
    double m_time = 0.0;
    double m_turned = 0.0; // rad turned round the centre since the last full turn
};

} // namespace forcelab::sim
