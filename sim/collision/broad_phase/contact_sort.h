#pragma once
// Puts contacts in ascending (a, b) order, the one order every detector must
// report. Two stable counting sorts (LSD radix): first by b, then by a. Each
// is one pass over the contacts (O(N + contacts)) with no comparisons, which
// beats sorting each ball's partners by b after a counting sort by a.

#include "sim/collision/contact.h"

#include <vector>

namespace forcelab::sim {

class ContactSorter {
public:
    /// Sorts contacts of balls 0..n−1 in place.
    void sort(std::vector<Contact>& contacts, int n);

private:
    std::vector<int> m_startA; // where each ball's run by a starts
    std::vector<int> m_startB; // where each ball's run by b starts
    std::vector<Contact> m_spare;
};

} // namespace forcelab::sim
