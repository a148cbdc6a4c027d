// Islands of a resting-contact solve (contact_islands.h): union–find with
// path halving, the lower root kept.

#include "sim/collision/resting/contact_islands.h"

#include <numeric>
#include <utility>

namespace forcelab::sim {

void ContactIslands::reset(int n)
{
    const auto size = static_cast<std::size_t>(n);
    m_parent.resize(size);
    std::iota(m_parent.begin(), m_parent.end(), 0);
    m_needy.assign(size, 0);
}

int ContactIslands::root(int a)
{
    int* parent = m_parent.data();
    while (parent[a] != a) {
        parent[a] = parent[parent[a]];
        a = parent[a];
    }
    return a;
}

void ContactIslands::join(int a, int b)
{
    int ra = root(a), rb = root(b);
    if (ra == rb)
        return;
    if (rb < ra)
        std::swap(ra, rb);
    // The lower root stays; it needs the solver if either did.
    m_parent[static_cast<std::size_t>(rb)] = ra;
    m_needy[static_cast<std::size_t>(ra)] |= m_needy[static_cast<std::size_t>(rb)];
}

} // namespace forcelab::sim
