// Exact impulses for the pairs of free islands (free_impacts.h).

#include "sim/collision/resting/free_impacts.h"

#include "sim/collision/resting/resting_rows.h"
#include "sim/collision/response/positional_correction.h"
#include "sim/collision/response/response.h"

#include <algorithm>
#include <cmath>

namespace forcelab::sim {

bool resolveFreePairs(BallState& balls, const SubStepContext& c, const std::vector<FreePair>& pairs)
{
    double* x = balls.position.data();
    double* v = balls.velocity.data();
    const double* radius = balls.radius.data();
    const double* inverseMass = balls.inverseMass.data();
    const WallCheck check{{{c.walls.left, c.walls.right}, {c.walls.top, c.walls.bottom}}, {c.box.width, c.box.height}};
    bool bounced = false;
    for (const FreePair& p : pairs) {
        const auto a = static_cast<std::size_t>(p.a), b = static_cast<std::size_t>(p.b);
        const double wa = inverseMass[a], wb = inverseMass[b];
        const Vec2 n(p.nx, p.ny);
        const Vec2 va0(v[2 * a], v[2 * a + 1]), vb0(v[2 * b], v[2 * b + 1]);
        const double vn = (vb0 - va0).dot(n);
        const double e = c.ownRestitution ? pairRestitution(c.ownRestitution[a], c.ownRestitution[b], c.restitution)
                                          : c.restitution;
        Vec2 va = va0, vb = vb0;
        if (impulse2D(e, n, wa, wb, va, vb)) { // the response model's own impulse (response.h)
            v[2 * a] = va.x();
            v[2 * a + 1] = va.y();
            v[2 * b] = vb.x();
            v[2 * b + 1] = vb.y();
            // The pair met τ into the sub-step; from then on each ball
            // moved with its new velocity.
            const double met = p.gapStart > 0.0 ? std::min(p.gapStart / -vn, c.h) : 0.0;
            const Vec2 da = (va - va0) * (c.h - met), db = (vb - vb0) * (c.h - met);
            moveWithinWalls(x[2 * a], x[2 * a + 1], radius[a], da.x(), da.y(), c);
            moveWithinWalls(x[2 * b], x[2 * b + 1], radius[b], db.x(), db.y(), c);
            bounced = true;
        }
        Vec2 pa(x[2 * a], x[2 * a + 1]), pb(x[2 * b], x[2 * b + 1]);
        const double s = radius[a] + radius[b];
        const Vec2 d = pb - pa;
        const double depth = s - d.norm();
        if (!(depth > 0.0))
            continue;
        pushApartWithin(pa, pb, {radius[a], radius[b], lineOfImpact(d, s, p.a, p.b), wa, wb}, depth, check, c.box,
                        c.walls);
        x[2 * a] = pa.x();
        x[2 * a + 1] = pa.y();
        x[2 * b] = pb.x();
        x[2 * b + 1] = pb.y();
    }
    return bounced;
}

} // namespace forcelab::sim
