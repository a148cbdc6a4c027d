#pragma once
// Where the balls have been: a bounded ring of past positions per ball, for
// the "trails" overlay. One record per frame (not per step), so a trail spans
// the same real time whatever dt is, and its memory is capacity × balls
// positions whatever the run's length. The canvas clears it on a new scene.

#include "sim/ball_state.h"

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

    /// Records kept per ball (the trail's length in frames).
    void setCapacity(int frames);
    int capacity() const { return m_capacity; }

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
    /// World position of tracked ball `slot` (an index into balls()) in record
    /// `age` (0 = newest, length() - 1 = oldest).
    QPointF at(int slot, int age) const;

private:
    void restart(const sim::BallState& balls);

    Scope m_scope = Scope::All;
    int m_capacity = 120;
    int m_selected = -1;
    std::vector<int> m_balls;       // tracked ball indices
    std::vector<QPointF> m_ring;    // capacity × tracked positions, record-major
    int m_head = 0;                 // record slot written next
    int m_length = 0;
    int m_ballCount = -1;           // ball count the tracking was set up for
    double m_lastTime = 0.0;
};

} // namespace forcelab
