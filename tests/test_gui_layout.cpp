// Layout that holds, in every shipped language: at 1280x720 and 1024x768, with every parameter shown,
// no label of the Parameters panel, the Inspector or the stage bar is cut,
// every number field shows its whole text with its unit, and every tab of
// the docks shows its whole name. ctest runs this
// twice: as is, and with QT_SCALE_FACTOR=2 (test_gui_layout_scale2), where
// the same window sizes are logical pixels of a screen twice as dense.
#include "gui_settle.h"
#include "ui/window/main_window.h"
#include "ui/controls/parameter_panel.h"
#include "ui/window/language.h"

#include <QAbstractSpinBox>
#include <QCheckBox>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QStyle>
#include <QStandardPaths>
#include <QTabBar>
#include <QTest>
#include <QScopeGuard>

using namespace forcelab;

namespace {

// The widgets under `root` that the user can see now and whose text does not fit.
QStringList cutTexts(QWidget* root)
{
    QStringList cut;
    for (QLabel* label : root->findChildren<QLabel*>()) {
        if (!label->isVisibleTo(root) || label->text().isEmpty() || label->wordWrap() ||
            label->textFormat() == Qt::RichText || label->text().contains(QLatin1Char('<')) ||
            label->sizePolicy().horizontalPolicy() == QSizePolicy::Ignored)
            continue;
        // A label inside a scroll area that is scrolled out of view is not cut.
        const int need = label->fontMetrics().horizontalAdvance(label->text());
        if (need > label->contentsRect().width() + 1)
            cut << QStringLiteral("label %1 \"%2\": %3 px in %4").arg(label->objectName(), label->text()).arg(need)
                       .arg(label->contentsRect().width());
    }
    for (QCheckBox* box : root->findChildren<QCheckBox*>()) {
        if (!box->isVisibleTo(root) || box->text().isEmpty())
            continue;
        if (box->sizeHint().width() > box->width() + 1)
            cut << QStringLiteral("check box \"%1\": %2 px in %3").arg(box->text()).arg(box->sizeHint().width())
                       .arg(box->width());
    }
    for (QAbstractSpinBox* spin : root->findChildren<QAbstractSpinBox*>()) {
        if (!spin->isVisibleTo(root))
            continue;
        QLineEdit* edit = spin->findChild<QLineEdit*>();
        if (!edit)
            continue;
        const int need = edit->fontMetrics().horizontalAdvance(edit->text());
        if (need > edit->contentsRect().width())
            cut << QStringLiteral("field %1 \"%2\": %3 px in %4").arg(spin->objectName(), edit->text()).arg(need)
                       .arg(edit->contentsRect().width());
    }
    return cut;
}

// The dock tabs under `root` whose name does not fit its tab ("Plots" and
// "Predict" both squeezed to "P…" tell a student nothing).
QStringList cutTabs(QWidget* root)
{
    QStringList cut;
    for (QTabBar* bar : root->findChildren<QTabBar*>()) {
        if (!bar->isVisibleTo(root))
            continue;
        for (int i = 0; i < bar->count(); ++i) {
            // The name and the style's padding around it (below that the
            // style elides the name).
            const int need = bar->fontMetrics().horizontalAdvance(bar->tabText(i)) +
                             bar->style()->pixelMetric(QStyle::PM_TabBarTabHSpace, nullptr, bar);
            if (need > bar->tabRect(i).width())
                cut << QStringLiteral("tab \"%1\": %2 px in %3").arg(bar->tabText(i)).arg(need).arg(bar->tabRect(i).width());
        }
    }
    return cut;
}

} // namespace

class GuiLayoutTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void nothingIsCut_data();
    void nothingIsCut();
};

void GuiLayoutTest::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
}

void GuiLayoutTest::nothingIsCut_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<QSize>("size");
    QTest::addColumn<QString>("language");
    // In every shipped language: German's long words are the test of a layout.
    for (const Language& language : shippedLanguages())
        for (const char* lesson : {"gravity", "smoother-wind", "break-shot", "two-bodies-in-orbit"})
            for (const QSize size : {QSize(1280, 720), QSize(1024, 768)})
                QTest::newRow(qPrintable(QStringLiteral("%1 %2x%3 %4")
                                             .arg(lesson)
                                             .arg(size.width())
                                             .arg(size.height())
                                             .arg(language.code)))
                    << QString::fromLatin1(lesson) << size << language.code;
}

void GuiLayoutTest::nothingIsCut()
{
    QFETCH(QString, lesson);
    QFETCH(QSize, size);
    QFETCH(QString, language);
    QSettings().clear();
    QVERIFY(applyLanguage(language));
    const auto english = qScopeGuard([] { applyLanguage(QStringLiteral("en")); });
    MainWindow window(lesson);
    window.resize(size);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTRY_COMPARE(window.size(), size);
    window.parameterPanel()->setShowAll(true);
    // Each tab of the right column in turn: the Parameters, then the rest.
    for (QDockWidget* dock : window.findChildren<QDockWidget*>()) {
        if (dock->objectName() == QStringLiteral("accuracyDock"))
            continue; // closed at first
        dock->show();
        dock->raise();
        QVERIFY2(test::waitForSettledLayout(&window), qPrintable(dock->objectName()));
        const QStringList cut = cutTexts(dock);
        QVERIFY2(cut.isEmpty(), qPrintable(dock->objectName() + QStringLiteral(": ") + cut.join(QStringLiteral("; "))));
    }
    const QStringList tabs = cutTabs(&window);
    QVERIFY2(tabs.isEmpty(), qPrintable(tabs.join(QStringLiteral("; "))));
}

QTEST_MAIN(GuiLayoutTest)
#include "test_gui_layout.moc"
