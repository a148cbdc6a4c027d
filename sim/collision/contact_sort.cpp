#include "contact_sort.h"

#include <algorithm>

namespace forcelab::sim {

void ContactSorter::sort(std::vector<Contact>& contacts, int n)
{
    if (contacts.size() < 2)
        return;
    m_start.assign(static_cast<std::size_t>(n) + 1, 0);
    for (const Contact& c : contacts)
        ++m_start[static_cast<std::size_t>(c.a) + 1];
    for (std::size_t i = 1; i < m_start.size(); ++i)
        m_start[i] += m_start[i - 1];
    m_spare.resize(contacts.size());
    for (const Contact& c : contacts)
        m_spare[static_cast<std::size_t>(m_start[static_cast<std::size_t>(c.a)]++)] = c;
    contacts.swap(m_spare);
    // m_start[a] is now the end of ball a's run.
    std::size_t begin = 0;
    for (int a = 0; a < n; ++a) {
        const auto end = static_cast<std::size_t>(m_start[static_cast<std::size_t>(a)]);
        if (end - begin > 32) {
            std::sort(contacts.begin() + static_cast<std::ptrdiff_t>(begin),
                      contacts.begin() + static_cast<std::ptrdiff_t>(end),
                      [](const Contact& x, const Contact& y) { return x.b < y.b; });
        } else {
            for (std::size_t i = begin + 1; i < end; ++i) {
                const Contact c = contacts[i];
                std::size_t j = i;
                while (j > begin && c.b < contacts[j - 1].b) {
                    contacts[j] = contacts[j - 1];
                    --j;
                }
                contacts[j] = c;
            }
        }
        begin = end;
    }
}

} // namespace forcelab::sim
