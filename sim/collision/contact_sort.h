#pragma once
// Puts contacts in ascending (a, b) order, the one order every detector must
// report. A counting sort by a (O(N + contacts)), then a short sort of each
// ball's partners by b: much faster than a comparison sort of all pairs.

#include "contact.h"

#include <vector>

namespace forcelab::sim {

class ContactSorter {
public:
    /// Sorts contacts of balls 0..n−1 in place.
    void sort(std::vector<Contact>& contacts, int n);

private:
    std::vector<int> m_start;
    std::vector<Contact> m_spare;
};

} // namespace forcelab::sim
