#include "lesson_controls.h"

#include "sim/world/parameters.h"

#include <QSet>

namespace forcelab::lessons {

// Which rows each lesson `controls` name shows. A name may show rows of
// several sections ("restitution": the walls' and the balls').
const QHash<QString, QStringList>& controlRows()
{
    static const QHash<QString, QStringList> rows = [] {
    QHash<QString, QStringList> rows{
        {QStringLiteral("gravity"), {"gravity_x", "gravity_y"}},
        {QStringLiteral("drag"), {"drag_law", "drag_k", "drag_scale"}},
        {QStringLiteral("wind"), {"wind_mode", "wind_strength", "wind_scale", "wind_smoothed_step", "wind_frequency"}},
        {QStringLiteral("wind_compare"), {"wind_mode", "wind_compare", "wind_strength"}},
        {QStringLiteral("random_accel"), {"random_fixed", "random_strength"}},
        {QStringLiteral("point"), {"point_kind", "point_x", "point_y", "point_strength", "point_clamp", "point_scale"}},
        {QStringLiteral("spring"), {"spring_k", "spring_x", "spring_y"}},
        {QStringLiteral("mutual_gravity"), {"mutual_g", "mutual_softening"}},
        {QStringLiteral("homing"), {"homing_strength"}},
        {QStringLiteral("pointer"), {"pointer_strength", "pointer_clamp"}},
        {QStringLiteral("speed_limit"), {"speed_limit"}},
        {QStringLiteral("custom"), {"custom_acceleration"}},
        {QStringLiteral("collisions"), {"detection", "response", "ball_restitution", "continuous", "resting"}},
        {QStringLiteral("walls"), {"wall_sides", "wall_model", "wall_restitution"}},
        {QStringLiteral("box"), {"box_width", "box_height"}},
        {QStringLiteral("wall_model"), {"wall_model"}},
        {QStringLiteral("restitution"), {"wall_restitution", "ball_restitution"}},
        {QStringLiteral("middle_wall"), {"middle_wall"}},
        {QStringLiteral("centre_only"), {"centre_only"}},
        {QStringLiteral("integrator"), {"integrator"}},
        {QStringLiteral("dt"), {"dt"}},
        {QStringLiteral("substeps"), {"substeps"}},
        {QStringLiteral("tolerance"), {"tolerance"}},
        {QStringLiteral("per_frame"), {"per_frame"}},
        {QStringLiteral("close_passes"), {"close_passes"}},
        {QStringLiteral("seed"), {"seed"}},
        {QStringLiteral("spawn"), {"ball_count"}},
        {QStringLiteral("fully_inside"), {"fully_inside"}},
        {QStringLiteral("point_clamp"), {"point_clamp"}},
        {QStringLiteral("response"), {"response"}},
        {QStringLiteral("detection"), {"detection"}},
        {QStringLiteral("resting"), {"resting"}},
        {QStringLiteral("time_scale"), {"time_scale"}},
    };
    // A model that has no entry above shows its own rows under its own name
    // ("models.magnetic.*" → "magnetic"), so a new model needs no entry here.
    QSet<QString> added;
    for (const sim::Parameter& p : sim::parameters()) {
        const QString key = QString::fromUtf8(p.key.data(), static_cast<qsizetype>(p.key.size()));
        if (!key.startsWith(QStringLiteral("models.")) || key.endsWith(QStringLiteral(".enabled")))
            continue;
        const QString model = key.section(QLatin1Char('.'), 1, 1);
        if (rows.contains(model) && !added.contains(model))
            continue;
        added.insert(model);
        rows[model] << QString::fromUtf8(p.control.data(), static_cast<qsizetype>(p.control.size()));
    }
    return rows;
    }();
    return rows;
}

const QStringList& controlNames()
{
    static const QStringList names = [] {
        QStringList out = controlRows().keys();
        out.sort();
        return out;
    }();
    return names;
}

} // namespace forcelab::lessons
