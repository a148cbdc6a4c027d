#pragma once
// File > Save Scene as Lesson…: asks for the new lesson's title, its text,
// whether to keep the teacher notes, and the file. The lesson itself is
// made by lessons::deriveLesson (lessons/lesson_derive.h), which keeps only
// the claims and questions that still hold on the scene.

#include "lessons/lesson.h"
#include "lessons/lesson_derive.h"

#include <QDialog>
#include <QString>

#include <functional>

class QCheckBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;

namespace forcelab {

class SaveLessonDialog : public QDialog {
    Q_OBJECT
public:
    /// `from` is the lesson on screen; `suggestedPath` the file offered first.
    SaveLessonDialog(const Lesson& from, const QString& suggestedPath, QWidget* parent = nullptr);

    /// The title, text and teacher-notes choice, the file's name as the wished id.
    lessons::DeriveChoices choices() const;
    /// The file to write, with ".json" added when it has no suffix.
    QString path() const;

    /// What "Choose…" asks for a file name with (a save-file dialog unless
    /// replaced, e.g. by a test); an empty answer keeps the file as it is.
    using FileChooser = std::function<QString(QWidget* parent, const QString& suggested)>;
    void setFileChooser(FileChooser chooser) { m_chooser = std::move(chooser); }

private:
    void chooseFile();
    void updateState();

    Lesson m_from;
    QLineEdit* m_title = nullptr;
    QPlainTextEdit* m_text = nullptr;
    QCheckBox* m_keepNotes = nullptr;
    QLineEdit* m_file = nullptr;
    QLabel* m_problem = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
    FileChooser m_chooser;
};

} // namespace forcelab
