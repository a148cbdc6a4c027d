#include "ui/docks/lessons_dock.h"
#include "ui/window/language.h"

#include "lessons/lesson_languages.h"
#include "lessons/lesson_markup.h"

#include "ui/drawing/handbook.h"

#include "lessons/lesson_loader.h"

#include <QAction>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QSignalBlocker>
#include <QSplitter>
#include <QTextBrowser>
#include <QTextDocument>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace forcelab {

namespace {
constexpr int kSourceRole = Qt::UserRole;
} // namespace

LessonsDock::LessonsDock(QWidget* parent)
    : QDockWidget(tr("Lessons"), parent)
{
    setObjectName(QStringLiteral("lessonsDock"));

    m_tree = new QTreeWidget;
    m_tree->setObjectName(QStringLiteral("lessonTree"));
    m_tree->setHeaderHidden(true);
    m_tree->setRootIsDecorated(true);
    m_tree->setUniformRowHeights(true);
    m_tree->setFocusPolicy(Qt::ClickFocus);
    connect(m_tree, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
        const QString source = item->data(0, kSourceRole).toString();
        if (!source.isEmpty() && source != m_current)
            emit lessonChosen(source);
    });
    connect(m_tree, &QTreeWidget::itemClicked, m_tree, &QTreeWidget::itemActivated);

    m_teacherAction = new QAction(tr("Teacher notes"), this);
    m_teacherAction->setObjectName(QStringLiteral("teacherNotesAction"));
    m_teacherAction->setCheckable(true);
    m_teacherAction->setToolTip(tr("Show the goal, expected answers and misconceptions under the lesson text"));
    connect(m_teacherAction, &QAction::toggled, this, [this] {
        if (m_lesson)
            showText(*m_lesson);
    });

    m_text = new LessonTextView;
    m_text->setObjectName(QStringLiteral("lessonText"));
    m_text->setFocusPolicy(Qt::ClickFocus);
    m_text->document()->setDocumentMargin(10);

    m_previousButton = new QToolButton;
    m_previousButton->setObjectName(QStringLiteral("previousLessonButton"));
    m_previousButton->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_nextButton = new QToolButton;
    m_nextButton->setObjectName(QStringLiteral("nextLessonButton"));
    m_nextButton->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_nextButton->setLayoutDirection(Qt::RightToLeft); // the arrow after "Next"
    auto* buttons = new QHBoxLayout;
    buttons->setContentsMargins(4, 0, 4, 4);
    buttons->addWidget(m_previousButton);
    buttons->addStretch(1);
    buttons->addWidget(m_nextButton);

    auto* lower = new QWidget;
    auto* lowerLayout = new QVBoxLayout(lower);
    lowerLayout->setContentsMargins(0, 0, 0, 0);
    lowerLayout->setSpacing(2);
    lowerLayout->addWidget(m_text, 1);
    lowerLayout->addLayout(buttons);

    auto* splitter = new QSplitter(Qt::Vertical);
    splitter->setObjectName(QStringLiteral("lessonsSplitter"));
    splitter->addWidget(m_tree);
    splitter->addWidget(lower);
    splitter->setStretchFactor(0, 2);
    splitter->setStretchFactor(1, 3);
    splitter->setChildrenCollapsible(false);
    setWidget(splitter);
}

int LessonsDock::partOf(int stage)
{
    if (stage <= 0)
        return 0;
    if (stage <= 9)
        return 1;
    if (stage <= 22)
        return 2;
    if (stage <= 29)
        return 3;
    return 4;
}

QList<LessonsDock::Entry> LessonsDock::builtInCourse()
{
    QList<Entry> entries;
    for (const QString& file : LessonLoader::builtInFiles()) {
        const LoadResult result = LessonLoader::load(file);
        if (!result.ok()) {
            // A built-in lesson that does not load is a bug of the build; the
            // lesson tests name it. Leave it out of the course.
            qWarning("Lessons: %s", qPrintable(result.errors().value(0)));
            continue;
        }
        const Lesson shown = lessons::shownIn(*result.lesson, currentLanguage());
        entries.append(Entry{shown.source, lessons::markupToPlainText(shown.title), shown.stage});
    }
    // builtInFiles() is sorted by file name; keep that order within a stage.
    std::stable_sort(entries.begin(), entries.end(),
                     [](const Entry& a, const Entry& b) { return a.stage < b.stage; });
    return entries;
}

void LessonsDock::setCourse(const QList<Entry>& entries)
{
    const QSignalBlocker block(m_tree);
    m_tree->clear();
    const QString parts[] = {QString(), tr("Part A · Motion and walls"), tr("Part B · Forces"),
                             tr("Part C · Collisions"), tr("Beyond the course")};
    QTreeWidgetItem* partItems[5] = {};
    for (const Entry& entry : entries) {
        const int part = partOf(entry.stage);
        QTreeWidgetItem* item = nullptr;
        if (part == 0) {
            // The showcase sits at the top, outside the parts.
            item = new QTreeWidgetItem(m_tree);
            item->setText(0, entry.title);
            QFont bold = item->font(0);
            bold.setBold(true);
            item->setFont(0, bold);
        } else {
            if (!partItems[part]) {
                partItems[part] = new QTreeWidgetItem(m_tree);
                partItems[part]->setText(0, parts[part]);
                partItems[part]->setFlags(Qt::ItemIsEnabled);
                QFont bold = partItems[part]->font(0);
                bold.setBold(true);
                partItems[part]->setFont(0, bold);
            }
            item = new QTreeWidgetItem(partItems[part]);
            item->setText(0, QStringLiteral("%1  %2").arg(entry.stage, 2, 10, QLatin1Char('0')).arg(entry.title));
        }
        item->setData(0, kSourceRole, entry.source);
        item->setToolTip(0, entry.source);
    }
    m_tree->expandAll();
    if (QTreeWidgetItem* item = itemFor(m_current))
        m_tree->setCurrentItem(item);
}

QStringList LessonsDock::order() const
{
    QStringList sources;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        const QTreeWidgetItem* top = m_tree->topLevelItem(i);
        if (const QString s = top->data(0, kSourceRole).toString(); !s.isEmpty())
            sources.append(s);
        for (int j = 0; j < top->childCount(); ++j)
            sources.append(top->child(j)->data(0, kSourceRole).toString());
    }
    return sources;
}

QTreeWidgetItem* LessonsDock::itemFor(const QString& source) const
{
    if (source.isEmpty())
        return nullptr;
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it)
        if ((*it)->data(0, kSourceRole).toString() == source)
            return *it;
    return nullptr;
}

void LessonsDock::setCurrentLesson(const Lesson& lesson)
{
    m_current = lesson.source;
    m_lesson = lesson;
    {
        const QSignalBlocker block(m_tree);
        QTreeWidgetItem* item = itemFor(m_current);
        m_tree->setCurrentItem(item);
        if (!item)
            m_tree->clearSelection();
        else
            m_tree->scrollToItem(item);
    }
    showText(lesson);
    if (m_previousButton->defaultAction())
        m_previousButton->defaultAction()->setEnabled(!previousSource().isEmpty());
    if (m_nextButton->defaultAction())
        m_nextButton->defaultAction()->setEnabled(!nextSource().isEmpty());
}

QString LessonsDock::previousSource() const
{
    const QStringList sources = order();
    const qsizetype i = sources.indexOf(m_current);
    return i > 0 ? sources.at(i - 1) : QString();
}

QString LessonsDock::nextSource() const
{
    const QStringList sources = order();
    const qsizetype i = sources.indexOf(m_current);
    // A lesson from disk is not in the course: Next starts the course.
    if (i < 0)
        return sources.value(0);
    return sources.value(i + 1);
}

void LessonsDock::setNavigationActions(QAction* previous, QAction* next)
{
    m_previousButton->setDefaultAction(previous);
    m_nextButton->setDefaultAction(next);
}

void LessonsDock::showText(const Lesson& lesson)
{
    QString html = QStringLiteral("<h2 style='margin-bottom:2px'>%1</h2>")
                       .arg(lessons::markupToPlainText(lesson.title).toHtmlEscaped());
    QString where;
    if (lesson.stage > 0 && lesson.stage <= 29)
        where = tr("Stage %1 of 29").arg(lesson.stage);
    else if (lesson.stage > 29)
        where = tr("Beyond the course · %1").arg(lesson.stage);
    if (!lesson.source.startsWith(QStringLiteral(":/")) && !lesson.source.isEmpty())
        where += (where.isEmpty() ? QString() : QStringLiteral(" · ")) + QFileInfo(lesson.source).fileName();
    if (!where.isEmpty())
        html += QStringLiteral("<p style='color:#5a6270; margin-top:0'>%1</p>").arg(where.toHtmlEscaped());
    // A lesson without the program's language is shown in its own; the
    // panel says so rather than leave a class wondering why the panels
    // changed and the text did not.
    if (lesson.language != currentLanguage())
        html += QStringLiteral("<p style='color:#8a4b00'><i>%1</i></p>").arg(lessonLanguageNote(lesson).toHtmlEscaped());
    // The lesson's own words in the markup subset only: nothing in them can
    // open a file or a page (lessons/lesson_markup.h).
    const lessons::MarkupHtml text = lessons::markupToHtml(lesson.text);
    html += text.html;
    if (!lesson.challenges.isEmpty()) {
        html += QStringLiteral("<h3>%1</h3><ol>").arg(tr("Try this"));
        for (const QString& challenge : lesson.challenges)
            html += QStringLiteral("<li style='margin-bottom:6px'>%1</li>")
                        .arg(lessons::markupToPlainText(challenge).toHtmlEscaped());
        html += QStringLiteral("</ol>");
    }
    // The teacher's notes only when asked for, so a projected dock shows none.
    if (m_teacherAction->isChecked()) {
        const QString notes = teacherNotesHtml(lesson);
        html += QStringLiteral("<h3>%1</h3>").arg(tr("For the teacher")) +
                (notes.isEmpty() ? tr("<p>This lesson has no teacher notes.</p>") : notes);
    }
    const QString folder = lesson.source.startsWith(QStringLiteral(":/"))
                               ? QStringLiteral(":/lessons")
                               : QFileInfo(lesson.source).absolutePath();
    m_text->showLesson(html, text.images, lesson.source.isEmpty() ? QString() : folder);
}

} // namespace forcelab
