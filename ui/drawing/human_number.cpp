#include "ui/drawing/human_number.h"

#include <algorithm>
#include <cmath>

namespace forcelab {

namespace {

QString superscript(int n)
{
    static const QString digits = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
    QString out = n < 0 ? QStringLiteral("⁻") : QString();
    for (const QChar c : QString::number(std::abs(n)))
        out += digits[c.digitValue()];
    return out;
}

// Fixed-point digits without trailing zeros ("1.50" → "1.5", "2." → "2").
QString trimmedFixed(double v, int decimals)
{
    QString text = QString::number(v, 'f', std::max(0, decimals));
    if (text.contains(QLatin1Char('.'))) {
        while (text.endsWith(QLatin1Char('0')))
            text.chop(1);
        if (text.endsWith(QLatin1Char('.')))
            text.chop(1);
    }
    return text;
}

} // namespace

std::optional<double> humanNumberValue(const QString& text)
{
    static const QString superDigits = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
    QString t = text.trimmed();
    t.replace(QChar(0x2212), QLatin1Char('-'));
    // The mantissa: sign, digits and a point.
    qsizetype end = 0;
    while (end < t.size() && (t[end].isDigit() || t[end] == QLatin1Char('-') || t[end] == QLatin1Char('.')))
        ++end;
    bool ok = false;
    double value = t.left(end).toDouble(&ok);
    if (!ok)
        return std::nullopt;
    static const QString times = QStringLiteral(" × 10");
    if (t.mid(end, times.size()) == times) {
        qsizetype at = end + times.size();
        const bool negative = at < t.size() && t[at] == QChar(0x207B); // ⁻
        if (negative)
            ++at;
        int exponent = 0, digits = 0;
        for (; at < t.size() && superDigits.contains(t[at]); ++at, ++digits)
            exponent = 10 * exponent + static_cast<int>(superDigits.indexOf(t[at]));
        if (digits == 0)
            return std::nullopt;
        value *= std::pow(10.0, negative ? -exponent : exponent);
    }
    return value;
}

QString humanNumber(double value, int digits)
{
    if (std::isnan(value))
        return QStringLiteral("—");
    if (std::isinf(value))
        return value > 0 ? QStringLiteral("∞") : QStringLiteral("−∞");
    if (value == 0.0)
        return QStringLiteral("0");
    digits = std::max(1, digits);
    int exponent = static_cast<int>(std::floor(std::log10(std::abs(value))));
    QString text;
    if (exponent >= 6 || exponent < -3) {
        double mantissa = value / std::pow(10.0, exponent);
        // Rounding may carry into another digit (9.9996 → 10.00).
        if (std::abs(std::round(mantissa * std::pow(10.0, digits - 1))) >= std::pow(10.0, digits)) {
            ++exponent;
            mantissa = value / std::pow(10.0, exponent);
        }
        text = trimmedFixed(mantissa, digits - 1) + QStringLiteral(" × 10") + superscript(exponent);
    } else {
        text = trimmedFixed(value, digits - 1 - exponent);
    }
    text.replace(QLatin1Char('-'), QChar(0x2212));
    if (text == QStringLiteral("−0"))
        text = QStringLiteral("0");
    return text;
}

QString rounded(double value, double scale, int digits)
{
    if (!std::isfinite(value))
        return std::isnan(value) ? QStringLiteral("—") : value > 0 ? QStringLiteral("∞") : QStringLiteral("−∞");
    scale = std::max(std::abs(scale), std::abs(value));
    if (scale == 0.0)
        return QStringLiteral("0");
    // The last digit kept is `digits` places below the leading digit of scale.
    const int last = static_cast<int>(std::floor(std::log10(scale))) - digits + 1;
    const double quantum = std::pow(10.0, last);
    double r = std::round(value / quantum) * quantum;
    if (r == 0.0)
        r = 0.0; // no "−0"
    if (scale >= 1e6 || scale < 1e-3) {
        if (r == 0.0)
            return QStringLiteral("0");
        const int lead = static_cast<int>(std::floor(std::log10(std::abs(r))));
        return humanNumber(r, std::max(1, lead - last + 1));
    }
    QString text = QString::number(r, 'f', std::max(0, -last));
    text.replace(QLatin1Char('-'), QChar(0x2212));
    return text;
}

QString oneDecimal(double value)
{
    if (!std::isfinite(value) || std::abs(value) >= 1e5)
        return humanNumber(value, 4);
    QString text = QString::number(value, 'f', 1);
    if (text == QStringLiteral("-0.0"))
        return QStringLiteral("0.0");
    text.replace(QLatin1Char('-'), QChar(0x2212));
    return text;
}

} // namespace forcelab
