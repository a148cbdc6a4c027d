// The formatter for numbers and ranges (number_text.h): shortest round-trip
// digits, whole numbers in full, printf-style rounding, and interval text.

#include "sim/world/number_text.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace forcelab::sim {

std::string shortestText(double v)
{
    char buf[64];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

std::string numberText(double v)
{
    if (std::isfinite(v) && std::floor(v) == v && std::abs(v) <= 1e9)
        return std::to_string(static_cast<long long>(v));
    return shortestText(v);
}

std::string roundedText(double v, int digits)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

std::string rangeText(double lo, double hi, std::string_view unit, bool loOpen, bool hiOpen)
{
    std::string s(loOpen ? "(" : "[");
    s.append(numberText(lo)).append(", ").append(numberText(hi)).append(hiOpen ? ")" : "]");
    if (!unit.empty())
        s.append(" ").append(unit);
    return s;
}

} // namespace forcelab::sim
