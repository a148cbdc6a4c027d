#include "ui/controls/readable_numbers.h"

#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace forcelab {

double NiceAxis::factor() const
{
    return std::pow(10.0, exponent);
}

QString NiceAxis::factorText() const
{
    if (exponent == 0)
        return {};
    static const QString superscripts = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
    QString power;
    for (const QChar c : QString::number(std::abs(exponent)))
        power += superscripts[c.digitValue()];
    return QStringLiteral("×10") + (exponent < 0 ? QStringLiteral("⁻") : QString()) + power + QLatin1Char(' ');
}

NiceAxis niceAxis(double lo, double hi, int ticks)
{
    NiceAxis a;
    if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi)
        return a;
    if (hi == lo) { // a flat line: a range of ±5% around it, or ±1 around 0
        const double half = lo == 0.0 ? 1.0 : 0.05 * std::abs(lo);
        lo -= half;
        hi += half;
    }
    // The step: the range over the number of intervals, raised to the next
    // 1, 2 or 5 times a power of ten.
    const double raw = (hi - lo) / std::max(1, ticks);
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    const double mantissa = raw / decade;
    a.step = (mantissa <= 1.0 ? 1.0 : mantissa <= 2.0 ? 2.0 : mantissa <= 5.0 ? 5.0 : 10.0) * decade;
    a.min = std::floor(lo / a.step) * a.step;
    a.max = std::ceil(hi / a.step) * a.step;
    // One common factor, a power of 1000, once the labels would need more
    // than four digits before the point or three zeros after it.
    const double biggest = std::max(std::abs(a.min), std::abs(a.max));
    const int magnitude = biggest > 0.0 ? static_cast<int>(std::floor(std::log10(biggest))) : 0;
    if (magnitude >= 4 || magnitude <= -3)
        a.exponent = 3 * static_cast<int>(std::floor(magnitude / 3.0));
    // Enough decimals to tell two ticks apart after the factor.
    const double shownStep = a.step / a.factor();
    a.decimals = std::max(0, -static_cast<int>(std::floor(std::log10(shownStep) + 1e-9)));
    return a;
}

void applyNiceAxis(QValueAxis* valueAxis, const NiceAxis& a)
{
    const double f = a.factor();
    valueAxis->setRange(a.min / f, a.max / f);
    valueAxis->setTickType(QValueAxis::TicksDynamic);
    valueAxis->setTickAnchor(a.min / f);
    valueAxis->setTickInterval(a.step / f);
    valueAxis->setLabelFormat(QStringLiteral("%.%1f").arg(a.decimals));
}

QString countText(long long n, const QString& one, const QString& many)
{
    return QStringLiteral("%1 %2").arg(n).arg(n == 1 ? one : many);
}

} // namespace forcelab
