#include "sim/world/ball_state.h"

#include <algorithm>
#include <numbers>

namespace forcelab::sim {

double sphereMass(double radius)
{
    return kDefaultDensity * (4.0 / 3.0) * std::numbers::pi * radius * radius * radius;
}

void BallState::clear()
{
    position.resize(2, 0);
    velocity.resize(2, 0);
    radius.resize(0);
    mass.resize(0);
    inverseMass.resize(0);
    charge.resize(0);
    color.clear();
    home.resize(2, 0);
    colliding.clear();
    pinned.clear();
    restitution.resize(0);
}

void BallState::resize(int n)
{
    // conservativeResize keeps the existing columns; new ones are zeroed.
    const int old = size();
    position.conservativeResize(2, n);
    velocity.conservativeResize(2, n);
    home.conservativeResize(2, n);
    radius.conservativeResize(n);
    mass.conservativeResize(n);
    inverseMass.conservativeResize(n);
    charge.conservativeResize(n);
    restitution.conservativeResize(n);
    color.resize(static_cast<std::size_t>(n), 0);
    colliding.resize(static_cast<std::size_t>(n), 0);
    pinned.resize(static_cast<std::size_t>(n), 0);
    if (n > old) {
        position.rightCols(n - old).setZero();
        velocity.rightCols(n - old).setZero();
        home.rightCols(n - old).setZero();
        radius.tail(n - old).setZero();
        mass.tail(n - old).setZero();
        inverseMass.tail(n - old).setZero();
        charge.tail(n - old).setZero();
        restitution.tail(n - old).setConstant(kWorldRestitution);
    }
}

void BallState::assign(std::span<const Ball> balls)
{
    clear();
    resize(static_cast<int>(balls.size()));
    for (int i = 0; i < size(); ++i)
        set(i, balls[static_cast<std::size_t>(i)]);
}

void BallState::append(const Ball& b)
{
    const int n = size();
    resize(n + 1);
    set(n, b);
}

namespace {

// Ball `from`'s every entry written over ball `to`'s (insert and remove shift
// the balls after an index by one).
void copyBall(BallState& s, int from, int to)
{
    s.position.col(to) = s.position.col(from);
    s.velocity.col(to) = s.velocity.col(from);
    s.home.col(to) = s.home.col(from);
    s.radius[to] = s.radius[from];
    s.mass[to] = s.mass[from];
    s.inverseMass[to] = s.inverseMass[from];
    s.charge[to] = s.charge[from];
    s.restitution[to] = s.restitution[from];
    s.color[static_cast<std::size_t>(to)] = s.color[static_cast<std::size_t>(from)];
    s.colliding[static_cast<std::size_t>(to)] = s.colliding[static_cast<std::size_t>(from)];
    s.pinned[static_cast<std::size_t>(to)] = s.pinned[static_cast<std::size_t>(from)];
}

} // namespace

void BallState::insert(int i, const Ball& b)
{
    const int n = size();
    resize(n + 1);
    for (int k = n; k > i; --k) // the tail up one, last first
        copyBall(*this, k - 1, k);
    set(i, b);
}

void BallState::remove(int i)
{
    const int n = size();
    for (int k = i; k + 1 < n; ++k)
        copyBall(*this, k + 1, k);
    resize(n - 1);
}

void BallState::set(int i, const Ball& b)
{
    position.col(i) = b.position;
    velocity.col(i) = b.pinned ? Vec2::Zero() : b.velocity; // a pinned ball is at rest
    home.col(i) = b.home;
    radius[i] = b.radius;
    charge[i] = b.charge;
    restitution[i] = b.restitution;
    color[static_cast<std::size_t>(i)] = b.color;
    colliding[static_cast<std::size_t>(i)] = 0;
    pinned[static_cast<std::size_t>(i)] = b.pinned ? 1 : 0;
    setMass(i, b.mass > 0.0 ? b.mass : sphereMass(b.radius));
}

void BallState::setMass(int i, double m)
{
    mass[i] = m;
    inverseMass[i] = pinned[static_cast<std::size_t>(i)] ? 0.0 : 1.0 / m;
}

void BallState::setPinned(int i, bool on)
{
    pinned[static_cast<std::size_t>(i)] = on ? 1 : 0;
    if (on)
        velocity.col(i).setZero();
    setMass(i, mass[i]);
}

const double* BallState::ownRestitutions() const
{
    return (restitution.array() >= 0.0).any() ? restitution.data() : nullptr;
}

bool BallState::anyPinned() const
{
    return std::find(pinned.begin(), pinned.end(), static_cast<unsigned char>(1)) != pinned.end();
}

Ball BallState::ball(int i) const
{
    Ball b;
    b.position = position.col(i);
    b.velocity = velocity.col(i);
    b.radius = radius[i];
    b.mass = mass[i];
    b.charge = charge[i];
    b.restitution = restitution[i];
    b.color = color[static_cast<std::size_t>(i)];
    b.home = home.col(i);
    b.pinned = pinned[static_cast<std::size_t>(i)] != 0;
    return b;
}

} // namespace forcelab::sim
