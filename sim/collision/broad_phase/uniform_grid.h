#pragma once
// Uniform grid. The plane is cut into square cells about as wide as a typical
// ball; each ball is listed in every cell its box covers (one to four cells
// for a ball the size of a cell, many for a ball a hundred times larger), and
// only balls that share a cell reach the narrow phase. Two balls share several
// cells when their boxes overlap over a cell border, so a pair is kept only in
// the cell that holds the lower-left corner of the overlap of their boxes
// (the cell that is the first column of one of them and the first row of one
// of them): each pair is tested once.
//
// The cells are counted from the smallest box corner of this step, so balls
// outside the walls are simply more cells. When the balls are spread so far
// apart that a dense array of cells would be mostly empty, the cells are
// hashed into a table twice as large as the number of entries instead; two
// cells that land in the same slot are told apart by their coordinates.

#include "sim/collision/broad_phase/broad_phase_input.h"
#include "sim/collision/collision_profile.h"
#include "sim/collision/contact.h"

#include <cstdint>
#include <vector>

namespace forcelab::sim {

class UniformGrid {
public:
    /// Appends every touching pair (a < b), in no particular order.
    /// `clock` laps into `profile` after the balls are placed in cells and after the pairs.
    template <class Test>
    void findPairs(const BroadPhaseInput& in, const Test& test, std::vector<Contact>& out, CollisionStats& stats,
                   StageClock& clock, CollisionProfile& profile);

    /// Cell side as a multiple of the mean ball box size (default 1).
    void setCellScale(double scale) { m_cellScale = scale; }
    /// px, cell side of the last call.
    double cellSize() const { return m_cellSize; }
    /// px, the corner the cells of the last call are counted from (the
    /// smallest corner of the balls' boxes): cell (i, j) starts at
    /// (originX + i cellSize, originY + j cellSize).
    double originX() const { return m_originX; }
    double originY() const { return m_originY; }
    /// Chooses the cells for these balls as findPairs does, without finding
    /// pairs (for drawing them: ui's broad-phase overlay).
    void layOut(const BroadPhaseInput& in) { chooseCells(in); }
    /// Whether the last call hashed its cells (balls far apart) instead of a dense array.
    bool hashed() const { return m_hashed; }
    /// (ball, cell) entries of the last call.
    std::int64_t entries() const { return m_entries; }

private:
    void chooseCells(const BroadPhaseInput& in);
    void sortEntries(const BroadPhaseInput& in);
    bool placeBalls(const BroadPhaseInput& in, double cell, double minX, double minY);

    // The pairs of at least kParallelEntries entries are found in kChunks
    // runs of slots on every core (uniform_grid.cpp).
    static constexpr std::size_t kParallelEntries = 16384;
    static constexpr std::size_t kChunks = 16;

    double m_cellScale = 1.5;
    double m_cellSize = 0.0;
    double m_originX = 0.0, m_originY = 0.0;
    bool m_hashed = false;
    std::int64_t m_entries = 0;
    std::int64_t m_nx = 0, m_ny = 0;
    // Cell range of each ball's box, by ball index.
    std::vector<std::int32_t> m_x0, m_x1, m_y0, m_y1;
    // Counting sort of the entries by slot.
    std::vector<std::uint32_t> m_slotEnd;
    // Per entry, in slot order: the ball, copies of what the narrow phase
    // reads (so a cell's pairs read memory in order), and two bits: the cell
    // is the ball's first column (1) / first row (2) of its range.
    // One record per entry, so that the scatter of the counting sort writes
    // one cache line per entry, not one per array.
    struct Entry {
        double x, y, r;
        std::int32_t ball;
        std::uint32_t first;
    };
    std::vector<Entry> m_entry;
    std::vector<double> m_ex0, m_ey0, m_ex, m_ey, m_er; // continuous mode only
    std::vector<std::int32_t> m_entryCx, m_entryCy; // hashed mode only
    std::vector<std::vector<Contact>> m_chunkPairs; // per run of slots: its pairs (many entries only)
};

} // namespace forcelab::sim
