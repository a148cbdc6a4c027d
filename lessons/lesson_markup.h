#pragma once
// The markup a lesson's words may use: a small part of HTML that cannot
// reach anything outside the lesson. A lesson file comes from a stranger,
// and Qt's rich text would otherwise open any path or URL an <img>, a link
// or a style names (/dev/zero, a FIFO, /etc/passwd, a web address).
//
// Allowed: <p> <br> <b> <i> <em> <strong> <u> <sub> <sup> <code> <ul> <ol>
// <li>, the entities &lt; &gt; &amp; &quot; &apos; &nbsp; and &#N; / &#xN;,
// <img src="NAME" alt="…"> where NAME is a picture in the lesson's own
// folder (or beside a built-in lesson), and <a href="https://…">. Nothing
// else: no other tag or attribute, no style, no file or data URL. A "<" that
// does not start a tag ("k·dt < 2") is text.

#include <QString>
#include <QStringList>

#include <optional>

namespace forcelab::lessons {

inline constexpr qsizetype kMaxTextChars = 20000;  ///< the teaching text, characters (the longest shipped: about 1,900)
inline constexpr qsizetype kMaxProseChars = 2000;  ///< a title, challenge, question, choice, answer or note, characters
inline constexpr int kMaxImagesPerText = 8;        ///< pictures in one text
inline constexpr qint64 kMaxImageBytes = 4 << 20;  ///< one picture file, bytes
inline constexpr int kMaxImageSide = 2048;         ///< one picture's width or height, px

/// What is wrong with a text, and where: `at` is the 0-based character in
/// the string (as the file's editor counts within the value).
struct MarkupProblem {
    qsizetype at = 0;
    QString message;
};

/// The first thing in `text` the subset does not allow, or that is over
/// `maxChars` characters; nullopt when it is all allowed.
std::optional<MarkupProblem> checkMarkup(const QString& text, qsizetype maxChars);

/// Whether `name` is a picture name the subset allows: relative, inside the
/// lesson's folder (no "..", no leading "/", no scheme), ending in .png,
/// .jpg or .jpeg, of letters, digits, ".", "_", "-" and "/".
bool isAllowedImageName(const QString& name);

/// `text` as HTML in which only the subset's tags and entities remain;
/// anything else is shown as the characters it was written with. Plain text
/// (no allowed tag) becomes paragraphs at blank lines. With `images` false,
/// a picture becomes its alt text (for labels and exported pages, which
/// must not load files); links keep their text and lose their target when
/// `links` is false.
struct MarkupHtml {
    QString html;
    QStringList images; ///< the picture names, in order
};
MarkupHtml markupToHtml(const QString& text, bool images = true, bool links = true);

/// `text` without any markup: tags dropped, entities decoded (for a title
/// bar, a tooltip or a plain label).
QString markupToPlainText(const QString& text);

} // namespace forcelab::lessons
