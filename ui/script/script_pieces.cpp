#include "ui/script/script_pieces.h"

#include "sim/integrators/integrator_info.h"

#include <QDir>
#include <QFile>

namespace forcelab {

namespace {

bool anyWall(const sim::WallSettings& w)
{
    return w.left || w.right || w.top || w.bottom || w.middle;
}

} // namespace

ScriptPieces scriptPiecesFor(const sim::WorldSettings& s, const sim::SpawnSettings& spawn)
{
    ScriptPieces p;
    QStringList& f = p.files;
    const bool windOn = s.wind.mode != sim::WindMode::Off;
    if (windOn || s.randomAccel.enabled || spawn.perStep > 0.0)
        f << QStringLiteral("random.js");
    f << QStringLiteral("world.js");
    if (windOn || (s.drag.enabled && s.drag.scale != sim::ForceScale::None) ||
        (s.point.enabled && s.point.scale != sim::ForceScale::None))
        f << QStringLiteral("scale.js");
    switch (s.time.integrator) {
    case sim::IntegratorKind::Euler:
        f << QStringLiteral("step_euler.js");
        break;
    case sim::IntegratorKind::SemiImplicitEuler:
        f << QStringLiteral("step_semi_implicit_euler.js");
        break;
    case sim::IntegratorKind::Exact:
        f << QStringLiteral("step_exact.js");
        break;
    case sim::IntegratorKind::Rk4:
        f << QStringLiteral("step_rk4.js");
        break;
    case sim::IntegratorKind::Verlet:
    case sim::IntegratorKind::Yoshida4:
    case sim::IntegratorKind::Rk45:
    case sim::IntegratorKind::Ias15:
        p.missing << QStringLiteral("the %1 integrator").arg(QString::fromUtf8(sim::integratorInfo(s.time.integrator).name.data(),
                                                                               static_cast<qsizetype>(sim::integratorInfo(s.time.integrator).name.size())));
        break;
    }
    // The forces in the order the engine adds them (sim/forces/force_models.cpp):
    // the sums round alike only in the same order.
    if (s.gravity.enabled)
        f << QStringLiteral("gravity.js");
    if (s.drag.enabled)
        f << QStringLiteral("drag.js");
    if (windOn) // every wind mode keeps the generators of all of them, as the engine's does
        f << QStringLiteral("noise.js") << QStringLiteral("wind.js");
    if (s.randomAccel.enabled)
        f << QStringLiteral("random_acceleration.js");
    if (s.point.enabled || s.pointer.enabled)
        f << QStringLiteral("inverse_square.js"); // the rule both use, as the engine's addInverseSquare
    if (s.point.enabled)
        f << QStringLiteral("point_force.js");
    if (s.pointer.enabled)
        f << QStringLiteral("pointer_force.js");
    if (s.spring.enabled)
        f << QStringLiteral("spring.js");
    if (s.homing.enabled)
        f << QStringLiteral("homing.js");
    if (s.mutualGravity.enabled)
        f << QStringLiteral("mutual_gravity.js");
    if (s.magnetic.enabled)
        f << QStringLiteral("magnetic.js");
    if (s.custom.enabled)
        p.missing << QStringLiteral("a custom force law");
    // After the move, in the engine's order: speed limit, walls, collisions.
    if (s.speedLimit.enabled)
        f << QStringLiteral("speed_limit.js");
    if (anyWall(s.walls)) {
        f << QStringLiteral("walls.js");
        if (s.walls.model == sim::WallModel::Exact)
            f << QStringLiteral("walls_exact.js");
    }
    const sim::CollisionSettings& c = s.collisions;
    if (c.response != sim::Response::None) {
        f << QStringLiteral("touching.js"); // the test every detection loop uses
        switch (c.detection) {
        case sim::Detection::Brute:
            f << QStringLiteral("detect_brute.js");
            break;
        case sim::Detection::Halved:
            f << QStringLiteral("detect_halved.js");
            break;
        case sim::Detection::Sweep:
            f << QStringLiteral("detect_sweep.js");
            break;
        case sim::Detection::Grid:
            p.missing << QStringLiteral("grid detection");
            break;
        }
        f << QStringLiteral("collisions.js");
        if (c.continuous)
            p.missing << QStringLiteral("continuous collision detection");
        if (c.response == sim::Response::Impulse2D && c.resting && s.gravity.enabled && s.gravity.g.norm() > 0.0)
            p.missing << QStringLiteral("the resting-contact solver (2d-impulse under gravity)");
        switch (c.response) {
        case sim::Response::None:
        case sim::Response::Flag:
            break;
        case sim::Response::Reverse1D:
            f << QStringLiteral("response_1d_reverse.js") << QStringLiteral("push_apart.js");
            break;
        case sim::Response::Elastic1D:
            f << QStringLiteral("response_1d_elastic.js") << QStringLiteral("push_apart.js");
            break;
        case sim::Response::Axis2D:
            f << QStringLiteral("response_2d_axis.js") << QStringLiteral("push_apart.js");
            break;
        case sim::Response::Impulse2D:
            f << QStringLiteral("response_2d_impulse.js") << QStringLiteral("push_apart.js");
            break;
        }
    }
    if (spawn.perStep > 0.0) // at the end of the step
        f << QStringLiteral("spawn.js");
    return p;
}

QString scriptPieceSource(const QString& name)
{
    QFile file(QStringLiteral(":/lesson-code/") + name);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(file.readAll());
}

QStringList allScriptPieces()
{
    QStringList names = QDir(QStringLiteral(":/lesson-code")).entryList(QDir::Files, QDir::Name);
    return names;
}

} // namespace forcelab
