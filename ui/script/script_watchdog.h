#pragma once
// Stops a script that runs too long: armed before each call into the engine,
// it calls QJSEngine::setInterrupted(true) from its own thread once the time
// is up, so `while (true) {}` ends with an error instead of hanging the program.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
class QJSEngine;
namespace forcelab {
class ScriptWatchdog {
public:
    explicit ScriptWatchdog(QJSEngine* engine);
    ~ScriptWatchdog();
    ScriptWatchdog(const ScriptWatchdog&) = delete;
    ScriptWatchdog& operator=(const ScriptWatchdog&) = delete;
    /// Starts the clock: the engine is interrupted after `limit` unless disarm() comes first.
    void arm(std::chrono::milliseconds limit);
    /// Stops the clock; returns whether it had run out (the engine was interrupted).
    bool disarm();
private:
    void watch();
    QJSEngine* m_engine; // not owned
    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::chrono::steady_clock::time_point m_deadline;
    bool m_armed = false;
    bool m_fired = false;
    bool m_quit = false;
    std::thread m_thread; // last: started once the members above exist
};
} // namespace forcelab
