#pragma once
// The names of the enumerations as they appear in lesson files, on the command
// line and in the UI. parse* return std::nullopt for an unknown name; allNames
// lists the accepted names for error messages.

#include "sim/world/world_settings.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace forcelab::sim {

std::string_view toString(WallModel v);
std::string_view toString(DragLaw v);
std::string_view toString(WindMode v);
std::string_view toString(ForceScale v);
std::string_view toString(PointKind v);
std::string_view toString(Detection v);
std::string_view toString(Response v);
std::string_view toString(IntegratorKind v);

std::optional<WallModel> parseWallModel(std::string_view name);
std::optional<DragLaw> parseDragLaw(std::string_view name);
std::optional<WindMode> parseWindMode(std::string_view name);
std::optional<ForceScale> parseForceScale(std::string_view name);
std::optional<PointKind> parsePointKind(std::string_view name);
std::optional<Detection> parseDetection(std::string_view name);
std::optional<Response> parseResponse(std::string_view name);
/// Also accepts the alias "reference" for the reference integrator (ias15).
std::optional<IntegratorKind> parseIntegrator(std::string_view name);

/// The accepted names, in declaration order, e.g. {"clamp", "mirror", "exact"}.
std::span<const std::string_view> wallModelNames();
std::span<const std::string_view> dragLawNames();
std::span<const std::string_view> windModeNames();
std::span<const std::string_view> forceScaleNames();
std::span<const std::string_view> pointKindNames();
std::span<const std::string_view> detectionNames();
std::span<const std::string_view> responseNames();
std::span<const std::string_view> integratorNames();

/// "a, b, c" for error messages.
std::string joinNames(std::span<const std::string_view> names);

} // namespace forcelab::sim
