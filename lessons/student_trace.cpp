#include "lessons/student_trace.h"

#include "lessons/message_text.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iomanip>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>

namespace forcelab::lessons {
namespace {

/// The most a ball's number may be in a trace.
constexpr std::int64_t kMaxBall = 1'000'000;

std::string echo(const std::string& value)
{
    return cutForMessage(QString::fromStdString(value)).toStdString();
}

// The whole text as one finite number, read the same in every locale (the
// workbench runs in the user's; a trace's numbers are written with a point).
std::optional<double> parseFiniteNumber(const std::string& text)
{
    double v = 0.0;
    const char* first = text.data();
    const char* last = first + text.size();
    if (first != last && *first == '+')
        ++first;
    const auto [end, error] = std::from_chars(first, last, v);
    if (error != std::errc() || end != last || !std::isfinite(v))
        return std::nullopt;
    return v;
}

// A field's text as the number it must be: finite; whole within [lo, hi] for step and ball.
std::optional<std::string> readField(const std::string& name, const std::string& text, sim::StudentRow& row)
{
    const auto v = parseFiniteNumber(text);
    if (!v)
        return name + ": '" + echo(text) + "' is not a finite number";
    const bool whole = name == "step" || name == "ball";
    if (whole) {
        const double hi = name == "step" ? static_cast<double>(sim::kMaxTraceSteps) : static_cast<double>(kMaxBall);
        if (std::floor(*v) != *v || *v < 0 || *v > hi)
            return name + ": '" + echo(text) + "' is not a whole number from 0 to " +
                   std::to_string(static_cast<std::int64_t>(hi));
    }
    if (name == "step")
        row.step = static_cast<std::int64_t>(*v);
    else if (name == "ball")
        row.ball = static_cast<int>(*v);
    else if (name == "x")
        row.x = *v;
    else if (name == "y")
        row.y = *v;
    else if (name == "vx")
        row.vx = *v;
    else if (name == "vy")
        row.vy = *v;
    return std::nullopt;
}

const char* const kNeeded[] = {"step", "ball", "x", "y"};
const char* const kRead[] = {"step", "ball", "x", "y", "vx", "vy"};

std::string trimmed(const std::string& s)
{
    const auto a = s.find_first_not_of(" \t\r");
    const auto b = s.find_last_not_of(" \t\r");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

std::vector<std::string> splitCsv(const std::string& line)
{
    std::vector<std::string> out;
    std::string::size_type start = 0;
    while (true) {
        const auto comma = line.find(',', start);
        out.push_back(trimmed(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
        if (comma == std::string::npos)
            return out;
        start = comma + 1;
    }
}

StudentTrace readCsv(const std::string& file, const QByteArray& bytes)
{
    StudentTrace r;
    std::istringstream in(bytes.toStdString());
    std::string line;
    long number = 0;
    std::map<std::string, std::size_t> column;
    std::size_t width = 0;
    auto fail = [&](const std::string& what) {
        r.error = file + ":" + std::to_string(number) + ": " + what;
        r.rows.clear();
        return r;
    };
    while (std::getline(in, line)) {
        ++number;
        const std::string text = trimmed(line);
        if (text.empty() || text[0] == '#')
            continue;
        const std::vector<std::string> fields = splitCsv(text);
        if (column.empty()) {
            for (std::size_t k = 0; k < fields.size(); ++k)
                if (!column.emplace(fields[k], k).second)
                    return fail("the header names column '" + echo(fields[k]) + "' twice");
            for (const char* need : kNeeded)
                if (!column.count(need))
                    return fail(std::string("the header has no column '") + need +
                                "' (a trace needs step, ball, x and y; vx and vy are compared when given)");
            width = fields.size();
            continue;
        }
        if (fields.size() != width)
            return fail("expected " + std::to_string(width) + " fields as in the header, found " +
                        std::to_string(fields.size()));
        if (static_cast<std::int64_t>(r.rows.size()) >= sim::kMaxTraceRows)
            return fail("more than " + std::to_string(sim::kMaxTraceRows) + " rows; a trace may have at most that many");
        sim::StudentRow row;
        row.line = number;
        for (const char* name : kRead)
            if (const auto k = column.find(name); k != column.end())
                if (auto problem = readField(name, fields[k->second], row))
                    return fail(*problem);
        r.rows.push_back(row);
    }
    if (column.empty())
        return fail("no header line (step,ball,x,y,…)");
    if (r.rows.empty())
        return fail("no rows after the header");
    return r;
}

StudentTrace readJson(const std::string& file, const QByteArray& bytes)
{
    StudentTrace r;
    r.json = true;
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        const auto upTo = bytes.left(parseError.offset);
        const long line = static_cast<long>(upTo.count('\n')) + 1;
        r.error = file + ":" + std::to_string(line) + ": not JSON: " + parseError.errorString().toStdString();
        return r;
    }
    QJsonArray rows;
    if (doc.isArray())
        rows = doc.array();
    else if (doc.isObject() && doc.object().value(QStringLiteral("rows")).isArray())
        rows = doc.object().value(QStringLiteral("rows")).toArray();
    else {
        r.error = file + ": rows: expected an array of rows, or an object with \"rows\": [ … ]";
        return r;
    }
    if (rows.size() > sim::kMaxTraceRows) {
        r.error = file + ": rows: " + std::to_string(rows.size()) + " rows; a trace may have at most " +
                  std::to_string(sim::kMaxTraceRows);
        return r;
    }
    if (rows.isEmpty()) {
        r.error = file + ": rows: no rows";
        return r;
    }
    for (qsizetype i = 0; i < rows.size(); ++i) {
        const std::string where = file + ": rows[" + std::to_string(i) + "].";
        if (!rows[i].isObject()) {
            r.error = file + ": rows[" + std::to_string(i) + "]: expected an object {\"step\": …, \"ball\": …, \"x\": …, \"y\": …}";
            r.rows.clear();
            return r;
        }
        const QJsonObject o = rows[i].toObject();
        sim::StudentRow row;
        row.line = static_cast<long>(i);
        for (const char* name : kRead) {
            const QJsonValue v = o.value(QString::fromLatin1(name));
            const bool needed = std::find(std::begin(kNeeded), std::end(kNeeded), std::string_view(name)) !=
                                std::end(kNeeded);
            if (v.isUndefined()) {
                if (needed) {
                    r.error = where + name + ": missing (a row needs step, ball, x and y)";
                    r.rows.clear();
                    return r;
                }
                continue;
            }
            if (!v.isDouble()) {
                r.error = where + name + ": expected a number";
                r.rows.clear();
                return r;
            }
            std::ostringstream text;
            text << std::setprecision(17) << v.toDouble();
            if (auto problem = readField(name, text.str(), row)) {
                r.error = where + *problem;
                r.rows.clear();
                return r;
            }
        }
        r.rows.push_back(row);
    }
    return r;
}

} // namespace

StudentTrace readStudentTrace(const QString& path)
{
    const std::string file = path.toStdString();
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {{}, file + ": cannot read: " + f.errorString().toStdString(), false};
    if (f.size() > kMaxTraceFileBytes)
        return {{}, file + ": " + std::to_string(f.size()) + " bytes; a trace may have at most " +
                        std::to_string(kMaxTraceFileBytes) + " (64 MiB)", false};
    const QByteArray bytes = f.read(kMaxTraceFileBytes + 1);
    if (bytes.size() > kMaxTraceFileBytes)
        return {{}, file + ": more than " + std::to_string(kMaxTraceFileBytes) + " bytes (64 MiB); a trace may have no more", false};
    const bool json = path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive) ||
                      (!path.endsWith(QStringLiteral(".csv"), Qt::CaseInsensitive) &&
                       (bytes.trimmed().startsWith('{') || bytes.trimmed().startsWith('[')));
    return readStudentTraceText(file, bytes, json);
}


StudentTrace readStudentTraceText(const std::string& file, const QByteArray& bytes, bool json)
{
    return json ? readJson(file, bytes) : readCsv(file, bytes);
}

} // namespace forcelab::lessons
