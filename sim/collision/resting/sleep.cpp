// Balls at rest put to sleep and woken again (sleep.h).

#include "sim/collision/resting/sleep.h"

#include <algorithm>
#include <cmath>

namespace forcelab::sim {

void SleepingBalls::wakeAll()
{
    if (m_awake)
        return; // nothing to clear: a scene that never sleeps pays nothing
    m_awake = true;
    std::fill(m_asleep.begin(), m_asleep.end(), 0);
    std::fill(m_still.begin(), m_still.end(), 0.0);
    m_count = 0;
    m_lastWoken = 0;
}

void SleepingBalls::hold(BallState& balls)
{
    const auto n = static_cast<std::size_t>(balls.size());
    m_lastWoken = 0;
    m_graph.clear(); // the neighbour lists are this step's, built when first needed
    m_awake = false;
    if (m_asleep.size() != n) {
        m_asleep.assign(n, 0);
        m_still.assign(n, 0.0);
        m_frozen.assign(2 * n, 0.0);
        m_lastVelocity.assign(2 * n, 0.0);
        m_count = 0;
        return;
    }
    if (m_count == 0)
        return;
    double* x = balls.position.data();
    double* v = balls.velocity.data();
    for (std::size_t i = 0; i < n; ++i)
        if (m_asleep[i]) {
            x[2 * i] = m_frozen[2 * i];
            x[2 * i + 1] = m_frozen[2 * i + 1];
            v[2 * i] = 0.0;
            v[2 * i + 1] = 0.0;
        }
}

void SleepingBalls::buildNeighbours(int n, const std::vector<Contact>& pairs)
{
    m_graph.build(n, pairs.size(), [&](std::size_t k) { return pairs[k].a; }, [&](std::size_t k) { return pairs[k].b; });
}

void SleepingBalls::wakeNear(BallState& balls, const std::vector<Contact>& pairs, const Vec2& gh, double h,
                             double startLag, double pushSpeed, double wakeSpeed, int layers)
{
    if (m_count == 0 || layers <= 0)
        return;
    const int n = balls.size();
    const double* x = balls.position.data();
    const double* u = m_lastVelocity.data();
    // Layer 0: both balls of every pair that approaches. A sleeper's speed
    // is 0; an awake ball's is the one it ended the last step with (the
    // integrator has since given it gravity's g·h, which every ball shares
    // and which a resting contact takes out again).
    m_layer.assign(static_cast<std::size_t>(n), PairGraph::kFar);
    m_queue.clear();
    for (const Contact& c : pairs) {
        const auto a = static_cast<std::size_t>(c.a), b = static_cast<std::size_t>(c.b);
        if (m_asleep[a] && m_asleep[b])
            continue;
        const double dx = x[2 * b] - x[2 * a], dy = x[2 * b + 1] - x[2 * a + 1];
        const double len = std::sqrt(dx * dx + dy * dy);
        if (!(len > 0.0) || !std::isfinite(len))
            continue;
        const double uax = m_asleep[a] ? 0.0 : u[2 * a], uay = m_asleep[a] ? 0.0 : u[2 * a + 1];
        const double ubx = m_asleep[b] ? 0.0 : u[2 * b], uby = m_asleep[b] ? 0.0 : u[2 * b + 1];
        const double approach = -((ubx - uax) * dx + (uby - uay) * dy) / len;
        if (!(approach > (m_asleep[a] || m_asleep[b] ? pushSpeed : wakeSpeed)))
            continue;
        for (const std::size_t i : {a, b})
            if (m_layer[i] != 0) {
                m_layer[i] = 0;
                m_queue.push_back(static_cast<int>(i));
            }
    }
    if (m_queue.empty())
        return;
    // Then breadth-first over the pairs, as far as `layers`.
    buildNeighbours(n, pairs);
    m_graph.spread(m_queue, m_layer, layers, static_cast<std::size_t>(n) + 1);
    // The queue holds the region in breadth-first order, which depends on
    // the pairs alone: the same balls wake on any thread count.
    double* xw = balls.position.data();
    double* v = balls.velocity.data();
    for (const int q : m_queue) {
        const auto i = static_cast<std::size_t>(q);
        if (!m_asleep[i])
            continue;
        m_asleep[i] = 0;
        m_still[i] = 0.0;
        --m_count;
        ++m_lastWoken;
        // As if the integrator had moved it from rest over the sub-step:
        // v = g·h and x moved by (1 − startLag)·g·h², which the solver
        // takes back again.
        v[2 * i] = gh.x();
        v[2 * i + 1] = gh.y();
        xw[2 * i] = m_frozen[2 * i] + (1.0 - startLag) * gh.x() * h;
        xw[2 * i + 1] = m_frozen[2 * i + 1] + (1.0 - startLag) * gh.y() * h;
    }
}

void SleepingBalls::settle(BallState& balls, const std::vector<Contact>& pairs, const std::vector<unsigned char>& held,
                           double h, double stillSpeed, double sleepTime)
{
    const int n = balls.size();
    const auto size = static_cast<std::size_t>(n);
    double* x = balls.position.data();
    double* v = balls.velocity.data();
    // Still: held by a contact and slower than stillSpeed, step after step.
    const double still2 = stillSpeed * stillSpeed;
    bool any = false;
    const double enough = sleepTime - 0.5 * h; // the sum of steps of h, rounded
    for (std::size_t i = 0; i < size; ++i) {
        if (m_asleep[i])
            continue;
        const double s2 = v[2 * i] * v[2 * i] + v[2 * i + 1] * v[2 * i + 1];
        if (i < held.size() && held[i] && s2 < still2) {
            m_still[i] += h;
            any = any || m_still[i] >= enough;
        } else {
            m_still[i] = 0.0;
        }
    }
    if (any) {
        if (!m_graph.built())
            buildNeighbours(n, pairs);
        // A ball sleeps when all its neighbours sleep or are as still: a
        // ball resting on one that still sinks, or next to one still rolling,
        // stays awake with it.
        for (std::size_t i = 0; i < size; ++i) {
            if (m_asleep[i] || m_still[i] < enough)
                continue;
            bool calm = true;
            for (const int* j = m_graph.neighbourBegin(i); j != m_graph.neighbourEnd(i) && calm; ++j)
                calm = m_asleep[static_cast<std::size_t>(*j)] || m_still[static_cast<std::size_t>(*j)] >= enough;
            if (!calm)
                continue;
            m_asleep[i] = 1;
            ++m_count;
            m_frozen[2 * i] = x[2 * i];
            m_frozen[2 * i + 1] = x[2 * i + 1];
            v[2 * i] = 0.0;
            v[2 * i + 1] = 0.0;
        }
    }
    std::copy_n(v, 2 * size, m_lastVelocity.begin());
}

} // namespace forcelab::sim
