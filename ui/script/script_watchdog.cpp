#include "ui/script/script_watchdog.h"

#include <QJSEngine>

namespace forcelab {

ScriptWatchdog::ScriptWatchdog(QJSEngine* engine)
    : m_engine(engine)
    , m_thread([this] { watch(); })
{
}

ScriptWatchdog::~ScriptWatchdog()
{
    {
        const std::lock_guard lock(m_mutex);
        m_quit = true;
    }
    m_wake.notify_all();
    m_thread.join();
}

void ScriptWatchdog::arm(std::chrono::milliseconds limit)
{
    {
        const std::lock_guard lock(m_mutex);
        m_deadline = std::chrono::steady_clock::now() + limit;
        m_armed = true;
        m_fired = false;
    }
    m_wake.notify_all();
}

bool ScriptWatchdog::disarm()
{
    bool fired = false;
    {
        const std::lock_guard lock(m_mutex);
        m_armed = false;
        fired = m_fired;
        m_fired = false;
        if (fired)
            m_engine->setInterrupted(false); // ready for the next call
    }
    m_wake.notify_all();
    return fired;
}

void ScriptWatchdog::watch()
{
    std::unique_lock lock(m_mutex);
    while (!m_quit) {
        if (!m_armed) {
            m_wake.wait(lock);
            continue;
        }
        if (m_wake.wait_until(lock, m_deadline) == std::cv_status::timeout && m_armed && !m_fired &&
            std::chrono::steady_clock::now() >= m_deadline) {
            m_fired = true;
            m_engine->setInterrupted(true); // thread-safe: the engine checks the flag as it runs
        }
        if (m_fired)
            m_wake.wait(lock, [this] { return m_quit || !m_armed || !m_fired; });
    }
}

} // namespace forcelab
