// The balls and spawn sections of a lesson file: the listed balls, and the
// random balls with their count, ranges, seed and palette.

#include "lesson_parse_sections.h"

#include "sim/world/number_text.h"

namespace forcelab::lessons::parsing {

void parseBalls(Reader& r, const QJsonArray& balls, std::vector<sim::Ball>& out)
{
    const QString base = QStringLiteral("balls");
    if (balls.size() > kMaxBalls) {
        r.fail(base, QStringLiteral("%1 balls is more than the limit of %2").arg(balls.size()).arg(kMaxBalls));
        return;
    }
    const QStringList known{"x", "y", "vx", "vy", "r", "mass", "density", "q", "color", "pinned", "restitution"};
    out.clear();
    out.reserve(static_cast<std::size_t>(balls.size()));
    for (qsizetype i = 0; i < balls.size(); ++i) {
        const QString p = join(base, i);
        const QJsonValue v = balls.at(i);
        if (!v.isObject()) {
            r.fail(p, QStringLiteral("expected a ball object {\"x\": …, \"y\": …}, got ") + describe(v));
            continue;
        }
        const QJsonObject o = v.toObject();
        r.checkKeys(o, p, known);
        sim::Ball b;
        r.require(o, p, "x", QStringLiteral("the ball's centre x in px"));
        r.require(o, p, "y", QStringLiteral("the ball's centre y in px"));
        r.number(o, p, "x", range::kBallPosition, b.position.x());
        r.number(o, p, "y", range::kBallPosition, b.position.y());
        r.number(o, p, "vx", range::kBallVelocity, b.velocity.x());
        r.number(o, p, "vy", range::kBallVelocity, b.velocity.y());
        r.number(o, p, "r", range::kRadius, b.radius);
        r.number(o, p, "mass", range::kMass, b.mass);
        // A density instead of a mass: m = density × (4/3) π r³, so a lesson
        // can make a small heavy ball without working out its mass.
        if (double density = 0.0; o.contains("density") && r.number(o, p, "density", range::kDensity, density)) {
            if (o.contains("mass"))
                r.fail(join(p, "density"), QStringLiteral("give the ball a mass or a density, not both"));
            else if (const double m = density * sim::sphereMass(b.radius); !(m >= sim::kMinMass && m <= sim::kMaxMass))
                r.fail(join(p, "density"),
                       QStringLiteral("%1 makes a mass of %2, outside %3")
                           .arg(QString::fromStdString(sim::numberText(density)),
                                QString::fromStdString(sim::roundedText(m, 3)),
                                QString::fromStdString(sim::rangeText(sim::kMinMass, sim::kMaxMass, "mass units"))));
            else
                b.mass = m;
        }
        r.number(o, p, "q", range::kCharge, b.charge);
        r.boolean(o, p, "pinned", b.pinned);
        // Its own bounce, against walls and balls; absent: the world's.
        r.number(o, p, "restitution", range::kUnit, b.restitution);
        if (o.contains("color"))
            r.colourValue(o.value("color"), join(p, "color"), b.color);
        out.push_back(b);
    }
}

void parseSpawn(Reader& r, const QJsonObject& o, int listed, sim::SpawnSettings& s)
{
    const QString path = QStringLiteral("spawn");
    r.checkKeys(o, path,
                {"count", "radius", "speed", "seed", "palette", "horizontal", "fully_inside", "per_step", "max_count"});
    if (r.integer(o, path, "count", 0, kMaxBalls, s.count) && listed + s.count > kMaxBalls) {
        r.fail(join(path, "count"), QStringLiteral("%1 spawned + %2 listed balls is more than the limit of %3")
                                        .arg(s.count)
                                        .arg(listed)
                                        .arg(kMaxBalls));
    }
    r.interval(o, path, "radius", range::kRadius, s.minRadius, s.maxRadius);
    r.interval(o, path, "speed", range::kSpawnSpeed, s.minSpeed, s.maxSpeed);
    r.seed(o, path, "seed", s.seed);
    r.boolean(o, path, "horizontal", s.horizontal);
    r.boolean(o, path, "fully_inside", s.fullyInside);
    r.number(o, path, "per_step", range::kUnit, s.perStep);
    r.integer(o, path, "max_count", 0, kMaxBalls, s.maxCount);
    if (const auto a = r.array(o, path, "palette", QStringLiteral("an array of colours \"#rrggbb\""))) {
        const QString p = join(path, "palette");
        if (a->size() > kMaxPaletteColours) {
            r.fail(p, QStringLiteral("%1 colours is more than the limit of %2").arg(a->size()).arg(kMaxPaletteColours));
            return;
        }
        std::vector<sim::Rgb> palette;
        bool ok = true;
        for (qsizetype i = 0; i < a->size(); ++i) {
            sim::Rgb c = 0;
            if (r.colourValue(a->at(i), join(p, i), c))
                palette.push_back(c);
            else
                ok = false;
        }
        if (ok)
            s.palette = std::move(palette);
    }
}

} // namespace forcelab::lessons::parsing
