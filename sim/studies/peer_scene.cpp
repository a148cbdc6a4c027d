#include "sim/studies/peer_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace forcelab::sim {

Scene boxScene(int n, double rMin, double rMax, double speed, double e, Detection detection, std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> radius(static_cast<std::size_t>(n));
    double area = 0.0;
    for (double& r : radius) {
        r = rMin + (rMax - rMin) * u(rng);
        area += std::numbers::pi * r * r;
    }
    const double side = std::sqrt(area / 0.3);
    const int cols = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n)))));
    const double cell = side / cols;
    Scene s;
    s.settings.box = BoxSettings{side, side};
    s.settings.walls = WallSettings{true, true, true, true, WallModel::Clamp, e};
    s.settings.gravity.enabled = true;
    s.settings.gravity.g = Vec2(0.0, 980.0);
    s.settings.collisions.detection = detection;
    s.settings.collisions.response = Response::Impulse2D;
    s.settings.collisions.restitution = e;
    s.settings.time.integrator = IntegratorKind::SemiImplicitEuler;
    s.settings.time.dt = 1.0 / 60.0;
    s.settings.time.substeps = 1;
    s.balls.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        Ball& b = s.balls[static_cast<std::size_t>(i)];
        b.radius = radius[static_cast<std::size_t>(i)];
        const double slack = std::max(0.0, 0.5 * cell - b.radius);
        b.position = Vec2((i % cols + 0.5) * cell + slack * (2.0 * u(rng) - 1.0),
                          (i / cols + 0.5) * cell + slack * (2.0 * u(rng) - 1.0));
        const double angle = 2.0 * std::numbers::pi * u(rng);
        b.velocity = speed * u(rng) * Vec2(std::cos(angle), std::sin(angle));
    }
    return s;
}

Scene peerScene(int n)
{
    return boxScene(n, 5.0, 5.0, 0.0, 0.9, Detection::Grid, 3);
}

PileMeasures measurePile(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& vx,
                         const std::vector<double>& vy, const std::vector<double>& r, double height)
{
    PileMeasures m;
    const std::size_t n = x.size();
    if (n == 0)
        return m;
    double rMax = 0.0, speed2 = 0.0, heights = 0.0;
    double minX = x[0], minY = y[0];
    std::vector<char> inPile(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        rMax = std::max(rMax, r[i]);
        speed2 += vx[i] * vx[i] + vy[i] * vy[i];
        heights += height - y[i];
        minX = std::min(minX, x[i]);
        minY = std::min(minY, y[i]);
        inPile[i] = height - y[i] - r[i] < kTouching * r[i] ? 1 : 0; // on the floor
    }
    m.rmsSpeed = std::sqrt(speed2 / static_cast<double>(n));
    m.meanHeight = heights / static_cast<double>(n);
    // Cells as wide as the farthest two touching balls can be apart: a pair
    // that touches is in the same or a neighbouring cell.
    const double cell = (2.0 + kTouching) * rMax;
    std::vector<std::pair<std::int64_t, std::size_t>> keyed(n);
    auto cellOf = [&](double v, double lo) { return static_cast<std::int64_t>(std::floor((v - lo) / cell)); };
    const std::int64_t width = 1 << 20;
    for (std::size_t i = 0; i < n; ++i)
        keyed[i] = {cellOf(y[i], minY) * width + cellOf(x[i], minX), i};
    std::sort(keyed.begin(), keyed.end());
    double sum = 0.0;
    auto visit = [&](std::size_t i, std::size_t j) {
        const double dx = x[j] - x[i], dy = y[j] - y[i], s = r[i] + r[j], smaller = std::min(r[i], r[j]);
        const double d2 = dx * dx + dy * dy;
        const double touch = s + kTouching * smaller;
        if (!(d2 < touch * touch))
            return;
        inPile[i] = inPile[j] = 1;
        if (!(d2 < s * s))
            return;
        const double depth = (s - std::sqrt(d2)) / smaller;
        m.deepestOverlap = std::max(m.deepestOverlap, depth);
        sum += depth;
        ++m.overlapping;
    };
    for (std::size_t a = 0; a < n; ++a) {
        const auto [key, i] = keyed[a];
        // This cell after i, then the cells to the right, below-left, below and below-right.
        for (std::size_t b = a + 1; b < n && keyed[b].first == key; ++b)
            visit(i, keyed[b].second);
        for (const std::int64_t other : {key + 1, key + width - 1, key + width, key + width + 1}) {
            auto it = std::lower_bound(keyed.begin(), keyed.end(), std::pair<std::int64_t, std::size_t>{other, 0});
            for (; it != keyed.end() && it->first == other; ++it)
                visit(i, it->second);
        }
    }
    double pileSpeed2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        if (inPile[i])
            pileSpeed2 += vx[i] * vx[i] + vy[i] * vy[i];
        else
            ++m.inFlight;
    }
    const std::size_t piled = n - static_cast<std::size_t>(m.inFlight);
    if (piled > 0)
        m.pileRmsSpeed = std::sqrt(pileSpeed2 / static_cast<double>(piled));
    if (m.overlapping > 0)
        m.meanOverlap = sum / m.overlapping;
    return m;
}

PileMeasures measurePile(const World& world)
{
    const BallState& b = world.balls();
    const auto n = static_cast<std::size_t>(b.size());
    std::vector<double> x(n), y(n), vx(n), vy(n), r(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto k = static_cast<Eigen::Index>(i);
        x[i] = b.position(0, k);
        y[i] = b.position(1, k);
        vx[i] = b.velocity(0, k);
        vy[i] = b.velocity(1, k);
        r[i] = b.radius[k];
    }
    return measurePile(x, y, vx, vy, r, world.settings().box.height);
}

} // namespace forcelab::sim
