// How far each ball grows for speculative contacts (speculative_margin.h).

#include "sim/collision/resting/speculative_margin.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace forcelab::sim {
namespace {

// Cells per side at most: beyond that the cells grow instead (the
// neighbourhood argument only needs them wide enough, never narrow).
constexpr int kMostCellsPerSide = 512;

} // namespace

void SpeculativeMargin::compute(const BallState& balls, double h, double fall, double cap, std::vector<double>& grow)
{
    const int n = balls.size();
    const auto count = static_cast<std::size_t>(n);
    grow.resize(count);
    m_cellOf.resize(count);
    const double* x = balls.position.data();
    const double* v = balls.velocity.data();
    const double* radius = balls.radius.data();

    // 1. The bounding box of the finite centres and the largest radius.
    double loX = HUGE_VAL, hiX = -HUGE_VAL, loY = HUGE_VAL, hiY = -HUGE_VAL, rMax = 0.0;
    for (int i = 0; i < n; ++i) {
        const double px = x[2 * i], py = x[2 * i + 1];
        if (!std::isfinite(px) || !std::isfinite(py))
            continue;
        loX = std::min(loX, px);
        hiX = std::max(hiX, px);
        loY = std::min(loY, py);
        hiY = std::max(hiY, py);
        if (std::isfinite(radius[i]))
            rMax = std::max(rMax, radius[i]);
    }
    if (!(loX <= hiX)) { // no finite centre
        for (int i = 0; i < n; ++i)
            grow[static_cast<std::size_t>(i)] = cap * radius[i];
        m_columns = m_rows = 0;
        return;
    }

    // 2. Cells as wide as the farthest pair: r_a + r_b + grow_a + grow_b is
    // at most 2·(1 + cap)·r_max. A little wider, so a pair at exactly that
    // distance is not split by rounding.
    const double reach = 2.0 * (1.0 + cap) * rMax * (1.0 + 1e-9) + 1e-9;
    const double extent = std::max(hiX - loX, hiY - loY);
    const double side = std::max(reach, extent / (kMostCellsPerSide - 1));
    m_columns = static_cast<int>((hiX - loX) / side) + 1;
    m_rows = static_cast<int>((hiY - loY) / side) + 1;
    const auto cellCount = static_cast<std::size_t>(m_columns) * static_cast<std::size_t>(m_rows);
    m_cells.assign(cellCount, Cell{});
    const double inverseSide = 1.0 / side;

    // 3. Each ball's cell, and every cell's sum of velocities. A ball with a
    // velocity that is not finite is left out of the means (it gets the cap).
    for (int i = 0; i < n; ++i) {
        const double px = x[2 * i], py = x[2 * i + 1];
        if (!std::isfinite(px) || !std::isfinite(py)) {
            m_cellOf[static_cast<std::size_t>(i)] = -1;
            continue;
        }
        const int cx = std::min(static_cast<int>((px - loX) * inverseSide), m_columns - 1);
        const int cy = std::min(static_cast<int>((py - loY) * inverseSide), m_rows - 1);
        const int cell = cy * m_columns + cx;
        m_cellOf[static_cast<std::size_t>(i)] = cell;
        const double vx = v[2 * i], vy = v[2 * i + 1];
        if (std::isfinite(vx) && std::isfinite(vy)) {
            Cell& c = m_cells[static_cast<std::size_t>(cell)];
            c.vx += vx;
            c.vy += vy;
            ++c.count;
        }
    }

    // 4. Per cell, the mean velocity of its balls (the sums become means);
    // then the box spanned by the means of the non-empty cells among it and
    // its eight neighbours (an empty box when all are empty).
    for (Cell& c : m_cells) {
        if (c.count > 0) {
            c.vx /= c.count;
            c.vy /= c.count;
        }
    }
    m_boxes.resize(cellCount);
    for (int cy = 0; cy < m_rows; ++cy) {
        for (int cx = 0; cx < m_columns; ++cx) {
            VelocityBox box{HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
            for (int ny = std::max(cy - 1, 0); ny <= std::min(cy + 1, m_rows - 1); ++ny) {
                for (int nx = std::max(cx - 1, 0); nx <= std::min(cx + 1, m_columns - 1); ++nx) {
                    const Cell& c = m_cells[static_cast<std::size_t>(ny * m_columns + nx)];
                    if (c.count == 0)
                        continue;
                    const double ux = c.vx, uy = c.vy;
                    box.loX = std::min(box.loX, ux);
                    box.hiX = std::max(box.hiX, ux);
                    box.loY = std::min(box.loY, uy);
                    box.hiY = std::max(box.hiY, uy);
                }
            }
            m_boxes[static_cast<std::size_t>(cy * m_columns + cx)] = box;
        }
    }

    // 5. Each ball's growth: the farthest corner of its neighbourhood's box
    // bounds |v_i − u_C| for every one of the nine cells.
    for (int i = 0; i < n; ++i) {
        const auto ii = static_cast<std::size_t>(i);
        const double most = cap * radius[i];
        const int cell = m_cellOf[ii];
        const double vx = v[2 * i], vy = v[2 * i + 1];
        if (cell < 0 || !std::isfinite(vx) || !std::isfinite(vy)) {
            grow[ii] = most;
            continue;
        }
        const VelocityBox& b = m_boxes[static_cast<std::size_t>(cell)];
        // The ball's own cell holds it, so the box is never empty here.
        const double dx = std::max(std::abs(vx - b.loX), std::abs(vx - b.hiX));
        const double dy = std::max(std::abs(vy - b.loY), std::abs(vy - b.hiY));
        const double g = std::sqrt(dx * dx + dy * dy) * h + fall;
        grow[ii] = g < most ? g : most; // NaN: the cap
    }
}

} // namespace forcelab::sim
