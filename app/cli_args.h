#pragma once
// Small helpers shared by the subcommands' argument parsing.

#include <optional>
#include <string>

namespace forcelab::cli {

/// The whole text as a finite number ("12", "1e-3"); nullopt for anything
/// else: trailing characters, "nan", "inf", out of range.
std::optional<double> parseFiniteNumber(const std::string& text);

} // namespace forcelab::cli
