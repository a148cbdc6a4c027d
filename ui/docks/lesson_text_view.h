#pragma once
// The lesson pane's text view: shows a lesson's words (in the markup subset
// of lessons/lesson_markup.h) and reaches nothing outside the lesson. A
// picture is served only from the lesson's own folder (or from beside a
// built-in lesson), by a name the subset allows, from a regular file that
// is small enough; any other resource Qt asks for is refused. A link opens
// a web page in the browser only after the reader confirms it; nothing is
// ever opened inside the pane.

#include <QHash>
#include <QImage>
#include <QTextBrowser>

#include <functional>

namespace forcelab {

class LessonTextView : public QTextBrowser {
    Q_OBJECT
public:
    explicit LessonTextView(QWidget* parent = nullptr);

    /// Shows `html` (already made safe by lessons::markupToHtml), whose
    /// pictures `images` are looked up in `folder` (a lesson's folder on disk,
    /// or ":/lessons" for a built-in one).
    void showLesson(const QString& html, const QStringList& images, const QString& folder);

    /// Asks the reader whether to open `url`; the default asks with a dialog.
    /// Tests put their own answer here.
    void setConfirmLink(std::function<bool(const QUrl&)> confirm) { m_confirm = std::move(confirm); }
    /// Opens `url` in the browser; the default is QDesktopServices. Tests
    /// record instead.
    void setOpenLink(std::function<void(const QUrl&)> open) { m_open = std::move(open); }

    /// A picture of the lesson's folder as the pane would show it, or a null
    /// image with the reason (missing, not a file, too large, not a picture).
    static QImage loadLessonImage(const QString& folder, const QString& name, QString* why = nullptr);

protected:
    QVariant loadResource(int type, const QUrl& name) override;

private:
    void linkClicked(const QUrl& url);

    QHash<QString, QImage> m_images; // name → picture, read when the lesson is shown
    std::function<bool(const QUrl&)> m_confirm;
    std::function<void(const QUrl&)> m_open;
};

} // namespace forcelab
