#include "sim/world/names.h"

#include "sim/integrators/integrator_info.h"

#include <array>
#include <vector>

namespace forcelab::sim {
namespace {

// One table per enumeration; the enum value is the index.
constexpr std::array<std::string_view, 4> kWallModels{"clamp", "mirror", "exact", "reverse"};
constexpr std::array<std::string_view, 2> kDragLaws{"linear", "quadratic"};
constexpr std::array<std::string_view, 5> kWindModes{"off", "random", "smoothed", "noise", "pointer"};
constexpr std::array<std::string_view, 3> kForceScales{"none", "radius", "mass"};
constexpr std::array<std::string_view, 2> kPointKinds{"attract", "repel"};
constexpr std::array<std::string_view, 4> kDetections{"brute", "halved", "sweep", "grid"};
constexpr std::array<std::string_view, 6> kResponses{"none", "flag", "1d-reverse", "1d-elastic", "2d-axis", "2d-impulse"};

template <typename E, std::size_t N>
std::optional<E> lookup(const std::array<std::string_view, N>& table, std::string_view name)
{
    for (std::size_t i = 0; i < N; ++i)
        if (table[i] == name)
            return static_cast<E>(i);
    return std::nullopt;
}

} // namespace

std::string_view toString(WallModel v) { return kWallModels.at(static_cast<std::size_t>(v)); }
std::string_view toString(DragLaw v) { return kDragLaws.at(static_cast<std::size_t>(v)); }
std::string_view toString(WindMode v) { return kWindModes.at(static_cast<std::size_t>(v)); }
std::string_view toString(ForceScale v) { return kForceScales.at(static_cast<std::size_t>(v)); }
std::string_view toString(PointKind v) { return kPointKinds.at(static_cast<std::size_t>(v)); }
std::string_view toString(Detection v) { return kDetections.at(static_cast<std::size_t>(v)); }
std::string_view toString(Response v) { return kResponses.at(static_cast<std::size_t>(v)); }
std::string_view toString(IntegratorKind v) { return integratorInfo(v).name; }

std::optional<WallModel> parseWallModel(std::string_view n) { return lookup<WallModel>(kWallModels, n); }
std::optional<DragLaw> parseDragLaw(std::string_view n) { return lookup<DragLaw>(kDragLaws, n); }
std::optional<WindMode> parseWindMode(std::string_view n) { return lookup<WindMode>(kWindModes, n); }
std::optional<ForceScale> parseForceScale(std::string_view n) { return lookup<ForceScale>(kForceScales, n); }
std::optional<PointKind> parsePointKind(std::string_view n) { return lookup<PointKind>(kPointKinds, n); }
std::optional<Detection> parseDetection(std::string_view n) { return lookup<Detection>(kDetections, n); }
std::optional<Response> parseResponse(std::string_view n) { return lookup<Response>(kResponses, n); }
std::optional<IntegratorKind> parseIntegrator(std::string_view n)
{
    if (n == "reference") // the most accurate integrator, whatever it is called
        return IntegratorKind::Ias15;
    for (const IntegratorInfo& info : integrators())
        if (info.name == n)
            return info.kind;
    return std::nullopt;
}

std::span<const std::string_view> wallModelNames() { return kWallModels; }
std::span<const std::string_view> dragLawNames() { return kDragLaws; }
std::span<const std::string_view> windModeNames() { return kWindModes; }
std::span<const std::string_view> forceScaleNames() { return kForceScales; }
std::span<const std::string_view> pointKindNames() { return kPointKinds; }
std::span<const std::string_view> detectionNames() { return kDetections; }
std::span<const std::string_view> responseNames() { return kResponses; }
std::span<const std::string_view> integratorNames()
{
    static const std::vector<std::string_view> names = [] {
        std::vector<std::string_view> out;
        for (const IntegratorInfo& info : integrators())
            out.push_back(info.name);
        return out;
    }();
    return names;
}

std::string joinNames(std::span<const std::string_view> names)
{
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i)
            out += ", ";
        out += names[i];
    }
    return out;
}

} // namespace forcelab::sim
