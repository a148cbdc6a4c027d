// Every control a student can reach has a name a screen reader can say: the
// test walks every widget of the window (menus' actions, every dock, the
// stage view's bar) for each lesson and fails on a control without one.

#include "gui_workbench.h"

#include "lessons/lesson_loader.h"
#include "ui/controls/number_control.h"

#include <QAbstractButton>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QAccessible>
#include <QAction>
#include <QComboBox>
#include <QFileInfo>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QStandardPaths>
#include <QTabBar>
#include <QTest>
#include <QTextEdit>

using namespace forcelab;

namespace {

bool isControl(QWidget* w)
{
    // Qt's own parts (scroll bars, a tool bar's "more" button, a table's
    // corner) are told by their role; a widget hidden on purpose cannot be reached.
    if (w->isHidden() || w->objectName().startsWith(QLatin1String("qt_")) ||
        qobject_cast<QScrollBar*>(w) || w->inherits("QTableCornerButton"))
        return false;
    if (qobject_cast<QTabBar*>(w))
        return false; // its tabs are named by their text
    if (auto* text = qobject_cast<QTextEdit*>(w))
        return !text->isReadOnly();
    if (auto* plain = qobject_cast<QPlainTextEdit*>(w))
        return !plain->isReadOnly();
    if (qobject_cast<QLineEdit*>(w) && qobject_cast<QAbstractSpinBox*>(w->parentWidget()))
        return false; // the spin box's own line edit: the spin box is named
    if (qobject_cast<QLineEdit*>(w) && qobject_cast<QComboBox*>(w->parentWidget()))
        return false;
    return qobject_cast<QAbstractButton*>(w) || qobject_cast<QAbstractSlider*>(w) || qobject_cast<QAbstractSpinBox*>(w) ||
           qobject_cast<QComboBox*>(w) || qobject_cast<QLineEdit*>(w);
}

QString describe(QWidget* w)
{
    QStringList path;
    for (QWidget* p = w; p; p = p->parentWidget())
        path.prepend(QStringLiteral("%1(%2)").arg(QString::fromLatin1(p->metaObject()->className()), p->objectName()));
    return path.mid(std::max<qsizetype>(0, path.size() - 4)).join(QStringLiteral(" > "));
}

QStringList unnamedControls(QWidget* root)
{
    QStringList unnamed;
    for (QWidget* w : root->findChildren<QWidget*>()) {
        if (!isControl(w))
            continue;
        QAccessibleInterface* a = QAccessible::queryAccessibleInterface(w);
        const QString name = a ? a->text(QAccessible::Name).trimmed() : QString();
        if (name.isEmpty())
            unnamed << describe(w);
    }
    unnamed.removeDuplicates();
    return unnamed;
}

} // namespace

class GuiAccessibleTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void everyControlHasAName();
    void numberRowsSayTheirValueWithTheUnit();
};

void GuiAccessibleTest::everyControlHasAName()
{
    QStringList problems;
    for (const QString& file : LessonLoader::builtInFiles()) {
        test::Workbench w(file);
        QVERIFY(w.ready());
        for (const QString& u : unnamedControls(&w.window))
            problems << u;
        // Every menu item says what it does (separators aside), in every menu and sub-menu.
        for (QMenu* menu : w.window.findChildren<QMenu*>())
            for (QAction* a : menu->actions())
                if (!a->isSeparator() && a->text().remove(QLatin1Char('&')).trimmed().isEmpty())
                    problems << QStringLiteral("an untitled item in menu \"%1\"").arg(menu->title());
        // And the stage view, whose bar has its own buttons and sliders.
        auto* stage = w.window.findChild<QAction*>(QStringLiteral("presentationAction"));
        QVERIFY(stage);
        stage->setChecked(true);
        QVERIFY(QTest::qWaitFor([&] { return w.window.isStaged(); }));
        for (const QString& u : unnamedControls(&w.window))
            problems << QStringLiteral("stage: ") + u;
        stage->setChecked(false);
    }
    problems.removeDuplicates();
    for (const QString& p : problems)
        qInfo("no name: %s", qPrintable(p));
    QVERIFY2(problems.isEmpty(), qPrintable(QStringLiteral("%1 unnamed:\n").arg(problems.size()) + problems.mid(0, 400).join(QLatin1Char('\n'))));
}

// Lesson 07's gravity row: the field is "…, value", the slider "…, slider",
// and the slider's description is the value with its unit as the field shows
// it, following every change.
void GuiAccessibleTest::numberRowsSayTheirValueWithTheUnit()
{
    test::Workbench w(QStringLiteral("gravity"));
    QVERIFY(w.ready());
    int withAcceleration = 0;
    NumberControl* g = nullptr;
    for (NumberControl* c : w.window.findChildren<NumberControl*>()) {
        if (c->spinBox()->isHidden() || c->objectName().startsWith(QLatin1String("stage")))
            continue; // the stage's sliders show their value in a large label above them
        QVERIFY2(c->spinBox()->accessibleName().endsWith(QStringLiteral(", value")), qPrintable(c->objectName()));
        QVERIFY2(c->slider()->accessibleName().endsWith(QStringLiteral(", slider")), qPrintable(c->objectName()));
        QCOMPARE(c->slider()->accessibleDescription(), c->spinBox()->text());
        if (c->spinBox()->text().contains(QStringLiteral("/s²"))) {
            ++withAcceleration;
            g = c;
        }
    }
    QVERIFY(withAcceleration > 0 && g); // gravity, in m/s² (lesson 07 speaks SI)
    g->spinBox()->setValue(g->spinBox()->value() / 2);
    QCOMPARE(g->slider()->accessibleDescription(), g->spinBox()->text());
}

QTEST_MAIN(GuiAccessibleTest)
#include "test_gui_accessible.moc"
