#pragma once
// Where the balls have been: a bounded ring of past positions per ball, for
// the "trails" overlay. One record per frame (not per step), so a trail spans
// the same real time whatever dt is, and its memory is at most capacity ×
// balls positions whatever the run's length. The canvas clears it on a new scene.

#include "sim/world/ball_state.h"

#include <QPointF>

#include <vector>

namespace forcelab {

class TrailRecorder {
public:
    enum class Scope {
        All,      ///< every ball (up to kMaxBalls; above that, the selected ball only)
        Selected, ///< the selected ball only
    };

    /// Above this many balls only the selected ball leaves a trail.
    static constexpr int kMaxBalls = 2000;

    /// Records kept per ball (the trail's length in frames), at most
    /// kPointBudget / balls tracked (but 120 at least).
    void setCapacity(int frames);
    int capacity() const { return m_capacity; }
    /// Positions kept at most, over all balls.
    static constexpr int kPointBudget = 1'000'000;

    void setScope(Scope scope);
    Scope scope() const { return m_scope; }
    /// The ball followed by the Selected scope (and above kMaxBalls); -1 for none.
    void setSelected(int ball);

    /// Appends the balls' positions at simulated time `time`. A time that is
    /// not later than the last record's (a redraw while paused) adds nothing;
    /// an earlier one (a reset) or a changed ball count starts afresh.
    void record(const sim::BallState& balls, double time);
    void clear();

    /// The balls that have a trail (indices into the world's balls).
    const std::vector<int>& balls() const { return m_balls; }
    /// Records held, 0 … capacity().
    int length() const { return m_length; }
    /// Records made since the tracking started (the newest is number recorded() − 1).
    qint64 recorded() const { return m_recorded; }
    /// Changes whenever the records start afresh (clear, a new ball count, a reset).
    quint64 generation() const { return m_generation; }
    /// The records a path shows: from windowStart() to the newest. It moves on
    /// by half the ring at a time, once the ring has dropped records, so a
    /// path is between half and all of the ring long and a drawing of it can
    /// be appended to for half a ring of frames before it starts afresh.
    qint64 windowStart() const;
    /// World position of tracked ball `slot` in record number `record`
    /// (recorded() − length() ≤ record < recorded()).
    QPointF atRecord(int slot, qint64 record) const;
    /// World position of tracked ball `slot` (an index into balls()) in record
    /// `age` (0 = newest, length() - 1 = oldest).
    QPointF at(int slot, int age) const;

private:
    void restart(const sim::BallState& balls);

    Scope m_scope = Scope::All;
    int m_capacity = 1200;
    int m_selected = -1;
    std::vector<int> m_balls;       // tracked ball indices
    std::vector<QPointF> m_ring;    // capacity × tracked positions, record-major
    int m_head = 0;                 // record slot written next
    int m_length = 0;
    int m_ballCount = -1;           // ball count the tracking was set up for
    double m_lastTime = 0.0;
    int m_ringSize = 120;           // records per ball in the ring now (capacity within the budget)
    qint64 m_recorded = 0;
    quint64 m_generation = 0;
};

} // namespace forcelab
