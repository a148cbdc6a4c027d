#include "ui/drawing/display_units.h"

#include "ui/drawing/human_number.h"

#include <QStringList>

#include <cmath>

namespace forcelab {

namespace {

// Recursive descent over "a·b/c", "(a·b)", "x²", "x^2", "x⁻¹": a product
// of factors, each an atom or a bracketed product with an optional power;
// "/" turns the factor after it (one atom or one bracket) upside down.
class UnitReader {
public:
    explicit UnitReader(const QString& text)
        : m_text(text)
    {
    }

    std::optional<UnitPowers> read()
    {
        skipSpaces();
        if (atEnd())
            return UnitPowers{};
        std::optional<UnitPowers> p = product();
        skipSpaces();
        if (!p || !atEnd())
            return std::nullopt;
        return p;
    }

private:
    bool atEnd() const { return m_at >= m_text.size(); }
    QChar peek() const { return atEnd() ? QChar() : m_text[m_at]; }
    void skipSpaces()
    {
        while (!atEnd() && peek().isSpace())
            ++m_at;
    }

    std::optional<UnitPowers> product()
    {
        std::optional<UnitPowers> total = factor();
        if (!total)
            return std::nullopt;
        for (;;) {
            skipSpaces();
            const QChar c = peek();
            const bool divide = c == u'/';
            if (!divide && c != u'·' && c != u'*' && c != u'⋅')
                return total;
            ++m_at;
            const std::optional<UnitPowers> next = factor();
            if (!next)
                return std::nullopt;
            const int sign = divide ? -1 : 1;
            total->px += sign * next->px;
            total->mass += sign * next->mass;
            total->s += sign * next->s;
            total->rad += sign * next->rad;
        }
    }

    std::optional<UnitPowers> factor()
    {
        skipSpaces();
        std::optional<UnitPowers> base;
        if (peek() == u'(') {
            ++m_at;
            base = product();
            skipSpaces();
            if (!base || peek() != u')')
                return std::nullopt;
            ++m_at;
        } else {
            base = atom();
            if (!base)
                return std::nullopt;
        }
        const int n = power();
        if (n == 0)
            return std::nullopt;
        return UnitPowers{base->px * n, base->mass * n, base->s * n, base->rad * n};
    }

    std::optional<UnitPowers> atom()
    {
        const qsizetype start = m_at;
        while (!atEnd() && (peek().isLetterOrNumber() && !isSuperscript(peek())))
            ++m_at;
        const QString name = m_text.mid(start, m_at - start);
        if (name == QLatin1String("px"))
            return UnitPowers{1, 0, 0, 0};
        if (name == QLatin1String("mass"))
            return UnitPowers{0, 1, 0, 0};
        if (name == QLatin1String("s"))
            return UnitPowers{0, 0, 1, 0};
        if (name == QLatin1String("Hz"))
            return UnitPowers{0, 0, -1, 0};
        if (name == QLatin1String("rad"))
            return UnitPowers{0, 0, 0, 1};
        if (name == QLatin1String("1"))
            return UnitPowers{};
        return std::nullopt;
    }

    static bool isSuperscript(QChar c)
    {
        return QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹⁻").contains(c);
    }

    // "²", "⁻¹", "^2", "^-1"; none: 1. 0 for a malformed power.
    int power()
    {
        static const QString supers = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
        int sign = 1;
        QString digits;
        if (peek() == u'^') {
            ++m_at;
            if (peek() == u'-') {
                sign = -1;
                ++m_at;
            }
            while (!atEnd() && peek().isDigit())
                digits += m_text[m_at++];
        } else if (isSuperscript(peek())) {
            if (peek() == u'⁻') {
                sign = -1;
                ++m_at;
            }
            while (!atEnd() && supers.contains(peek()))
                digits += QChar(static_cast<char16_t>(u'0' + supers.indexOf(m_text[m_at++])));
        } else {
            return 1;
        }
        bool ok = false;
        const int n = digits.toInt(&ok);
        return ok ? sign * n : 0;
    }

    const QString& m_text;
    qsizetype m_at = 0;
};

QString superscript(int n)
{
    static const QString supers = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
    if (n == 1)
        return {};
    QString out;
    for (const QChar c : QString::number(n))
        out += supers[c.digitValue()];
    return out;
}

// "kg·m²", or "(kg·s²)" in a denominator of more than one factor.
QString joined(const QStringList& parts, bool bracket)
{
    const QString text = parts.join(u'·');
    return bracket && parts.size() > 1 ? u'(' + text + u')' : text;
}

QString siText(const UnitPowers& p)
{
    // The named units where they apply; everything else as kg, m, s, rad.
    if (p.rad == 0 && p.mass == 1 && p.s == -2 && p.px == 1)
        return QStringLiteral("N");
    if (p.rad == 0 && p.mass == 1 && p.s == -2 && p.px == 2)
        return QStringLiteral("J");
    QStringList up, down;
    const std::pair<const char*, int> powers[] = {{"kg", p.mass}, {"m", p.px}, {"rad", p.rad}, {"s", p.s}};
    for (const auto& [name, n] : powers) {
        if (n > 0)
            up << QLatin1String(name) + superscript(n);
        else if (n < 0)
            down << QLatin1String(name) + superscript(-n);
    }
    const QString top = up.isEmpty() ? QStringLiteral("1") : joined(up, false);
    return down.isEmpty() ? top : top + u'/' + joined(down, true);
}

// v × base^n, with n ≥ 0 as a product and n < 0 as a division: whole
// scales (100 px per m) are exact, no rounded reciprocal is used.
double timesPower(double v, double base, int n)
{
    return n >= 0 ? v * std::pow(base, n) : v / std::pow(base, -n);
}

// A converted value to 15 significant digits: 9.8 m/s² × 100 is
// 980.0000000000001 in doubles (9.8 is not exact), which would reach the
// world as a value nobody typed. No unit scale carries meaning in the last
// two of a double's 17 digits.
double cleaned(double v)
{
    if (!std::isfinite(v) || v == 0.0)
        return v;
    return QString::number(v, 'g', 15).toDouble();
}

DisplayUnits g_units; // the application's choice (displayUnits())

} // namespace

double ShownUnit::toShown(double pixelValue) const
{
    if (px == 0 && mass == 0)
        return pixelValue;
    return cleaned(timesPower(timesPower(pixelValue, pxPerMetre, -px), kgPerMass, mass));
}

double ShownUnit::fromShown(double shownValue) const
{
    if (px == 0 && mass == 0)
        return shownValue;
    return cleaned(timesPower(timesPower(shownValue, pxPerMetre, px), kgPerMass, -mass));
}

std::optional<UnitPowers> parseUnit(const QString& pixelUnit)
{
    return UnitReader(pixelUnit).read();
}

ShownUnit shownUnit(const QString& pixelUnit, const DisplayUnits& units)
{
    if (!units.si)
        return {pixelUnit};
    const std::optional<UnitPowers> p = parseUnit(pixelUnit);
    if (!p || (p->px == 0 && p->mass == 0))
        return {pixelUnit};
    return {siText(*p), p->px, p->mass, units.pxPerMetre, units.kgPerMass};
}

const DisplayUnits& displayUnits()
{
    return g_units;
}

void setDisplayUnits(const DisplayUnits& units)
{
    g_units = units;
}

QString unitText(const QString& pixelUnit)
{
    return shownUnit(pixelUnit, g_units).text;
}

QString quantityText(double pixelValue, const QString& pixelUnit, int digits)
{
    const ShownUnit unit = shownUnit(pixelUnit, g_units);
    const QString number = humanNumber(unit.toShown(pixelValue), digits);
    return unit.text.isEmpty() ? number : number + QLatin1Char(' ') + unit.text;
}

double toShown(double pixelValue, const QString& pixelUnit)
{
    return shownUnit(pixelUnit, g_units).toShown(pixelValue);
}

double fromShown(double shownValue, const QString& pixelUnit)
{
    return shownUnit(pixelUnit, g_units).fromShown(shownValue);
}

} // namespace forcelab
