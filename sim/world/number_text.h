#pragma once
// The one formatter for numbers and ranges in text a person reads: messages
// from sim and the lesson reader, the parameter reference in docs/, and the
// digits of a saved lesson. Pure C++ (no Qt), so sim and lessons share it.

#include <string>
#include <string_view>

namespace forcelab::sim {

/// The shortest digits that read back to the same double, as std::to_chars
/// writes them: "0.1", "1e-09", "1e+05", "nan", "inf". A saved lesson's numbers.
std::string shortestText(double v);

/// A number for messages and the docs: whole numbers up to 1e9 in full
/// ("100000", "-3"), others as shortestText ("0.5", "1e-09", "1e+15").
std::string numberText(double v);

/// `v` rounded to `digits` significant digits, trailing zeros dropped, as
/// printf's "%.*g" writes it: roundedText(0.016666, 2) is "0.017",
/// roundedText(123456.7, 4) is "1.235e+05". For measured values in messages.
std::string roundedText(double v, int digits);

/// An interval for messages and the docs: "[0, 1]", "(0, 1] s", "[-1e+12, 1e+12]".
/// `unit`, when not empty, follows after a space; open ends use ( and ).
std::string rangeText(double lo, double hi, std::string_view unit = {}, bool loOpen = false, bool hiOpen = false);

} // namespace forcelab::sim
