#pragma once
// The tools a lesson may list in "tools": the workbench's panels its text
// and challenges send students to. The stage view offers exactly these
// (keys 1, 2, … and the right-click menu), and the lesson reader refuses a
// text or challenge that names a tool its lesson does not list, so no
// challenge asks for something the stage cannot show.

#include <QList>
#include <QString>
#include <QStringList>

namespace forcelab {
struct Lesson;
}

namespace forcelab::lessons {

struct ToolInfo {
    QString name;      ///< as a lesson lists it: "stopwatch"
    QString title;     ///< as the workbench names it: "Stopwatch"
    QStringList words; ///< what names it in a lesson's text (case-sensitive)
};

/// Every tool, in the order the stage offers them.
const QList<ToolInfo>& lessonTools();

/// Every tool's name (for "tools" and its messages).
QStringList toolNames();

/// The tool named `name`, or null.
const ToolInfo* findTool(const QString& name);

/// The tools the stage offers for `lesson`: those it lists, and Predict when
/// it has questions to predict, in lessonTools()'s order.
QStringList stageTools(const Lesson& lesson);

/// The tools `plainText` names that `lesson` does not offer (stageTools).
QStringList undeclaredToolsIn(const QString& plainText, const Lesson& lesson);

} // namespace forcelab::lessons
