#pragma once
// A student's trace of a lesson, read from CSV (a header naming step, ball,
// x, y and maybe vx, vy) or JSON (rows of {step, ball, x, y[, vx, vy]}),
// for sim::matchTrace. The file comes from a stranger: at most 64 MiB and
// sim::kMaxTraceRows rows, every number finite, step and ball whole; any
// problem is one line naming the file, the line (CSV) or row (JSON) and
// the field, and no rows are kept. Used by `forcelab-cli compare` and the
// workbench's File → Check a Student's Trace.

#include "sim/studies/trace.h"
#include "sim/studies/trace_compare.h"

#include <QString>

#include <string>
#include <vector>

namespace forcelab::lessons {

/// The most bytes a trace file may have (64 MiB); larger is refused, not cut.
inline constexpr long long kMaxTraceFileBytes = 64LL * 1024 * 1024;

struct StudentTrace {
    std::vector<sim::StudentRow> rows;
    std::string error; ///< empty when read
    bool json = false; ///< rows are numbered from 0 (JSON), not by file line (CSV)
};

/// Reads the file at `path`: JSON by its name (.json) or its first
/// character, CSV otherwise.
StudentTrace readStudentTrace(const QString& path);

/// Reads `bytes` as the file `file` (the name is only for messages).
StudentTrace readStudentTraceText(const std::string& file, const QByteArray& bytes, bool json);

} // namespace forcelab::lessons
