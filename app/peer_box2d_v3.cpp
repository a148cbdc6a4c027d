// The peer scene in Box2D 3 (its C API), for forcelab-peer-box2d. Debian 12
// has no Box2D 3: build and install one (cmake --install build --prefix P),
// then configure ForceLab with -DCMAKE_PREFIX_PATH=P.
//
// Lengths are pixels, with 100 px a metre (b2SetLengthUnitsPerMeter), so the
// scene goes in as it is: r = 5 px, gravity 980 px/s². No friction (ForceLab's
// balls have none), restitution 0.9 for balls and walls, one worker thread,
// sleeping on (Box2D's default). Two rows per size: Box2D's defaults (4
// sub-steps, soft contacts at 30 Hz), and 16 sub-steps with the contacts at
// 240 Hz (a quarter of the sub-step rate, the stiffest Box2D allows), the
// setting at which its piles first stand as deep and as high as ForceLab's.

#include "peer_box2d.h"

#include <box2d/box2d.h>

#include <vector>

namespace forcelab::peer {

const char* box2dName()
{
    return "Box2D 3";
}

namespace {

void runOnce(const sim::Scene& scene, int subSteps, float contactHertz, const char* name)
{
    b2SetLengthUnitsPerMeter(100.0f);
    b2WorldDef def = b2DefaultWorldDef();
    const sim::Vec2& g = scene.settings.gravity.g;
    def.gravity = b2Vec2{static_cast<float>(g.x()), static_cast<float>(g.y())};
    def.workerCount = 1;
    def.contactHertz = contactHertz;
    const b2WorldId world = b2CreateWorld(&def);

    // Four thick walls just outside the box.
    const float w = static_cast<float>(scene.settings.box.width), h = static_cast<float>(scene.settings.box.height);
    const b2BodyDef wallDef = b2DefaultBodyDef();
    const b2BodyId walls = b2CreateBody(world, &wallDef);
    const float t = 100.0f;
    const b2Vec2 halves[4] = {{t, h / 2 + 2 * t}, {t, h / 2 + 2 * t}, {w / 2 + 2 * t, t}, {w / 2 + 2 * t, t}};
    const b2Vec2 centres[4] = {{-t, h / 2}, {w + t, h / 2}, {w / 2, -t}, {w / 2, h + t}};
    for (int i = 0; i < 4; ++i) {
        const b2Polygon box = b2MakeOffsetBox(halves[i].x, halves[i].y, centres[i], b2MakeRot(0.0f));
        b2ShapeDef shape = b2DefaultShapeDef();
        shape.material.friction = 0.0f;
        shape.material.restitution = static_cast<float>(scene.settings.walls.restitution);
        b2CreatePolygonShape(walls, &shape, &box);
    }
    std::vector<b2BodyId> bodies;
    bodies.reserve(scene.balls.size());
    for (const sim::Ball& ball : scene.balls) {
        b2BodyDef body = b2DefaultBodyDef();
        body.type = b2_dynamicBody;
        body.position = b2Vec2{static_cast<float>(ball.position.x()), static_cast<float>(ball.position.y())};
        body.linearVelocity = b2Vec2{static_cast<float>(ball.velocity.x()), static_cast<float>(ball.velocity.y())};
        const b2BodyId id = b2CreateBody(world, &body);
        b2ShapeDef shape = b2DefaultShapeDef();
        shape.density = 1.0f;
        shape.material.friction = 0.0f;
        shape.material.restitution = static_cast<float>(scene.settings.collisions.restitution);
        const b2Circle circle{{0.0f, 0.0f}, static_cast<float>(ball.radius)};
        b2CreateCircleShape(id, &shape, &circle);
        bodies.push_back(id);
    }

    const StepTimes ms = timeSteps([&] { b2World_Step(world, static_cast<float>(scene.settings.time.dt), subSteps); });

    const std::size_t n = bodies.size();
    std::vector<double> x(n), y(n), vx(n), vy(n), r(n);
    for (std::size_t i = 0; i < n; ++i) {
        const b2Vec2 p = b2Body_GetPosition(bodies[i]), v = b2Body_GetLinearVelocity(bodies[i]);
        x[i] = p.x;
        y[i] = p.y;
        vx[i] = v.x;
        vy[i] = v.y;
        r[i] = scene.balls[i].radius;
    }
    b2DestroyWorld(world);
    print(name, static_cast<int>(n), ms, sim::measurePile(x, y, vx, vy, r, h));
}

} // namespace

void runBox2D(const sim::Scene& scene)
{
    runOnce(scene, 4, 30.0f, "Box2D 3/4");
    runOnce(scene, 16, 240.0f, "Box2D 3/16");
}

} // namespace forcelab::peer
