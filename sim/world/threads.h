#pragma once
// How many cores the simulation may use. The solver's passes run on oneTBB
// (collision/row_strips.h) and give the same bits for any count, so this
// only changes the speed: the bench measures 1 and 2 threads, and the
// reproducibility test compares them bit for bit.

#include <memory>

namespace forcelab::sim {

/// The most threads a user may ask for (the commands' --threads options).
constexpr int kMostThreads = 256;

/// While it lives, at most `threads` threads run the simulation's parallel
/// work (1: the calling thread alone). A later, inner limit replaces it.
class ThreadLimit {
public:
    explicit ThreadLimit(int threads);
    ~ThreadLimit();
    ThreadLimit(const ThreadLimit&) = delete;
    ThreadLimit& operator=(const ThreadLimit&) = delete;

private:
    struct Control;
    std::unique_ptr<Control> m_control;
};

/// The threads the parallel work may use now (the cores, or the limit in force).
int availableThreads();

} // namespace forcelab::sim
