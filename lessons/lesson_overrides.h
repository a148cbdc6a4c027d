#pragma once
// `--set KEY.PATH=VALUE` applied to a lesson's JSON object before it is parsed,
// so an overridden value goes through exactly the same checks as one written
// in the file.

#include "lesson_loader.h"
#include "lesson_parser.h"

#include <QJsonObject>
#include <QString>

#include <optional>

namespace forcelab::lessons {

/// "--set KEY.PATH=VALUE", the source named in messages about an override.
QString overrideSource(const Override& o);

/// The override's value as JSON: its text when it is valid JSON, otherwise the
/// bare word as a string. Words and numbers that mean NaN or infinity
/// ("nan", "inf", "1e999") are refused with a message.
std::optional<QJsonValue> overrideValue(const Override& o, QString* problem);

/// Sets the value at the key path, creating missing objects on the way
/// ("models.drag.k" creates "drag"). A numeric segment indexes an array
/// ("balls.0.vx"); index == size appends. On failure returns the problem with
/// the key path where the path could not go on, and leaves `root` unchanged.
std::optional<KeyProblem> applyOverride(QJsonObject& root, const QString& keyPath, const QJsonValue& value);

} // namespace forcelab::lessons
