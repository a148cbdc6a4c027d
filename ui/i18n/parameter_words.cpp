#include "ui/i18n/parameter_words.h"

#include <QCoreApplication>

#include <array>

namespace forcelab {

namespace {

// One entry per label of sim/world/parameters.cpp, in its order.
constexpr std::array kLabels{
    QT_TRANSLATE_NOOP("Parameter", "Box width"),
    QT_TRANSLATE_NOOP("Parameter", "Box height"),
    QT_TRANSLATE_NOOP("Parameter", "Wall model"),
    QT_TRANSLATE_NOOP("Parameter", "Wall restitution"),
    QT_TRANSLATE_NOOP("Parameter", "Middle wall"),
    QT_TRANSLATE_NOOP("Parameter", "Test the centre only"),
    QT_TRANSLATE_NOOP("Parameter", "Left wall"),
    QT_TRANSLATE_NOOP("Parameter", "Right wall"),
    QT_TRANSLATE_NOOP("Parameter", "Top wall"),
    QT_TRANSLATE_NOOP("Parameter", "Floor"),
    QT_TRANSLATE_NOOP("Parameter", "Integrator"),
    QT_TRANSLATE_NOOP("Parameter", "Step dt"),
    QT_TRANSLATE_NOOP("Parameter", "Sub-steps"),
    QT_TRANSLATE_NOOP("Parameter", "Tolerance"),
    QT_TRANSLATE_NOOP("Parameter", "Move per frame"),
    QT_TRANSLATE_NOOP("Parameter", "Step past close passes"),
    QT_TRANSLATE_NOOP("Parameter", "Gravity"),
    QT_TRANSLATE_NOOP("Parameter", "g x (right)"),
    QT_TRANSLATE_NOOP("Parameter", "g y (down)"),
    QT_TRANSLATE_NOOP("Parameter", "Drag"),
    QT_TRANSLATE_NOOP("Parameter", "Drag law"),
    QT_TRANSLATE_NOOP("Parameter", "Drag k"),
    QT_TRANSLATE_NOOP("Parameter", "Drag scaling"),
    QT_TRANSLATE_NOOP("Parameter", "Wind"),
    QT_TRANSLATE_NOOP("Parameter", "Wind strength"),
    QT_TRANSLATE_NOOP("Parameter", "Wind scaling"),
    QT_TRANSLATE_NOOP("Parameter", "Smoothed step"),
    QT_TRANSLATE_NOOP("Parameter", "Noise frequency"),
    QT_TRANSLATE_NOOP("Parameter", "Compare with"),
    QT_TRANSLATE_NOOP("Parameter", "Random acceleration"),
    QT_TRANSLATE_NOOP("Parameter", "One value per ball"),
    QT_TRANSLATE_NOOP("Parameter", "Random strength"),
    QT_TRANSLATE_NOOP("Parameter", "Un-centred (0 to strength)"),
    QT_TRANSLATE_NOOP("Parameter", "Point force"),
    QT_TRANSLATE_NOOP("Parameter", "Point kind"),
    QT_TRANSLATE_NOOP("Parameter", "Point x"),
    QT_TRANSLATE_NOOP("Parameter", "Point y"),
    QT_TRANSLATE_NOOP("Parameter", "Point strength"),
    QT_TRANSLATE_NOOP("Parameter", "Point clamp (0 = off)"),
    QT_TRANSLATE_NOOP("Parameter", "Point scaling"),
    QT_TRANSLATE_NOOP("Parameter", "Un-normalised (S d / d²)"),
    QT_TRANSLATE_NOOP("Parameter", "Spring"),
    QT_TRANSLATE_NOOP("Parameter", "Anchor x"),
    QT_TRANSLATE_NOOP("Parameter", "Anchor y"),
    QT_TRANSLATE_NOOP("Parameter", "Spring k"),
    QT_TRANSLATE_NOOP("Parameter", "Gravity between balls"),
    QT_TRANSLATE_NOOP("Parameter", "G"),
    QT_TRANSLATE_NOOP("Parameter", "Softening ε"),
    QT_TRANSLATE_NOOP("Parameter", "Homing"),
    QT_TRANSLATE_NOOP("Parameter", "Homing strength"),
    QT_TRANSLATE_NOOP("Parameter", "Pointer force"),
    QT_TRANSLATE_NOOP("Parameter", "Pointer strength"),
    QT_TRANSLATE_NOOP("Parameter", "Pointer clamp (0 = off)"),
    QT_TRANSLATE_NOOP("Parameter", "Magnetic field"),
    QT_TRANSLATE_NOOP("Parameter", "Field B"),
    QT_TRANSLATE_NOOP("Parameter", "Custom force"),
    QT_TRANSLATE_NOOP("Parameter", "Formulas give a, not F"),
    QT_TRANSLATE_NOOP("Parameter", "Speed limit"),
    QT_TRANSLATE_NOOP("Parameter", "Largest speed"),
    QT_TRANSLATE_NOOP("Parameter", "Detection"),
    QT_TRANSLATE_NOOP("Parameter", "Response"),
    QT_TRANSLATE_NOOP("Parameter", "Ball restitution"),
    QT_TRANSLATE_NOOP("Parameter", "Continuous"),
    QT_TRANSLATE_NOOP("Parameter", "Resting contacts"),
};

} // namespace

QString parameterLabel(const sim::Parameter& p)
{
    const QByteArray english(p.label.data(), static_cast<qsizetype>(p.label.size()));
    return QCoreApplication::translate("Parameter", english.constData());
}

QStringList listedParameterLabels()
{
    QStringList out;
    for (const char* label : kLabels)
        out << QString::fromUtf8(label);
    return out;
}

} // namespace forcelab
