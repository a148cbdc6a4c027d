#pragma once
// Balls (or a solver's bodies) and the pairs between them as a graph: each
// node's neighbours in one list, and the layers of nodes around some seeds,
// breadth-first (layer k + 1: every node next to one of layer k not reached
// before). The resting solver's bounce region (staged_solve.cpp) and the
// sleepers a pair wakes (sleep.cpp) are both such layers.
//
// Everything depends on the pairs and seeds alone, in their order, so the
// layers are the same whatever the thread count.

#include <cstddef>
#include <vector>

namespace forcelab::sim {

class PairGraph {
public:
    static constexpr unsigned char kFar = 255; ///< a layer: farther than any layer asked for

    /// The graph of `nodes` nodes and `pairs` pairs; pair k joins a(k) and b(k).
    template <class A, class B>
    void build(int nodes, std::size_t pairs, A a, B b);
    /// Forgets the graph (built() is false until the next build).
    void clear() { m_first.clear(); }
    bool built() const { return !m_first.empty(); }

    /// Node i's neighbours: [neighbourBegin(i), neighbourEnd(i)).
    const int* neighbourBegin(std::size_t i) const { return m_neighbour.data() + m_first[i]; }
    const int* neighbourEnd(std::size_t i) const { return m_neighbour.data() + m_first[i + 1]; }

    /// Breadth-first from the nodes in `region` (each with layer[node] = 0,
    /// every other node's layer kFar): every node within `layers` − 1 pairs
    /// of a seed gets its layer and joins `region`, in the order reached.
    /// Stops, returning false, once `most` nodes have been reached.
    bool spread(std::vector<int>& region, std::vector<unsigned char>& layer, int layers, std::size_t most) const;

private:
    std::vector<int> m_first, m_neighbour, m_fill;
};

template <class A, class B>
void PairGraph::build(int nodes, std::size_t pairs, A a, B b)
{
    const auto n = static_cast<std::size_t>(nodes);
    m_first.assign(n + 1, 0);
    for (std::size_t k = 0; k < pairs; ++k) {
        ++m_first[static_cast<std::size_t>(a(k)) + 1];
        ++m_first[static_cast<std::size_t>(b(k)) + 1];
    }
    for (std::size_t i = 0; i < n; ++i)
        m_first[i + 1] += m_first[i];
    m_neighbour.resize(2 * pairs);
    m_fill.assign(m_first.begin(), m_first.end() - 1);
    for (std::size_t k = 0; k < pairs; ++k) {
        const int i = a(k), j = b(k);
        m_neighbour[static_cast<std::size_t>(m_fill[static_cast<std::size_t>(i)]++)] = j;
        m_neighbour[static_cast<std::size_t>(m_fill[static_cast<std::size_t>(j)]++)] = i;
    }
}

inline bool PairGraph::spread(std::vector<int>& region, std::vector<unsigned char>& layer, int layers,
                              std::size_t most) const
{
    if (layers > static_cast<int>(kFar) - 1)
        layers = static_cast<int>(kFar) - 1;
    if (region.size() >= most)
        return false;
    for (std::size_t next = 0; next < region.size(); ++next) {
        const auto i = static_cast<std::size_t>(region[next]);
        const int out = layer[i] + 1;
        if (out >= layers)
            continue;
        for (const int* j = neighbourBegin(i); j != neighbourEnd(i); ++j)
            if (layer[static_cast<std::size_t>(*j)] == kFar) {
                layer[static_cast<std::size_t>(*j)] = static_cast<unsigned char>(out);
                region.push_back(*j);
                if (region.size() >= most)
                    return false;
            }
    }
    return true;
}

} // namespace forcelab::sim
