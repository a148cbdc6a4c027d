#pragma once
// Numbers as a student writes them, for every panel, readout and label:
// a true minus sign, and a power of ten ("4.2 × 10⁹") where a computer would
// write "4.2e+09". Qt Core only, so the painters in ui/drawing use it too.

#include <QString>

#include <optional>

namespace forcelab {

/// `value` with `digits` significant digits as a student writes it: "12.35",
/// "0.0042", "−3" (a true minus sign), and from 10⁶ up or below 10⁻³ with a
/// power of ten: "4.2 × 10⁹", "1.5 × 10⁻⁵". "—" for not-a-number, "∞" for infinity.
QString humanNumber(double value, int digits = 4);

/// The value of a number as humanNumber writes it ("−1.5 × 10⁻⁵", "12.35"),
/// also when a unit follows it ("3.2 m"): nullopt when `text` does not start
/// with such a number. For tests and for reading a shown value back.
std::optional<double> humanNumberValue(const QString& text);

/// `value` with `digits` significant digits counted from `scale` (the size
/// of the largest value it is shown with), so rounding noise far below that
/// shows as 0: rounded(1.39698e-09, 1000) is "0", rounded(-12.34567, 1000) is
/// "−12", rounded(-12.34567, 100) is "−12.3" and rounded(2.5e7, 2.5e7) is
/// "2.5 × 10⁷" (the notation of humanNumber from 10⁶ up and below 10⁻³).
QString rounded(double value, double scale, int digits = 4);

/// `value` with one decimal below 10⁵ ("−12.3", for columns of
/// positions and speeds) and four significant digits with a power of ten
/// above ("−1.5 × 10⁶").
QString oneDecimal(double value);

} // namespace forcelab
