#include "lesson_tools.h"

#include "lesson.h"

namespace forcelab::lessons {

const QList<ToolInfo>& lessonTools()
{
    // The words are the panels' names as a sentence uses them; "Predict"
    // alone is also a verb ("Predict, and explain why"), so only "Predict
    // panel" names that tool.
    static const QList<ToolInfo> tools{
        {QStringLiteral("stopwatch"), QStringLiteral("Stopwatch"), {QStringLiteral("Stopwatch")}},
        {QStringLiteral("predict"), QStringLiteral("Predict"), {QStringLiteral("Predict panel")}},
        {QStringLiteral("inspector"), QStringLiteral("Inspector"), {QStringLiteral("Inspector")}},
        {QStringLiteral("plots"), QStringLiteral("Plots"), {QStringLiteral("Plots")}},
        {QStringLiteral("code"), QStringLiteral("Code"), {QStringLiteral("Code panel")}},
        {QStringLiteral("your_code"), QStringLiteral("Your Code"), {QStringLiteral("Your Code panel")}},
        {QStringLiteral("force_editor"), QStringLiteral("Force editor"), {QStringLiteral("Force editor")}},
        {QStringLiteral("accuracy"), QStringLiteral("Accuracy"),
         {QStringLiteral("Accuracy panel"), QStringLiteral("Accuracy menu")}},
        {QStringLiteral("step_apart"), QStringLiteral("One Step Apart"), {QStringLiteral("One Step Apart")}},
    };
    return tools;
}

QStringList toolNames()
{
    QStringList names;
    for (const ToolInfo& t : lessonTools())
        names << t.name;
    return names;
}

const ToolInfo* findTool(const QString& name)
{
    for (const ToolInfo& t : lessonTools())
        if (t.name == name)
            return &t;
    return nullptr;
}

QStringList stageTools(const Lesson& lesson)
{
    QStringList tools;
    for (const ToolInfo& t : lessonTools())
        if (lesson.tools.contains(t.name) || (t.name == QLatin1String("predict") && !lesson.predict.empty()))
            tools << t.name;
    return tools;
}

QStringList undeclaredToolsIn(const QString& plainText, const Lesson& lesson)
{
    const QStringList offered = stageTools(lesson);
    QStringList missing;
    for (const ToolInfo& t : lessonTools()) {
        if (offered.contains(t.name))
            continue;
        for (const QString& word : t.words)
            if (plainText.contains(word)) {
                missing << t.name;
                break;
            }
    }
    return missing;
}

} // namespace forcelab::lessons
