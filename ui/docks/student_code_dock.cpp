#include "ui/docks/student_code_dock.h"

#include "ui/canvas/simulation_controller.h"
#include "ui/drawing/display_units.h"
#include "ui/script/script_pieces.h"

#include <QComboBox>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QKeySequence>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QShortcut>
#include <QTextBlock>
#include <QVBoxLayout>

namespace forcelab {

namespace {

const QString kSettingsGroup = QStringLiteral("studentCode");

} // namespace

StudentCodeDock::StudentCodeDock(SimulationController* controller, QWidget* parent)
    : QDockWidget(tr("Your Code"), parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("studentCodeDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);

    auto* fileRow = new QHBoxLayout;
    auto* fileLabel = new QLabel(tr("Rewrite:"), body);
    m_files = new QComboBox(body);
    m_files->setAccessibleName(tr("JavaScript file to rewrite"));
    m_files->setToolTip(tr("The stage's code, one file per rule. Pick one and write your own version."));
    fileLabel->setBuddy(m_files);
    fileRow->addWidget(fileLabel);
    fileRow->addWidget(m_files, 1);
    layout->addLayout(fileRow);

    m_editor = new QPlainTextEdit(body);
    m_editor->setAccessibleName(tr("Your JavaScript"));
    m_editor->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_editor->setTabChangesFocus(true); // Tab leaves the editor; the code is indented with spaces
    QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    mono.setPointSizeF(std::max(12.0, mono.pointSizeF()));
    m_editor->setFont(mono);
    layout->addWidget(m_editor, 1);

    // Two rows, so the panel stays as narrow as the others beside the canvas.
    auto* buttons = new QHBoxLayout;
    auto* more = new QHBoxLayout;
    m_run = new QPushButton(tr("Run beside the reference"), body);
    m_run->setToolTip(tr("Runs your version in place of the course's, beside the reference (Ctrl+Return)"));
    m_stop = new QPushButton(tr("Stop"), body);
    m_stop->setToolTip(tr("Takes your code off the canvas"));
    m_revert = new QPushButton(tr("Back to the course's file"), body);
    m_revert->setToolTip(tr("Throws away your changes to this file"));
    buttons->addWidget(m_run, 1);
    buttons->addWidget(m_stop);
    more->addStretch(1);
    more->addWidget(m_revert);
    layout->addLayout(buttons);
    layout->addLayout(more);

    m_status = new QLabel(body);
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont statusFont = m_status->font();
    statusFont.setPointSizeF(std::max(12.0, statusFont.pointSizeF()));
    m_status->setFont(statusFont);
    layout->addWidget(m_status);
    setWidget(body);

    connect(m_files, &QComboBox::currentIndexChanged, this, [this] { chooseFile(currentFile()); });
    connect(m_editor, &QPlainTextEdit::textChanged, this, &StudentCodeDock::textEdited);
    connect(m_run, &QPushButton::clicked, this, &StudentCodeDock::run);
    connect(m_stop, &QPushButton::clicked, this, &StudentCodeDock::stop);
    connect(m_revert, &QPushButton::clicked, this, &StudentCodeDock::revertFile);
    auto* runKey = new QShortcut(QKeySequence(Qt::CTRL | Qt::Key_Return), m_editor);
    runKey->setContext(Qt::WidgetShortcut);
    connect(runKey, &QShortcut::activated, this, &StudentCodeDock::run);
    connect(m_controller, &SimulationController::sceneChanged, this, &StudentCodeDock::refreshFiles);
    connect(m_controller, &SimulationController::settingsChanged, this, &StudentCodeDock::refreshFiles);
    connect(m_controller, &SimulationController::studentRunChanged, this, &StudentCodeDock::refreshStatus);
    connect(m_controller, &SimulationController::stepped, this, [this] {
        if (m_controller->studentRun() && isVisible())
            refreshStatus();
    });
    refreshFiles();
    refreshStatus();
}

QStringList StudentCodeDock::files() const
{
    return scriptPiecesFor(m_controller->world().settings(), m_controller->spawn()).files;
}

QString StudentCodeDock::currentFile() const
{
    return m_files->currentData().toString();
}

void StudentCodeDock::setLesson(const Lesson& lesson)
{
    m_controller->stopStudentCode();
    if (!m_lessonId.isEmpty())
        m_byLesson.insert(m_lessonId, m_edits);
    m_lessonId = lesson.id;
    if (!lesson.studentCode.isEmpty()) {
        m_edits = lesson.studentCode; // a saved lesson brings the code it was saved with
    } else if (m_byLesson.contains(m_lessonId)) {
        m_edits = m_byLesson.value(m_lessonId);
    } else {
        m_edits.clear();
        QSettings settings;
        settings.beginGroup(kSettingsGroup);
        settings.beginGroup(m_lessonId);
        for (const QString& file : settings.childKeys())
            m_edits.insert(file, settings.value(file).toString());
    }
    refreshFiles();
    chooseFile(m_edits.isEmpty() ? currentFile() : m_edits.firstKey());
    refreshStatus();
}

// The files follow the settings (another integrator is another file); a
// file the student changed stays listed, marked, even when it is not run now.
void StudentCodeDock::refreshFiles()
{
    const QString current = currentFile();
    QStringList names = files();
    for (auto it = m_edits.cbegin(); it != m_edits.cend(); ++it)
        if (!names.contains(it.key()))
            names << it.key();
    QStringList shown;
    for (const QString& name : names)
        shown << (m_edits.contains(name) ? tr("%1 (yours)").arg(name) : name);
    bool same = m_files->count() == names.size();
    for (int i = 0; same && i < names.size(); ++i)
        same = m_files->itemData(i).toString() == names[i] && m_files->itemText(i) == shown[i];
    if (same)
        return;
    const QSignalBlocker block(m_files);
    m_files->clear();
    for (int i = 0; i < names.size(); ++i)
        m_files->addItem(shown[i], names[i]);
    // Open at the file students rewrite first: the update step.
    int index = m_files->findData(current);
    if (index < 0)
        for (int i = 0; i < names.size() && index < 0; ++i)
            if (names[i].startsWith(QStringLiteral("step_")))
                index = i;
    m_files->setCurrentIndex(std::max(0, index));
    if (currentFile() != current)
        chooseFile(currentFile());
}

void StudentCodeDock::chooseFile(const QString& file)
{
    if (file.isEmpty())
        return;
    const int index = m_files->findData(file);
    if (index >= 0 && index != m_files->currentIndex()) {
        const QSignalBlocker block(m_files);
        m_files->setCurrentIndex(index);
    }
    m_loading = true;
    m_editor->setPlainText(m_edits.contains(file) ? m_edits.value(file) : scriptPieceSource(file));
    m_editor->setExtraSelections({});
    m_loading = false;
}

void StudentCodeDock::textEdited()
{
    if (m_loading)
        return;
    const QString file = currentFile();
    if (file.isEmpty())
        return;
    const QString text = m_editor->toPlainText();
    const bool had = m_edits.contains(file);
    if (text == scriptPieceSource(file))
        m_edits.remove(file);
    else
        m_edits.insert(file, text);
    if (had != m_edits.contains(file)) {
        const int index = m_files->findData(file);
        m_files->setItemText(index, m_edits.contains(file) ? tr("%1 (yours)").arg(file) : file);
    }
    remember();
}

// Kept between sessions too (QSettings writes its file whole, to a temporary
// file first), so closing the program does not lose an hour's work.
void StudentCodeDock::remember()
{
    if (m_lessonId.isEmpty())
        return;
    m_byLesson.insert(m_lessonId, m_edits);
    QSettings settings;
    settings.beginGroup(kSettingsGroup);
    settings.remove(m_lessonId);
    settings.beginGroup(m_lessonId);
    for (auto it = m_edits.cbegin(); it != m_edits.cend(); ++it)
        settings.setValue(it.key(), it.value());
}

void StudentCodeDock::revertFile()
{
    const QString file = currentFile();
    m_edits.remove(file);
    chooseFile(file);
    refreshFiles();
    remember();
}

void StudentCodeDock::run()
{
    m_editor->setExtraSelections({});
    m_markedError.clear();
    m_controller->setStudentCode(m_edits);
    refreshStatus();
}

void StudentCodeDock::stop()
{
    m_controller->stopStudentCode();
    refreshStatus();
}

// The error's line in red, and the cursor on it (at its column when the
// engine gives one), when the error is in the file on screen; else the
// status line names the file.
void StudentCodeDock::markError(const ScriptError& error)
{
    if (error.file != currentFile() || error.line <= 0)
        return;
    const QTextBlock block = m_editor->document()->findBlockByNumber(error.line - 1);
    if (!block.isValid())
        return;
    QTextEdit::ExtraSelection mark;
    mark.format.setBackground(QColor(0xff, 0xd0, 0xd0));
    mark.format.setForeground(QColor(0x60, 0x00, 0x00));
    mark.format.setProperty(QTextFormat::FullWidthSelection, true);
    mark.cursor = QTextCursor(block);
    m_editor->setExtraSelections({mark});
    QTextCursor cursor(block);
    if (error.column > 0)
        cursor.movePosition(QTextCursor::Right, QTextCursor::MoveAnchor, std::min(error.column - 1, block.length() - 1));
    m_editor->setTextCursor(cursor);
    m_editor->centerCursor();
}

QString StudentCodeDock::statusText() const
{
    return m_status->text();
}

void StudentCodeDock::refreshStatus()
{
    const StudentRun* run = m_controller->studentRun();
    m_stop->setEnabled(run != nullptr);
    m_revert->setEnabled(m_edits.contains(currentFile()));
    QString text;
    QString colour = QStringLiteral("palette(window-text)");
    if (!run) {
        text = m_edits.isEmpty() ? tr("Change the code above, then press Run: your version runs beside the course's.")
                                 : tr("Your changes: %1. Press Run to see them beside the reference.")
                                       .arg(QStringList(m_edits.keys()).join(QStringLiteral(", ")));
    } else if (const auto& error = run->error()) {
        text = tr("Your code stopped. %1").arg(error->text());
        colour = QStringLiteral("#b01010");
        if (error->text() != m_markedError) { // once, not at every frame while the student types
            m_markedError = error->text();
            markError(*error);
        }
    } else if (const auto& d = run->departure(); d && d->ball < 0) {
        text = tr("Departs at step %1: your code has %2 balls, the reference %3.")
                   .arg(d->step).arg(d->student).arg(d->reference);
        colour = QStringLiteral("#b01010");
    } else if (d) {
        const QString unit = d->field.startsWith(QLatin1Char('v')) ? QStringLiteral("px/s") : QStringLiteral("px");
        text = tr("Departs at step %1 (t = %2 s), ball %3: %4 is %5 in your code and %6 in the reference, "
                  "%7 apart. Now the balls are up to %8 apart.")
                   .arg(d->step)
                   .arg(d->time, 0, 'g', 6)
                   .arg(d->ball)
                   .arg(d->field, QString::number(d->student, 'g', 17), QString::number(d->reference, 'g', 17),
                        quantityText(d->size(), unit, 3), quantityText(run->separation(), QStringLiteral("px"), 3));
        colour = QStringLiteral("#b01010");
    } else {
        text = tr("Agrees with the reference for all %1 steps so far (x, y, vx and vy to 9 significant digits).")
                   .arg(run->steps());
    }
    m_status->setText(text);
    m_status->setStyleSheet(QStringLiteral("color: %1;").arg(colour));
}

} // namespace forcelab
