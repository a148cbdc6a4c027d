#pragma once
// Numbers as a student reads them: axes with round ticks (1, 2 or 5 × 10^k)
// and one common factor instead of e+10 on every label, values rounded to the
// digits that mean something, and counts with the right plural.

#include "ui/drawing/human_number.h"

#include <QString>

class QValueAxis;

namespace forcelab {

/// A linear axis over data in [lo, hi] with round ticks.
struct NiceAxis {
    double min = 0.0;  ///< first tick, a multiple of step (data units)
    double max = 1.0;  ///< last tick, a multiple of step (data units)
    double step = 0.2; ///< 1, 2 or 5 × 10^k (data units)
    int exponent = 0;  ///< the labels show value / 10^exponent; a multiple of 3, 0 for plain numbers
    int decimals = 1;  ///< decimals of the labels (after dividing by 10^exponent)

    double factor() const;     ///< 10^exponent
    /// The common factor as the axis title shows it: "×10⁶ " (with a trailing
    /// space) or empty when exponent is 0.
    QString factorText() const;
};

/// Round ticks that cover [lo, hi] with about `ticks` intervals (at most
/// ticks + 2). A flat or empty range gets a small range around it.
NiceAxis niceAxis(double lo, double hi, int ticks = 5);

/// Sets a chart axis to `axis`: range, a tick at every step, label format.
/// The values drawn on it must be divided by axis.factor() first.
void applyNiceAxis(QValueAxis* valueAxis, const NiceAxis& axis);

/// "1 evaluation", "3 evaluations": `one` is the singular, `many` the plural.
QString countText(long long n, const QString& one, const QString& many);

} // namespace forcelab
