#include "ui/canvas/scene_description.h"

#include "lessons/colour_names.h"
#include "sim/studies/wall_arrival.h"
#include "ui/drawing/display_units.h"
#include "ui/drawing/human_number.h"
#include "ui/drawing/world_painter.h"

#include <QCoreApplication>

#include <cmath>
#include <numbers>

namespace forcelab {

namespace {

// The lesson files' colour words (lessons/colour_names.cpp), listed for lupdate.
constexpr const char* kColourWords[] = {
    QT_TRANSLATE_NOOP("Colour", "sky blue"), QT_TRANSLATE_NOOP("Colour", "blue"),
    QT_TRANSLATE_NOOP("Colour", "red"),      QT_TRANSLATE_NOOP("Colour", "orange"),
    QT_TRANSLATE_NOOP("Colour", "yellow"),   QT_TRANSLATE_NOOP("Colour", "green"),
    QT_TRANSLATE_NOOP("Colour", "purple"),   QT_TRANSLATE_NOOP("Colour", "pink"),
    QT_TRANSLATE_NOOP("Colour", "black"),    QT_TRANSLATE_NOOP("Colour", "grey"),
    QT_TRANSLATE_NOOP("Colour", "white"),
};

QString colourName(const QString& english)
{
    for (const char* word : kColourWords)
        if (english == QLatin1String(word))
            return QCoreApplication::translate("Colour", word);
    return english;
}

// Screen directions (y grows downwards) in eight words.
QString direction(const sim::Vec2& v)
{
    const double angle = std::atan2(-v.y(), v.x()) * 180.0 / std::numbers::pi; // counter-clockwise from right
    const int sector = static_cast<int>(std::lround(angle / 45.0)) & 7;
    switch (sector) {
    case 0: return QCoreApplication::translate("SceneDescription", "right");
    case 1: return QCoreApplication::translate("SceneDescription", "up and to the right");
    case 2: return QCoreApplication::translate("SceneDescription", "up");
    case 3: return QCoreApplication::translate("SceneDescription", "up and to the left");
    case 4: return QCoreApplication::translate("SceneDescription", "left");
    case 5: return QCoreApplication::translate("SceneDescription", "down and to the left");
    case 6: return QCoreApplication::translate("SceneDescription", "down");
    default: return QCoreApplication::translate("SceneDescription", "down and to the right");
    }
}

QString wallName(sim::WallSide side)
{
    switch (side) {
    case sim::WallSide::Left: return QCoreApplication::translate("SceneDescription", "the left wall");
    case sim::WallSide::Right: return QCoreApplication::translate("SceneDescription", "the right wall");
    case sim::WallSide::Top: return QCoreApplication::translate("SceneDescription", "the ceiling");
    case sim::WallSide::Bottom: return QCoreApplication::translate("SceneDescription", "the floor");
    case sim::WallSide::Middle: return QCoreApplication::translate("SceneDescription", "the middle wall");
    }
    return {};
}

} // namespace

QString describeScene(const sim::World& world, int ball)
{
    const sim::BallState& balls = world.balls();
    const int n = balls.size();
    QString out = n == 0   ? QCoreApplication::translate("SceneDescription", "No balls.")
                  : n == 1 ? QCoreApplication::translate("SceneDescription", "One ball.")
                           : QCoreApplication::translate("SceneDescription", "%1 balls.").arg(n);
    if (n == 0)
        return out;
    const int i = ball >= 0 && ball < n ? ball : 0;
    // The colour's name is the lesson files' (English) word, said in the
    // program's language.
    const QString colour = colourName(lessons::nameOfColour(balls.color[static_cast<std::size_t>(i)]));
    const QString who = colour.isEmpty() ? QCoreApplication::translate("SceneDescription", "Ball %1").arg(i)
                                         : QCoreApplication::translate("SceneDescription", "Ball %1 (%2)").arg(i).arg(colour);
    const sim::Vec2 x = balls.position.col(i);
    const sim::Vec2 v = balls.velocity.col(i);
    const double speed = v.norm();
    if (balls.pinned[static_cast<std::size_t>(i)])
        out += QLatin1Char(' ') + QCoreApplication::translate("SceneDescription", "%1 is pinned in place.").arg(who);
    else if (!(speed > 1e-9))
        out += QLatin1Char(' ') + QCoreApplication::translate("SceneDescription", "%1 is at rest.").arg(who);
    else
        out += QLatin1Char(' ') + QCoreApplication::translate("SceneDescription", "%1 moves %2 at %3")
                                      .arg(who, direction(v), quantityText(speed, QStringLiteral("px/s"), 2));
    if (!balls.pinned[static_cast<std::size_t>(i)]) {
        const sim::Matrix2X a = world.accelerations();
        const auto arrival = sim::nextWallArrival(world.settings().box, world.settings().walls, x, v,
                                                  a.col(i), balls.radius[i]);
        // Exact only when gravity is the one force and no other ball can get in the way.
        bool exact = n == 1 || world.settings().collisions.response == sim::Response::None;
        for (const auto& source : world.accelerationBySource(i))
            exact = exact && source.model == "gravity";
        const bool moving = speed > 1e-9;
        if (arrival) {
            const QString when = humanNumber(arrival->seconds, 2);
            const QString sentence =
                exact ? QCoreApplication::translate("SceneDescription", "will hit %1 in %2 s").arg(wallName(arrival->side), when)
                      : QCoreApplication::translate("SceneDescription", "will hit %1 in about %2 s").arg(wallName(arrival->side), when);
            out += moving ? QStringLiteral(" ") + QCoreApplication::translate("SceneDescription", "and %1.").arg(sentence)
                          : QLatin1Char(' ') + QCoreApplication::translate("SceneDescription", "It %1.").arg(sentence);
        } else if (moving) {
            out += QLatin1Char('.');
        }
    }
    out += QLatin1Char(' ') + QCoreApplication::translate("SceneDescription", "Total energy %1.")
                                  .arg(quantityText(world.energy().total(), WorldPainter::kEnergyUnit, 2));
    return out;
}

} // namespace forcelab
