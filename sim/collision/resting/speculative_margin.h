#pragma once
// How far each ball's radius grows so that the broad phase finds every pair
// that can touch within one sub-step (the solver's speculative contacts).
//
// A pair closes its gap by at most |v_b − v_a|·h in a sub-step of length h
// (plus what the forces add, |g|·h² at most for the pair's fall). For any
// velocity u the two share, the triangle inequality gives
//
//   |v_b − v_a| ≤ |v_a − u| + |v_b − u|,
//
// so growing each ball by |v_i − u|·h finds the pair. Growing by |v_i|·h
// (u = 0) is the simplest choice, and a poor one for a falling cloud: its
// balls barely move against each other, yet at 1,000 px/s each grew by three
// radii and a 100,000-ball step had 24 rows per ball.
//
// Here u is local. The balls' bounding box is cut into square cells at least
// as wide as the farthest two balls can be apart and still be a pair
// (r_a + r_b + both largest growths), so the two balls of every pair lie in
// the same or neighbouring cells. u_C is the mean velocity of cell C's balls,
// and a ball grows by the largest |v_i − u_C|·h over the 3 × 3 cells around
// its own. For a pair a ∈ A, b ∈ B, cell B is among A's neighbours and among
// its own, so grow_a + grow_b ≥ (|v_a − u_B| + |v_b − u_B|)·h ≥ |v_b − v_a|·h:
// no pair is lost. The largest distance over the nine cells is bounded from
// above by the farthest corner of the box spanned by their nine mean
// velocities, one computation per ball.
//
// Each growth is capped at `cap` radii (a ball whose velocity is not finite
// gets the cap). The result depends on the balls alone, in ball order, so it
// is the same for every detector and every thread count.

#include "sim/world/ball_state.h"

#include <vector>

namespace forcelab::sim {

class SpeculativeMargin {
public:
    /// grow[i] (px) for every ball: h·max_C |v_i − u_C| + fall, at most cap·r_i.
    /// `fall` (px) is what the forces may add in the sub-step (|g|·h²).
    void compute(const BallState& balls, double h, double fall, double cap, std::vector<double>& grow);

    /// Cells across and down of the last compute() (tests, bench).
    int columns() const { return m_columns; }
    int rows() const { return m_rows; }

private:
    // Per cell: its balls' velocities summed and counted, then divided into
    // their mean (stage 4 of compute()); and the box of the means over the
    // cell and its eight neighbours.
    struct Cell {
        double vx = 0.0, vy = 0.0;
        int count = 0;
    };
    struct VelocityBox {
        double loX, hiX, loY, hiY;
    };
    std::vector<int> m_cellOf; // per ball: its cell (−1: position not finite)
    std::vector<Cell> m_cells;
    std::vector<VelocityBox> m_boxes;
    int m_columns = 0, m_rows = 0;
};

} // namespace forcelab::sim
