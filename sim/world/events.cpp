#include "sim/world/events.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace forcelab::sim {

void EventWatch::start(const EventSpec& spec, const BallState& balls, double time)
{
    m_spec = spec;
    m_watching = spec.ball >= 0 && spec.ball < balls.size();
    if (!m_watching)
        return;
    m_x = balls.position.col(spec.ball);
    m_v = balls.velocity.col(spec.ball);
    m_time = time;
    m_turned = 0.0;
}

std::optional<double> EventWatch::update(const BallState& balls, double time)
{
    if (!m_watching || m_spec.ball >= balls.size())
        return std::nullopt;
    const Vec2 x = balls.position.col(m_spec.ball), v = balls.velocity.col(m_spec.ball);
    const double t0 = m_time, dt = time - t0;
    std::optional<double> at;
    // Where a quantity q goes linearly from q0 to q1 over the step, it is
    // zero at the fraction q0 / (q0 − q1) of the step.
    auto zero = [&](double q0, double q1) { return t0 + dt * std::clamp(q0 / (q0 - q1), 0.0, 1.0); };
    switch (m_spec.kind) {
    case EventKind::Bounce:
        // A wall or a collision turns vy round within the step, not smoothly:
        // the step's end is the time, to one step.
        if (m_v.y() > 0.0 && v.y() <= 0.0)
            at = time;
        break;
    case EventKind::Apex:
        // In free flight vy changes smoothly through 0 at the top.
        if (m_v.y() < 0.0 && v.y() >= 0.0)
            at = zero(m_v.y(), v.y());
        break;
    case EventKind::CrossX:
        if ((m_x.x() - m_spec.value) * (x.x() - m_spec.value) < 0.0 || (x.x() == m_spec.value && m_x.x() != x.x()))
            at = zero(m_x.x() - m_spec.value, x.x() - m_spec.value);
        break;
    case EventKind::CrossY:
        if ((m_x.y() - m_spec.value) * (x.y() - m_spec.value) < 0.0 || (x.y() == m_spec.value && m_x.y() != x.y()))
            at = zero(m_x.y() - m_spec.value, x.y() - m_spec.value);
        break;
    case EventKind::Orbit: {
        // The angle swept in this step, taken the short way round (a step
        // covers less than half a turn), summed until it makes a whole turn.
        const Vec2 a = m_x - m_spec.centre, b = x - m_spec.centre;
        const double swept = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
        const double before = m_turned;
        m_turned += swept;
        const double turn = 2.0 * std::numbers::pi;
        if (std::abs(m_turned) >= turn) {
            const double need = std::copysign(turn, m_turned) - before; // of this step's sweep
            at = t0 + dt * std::clamp(need / swept, 0.0, 1.0);
            m_turned -= std::copysign(turn, m_turned);
        }
        break;
    }
    }
    m_x = x;
    m_v = v;
    m_time = time;
    return at;
}

} // namespace forcelab::sim
