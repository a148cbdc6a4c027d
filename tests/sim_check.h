#pragma once
// The checks of the simulation library's own tests, without Qt: doctest,
// with QtTest's rule for comparing floating point (REQUIRE_SAME), a line of
// output for measured figures (report), and a small text type whose arg()
// fills %1, %2, … the way the messages of these tests are written.

#include <doctest/doctest.h>

#include <cctype>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

namespace forcelab::test {

/// Equal as QtTest's QCOMPARE has it: integers, strings and the like exactly;
/// floating point to 12 significant digits (|a − b| · 10¹² ≤ min(|a|, |b|)),
/// an expected value within 10⁻¹² of zero needs an actual value as close, and
/// NaN equals NaN, infinities their own sign.
template <class A, class B>
bool same(const A& a, const B& b)
{
    if constexpr (std::is_floating_point_v<A> || std::is_floating_point_v<B>) {
        const double x = static_cast<double>(a), y = static_cast<double>(b);
        if (std::isnan(x) || std::isnan(y))
            return std::isnan(x) && std::isnan(y);
        if (std::isinf(x) || std::isinf(y))
            return x == y;
        if (std::abs(y) <= 1e-12)
            return std::abs(x) <= 1e-12;
        return std::abs(x - y) * 1e12 <= std::min(std::abs(x), std::abs(y));
    } else {
        return a == b;
    }
}

template <class T, class = void>
struct Streamable : std::false_type {};
template <class T>
struct Streamable<T, std::void_t<decltype(std::declval<std::ostream&>() << std::declval<const T&>())>>
    : std::true_type {};

/// A value for a failure message: 17 digits for floating point.
template <class T>
std::string show(const T& v)
{
    std::ostringstream s;
    if constexpr (std::is_enum_v<T>)
        s << static_cast<long long>(v);
    else if constexpr (Streamable<T>::value)
        s << std::setprecision(17) << v;
    else
        s << "(a value)";
    return s.str();
}

/// Text for messages: arg() replaces the lowest %N, numbers as Qt writes
/// them ('g', 6 significant digits unless told otherwise).
class Text {
public:
    Text() = default;
    Text(const char* s) : m_s(s) {}
    Text(std::string s) : m_s(std::move(s)) {}
    Text(std::string_view s) : m_s(s) {}

    static Text number(double v, char format = 'g', int precision = 6)
    {
        char fmt[8] = {'%', '.', '*', format, 0};
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, fmt, precision, v);
        return Text(std::string(buffer));
    }
    static Text number(int v) { return Text(std::to_string(v)); }
    static Text number(long v) { return Text(std::to_string(v)); }
    static Text number(long long v) { return Text(std::to_string(v)); }
    static Text number(unsigned long v) { return Text(std::to_string(v)); }

    Text arg(const Text& t) const { return fill(t.m_s); }
    Text arg(const char* t) const { return fill(t); }
    Text arg(const std::string& t) const { return fill(t); }
    Text arg(const Text& a, const Text& b) const { return arg(a).arg(b); }
    Text arg(const Text& a, const Text& b, const Text& c) const { return arg(a).arg(b).arg(c); }
    Text arg(double v, int width = 0, char format = 'g', int precision = -1) const
    {
        std::string s = number(v, format, precision < 0 ? 6 : precision).m_s;
        if (static_cast<int>(s.size()) < std::abs(width))
            s = width > 0 ? std::string(static_cast<std::size_t>(width) - s.size(), ' ') + s
                          : s + std::string(static_cast<std::size_t>(-width) - s.size(), ' ');
        return fill(s);
    }
    Text arg(float v) const { return arg(static_cast<double>(v)); }
    Text arg(int v) const { return fill(std::to_string(v)); }
    Text arg(long v) const { return fill(std::to_string(v)); }
    Text arg(long long v) const { return fill(std::to_string(v)); }
    Text arg(unsigned v) const { return fill(std::to_string(v)); }
    Text arg(unsigned long v) const { return fill(std::to_string(v)); }
    Text arg(unsigned long long v) const { return fill(std::to_string(v)); }

    bool contains(std::string_view t) const { return m_s.find(t) != std::string::npos; }
    bool startsWith(std::string_view t) const { return m_s.starts_with(t); }
    bool endsWith(std::string_view t) const { return m_s.ends_with(t); }
    bool isEmpty() const { return m_s.empty(); }
    const char* c_str() const { return m_s.c_str(); }
    const std::string& str() const { return m_s; }
    std::string toStdString() const { return m_s; }
    operator const std::string&() const { return m_s; }

    friend Text operator+(const Text& a, const Text& b) { return Text(a.m_s + b.m_s); }
    friend bool operator==(const Text& a, const Text& b) { return a.m_s == b.m_s; }
    friend std::ostream& operator<<(std::ostream& o, const Text& t) { return o << t.m_s; }

private:
    // The lowest-numbered %N marker is replaced by `value`.
    Text fill(const std::string& value) const
    {
        int lowest = 100;
        std::size_t at = std::string::npos, length = 0;
        for (std::size_t i = 0; i + 1 < m_s.size(); ++i) {
            if (m_s[i] != '%' || !std::isdigit(static_cast<unsigned char>(m_s[i + 1])))
                continue;
            std::size_t j = i + 1;
            int n = 0;
            while (j < m_s.size() && std::isdigit(static_cast<unsigned char>(m_s[j])) && n < 100)
                n = 10 * n + (m_s[j++] - '0');
            if (n < lowest) {
                lowest = n;
                at = i;
                length = j - i;
            }
        }
        if (at == std::string::npos)
            return *this;
        std::string out = m_s;
        out.replace(at, length, value);
        return Text(out);
    }

    std::string m_s;
};

/// A row's name written printf-style (QtTest's addRow).
inline Text format_row(const char* format, ...)
{
    va_list args;
    va_start(args, format);
    char buffer[512];
    std::vsnprintf(buffer, sizeof buffer, format, args);
    va_end(args);
    return Text(std::string(buffer));
}

/// A line of output beside the test results (measured figures), printf-style.
inline void report(const char* format, ...)
{
    va_list args;
    va_start(args, format);
    std::vprintf(format, args);
    va_end(args);
    std::printf("\n");
}

} // namespace forcelab::test

/// QtTest's QVERIFY and QVERIFY2: stop the test case when `condition` is
/// false (the condition is one boolean, so it may use && and ||).
#define VERIFY(condition) REQUIRE(static_cast<bool>(condition))
#define VERIFY2(condition, message) REQUIRE_MESSAGE(static_cast<bool>(condition), (message))
/// QtTest's qFatal in a test: the test case fails with the printf-style message.
#define FAIL_PRINTF(...) FAIL(::forcelab::test::format_row(__VA_ARGS__).str())

/// QtTest's QCOMPARE: stops the test case when `actual` is not the same as
/// `expected` (see same()), showing both.
#define REQUIRE_SAME(actual, expected)                                                                             \
    do {                                                                                                           \
        const auto requireActual_ = (actual); /* copies: the value may live in a temporary */                     \
        const auto requireExpected_ = (expected);                                                                  \
        REQUIRE_MESSAGE(::forcelab::test::same(requireActual_, requireExpected_),                                 \
                        #actual " is " << ::forcelab::test::show(requireActual_) << ", expected " #expected " = "  \
                                       << ::forcelab::test::show(requireExpected_));                               \
    } while (false)
