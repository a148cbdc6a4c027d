#pragma once
// The units a student reads (issue #36): the simulation always works in
// pixels (px, px/s, px/s², mass in the lesson's unnamed mass units); in SI
// mode every slider, readout, table and panel shows m, m/s, m/s², kg, N and
// J instead, at a scale a lesson or the teacher sets (100 px = 1 m). Only
// the text and the number shown change: a value typed in SI is converted
// back to px before it reaches the world. Qt Core only, like human_number,
// so the painters use it too.
//
// A unit is written as the parameter table (sim/world/parameters.cpp) and
// the readouts write it in pixel mode ("px/s²", "px³/(mass·s²)",
// "mass·px²/s²") and read as a product of powers of px, mass and s (plus
// the dimensionless rad and Hz = 1/s); one that does not read so is shown
// unchanged, in pixel mode.

#include <QString>

#include <optional>

namespace forcelab {

struct DisplayUnits {
    bool si = false;          ///< false: pixel mode, every unit as the simulation has it
    double pxPerMetre = 100.0; ///< px per m: how many pixels stand for one metre
    double kgPerMass = 1.0;    ///< kg per mass unit: what one of the lesson's mass units weighs
    friend bool operator==(const DisplayUnits&, const DisplayUnits&) = default;

    /// Sane scales (also the lesson file's limits): px per m and kg per mass unit.
    static constexpr double kMinScale = 1e-9;
    static constexpr double kMaxScale = 1e9;
};

/// Powers of the base units a pixel-mode unit is made of.
struct UnitPowers {
    int px = 0;
    int mass = 0;
    int s = 0;
    int rad = 0; ///< dimensionless, but kept in the text
    friend bool operator==(const UnitPowers&, const UnitPowers&) = default;
};

/// "px³/(mass·s²)" → {3, −1, −2, 0}; "1/s²" → {0, 0, −2, 0}; "" → all 0;
/// nullopt for text that is not such a product ("mass units", "1/s (linear) or …").
std::optional<UnitPowers> parseUnit(const QString& pixelUnit);

/// A pixel-mode unit as shown: its text, and the conversion of a value.
struct ShownUnit {
    QString text; ///< "m/s²", "J", or the pixel-mode text unchanged
    int px = 0;   ///< powers of px and mass converted (0 and 0: shown as it is)
    int mass = 0;
    double pxPerMetre = 1.0;
    double kgPerMass = 1.0;

    /// A value in px and mass units as shown: × (1 / pxPerMetre)^px × kgPerMass^mass,
    /// by divisions and multiplications by whole powers of the scales (not
    /// by a rounded reciprocal) and to 15 significant digits, so 980 px/s²
    /// is 9.8 m/s² exactly as typed, and back.
    double toShown(double pixelValue) const;
    /// A shown value back in px and mass units.
    double fromShown(double shownValue) const;
    /// shown = factor × pixel value.
    double factor() const { return toShown(1.0); }
};

/// How `pixelUnit` is shown under `units`: in pixel mode, or for a unit
/// without px and mass (s, 1/s², rad/s), or one parseUnit does not read,
/// unchanged with factor 1; in SI px → m, mass → kg, kg·m/s² → N,
/// kg·m²/s² → J ("px/s²" at 100 px/m → "m/s²", factor 0.01).
ShownUnit shownUnit(const QString& pixelUnit, const DisplayUnits& units);

/// The application's current choice, which every panel and painter reads
/// (one for the whole program, like the text size). Pixel mode at start.
const DisplayUnits& displayUnits();
void setDisplayUnits(const DisplayUnits& units);

/// Shorthands with the current choice: the shown unit's text, a pixel value
/// as shown, a shown value back in px.
QString unitText(const QString& pixelUnit);
/// A pixel value as a student reads it in the current units: "3.2 m",
/// "320 px" (humanNumber with `digits` significant digits, and the unit).
QString quantityText(double pixelValue, const QString& pixelUnit, int digits = 4);
double toShown(double pixelValue, const QString& pixelUnit);
double fromShown(double shownValue, const QString& pixelUnit);

} // namespace forcelab
