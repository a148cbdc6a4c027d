#include "sim/world/threads.h"

#include <oneapi/tbb/global_control.h>

#include <algorithm>

namespace forcelab::sim {

struct ThreadLimit::Control {
    explicit Control(std::size_t threads)
        : control(oneapi::tbb::global_control::max_allowed_parallelism, threads)
    {
    }
    oneapi::tbb::global_control control;
};

ThreadLimit::ThreadLimit(int threads)
    : m_control(std::make_unique<Control>(static_cast<std::size_t>(std::max(threads, 1))))
{
}

ThreadLimit::~ThreadLimit() = default;

int availableThreads()
{
    return static_cast<int>(
        oneapi::tbb::global_control::active_value(oneapi::tbb::global_control::max_allowed_parallelism));
}

} // namespace forcelab::sim
