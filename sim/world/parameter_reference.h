#pragma once
// The parameter reference (docs/parameters.md), written from the table in
// parameters.h so that it cannot drift from what the program accepts.

#include <string>

namespace forcelab::sim {

/// Markdown: one table per section (world, time, each model), one line per
/// parameter with its key, unit, default, allowed values and help.
std::string parameterReference();

} // namespace forcelab::sim
