#include "ui/docks/lesson_text_view.h"

#include "lessons/lesson_markup.h"

#include <QDesktopServices>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImageReader>
#include <QMessageBox>
#include <QRegularExpression>

namespace forcelab {

LessonTextView::LessonTextView(QWidget* parent)
    : QTextBrowser(parent)
{
    // Never follow a link inside the pane (a local path would be opened and
    // shown there), and never hand one to the system unasked.
    setOpenLinks(false);
    setOpenExternalLinks(false);
    connect(this, &QTextBrowser::anchorClicked, this, &LessonTextView::linkClicked);
    m_confirm = [this](const QUrl& url) {
        return QMessageBox::question(this, tr("Open a web page?"),
                                     tr("The lesson links to\n%1\n\nOpen it in your web browser?")
                                         .arg(url.toDisplayString())) == QMessageBox::Yes;
    };
    m_open = [](const QUrl& url) { QDesktopServices::openUrl(url); };
}

QImage LessonTextView::loadLessonImage(const QString& folder, const QString& name, QString* why)
{
    auto refuse = [why, &name](const QString& reason) {
        if (why)
            *why = QStringLiteral("%1: %2").arg(name, reason);
        return QImage();
    };
    if (!lessons::isAllowedImageName(name))
        return refuse(QStringLiteral("not a picture name of the lesson's folder"));
    const QString path = QDir(folder).filePath(name);
    const QFileInfo info(path);
    // Only a regular file inside the folder: not a device, a FIFO or a link
    // that leads out of it.
    if (!info.exists())
        return refuse(QStringLiteral("not in the lesson's folder"));
    if (!folder.startsWith(QLatin1Char(':'))) {
        const QString inside = QFileInfo(folder).canonicalFilePath() + QLatin1Char('/');
        if (info.isSymLink() || !info.canonicalFilePath().startsWith(inside))
            return refuse(QStringLiteral("leads out of the lesson's folder"));
    }
    if (!info.isFile())
        return refuse(QStringLiteral("not a file"));
    if (info.size() > lessons::kMaxImageBytes)
        return refuse(QStringLiteral("%1 bytes is more than the limit of %2").arg(info.size()).arg(lessons::kMaxImageBytes));
    QImageReader reader(path);
    const QSize size = reader.size();
    if (!size.isValid() || size.width() > lessons::kMaxImageSide || size.height() > lessons::kMaxImageSide)
        return refuse(size.isValid() ? QStringLiteral("%1 x %2 px is larger than %3 x %3 px")
                                           .arg(size.width())
                                           .arg(size.height())
                                           .arg(lessons::kMaxImageSide)
                                     : QStringLiteral("not a picture this program reads"));
    QImage image = reader.read();
    if (image.isNull())
        return refuse(reader.errorString());
    return image;
}

void LessonTextView::showLesson(const QString& html, const QStringList& images, const QString& folder)
{
    m_images.clear();
    QString shown = html;
    for (const QString& name : images) {
        if (m_images.contains(name))
            continue;
        QString why;
        const QImage image = loadLessonImage(folder, name, &why);
        if (!image.isNull())
            m_images.insert(name, image);
        else // say what is wrong where the picture would be, and leave no <img> for Qt to load by itself
            shown.replace(QRegularExpression(QStringLiteral("<img src=\"%1\" alt=\"[^\"]*\">")
                                                 .arg(QRegularExpression::escape(name.toHtmlEscaped()))),
                          QStringLiteral("<i>[%1]</i>").arg(why.toHtmlEscaped()));
    }
    setHtml(shown);
}

QVariant LessonTextView::loadResource(int type, const QUrl& name)
{
    // Only the lesson's own pictures, read already; never a file, a
    // stylesheet or a page that Qt would otherwise fetch by its name.
    if (type == QTextDocument::ImageResource) {
        const auto it = m_images.constFind(name.toString());
        if (it != m_images.constEnd())
            return *it;
        // Not null: for a null answer Qt's image handler loads the name as
        // a file path itself.
        QImage nothing(1, 1, QImage::Format_ARGB32);
        nothing.fill(Qt::transparent);
        return nothing;
    }
    return QByteArray();
}

void LessonTextView::linkClicked(const QUrl& url)
{
    const QString scheme = url.scheme().toLower();
    if ((scheme != QLatin1String("https") && scheme != QLatin1String("http")) || url.host().isEmpty())
        return; // never a local path, whatever the text says
    if (m_confirm && m_confirm(url) && m_open)
        m_open(url);
}

} // namespace forcelab
