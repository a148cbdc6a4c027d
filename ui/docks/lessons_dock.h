#pragma once
// The Lessons dock: the course as a tree by part (the showcase, then Part A
// motion and walls, Part B forces, Part C collisions, Beyond), the current
// lesson's text and challenges, and Previous / Next buttons. It only shows and
// asks: choosing a lesson emits lessonChosen(source); the main window loads it
// and tells the dock with setCurrentLesson.

#include "ui/docks/lesson_text_view.h"
#include "lessons/lesson.h"

#include <QDockWidget>
#include <QString>
#include <QStringList>

#include <optional>

class QAction;
class QTextBrowser;
class QToolButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace forcelab {

class LessonsDock : public QDockWidget {
    Q_OBJECT
public:
    explicit LessonsDock(QWidget* parent = nullptr);

    /// One entry of the course: where it loads from and how the tree shows it.
    struct Entry {
        QString source; ///< ":/lessons/07-gravity.json"
        QString title;
        int stage = 0;
    };
    /// The built-in lessons (each loaded once for its title and stage), in course order.
    static QList<Entry> builtInCourse();
    /// The part a stage belongs to: 0 showcase, 1 A (1–9), 2 B (10–22), 3 C (23–29), 4 beyond (30+).
    static int partOf(int stage);

    /// Fills the tree (course order: by stage, then file name).
    void setCourse(const QList<Entry>& entries);
    /// Sources in the order of the tree (what Previous / Next walk through).
    QStringList order() const;

    /// Shows the lesson's text and selects it in the tree (a lesson from disk selects nothing).
    void setCurrentLesson(const Lesson& lesson);
    QString currentSource() const { return m_current; }

    /// The source before / after the current one, or empty at the ends.
    QString previousSource() const;
    QString nextSource() const;

    /// The buttons under the text trigger these (the main window's actions, also in the menu).
    void setNavigationActions(QAction* previous, QAction* next);

    /// Checkable: shows the lesson's teacher notes under its text (off by default).
    QAction* teacherNotesAction() const { return m_teacherAction; }

    QTreeWidget* tree() const { return m_tree; }
    LessonTextView* textBrowser() const { return m_text; }

signals:
    /// The user picked a lesson in the tree.
    void lessonChosen(const QString& source);

private:
    void showText(const Lesson& lesson);
    QTreeWidgetItem* itemFor(const QString& source) const;

    QTreeWidget* m_tree = nullptr;
    LessonTextView* m_text = nullptr;
    QToolButton* m_previousButton = nullptr;
    QToolButton* m_nextButton = nullptr;
    QString m_current;
    QAction* m_teacherAction = nullptr;
    std::optional<Lesson> m_lesson; // the one shown, to redraw when the teacher notes are switched
};

} // namespace forcelab
