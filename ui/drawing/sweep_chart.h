#pragma once
// The work-precision chart of `forcelab-cli sweep`: error against force
// evaluations, log-log, one panel per reference problem and one line per
// integrator.

#include "sim/studies/reference_study.h"

#include <QString>

#include <vector>

namespace forcelab {

/// Draws the panels (two per row) into a PNG, written all or nothing;
/// false when the file cannot be written, with `error` saying why.
bool writeSweepChart(const QString& file, const std::vector<sim::ReferenceProblem>& problems,
                     const std::vector<sim::SweepRun>& runs, QString* error);

} // namespace forcelab
