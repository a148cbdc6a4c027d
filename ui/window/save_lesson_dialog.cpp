#include "ui/window/save_lesson_dialog.h"

#include "lessons/lesson_markup.h"
#include "lessons/sentence_check.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace forcelab {

SaveLessonDialog::SaveLessonDialog(const Lesson& from, const QString& suggestedPath, QWidget* parent)
    : QDialog(parent), m_from(from)
{
    setObjectName(QStringLiteral("saveLessonDialog"));
    setWindowTitle(tr("Save Scene as Lesson"));
    const lessons::DeriveChoices start = lessons::defaultDeriveChoices(from);

    auto* intro = new QLabel(tr("The scene is saved as a new lesson with your title and text. Of the claims and "
                                "questions of “%1”, only those that still hold in this scene are kept; the "
                                "others are listed after saving.")
                                 .arg(lessons::markupToPlainText(from.title)),
                             this);
    intro->setTextFormat(Qt::PlainText);
    intro->setWordWrap(true);

    m_title = new QLineEdit(start.title, this);
    m_title->setObjectName(QStringLiteral("lessonTitleEdit"));
    m_text = new QPlainTextEdit(start.text, this);
    m_text->setObjectName(QStringLiteral("lessonTextEdit"));
    m_text->setTabChangesFocus(true); // Tab moves on, as in every other field
    m_text->setToolTip(tr("Plain text; an empty line starts a new paragraph."));
    m_keepNotes = new QCheckBox(tr("&Keep the teacher notes"), this);
    m_keepNotes->setObjectName(QStringLiteral("keepTeacherNotesCheck"));
    m_keepNotes->setEnabled(!from.teacher.goal.isEmpty() || from.teacher.minutes > 0 ||
                            !from.teacher.misconceptions.isEmpty());
    m_keepNotes->setToolTip(tr("The goal, the minutes and the misconceptions. The answers to the challenges are "
                               "never kept: the new lesson has no challenges."));
    m_file = new QLineEdit(QDir::toNativeSeparators(suggestedPath), this);
    m_file->setObjectName(QStringLiteral("lessonFileEdit"));
    auto* choose = new QPushButton(tr("C&hoose…"), this);
    choose->setObjectName(QStringLiteral("chooseLessonFileButton"));
    choose->setAutoDefault(false);
    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(m_file, 1);
    fileRow->addWidget(choose);

    m_problem = new QLabel(this);
    m_problem->setObjectName(QStringLiteral("saveLessonProblemLabel"));
    m_problem->setWordWrap(true);
    m_problem->setTextFormat(Qt::PlainText);

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel, this);
    m_buttons->setObjectName(QStringLiteral("saveLessonButtons"));

    auto* form = new QFormLayout;
    auto* titleLabel = new QLabel(tr("&Title:"), this);
    titleLabel->setBuddy(m_title);
    auto* textLabel = new QLabel(tr("Te&xt:"), this);
    textLabel->setBuddy(m_text);
    auto* fileLabel = new QLabel(tr("&File:"), this);
    fileLabel->setBuddy(m_file);
    form->addRow(titleLabel, m_title);
    form->addRow(textLabel, m_text);
    form->addRow(QString(), m_keepNotes);
    form->addRow(fileLabel, fileRow);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    layout->addWidget(m_buttons);

    m_chooser = [](QWidget* parent, const QString& suggested) {
        return QFileDialog::getSaveFileName(parent, tr("Save Scene as Lesson"), suggested, tr("Lesson files (*.json)"));
    };
    connect(choose, &QPushButton::clicked, this, &SaveLessonDialog::chooseFile);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_title, &QLineEdit::textChanged, this, &SaveLessonDialog::updateState);
    connect(m_text, &QPlainTextEdit::textChanged, this, &SaveLessonDialog::updateState);
    connect(m_file, &QLineEdit::textChanged, this, &SaveLessonDialog::updateState);
    updateState();
    m_title->selectAll();
    m_title->setFocus();
}

lessons::DeriveChoices SaveLessonDialog::choices() const
{
    lessons::DeriveChoices c;
    c.title = m_title->text().simplified();
    c.text = m_text->toPlainText();
    c.keepTeacherNotes = m_keepNotes->isEnabled() && m_keepNotes->isChecked();
    c.ids = {QFileInfo(path()).completeBaseName()};
    return c;
}

QString SaveLessonDialog::path() const
{
    QString p = QDir::fromNativeSeparators(m_file->text().trimmed());
    if (!p.isEmpty() && QFileInfo(p).suffix().isEmpty())
        p += QStringLiteral(".json");
    return p;
}

void SaveLessonDialog::chooseFile()
{
    const QString chosen = m_chooser ? m_chooser(this, path()) : QString();
    if (!chosen.isEmpty())
        m_file->setText(QDir::toNativeSeparators(chosen));
}

void SaveLessonDialog::updateState()
{
    QString problem;
    if (m_title->text().trimmed().isEmpty())
        problem = tr("The lesson needs a title.");
    else if (const QStringList s = lessons::unmeasuredSentences(m_from, m_text->toPlainText()); !s.isEmpty())
        problem = tr("“%1” has a number or a comparison (“%2”) that nothing measures on this scene, and a lesson "
                     "must not say what it does not check. Write it without, or add a claim to the file later.")
                      .arg(s.front(), lessons::numberOrComparison(s.front(), m_from.language));
    else if (path().isEmpty())
        problem = tr("Choose the file to save to.");
    m_problem->setText(problem);
    m_problem->setVisible(!problem.isEmpty());
    m_buttons->button(QDialogButtonBox::Save)->setEnabled(problem.isEmpty());
}

} // namespace forcelab
