#include "ui/script/student_run.h"

#include <algorithm>
#include <cmath>

namespace forcelab {

StudentRun::StudentRun(ScriptEdits edits)
    : m_edits(std::move(edits))
{
}

void StudentRun::restart(const sim::World& world)
{
    m_error.reset();
    m_departure.reset();
    m_steps = 0;
    m_separation = 0.0;
    m_error = m_script.loadFrom(world, {}, m_edits);
    if (!m_error)
        m_script.setPointer(world.pointer());
}

void StudentRun::setPointer(const sim::PointerInput& pointer)
{
    if (!m_error)
        m_script.setPointer(pointer);
}

void StudentRun::follow(const sim::World& reference)
{
    if (m_error)
        return;
    if (auto error = m_script.step()) {
        m_error = error;
        return;
    }
    ++m_steps;
    const sim::BallState& b = reference.balls();
    if (m_script.ballCount() != b.size()) {
        if (!m_departure) {
            ScriptDeparture d;
            d.step = reference.stepCount();
            d.time = reference.time();
            d.reference = static_cast<double>(b.size());
            d.student = m_script.ballCount();
            m_departure = d;
        }
        m_separation = INFINITY;
        return;
    }
    double separation = 0.0;
    for (int i = 0; i < b.size(); ++i) {
        const ScriptBall s = m_script.ball(i);
        const sim::Vec2 mine(s.x, s.y);
        const sim::Vec2 theirs = b.position.col(i);
        separation = std::max(separation, (mine - theirs).norm());
        if (m_departure)
            continue;
        const std::pair<const char*, std::pair<double, double>> fields[] = {
            {"x", {s.x, theirs.x()}},
            {"y", {s.y, theirs.y()}},
            {"vx", {s.vx, b.velocity(0, i)}},
            {"vy", {s.vy, b.velocity(1, i)}},
        };
        for (const auto& [name, values] : fields) {
            const auto [student, engine] = values;
            // NaN departs too: the comparison is written so that it fails.
            if (std::abs(student - engine) <= kTolerance * std::max(1.0, std::abs(engine)))
                continue;
            ScriptDeparture d;
            d.step = reference.stepCount();
            d.time = reference.time();
            d.ball = i;
            d.field = QString::fromLatin1(name);
            d.reference = engine;
            d.student = student;
            d.referencePosition = theirs;
            d.studentPosition = mine;
            m_departure = d;
            break;
        }
    }
    m_separation = std::isnan(separation) ? INFINITY : separation;
}

bool StudentRun::copyInto(const sim::World& reference, sim::World& mirror) const
{
    const int n = m_script.ballCount();
    if (n != mirror.balls().size() && n != reference.balls().size())
        return false;
    sim::BallState& balls = mirror.mutableBalls();
    if (n != balls.size()) // a ball appeared in both: its colour and the rest as the engine drew it
        balls = reference.balls();
    for (int i = 0; i < balls.size(); ++i) {
        const ScriptBall s = m_script.ball(i);
        balls.position.col(i) = sim::Vec2(s.x, s.y);
        balls.velocity.col(i) = sim::Vec2(s.vx, s.vy);
        // Radius and mass as the student's code has them, where they are numbers a world can hold.
        if (std::isfinite(s.r) && s.r >= sim::kMinRadius && s.r <= sim::kMaxRadius)
            balls.radius[i] = s.r;
        if (std::isfinite(s.m) && s.m >= sim::kMinMass && s.m <= sim::kMaxMass && !balls.pinned[static_cast<std::size_t>(i)])
            balls.setMass(i, s.m);
    }
    return true;
}

} // namespace forcelab
