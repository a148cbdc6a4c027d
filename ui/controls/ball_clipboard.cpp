#include "ui/controls/ball_clipboard.h"

#include "sim/world/number_text.h"

#include <QColor>
#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace forcelab {

namespace {

QString number(double v)
{
    return QString::fromStdString(sim::shortestText(v));
}


} // namespace

QString ballToText(const sim::Ball& ball)
{
    // Pinned and an own restitution only when set, as a lesson file writes them.
    QString extra;
    if (ball.pinned)
        extra += QStringLiteral(", \"pinned\": true");
    if (sim::hasOwnRestitution(ball.restitution))
        extra += QStringLiteral(", \"restitution\": ") + number(ball.restitution);
    return QStringLiteral("{\"x\": %1, \"y\": %2, \"vx\": %3, \"vy\": %4, \"r\": %5, \"mass\": %6, \"q\": %7, "
                          "\"color\": \"%8\"%9}")
        .arg(number(ball.position.x()), number(ball.position.y()), number(ball.velocity.x()),
             number(ball.velocity.y()), number(ball.radius),
             number(ball.mass > 0.0 ? ball.mass : sim::sphereMass(ball.radius)), number(ball.charge),
             QColor::fromRgb(ball.color).name(), extra);
}

std::optional<sim::Ball> ballFromText(const QString& text, QString* why)
{
    auto fail = [why](const QString& reason) -> std::optional<sim::Ball> {
        if (why)
            *why = reason;
        return std::nullopt;
    };
    constexpr int kMaxCharacters = 4096;
    if (text.size() > kMaxCharacters)
        return fail(QCoreApplication::translate("BallClipboard", "the clipboard holds %1 characters, more than a ball's %2").arg(text.size()).arg(kMaxCharacters));
    const QJsonDocument doc = QJsonDocument::fromJson(text.trimmed().toUtf8());
    if (!doc.isObject())
        return fail(QCoreApplication::translate("BallClipboard", "the clipboard does not hold a ball"));
    const QJsonObject o = doc.object();
    for (auto it = o.begin(); it != o.end(); ++it) {
        static const QStringList known{"x", "y", "vx", "vy", "r", "mass", "q", "color", "pinned", "restitution"};
        if (!known.contains(it.key()))
            return fail(QCoreApplication::translate("BallClipboard", "the clipboard's ball has an unknown field \"%1\"").arg(it.key().left(40)));
    }
    sim::Ball ball;
    for (const char* key : {"x", "y", "r"})
        if (!o.value(QLatin1String(key)).isDouble())
            return fail(QCoreApplication::translate("BallClipboard", "the clipboard's ball has no number \"%1\"").arg(QLatin1String(key)));
    auto read = [&o](const char* key, double fallback) {
        const QJsonValue v = o.value(QLatin1String(key));
        return v.isDouble() ? v.toDouble() : fallback;
    };
    ball.position = {read("x", 0.0), read("y", 0.0)};
    ball.velocity = {read("vx", 0.0), read("vy", 0.0)};
    ball.radius = read("r", 10.0);
    ball.mass = read("mass", 0.0);
    ball.charge = read("q", 1.0);
    ball.home = ball.position;
    if (o.contains(QStringLiteral("pinned"))) {
        if (!o.value(QStringLiteral("pinned")).isBool())
            return fail(QCoreApplication::translate("BallClipboard", "the clipboard's ball has \"pinned\" that is not true or false"));
        ball.pinned = o.value(QStringLiteral("pinned")).toBool();
    }
    if (o.contains(QStringLiteral("restitution"))) { // absent: the world's
        const QJsonValue e = o.value(QStringLiteral("restitution"));
        if (!e.isDouble() || !(e.toDouble() >= 0.0))
            return fail(QCoreApplication::translate("BallClipboard", "the clipboard's ball has a restitution that is not a number from 0 to 1"));
        ball.restitution = e.toDouble();
    }
    if (o.contains(QStringLiteral("color"))) {
        const QColor colour = QColor::fromString(o.value(QStringLiteral("color")).toString());
        if (!colour.isValid())
            return fail(QCoreApplication::translate("BallClipboard", "the clipboard's ball has no valid colour"));
        ball.color = colour.rgb() & 0xffffffu;
    }
    return ball;
}

} // namespace forcelab
