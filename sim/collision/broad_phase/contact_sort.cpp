// Contacts sorted into (a, b) order (contact_sort.h).

#include "sim/collision/broad_phase/contact_sort.h"

namespace forcelab::sim {

void ContactSorter::sort(std::vector<Contact>& contacts, int n)
{
    if (contacts.size() < 2)
        return;
    // Both histograms in one pass, then their running sums: start of each run.
    const auto buckets = static_cast<std::size_t>(n) + 1;
    m_startA.assign(buckets, 0);
    m_startB.assign(buckets, 0);
    for (const Contact& c : contacts) {
        ++m_startA[static_cast<std::size_t>(c.a) + 1];
        ++m_startB[static_cast<std::size_t>(c.b) + 1];
    }
    for (std::size_t i = 1; i < buckets; ++i) {
        m_startA[i] += m_startA[i - 1];
        m_startB[i] += m_startB[i - 1];
    }
    // By b into the spare buffer, then stably by a back: within one a, the
    // contacts keep the ascending b order of the first pass.
    m_spare.resize(contacts.size());
    for (const Contact& c : contacts)
        m_spare[static_cast<std::size_t>(m_startB[static_cast<std::size_t>(c.b)]++)] = c;
    for (const Contact& c : m_spare)
        contacts[static_cast<std::size_t>(m_startA[static_cast<std::size_t>(c.a)]++)] = c;
}

} // namespace forcelab::sim
