#pragma once
// Sleeping balls (contact_solver.h, point 7): which balls of a pile at rest
// sleep, where they sleep, and which wake.
//
// One resting solve with sleeping runs
//
//   hold       the sleepers back where they fell asleep, at speed 0 (the
//              integrator has just moved them like every other ball)
//   (the broad phase finds the pairs)
//   wakeNear   every sleeper within wakeLayers balls of a pair that
//              approaches faster than the still speed wakes
//   (the solver: a sleeper is a body of infinite mass; no rows between two)
//   settle     a ball held still long enough, with all its neighbours still,
//              falls asleep
//
// Everything here runs on one thread in ball order, so which balls sleep is
// the same whatever the thread count.

#include "sim/world/ball_state.h"
#include "sim/collision/contact.h"
#include "sim/collision/resting/pair_graph.h"

#include <cstddef>
#include <vector>

namespace forcelab::sim {

class SleepingBalls {
public:
    /// Wakes every ball: an edit between steps, a force that changes with
    /// time, or a step without the staged solve.
    void wakeAll();

    /// Puts the sleepers back where they fell asleep, at speed 0. A new
    /// number of balls wakes every ball first.
    void hold(BallState& balls);

    /// Wakes the sleepers within `layers` balls of a pair (of `pairs`, the
    /// solve's pairs in (a, b) order) whose balls approach each other, with
    /// the speeds they had at the end of the last step, faster than
    /// `pushSpeed` (px/s) when one of them sleeps, or than `wakeSpeed` when
    /// both are awake. A ball that wakes starts as if the integrator had moved it
    /// from rest: speed g·h, position (1 − startLag)·g·h² further (`gh` =
    /// g·h, px/s; startLag as in sub_step_context.h), so the solver, taking
    /// v·h back and adding startLag·g·h², starts it where it slept.
    void wakeNear(BallState& balls, const std::vector<Contact>& pairs, const Vec2& gh, double h, double startLag,
                  double pushSpeed, double wakeSpeed, int layers);

    /// After the solve: a ball that a contact held (`held`, per ball) and
    /// that is slower than `stillSpeed` (px/s) has been still h longer; one
    /// still for `sleepTime` (s) whose neighbours in `pairs` are asleep or as
    /// still falls asleep where it is, at speed 0.
    void settle(BallState& balls, const std::vector<Contact>& pairs, const std::vector<unsigned char>& held, double h,
                double stillSpeed, double sleepTime);

    /// Per ball, 1 while it sleeps; nullptr when no ball sleeps.
    const unsigned char* asleep() const { return m_count > 0 ? m_asleep.data() : nullptr; }
    /// How many balls sleep now.
    int count() const { return m_count; }
    /// Balls woken by wakeNear in the last step.
    int lastWoken() const { return m_lastWoken; }

private:
    void buildNeighbours(int n, const std::vector<Contact>& pairs);

    std::vector<unsigned char> m_asleep; // per ball
    std::vector<double> m_still;         // per ball, s: how long it has been held and still
    std::vector<double> m_frozen;        // per ball, x and y where it fell asleep
    std::vector<double> m_lastVelocity;  // per ball, vx and vy at the end of the last step
    PairGraph m_graph; // this step's pairs as lists of neighbours, built when first needed
    std::vector<unsigned char> m_layer; // per ball, wakeNear: balls between it and an approaching pair
    std::vector<int> m_queue;
    int m_count = 0;
    int m_lastWoken = 0;
    bool m_awake = true; // every ball awake and no stillness counted since wakeAll
};

} // namespace forcelab::sim
