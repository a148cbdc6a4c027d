// forcelab-peer-box2d: the peer scene run by ForceLab and by Box2D 2.4 from
// the same initial state, one thread each, with the same end-state measures.
// Built only when CMake finds Debian's Box2D (libbox2d-dev).
//
//   forcelab-peer-box2d [N ...]      (default 5000 20000; 600 steps at 60 Hz)
//
// Box2D works in metres: 50 px are 1 m, so a 5 px ball is 0.1 m across its
// radius and gravity is 19.6 m/s². Its balls have no friction (ForceLab's
// have none), restitution 0.9 for balls and walls, 8 velocity and 3 position
// iterations (its defaults).

#include "sim/peer_scene.h"
#include "sim/threads.h"

#include <box2d/box2d.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using namespace forcelab::sim;

constexpr double kPixelsPerMetre = 50.0;
constexpr int kSteps = 600;

double nowMilliseconds()
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void print(const char* engine, int n, double ms, const PileMeasures& m)
{
    std::printf("%-10s %7d %10.2f %10.3f %10.4f %10.2f %10.1f %10.2f %10d\n", engine, n, ms, m.deepestOverlap,
                m.meanOverlap, m.rmsSpeed, m.meanHeight, m.pileRmsSpeed, m.inFlight);
}

// ForceLab on `threads` threads: the wall-clock time per step (with one
// thread the same as its CPU time), and the same end state for any count.
void runForceLab(const Scene& scene, int threads)
{
    const ThreadLimit limit(threads);
    World w(scene);
    const double t0 = nowMilliseconds();
    for (int s = 0; s < kSteps; ++s)
        w.step();
    const double ms = (nowMilliseconds() - t0) / kSteps;
    char name[32];
    std::snprintf(name, sizeof name, "ForceLab/%d", availableThreads());
    print(name, w.balls().size(), ms, measurePile(w));
}

void runBox2D(const Scene& scene)
{
    const double k = 1.0 / kPixelsPerMetre;
    const double side = scene.settings.box.width, height = scene.settings.box.height;
    b2World world(b2Vec2(0.0f, static_cast<float>(scene.settings.gravity.g.y() * k)));
    b2BodyDef wallDef;
    b2Body* walls = world.CreateBody(&wallDef);
    const float w = static_cast<float>(side * k), h = static_cast<float>(height * k);
    // Four thick walls just outside the box (thin edges let balls through at
    // the first impacts).
    const float t = 1.0f;
    const b2Vec2 halves[4] = {{t, h / 2 + 2 * t}, {t, h / 2 + 2 * t}, {w / 2 + 2 * t, t}, {w / 2 + 2 * t, t}};
    const b2Vec2 centres[4] = {{-t, h / 2}, {w + t, h / 2}, {w / 2, -t}, {w / 2, h + t}};
    for (int i = 0; i < 4; ++i) {
        b2PolygonShape box;
        box.SetAsBox(halves[i].x, halves[i].y, centres[i], 0.0f);
        b2FixtureDef f;
        f.shape = &box;
        f.friction = 0.0f;
        f.restitution = static_cast<float>(scene.settings.walls.restitution);
        walls->CreateFixture(&f);
    }
    std::vector<b2Body*> bodies;
    bodies.reserve(scene.balls.size());
    for (const Ball& ball : scene.balls) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(static_cast<float>(ball.position.x() * k), static_cast<float>(ball.position.y() * k));
        def.linearVelocity.Set(static_cast<float>(ball.velocity.x() * k), static_cast<float>(ball.velocity.y() * k));
        def.fixedRotation = true; // frictionless balls never spin
        b2Body* body = world.CreateBody(&def);
        b2CircleShape circle;
        circle.m_radius = static_cast<float>(ball.radius * k);
        b2FixtureDef f;
        f.shape = &circle;
        f.density = 1.0f;
        f.friction = 0.0f;
        f.restitution = static_cast<float>(scene.settings.collisions.restitution);
        body->CreateFixture(&f);
        bodies.push_back(body);
    }
    const double c0 = nowMilliseconds();
    for (int s = 0; s < kSteps; ++s)
        world.Step(static_cast<float>(scene.settings.time.dt), 8, 3);
    const double ms = (nowMilliseconds() - c0) / kSteps;
    const std::size_t n = bodies.size();
    std::vector<double> x(n), y(n), vx(n), vy(n), r(n);
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = bodies[i]->GetPosition().x * kPixelsPerMetre;
        y[i] = bodies[i]->GetPosition().y * kPixelsPerMetre;
        vx[i] = bodies[i]->GetLinearVelocity().x * kPixelsPerMetre;
        vy[i] = bodies[i]->GetLinearVelocity().y * kPixelsPerMetre;
        r[i] = scene.balls[i].radius;
    }
    print("Box2D 2.4", static_cast<int>(n), ms, measurePile(x, y, vx, vy, r, height));
}

} // namespace

int main(int argc, char** argv)
{
    std::setvbuf(stdout, nullptr, _IOLBF, 0); // each row as soon as it is measured
    std::vector<int> sizes;
    for (int i = 1; i < argc; ++i) {
        char* end = nullptr;
        const long n = std::strtol(argv[i], &end, 10);
        if (*end != '\0' || n < 1 || n > 1000000) {
            std::fprintf(stderr, "forcelab-peer-box2d: ball count '%s' is not a whole number in [1, 1000000]\n", argv[i]);
            return 2;
        }
        sizes.push_back(static_cast<int>(n));
    }
    if (sizes.empty())
        sizes = {5000, 20000};
    std::printf("Peer scene, %d steps at 60 Hz; ms per step (wall clock; ForceLab/T: T threads, Box2D one); "
                "end state after 10 s\n",
                kSteps);
    std::printf("%-10s %7s %10s %10s %10s %10s %10s %10s %10s\n", "engine", "N", "ms/step", "deepest r", "mean r",
                "rms px/s", "height px", "pile px/s", "in flight");
    for (int n : sizes) {
        const Scene scene = peerScene(n);
        runForceLab(scene, 1);
        runForceLab(scene, 2);
        runBox2D(scene);
    }
    return 0;
}
