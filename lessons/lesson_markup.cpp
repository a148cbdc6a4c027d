#include "lesson_markup.h"

#include <QRegularExpression>

#include <functional>

namespace forcelab::lessons {

namespace {

// Tags that carry no attribute at all.
bool isPlainTag(const QString& name)
{
    static const QStringList tags{QStringLiteral("p"),  QStringLiteral("br"),     QStringLiteral("b"),
                                  QStringLiteral("i"),  QStringLiteral("em"),     QStringLiteral("strong"),
                                  QStringLiteral("u"),  QStringLiteral("sub"),    QStringLiteral("sup"),
                                  QStringLiteral("code"), QStringLiteral("ul"),   QStringLiteral("ol"),
                                  QStringLiteral("li")};
    return tags.contains(name);
}

bool isVoidTag(const QString& name)
{
    return name == QLatin1String("br") || name == QLatin1String("img");
}

QString allowedTagsText()
{
    return QStringLiteral("<p> <br> <b> <i> <em> <strong> <u> <sub> <sup> <code> <ul> <ol> <li> <img src> <a href>");
}

struct Attribute {
    QString name;
    QString value;
    qsizetype at = 0;
};

struct Tag {
    qsizetype begin = 0, end = 0; // text[begin] is '<', text[end - 1] is '>'
    QString name;                 // lower case
    bool closing = false;
    QList<Attribute> attributes;

    QString value(const char* attribute) const
    {
        for (const Attribute& a : attributes)
            if (a.name == QLatin1String(attribute))
                return a.value;
        return {};
    }
};

bool isAsciiLetter(QChar c)
{
    return (c >= QLatin1Char('a') && c <= QLatin1Char('z')) || (c >= QLatin1Char('A') && c <= QLatin1Char('Z'));
}

bool isAsciiDigit(QChar c)
{
    return c >= QLatin1Char('0') && c <= QLatin1Char('9');
}

enum class Scan { NotATag, Tag, Malformed };

// Reads the tag that starts at s[i] == '<'. A '<' followed by anything but a
// letter, or '/' and a letter, is not a tag ("dt < 2"); one that starts a tag
// and does not end it well is Malformed, with `problem` set.
Scan scanTag(const QString& s, qsizetype i, Tag& tag, MarkupProblem& problem)
{
    qsizetype k = i + 1;
    tag = Tag{};
    tag.begin = i;
    if (k < s.size() && s[k] == QLatin1Char('/')) {
        tag.closing = true;
        ++k;
    }
    if (k >= s.size() || !isAsciiLetter(s[k]))
        return Scan::NotATag;
    const qsizetype nameStart = k;
    while (k < s.size() && (isAsciiLetter(s[k]) || isAsciiDigit(s[k])))
        ++k;
    tag.name = s.mid(nameStart, k - nameStart).toLower();
    auto malformed = [&](qsizetype at, const QString& message) {
        problem = {at, message};
        return Scan::Malformed;
    };
    for (;;) {
        while (k < s.size() && s[k].isSpace())
            ++k;
        if (k >= s.size())
            return malformed(i, QStringLiteral("<%1 has no closing >").arg(tag.name));
        if (s[k] == QLatin1Char('>')) {
            tag.end = k + 1;
            return Scan::Tag;
        }
        if (s[k] == QLatin1Char('/') && k + 1 < s.size() && s[k + 1] == QLatin1Char('>')) {
            tag.end = k + 2;
            return Scan::Tag;
        }
        if (!isAsciiLetter(s[k]))
            return malformed(k, QStringLiteral("'%1' inside the tag <%2>").arg(s[k]).arg(tag.name));
        Attribute a;
        a.at = k;
        const qsizetype attrStart = k;
        while (k < s.size() && (isAsciiLetter(s[k]) || s[k] == QLatin1Char('-')))
            ++k;
        a.name = s.mid(attrStart, k - attrStart).toLower();
        while (k < s.size() && s[k].isSpace())
            ++k;
        if (k < s.size() && s[k] == QLatin1Char('=')) {
            ++k;
            while (k < s.size() && s[k].isSpace())
                ++k;
            if (k < s.size() && (s[k] == QLatin1Char('"') || s[k] == QLatin1Char('\''))) {
                const QChar quote = s[k];
                const qsizetype close = s.indexOf(quote, k + 1);
                if (close < 0)
                    return malformed(k, QStringLiteral("the value of %1 has no closing quote").arg(a.name));
                a.value = s.mid(k + 1, close - k - 1);
                k = close + 1;
            } else {
                const qsizetype valueStart = k;
                while (k < s.size() && !s[k].isSpace() && s[k] != QLatin1Char('>'))
                    ++k;
                a.value = s.mid(valueStart, k - valueStart);
            }
        }
        tag.attributes << a;
    }
}

// The entity that starts at s[i] == '&' and the character(s) it stands for,
// or 0 characters long when it is not one the subset knows (then the '&'
// is text).
struct Entity {
    qsizetype length = 0;
    QString decoded;
};

Entity scanEntity(const QString& s, qsizetype i)
{
    static const QRegularExpression re(QStringLiteral("\\G&(?:([a-zA-Z]{2,6})|#([0-9]{1,7})|#[xX]([0-9a-fA-F]{1,6}));"));
    const QRegularExpressionMatch m = re.match(s, i);
    if (!m.hasMatch())
        return {};
    const qsizetype length = m.capturedLength();
    if (m.capturedLength(1) > 0) {
        static const QList<QPair<QString, QString>> named{
            {QStringLiteral("lt"), QStringLiteral("<")},   {QStringLiteral("gt"), QStringLiteral(">")},
            {QStringLiteral("amp"), QStringLiteral("&")},  {QStringLiteral("quot"), QStringLiteral("\"")},
            {QStringLiteral("apos"), QStringLiteral("'")}, {QStringLiteral("nbsp"), QString(QChar(0x00a0))}};
        for (const auto& [name, text] : named)
            if (m.captured(1) == name)
                return {length, text};
        return {};
    }
    bool ok = false;
    const uint code = m.capturedLength(2) > 0 ? m.captured(2).toUInt(&ok, 10) : m.captured(3).toUInt(&ok, 16);
    // Printable characters only: no NUL or control character, no half of a
    // surrogate pair, nothing past the last code point.
    if (!ok || code < 0x20 || (code >= 0x7f && code < 0xa0) || (code >= 0xd800 && code < 0xe000) || code > 0x10ffff)
        return {};
    const char32_t c = code;
    return {length, QString::fromUcs4(&c, 1)};
}

// Walks `s` as text runs, entities and tags; a '<' that is not a tag, or a
// malformed one, arrives as text.
struct Walker {
    std::function<void(const QString&)> text;
    std::function<void(const QString&)> entity; // the decoded character(s)
    std::function<void(const Tag&)> tag;
    std::function<void(const MarkupProblem&)> malformed;
};

void walk(const QString& s, const Walker& w)
{
    qsizetype i = 0, run = 0;
    auto flush = [&](qsizetype to) {
        if (to > run && w.text)
            w.text(s.mid(run, to - run));
    };
    while (i < s.size()) {
        if (s[i] == QLatin1Char('<')) {
            Tag tag;
            MarkupProblem problem;
            const Scan scan = scanTag(s, i, tag, problem);
            if (scan == Scan::Tag) {
                flush(i);
                if (w.tag)
                    w.tag(tag);
                i = run = tag.end;
                continue;
            }
            if (scan == Scan::Malformed && w.malformed)
                w.malformed(problem);
        } else if (s[i] == QLatin1Char('&')) {
            const Entity e = scanEntity(s, i);
            if (e.length > 0) {
                flush(i);
                if (w.entity)
                    w.entity(e.decoded);
                i = run = i + e.length;
                continue;
            }
        }
        ++i;
    }
    flush(s.size());
}

bool isAllowedLink(const QString& href)
{
    static const QRegularExpression re(QStringLiteral("^https?://[A-Za-z0-9.-]+(:[0-9]{1,5})?(/[^\\s\"'<>\\\\]*)?$"),
                                       QRegularExpression::CaseInsensitiveOption);
    return re.match(href).hasMatch();
}

// The first character that is no text at all: NUL (which ends the string
// for much of the system: a window title showed "a" for "a\u0000b"), or
// half of a surrogate pair (no character; shown as "?").
std::optional<qsizetype> firstUnprintable(const QString& s)
{
    for (qsizetype i = 0; i < s.size(); ++i) {
        const QChar c = s[i];
        if (c.isHighSurrogate() && i + 1 < s.size() && s[i + 1].isLowSurrogate()) {
            ++i;
            continue;
        }
        if (c.isSurrogate() || c.unicode() == 0)
            return i;
    }
    return std::nullopt;
}

bool hasAllowedTag(const QString& text)
{
    bool found = false;
    walk(text, {{}, {}, [&](const Tag& t) {
                    if (isPlainTag(t.name) || t.name == QLatin1String("img") || t.name == QLatin1String("a"))
                        found = true;
                }, {}});
    return found;
}

} // namespace

bool isAllowedImageName(const QString& name)
{
    static const QRegularExpression re(QStringLiteral("^[A-Za-z0-9_-][A-Za-z0-9._/-]{0,199}\\.(png|jpg|jpeg)$"),
                                       QRegularExpression::CaseInsensitiveOption);
    if (!re.match(name).hasMatch())
        return false;
    for (const QString& part : name.split(QLatin1Char('/')))
        if (part.isEmpty() || part == QLatin1String(".") || part == QLatin1String(".."))
            return false;
    return true;
}

std::optional<MarkupProblem> checkMarkup(const QString& text, qsizetype maxChars)
{
    if (text.size() > maxChars)
        return MarkupProblem{maxChars, QStringLiteral("%1 characters is more than the limit of %2")
                                           .arg(text.size())
                                           .arg(maxChars)};
    if (const auto at = firstUnprintable(text))
        return MarkupProblem{*at, text[*at].isSurrogate()
                                      ? QStringLiteral("half of a surrogate pair (U+%1), which is no character")
                                            .arg(QString::number(text[*at].unicode(), 16).toUpper())
                                      : QStringLiteral("a NUL character (U+0000), which is not text")};
    std::optional<MarkupProblem> first;
    int images = 0;
    auto fail = [&](qsizetype at, const QString& message) {
        if (!first)
            first = MarkupProblem{at, message};
    };
    Walker w;
    w.malformed = [&](const MarkupProblem& p) { fail(p.at, p.message); };
    w.tag = [&](const Tag& t) {
        const bool image = t.name == QLatin1String("img"), link = t.name == QLatin1String("a");
        if (!isPlainTag(t.name) && !image && !link) {
            fail(t.begin, QStringLiteral("<%1> is not allowed in lesson text (allowed: %2)")
                              .arg(t.name, allowedTagsText()));
            return;
        }
        if (t.closing)
            return;
        for (const Attribute& a : t.attributes) {
            const bool known = (image && (a.name == QLatin1String("src") || a.name == QLatin1String("alt"))) ||
                               (link && a.name == QLatin1String("href"));
            if (!known) {
                fail(a.at, isPlainTag(t.name)
                               ? QStringLiteral("<%1> takes no attributes (%2=…)").arg(t.name, a.name)
                               : QStringLiteral("<%1> takes only %2, not %3=…")
                                     .arg(t.name, image ? QStringLiteral("src and alt") : QStringLiteral("href"), a.name));
                return;
            }
        }
        if (image) {
            const QString src = t.value("src");
            if (src.isEmpty())
                fail(t.begin, QStringLiteral("<img> needs src=\"NAME.png\", a picture in the lesson's folder"));
            else if (!isAllowedImageName(src))
                fail(t.begin, QStringLiteral("<img src=\"%1\">: a picture comes only from the lesson's own folder, "
                                             "by a name such as \"pictures/orbit.png\" (no path, no URL)")
                                  .arg(src.left(60)));
            else if (++images > kMaxImagesPerText)
                fail(t.begin, QStringLiteral("more than %1 pictures in one text").arg(kMaxImagesPerText));
        }
        if (link && !isAllowedLink(t.value("href")))
            fail(t.begin, QStringLiteral("<a href=\"%1\">: a link may only go to a web page (https://…)")
                              .arg(t.value("href").left(60)));
    };
    walk(text, w);
    return first;
}

MarkupHtml markupToHtml(const QString& text, bool images, bool links)
{
    MarkupHtml out;
    if (!hasAllowedTag(text)) {
        for (const QString& paragraph : text.split(QStringLiteral("\n\n"), Qt::SkipEmptyParts))
            out.html += QStringLiteral("<p>%1</p>").arg(paragraph.toHtmlEscaped());
        return out;
    }
    int openLinks = 0; // <a> written and not yet closed
    Walker w;
    w.text = [&](const QString& run) { out.html += run.toHtmlEscaped(); };
    w.entity = [&](const QString& decoded) { out.html += decoded.toHtmlEscaped(); };
    w.tag = [&](const Tag& t) {
        const QString raw = text.mid(t.begin, t.end - t.begin);
        if (isPlainTag(t.name) && t.attributes.isEmpty()) {
            if (t.closing && isVoidTag(t.name))
                return;
            out.html += t.closing ? QStringLiteral("</%1>").arg(t.name) : QStringLiteral("<%1>").arg(t.name);
        } else if (t.name == QLatin1String("img") && !t.closing) {
            const QString src = t.value("src"), alt = t.value("alt");
            if (images && isAllowedImageName(src) && out.images.size() < kMaxImagesPerText) {
                out.images << src;
                out.html += QStringLiteral("<img src=\"%1\" alt=\"%2\">").arg(src.toHtmlEscaped(), alt.toHtmlEscaped());
            } else {
                out.html += QStringLiteral("[%1]").arg((alt.isEmpty() ? src : alt).toHtmlEscaped());
            }
        } else if (t.name == QLatin1String("a")) {
            if (t.closing) {
                if (openLinks > 0) {
                    --openLinks;
                    out.html += QStringLiteral("</a>");
                }
            } else if (links && isAllowedLink(t.value("href"))) {
                ++openLinks;
                out.html += QStringLiteral("<a href=\"%1\">").arg(t.value("href").toHtmlEscaped());
            }
        } else if (!(t.closing && t.name == QLatin1String("img"))) {
            out.html += raw.toHtmlEscaped(); // not in the subset: shown as written
        }
    };
    walk(text, w);
    while (openLinks-- > 0)
        out.html += QStringLiteral("</a>");
    return out;
}

QString markupToPlainText(const QString& text)
{
    QString out;
    Walker w;
    w.text = [&](const QString& run) { out += run; };
    w.entity = [&](const QString& decoded) { out += decoded; };
    w.tag = [&](const Tag& t) {
        if (t.name == QLatin1String("img") && !t.closing)
            out += t.value("alt");
        else if (t.name == QLatin1String("br") || (t.name == QLatin1String("p") && t.closing))
            out += QLatin1Char('\n');
        else if (!isPlainTag(t.name) && t.name != QLatin1String("a") && t.name != QLatin1String("img"))
            out += text.mid(t.begin, t.end - t.begin);
    };
    walk(text, w);
    return out.trimmed();
}

} // namespace forcelab::lessons
