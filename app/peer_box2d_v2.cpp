// The peer scene in Box2D 2.4 (Debian's libbox2d-dev), for forcelab-peer-box2d.
//
// Box2D 2.4 works in metres: 50 px are 1 m, so a 5 px ball is 0.1 m across its
// radius and gravity is 19.6 m/s². Its balls have no friction (ForceLab's
// have none), restitution 0.9 for balls and walls, 8 velocity and 3 position
// iterations (its defaults).

#include "peer_box2d.h"

#include <box2d/box2d.h>

#include <vector>

namespace forcelab::peer {

namespace {
constexpr double kPixelsPerMetre = 50.0;
} // namespace

const char* box2dName()
{
    return "Box2D 2.4";
}

void runBox2D(const sim::Scene& scene)
{
    using namespace forcelab::sim;
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
    const StepTimes ms = timeSteps([&] { world.Step(static_cast<float>(scene.settings.time.dt), 8, 3); });
    const std::size_t n = bodies.size();
    std::vector<double> x(n), y(n), vx(n), vy(n), r(n);
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = bodies[i]->GetPosition().x * kPixelsPerMetre;
        y[i] = bodies[i]->GetPosition().y * kPixelsPerMetre;
        vx[i] = bodies[i]->GetLinearVelocity().x * kPixelsPerMetre;
        vy[i] = bodies[i]->GetLinearVelocity().y * kPixelsPerMetre;
        r[i] = scene.balls[i].radius;
    }
    print(box2dName(), static_cast<int>(n), ms, measurePile(x, y, vx, vy, r, height));
}

} // namespace forcelab::peer
