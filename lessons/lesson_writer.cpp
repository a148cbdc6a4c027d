// saveLesson: a Lesson back to format-1 JSON text. Written by hand rather
// than with QJsonDocument so the keys come in reading order (QJsonObject sorts
// them) and every double is printed with the shortest digits that read back
// to the same bits (std::to_chars).

#include "lesson_limits.h"
#include "lesson_loader.h"
#include "sim/names.h"

#include <charconv>
#include <cmath>
#include <utility>
#include <vector>

namespace forcelab {
namespace {

using lessons::kMaxNumberSeed;

QByteArray num(double v)
{
    char buf[64];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    // Non-finite values cannot be written as JSON: they never pass the loader
    // either, so writing null makes the problem visible on the next load.
    if (ec != std::errc() || !std::isfinite(v))
        return "null";
    return QByteArray(buf, static_cast<qsizetype>(end - buf));
}

QByteArray num(int v)
{
    return QByteArray::number(v);
}

QByteArray seed(std::uint64_t v)
{
    // Larger seeds would lose digits as JSON numbers (doubles): write them as strings.
    return v <= kMaxNumberSeed ? QByteArray::number(static_cast<qulonglong>(v))
                               : '"' + QByteArray::number(static_cast<qulonglong>(v)) + '"';
}

QByteArray str(const QString& s)
{
    QByteArray out;
    out.reserve(s.size() + 2);
    out += '"';
    for (const char c : s.toUtf8()) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        case '\t': out += "\\t"; break;
        case '\b': out += "\\b"; break;
        case '\f': out += "\\f"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
                out += buf;
            } else {
                out += c;
            }
        }
    }
    out += '"';
    return out;
}

QByteArray str(std::string_view s)
{
    return str(QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())));
}

QByteArray colour(sim::Rgb c)
{
    char buf[16];
    std::snprintf(buf, sizeof buf, "\"#%06x\"", static_cast<unsigned>(c & 0xffffff));
    return buf;
}

using Fields = std::vector<std::pair<const char*, QByteArray>>;

/// {"a": 1, "b": 2} on one line.
QByteArray inlineObject(const Fields& fields)
{
    QByteArray out = "{";
    for (std::size_t i = 0; i < fields.size(); ++i) {
        if (i)
            out += ", ";
        out += '"';
        out += fields[i].first;
        out += "\": ";
        out += fields[i].second;
    }
    return out + '}';
}

QByteArray inlineArray(const QList<QByteArray>& items)
{
    return '[' + items.join(", ") + ']';
}

/// An array with one entry per line, indented by `indent` spaces.
QByteArray blockArray(const QList<QByteArray>& items, int indent)
{
    if (items.isEmpty())
        return "[]";
    const QByteArray pad(indent + 2, ' ');
    QByteArray out = "[\n";
    for (qsizetype i = 0; i < items.size(); ++i)
        out += pad + items[i] + (i + 1 < items.size() ? ",\n" : "\n");
    return out + QByteArray(indent, ' ') + ']';
}

QByteArray strings(const QStringList& list, bool block)
{
    QList<QByteArray> items;
    for (const QString& s : list)
        items << str(s);
    return block ? blockArray(items, 2) : inlineArray(items);
}

/// A model's fields, with "enabled": false in front when it is off. A model
/// that is off and still has its default values is left out entirely.
void addModel(QList<QByteArray>& models, const char* name, bool enabled, Fields fields, const Fields& defaults)
{
    if (!enabled) {
        if (fields == defaults)
            return;
        fields.insert(fields.begin(), {"enabled", "false"});
    }
    models << '"' + QByteArray(name) + "\": " + inlineObject(fields);
}

QByteArray modelsBlock(const sim::WorldSettings& s)
{
    const sim::WorldSettings d; // defaults
    QList<QByteArray> m;
    auto gravity = [](const sim::GravitySettings& g) {
        return Fields{{"x", num(g.g.x())}, {"y", num(g.g.y())}};
    };
    addModel(m, "gravity", s.gravity.enabled, gravity(s.gravity), gravity(d.gravity));
    auto drag = [](const sim::DragSettings& g) {
        return Fields{{"law", str(sim::toString(g.law))}, {"k", num(g.k)}};
    };
    addModel(m, "drag", s.drag.enabled, drag(s.drag), drag(d.drag));
    auto wind = [](const sim::WindSettings& w) {
        return Fields{{"mode", str(sim::toString(w.mode))},
                      {"strength", num(w.strength)},
                      {"scale", str(sim::toString(w.scale))},
                      {"smoothed_step", num(w.smoothedStep)},
                      {"frequency", num(w.noiseFrequency)},
                      {"compare", str(sim::toString(w.compare))}};
    };
    // Wind has no "enabled": mode "off" switches it off, and is written when
    // the other values differ from the defaults.
    if (wind(s.wind) != wind(d.wind))
        m << "\"wind\": " + inlineObject(wind(s.wind));
    auto randomAccel = [](const sim::RandomAccelSettings& r) {
        return Fields{{"fixed", r.fixed ? "true" : "false"}, {"strength", num(r.strength)}};
    };
    addModel(m, "random_accel", s.randomAccel.enabled, randomAccel(s.randomAccel), randomAccel(d.randomAccel));
    auto point = [](const sim::PointForceSettings& p) {
        return Fields{{"kind", str(sim::toString(p.kind))},  {"x", num(p.position.x())},
                      {"y", num(p.position.y())},            {"strength", num(p.strength)},
                      {"max_accel", num(p.maxAccel)},        {"scale", str(sim::toString(p.scale))}};
    };
    addModel(m, "point", s.point.enabled, point(s.point), point(d.point));
    auto spring = [](const sim::SpringSettings& p) {
        return Fields{{"x", num(p.anchor.x())}, {"y", num(p.anchor.y())}, {"k", num(p.k)}};
    };
    addModel(m, "spring", s.spring.enabled, spring(s.spring), spring(d.spring));
    auto mutual = [](const sim::MutualGravitySettings& p) {
        return Fields{{"G", num(p.G)}, {"softening", num(p.softening)}};
    };
    addModel(m, "mutual_gravity", s.mutualGravity.enabled, mutual(s.mutualGravity), mutual(d.mutualGravity));
    auto homing = [](const sim::HomingSettings& p) { return Fields{{"strength", num(p.strength)}}; };
    addModel(m, "homing", s.homing.enabled, homing(s.homing), homing(d.homing));
    auto pointer = [](const sim::PointerSettings& p) {
        return Fields{{"strength", num(p.strength)}, {"max_accel", num(p.maxAccel)}};
    };
    addModel(m, "pointer", s.pointer.enabled, pointer(s.pointer), pointer(d.pointer));
    auto limit = [](const sim::SpeedLimitSettings& p) { return Fields{{"max", num(p.max)}}; };
    addModel(m, "speed_limit", s.speedLimit.enabled, limit(s.speedLimit), limit(d.speedLimit));
    auto collisions = [](const sim::CollisionSettings& c) {
        return Fields{{"detection", str(sim::toString(c.detection))},
                      {"response", str(sim::toString(c.response))},
                      {"restitution", num(c.restitution)},
                      {"continuous", c.continuous ? "true" : "false"},
                      {"resting", c.resting ? "true" : "false"}};
    };
    // Like wind: response "none" is off; written when anything differs from the defaults.
    if (collisions(s.collisions) != collisions(d.collisions))
        m << "\"collisions\": " + inlineObject(collisions(s.collisions));

    if (m.isEmpty())
        return "{}";
    QByteArray out = "{\n";
    for (qsizetype i = 0; i < m.size(); ++i)
        out += "    " + m[i] + (i + 1 < m.size() ? ",\n" : "\n");
    return out + "  }";
}

QByteArray ballLine(const sim::Ball& b)
{
    Fields f{{"x", num(b.position.x())},
             {"y", num(b.position.y())},
             {"vx", num(b.velocity.x())},
             {"vy", num(b.velocity.y())},
             {"r", num(b.radius)}};
    if (b.mass != 0.0) // 0 means "density 1 sphere": leave the key out
        f.push_back({"mass", num(b.mass)});
    f.push_back({"color", colour(b.color)});
    return inlineObject(f);
}

} // namespace

QByteArray saveLesson(const Lesson& lesson)
{
    const sim::WorldSettings& s = lesson.scene.settings;
    const sim::SpawnSettings& spawn = lesson.scene.spawn;

    QList<QByteArray> walls;
    if (s.walls.left)
        walls << "\"left\"";
    if (s.walls.right)
        walls << "\"right\"";
    if (s.walls.top)
        walls << "\"top\"";
    if (s.walls.bottom)
        walls << "\"bottom\"";

    QList<QByteArray> balls;
    balls.reserve(static_cast<qsizetype>(lesson.scene.balls.size()));
    for (const sim::Ball& b : lesson.scene.balls)
        balls << ballLine(b);

    Fields spawnFields{{"count", num(spawn.count)},
                       {"radius", inlineArray({num(spawn.minRadius), num(spawn.maxRadius)})},
                       {"speed", inlineArray({num(spawn.minSpeed), num(spawn.maxSpeed)})},
                       {"seed", seed(spawn.seed)},
                       {"horizontal", spawn.horizontal ? "true" : "false"},
                       {"fully_inside", spawn.fullyInside ? "true" : "false"},
                       {"per_step", num(spawn.perStep)},
                       {"max_count", num(spawn.maxCount)}};
    if (!spawn.palette.empty()) {
        QList<QByteArray> colours;
        for (const sim::Rgb c : spawn.palette)
            colours << colour(c);
        spawnFields.push_back({"palette", inlineArray(colours)});
    }

    Fields top{
        {"format", num(lessons::kFormat)},
        {"id", str(lesson.id)},
        {"title", str(lesson.title)},
        {"stage", num(lesson.stage)},
        {"text", str(lesson.text)},
        {"challenges", strings(lesson.challenges, true)},
        {"world", inlineObject({{"width", num(s.box.width)},
                                {"height", num(s.box.height)},
                                {"walls", inlineArray(walls)},
                                {"wall_model", str(sim::toString(s.walls.model))},
                                {"restitution", num(s.walls.restitution)},
                                {"middle_wall", s.walls.middle ? "true" : "false"},
                                {"centre_only", s.walls.centreOnly ? "true" : "false"}})},
        {"time", inlineObject({{"integrator", str(sim::toString(s.time.integrator))},
                               {"dt", num(s.time.dt)},
                               {"substeps", num(s.time.substeps)},
                               {"tolerance", num(s.time.tolerance)},
                               {"seed", seed(s.time.seed)},
                               {"per_frame", s.time.perFrame ? "true" : "false"}})},
        {"models", modelsBlock(s)},
        {"balls", blockArray(balls, 2)},
        {"spawn", inlineObject(spawnFields)},
        {"controls", strings(lesson.controls, false)},
        {"overlays", strings(lesson.overlays, false)},
    };

    QByteArray out = "{\n";
    for (std::size_t i = 0; i < top.size(); ++i) {
        out += "  \"";
        out += top[i].first;
        out += "\": ";
        out += top[i].second;
        out += i + 1 < top.size() ? ",\n" : "\n";
    }
    return out + "}\n";
}

} // namespace forcelab
