#include "trail_recorder.h"

#include <algorithm>

namespace forcelab {

void TrailRecorder::setCapacity(int frames)
{
    frames = std::max(2, frames);
    if (frames == m_capacity)
        return;
    m_capacity = frames;
    clear();
}

void TrailRecorder::setScope(Scope scope)
{
    if (scope == m_scope)
        return;
    m_scope = scope;
    clear();
}

void TrailRecorder::setSelected(int ball)
{
    if (ball == m_selected)
        return;
    m_selected = ball;
    // Only a trail that follows the selection has to start again.
    if (m_scope == Scope::Selected || m_ballCount > kMaxBalls)
        clear();
}

void TrailRecorder::clear()
{
    m_balls.clear();
    m_ring.clear();
    m_head = 0;
    m_length = 0;
    m_ballCount = -1;
    m_lastTime = 0.0;
    m_recorded = 0;
    ++m_generation;
}

void TrailRecorder::restart(const sim::BallState& balls)
{
    clear();
    m_ballCount = balls.size();
    if (m_scope == Scope::All && m_ballCount <= kMaxBalls) {
        m_balls.resize(static_cast<std::size_t>(m_ballCount));
        for (int i = 0; i < m_ballCount; ++i)
            m_balls[static_cast<std::size_t>(i)] = i;
    } else if (m_selected >= 0 && m_selected < m_ballCount) {
        m_balls = {m_selected};
    }
    const int budget = m_balls.empty() ? m_capacity : kPointBudget / static_cast<int>(m_balls.size());
    m_ringSize = std::min(m_capacity, std::max(std::min(120, m_capacity), budget));
    m_ring.assign(static_cast<std::size_t>(m_ringSize) * m_balls.size(), QPointF());
}

void TrailRecorder::record(const sim::BallState& balls, double time)
{
    if (m_ballCount != balls.size() || (m_length > 0 && time < m_lastTime))
        restart(balls);
    else if (m_length > 0 && time == m_lastTime)
        return;
    m_lastTime = time;
    if (m_balls.empty())
        return;
    const std::size_t stride = m_balls.size();
    QPointF* row = m_ring.data() + static_cast<std::size_t>(m_head) * stride;
    for (std::size_t k = 0; k < stride; ++k) {
        const int i = m_balls[k];
        row[k] = QPointF(balls.position(0, i), balls.position(1, i));
    }
    m_head = (m_head + 1) % m_ringSize;
    m_length = std::min(m_length + 1, m_ringSize);
    ++m_recorded;
}

QPointF TrailRecorder::at(int slot, int age) const
{
    const int record = ((m_head - 1 - age) % m_ringSize + m_ringSize) % m_ringSize;
    return m_ring[static_cast<std::size_t>(record) * m_balls.size() + static_cast<std::size_t>(slot)];
}

QPointF TrailRecorder::atRecord(int slot, qint64 record) const
{
    return at(slot, static_cast<int>(m_recorded - 1 - record));
}

qint64 TrailRecorder::windowStart() const
{
    // The oldest record held is recorded − ringSize once the ring is full;
    // round it up to a whole number of half rings.
    const qint64 half = std::max(1, m_ringSize / 2);
    const qint64 oldest = m_recorded - m_ringSize;
    if (oldest <= 0)
        return 0;
    return (oldest + half - 1) / half * half;
}

} // namespace forcelab
