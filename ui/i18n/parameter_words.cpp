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

// One entry per row's help (its tooltip), in the table's order.
constexpr std::array kHelp{
    QT_TRANSLATE_NOOP("ParameterHelp", "Width of the box the balls live in."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Height of the box; y points down."),
    QT_TRANSLATE_NOOP("ParameterHelp", "How a ball that crossed a wall is put back: clamp, mirror, exact (time of impact) or reverse."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Share of the speed into a wall that a bounce keeps: 1 loses nothing, 0 stops the ball."),
    QT_TRANSLATE_NOOP("ParameterHelp", "A wall down the middle of the box; each ball stays on its side."),
    QT_TRANSLATE_NOOP("ParameterHelp", "The wall test uses the ball's centre instead of its edge (stage 3's bug)."),
    QT_TRANSLATE_NOOP("ParameterHelp", "A wall at x = 0 (in lesson files: \"left\" in the walls list)."),
    QT_TRANSLATE_NOOP("ParameterHelp", "A wall at x = width."),
    QT_TRANSLATE_NOOP("ParameterHelp", "A wall at y = 0."),
    QT_TRANSLATE_NOOP("ParameterHelp", "A wall at y = height."),
    QT_TRANSLATE_NOOP("ParameterHelp", "The method that moves the balls through one step."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Simulated time of one step."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Each step is split into this many equal sub-steps."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Error allowed per sub-step by the adaptive integrators (rk45, ias15); ias15 works to the rounding floor where this asks for less."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Ignore dt: every step moves the balls as if 1/60 s had passed (stage 5's bug)."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Let a fixed step jump past a close pass it cannot follow instead of stopping there (stage 17's slingshot bug)."),
    QT_TRANSLATE_NOOP("ParameterHelp", "The same downward pull on every ball."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Sideways part of gravity."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Downward part of gravity; 980 px/s² is Earth's if 1 px is 1 cm."),
    QT_TRANSLATE_NOOP("ParameterHelp", "A force against the velocity."),
    QT_TRANSLATE_NOOP("ParameterHelp", "linear: F ∝ −v; quadratic: F ∝ −|v| v."),
    QT_TRANSLATE_NOOP("ParameterHelp", "How strong the drag is: how fast a 10 px ball slows down."),
    QT_TRANSLATE_NOOP("ParameterHelp", "mass: drag is a force, F = −k m(10 px) v, so a heavy ball slows down less and falls faster; none: the tutorial's model, every ball loses the same share of its speed; radius: air drag on spheres, × 10 px / r."),
    QT_TRANSLATE_NOOP("ParameterHelp", "off, random (a new gust every step), smoothed (a bounded random walk), noise (smooth noise) or pointer (blown by the mouse)."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Largest sideways push on a 10 px ball."),
    QT_TRANSLATE_NOOP("ParameterHelp", "none: every ball is pushed alike; radius: by 10 px / r; mass: as a force, by m(10 px) / m."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Largest change of the smoothed wind per step, as a share of its strength."),
    QT_TRANSLATE_NOOP("ParameterHelp", "How fast the noise wind changes."),
    QT_TRANSLATE_NOOP("ParameterHelp", "A second wind computed beside the first for a second vane; it pushes nothing."),
    QT_TRANSLATE_NOOP("ParameterHelp", "A random push on every ball, centred on zero (stage 10)."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Off: a new random value every step. On: each ball keeps the value it drew first."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Largest value of each component."),
    QT_TRANSLATE_NOOP("ParameterHelp", "The course's Math.random() bug: each component is drawn in [0, strength) instead of [−strength, strength), so every ball drifts right and down at strength/2 on average."),
    QT_TRANSLATE_NOOP("ParameterHelp", "An inverse-square pull or push from a fixed point."),
    QT_TRANSLATE_NOOP("ParameterHelp", "attract or repel."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Where the point is, across."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Where the point is, down."),
    QT_TRANSLATE_NOOP("ParameterHelp", "S in a = S / d² for a 10 px ball."),
    QT_TRANSLATE_NOOP("ParameterHelp", "The point's pull is never more than this near it."),
    QT_TRANSLATE_NOOP("ParameterHelp", "none, radius or mass, as for the wind."),
    QT_TRANSLATE_NOOP("ParameterHelp", "The course's repulsion bug: the difference vector d times S / d² instead of its unit vector, so |a| = S / d, a 1/d law, not S / d²."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Every ball tied to one anchor by a spring (Hooke's law)."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Where the springs are tied, across."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Where the springs are tied, down."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Stiffness per unit mass: a = −k (x − anchor), so ω = √k."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Every pair of balls pulls together (or pushes apart for G < 0)."),
    QT_TRANSLATE_NOOP("ParameterHelp", "The constant in F = G m₁ m₂ / r²."),
    QT_TRANSLATE_NOOP("ParameterHelp", "ε in F = G m₁ m₂ r / (r² + ε²)^(3/2): the pull fades smoothly to zero inside ε."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Each ball tied by a spring to the home of its colour."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Stiffness of the spring to home, per unit mass."),
    QT_TRANSLATE_NOOP("ParameterHelp", "The mouse pointer pulls (hover) or pushes (pressed)."),
    QT_TRANSLATE_NOOP("ParameterHelp", "S in a = S / d²."),
    QT_TRANSLATE_NOOP("ParameterHelp", "The pointer's pull is never more than this."),
    QT_TRANSLATE_NOOP("ParameterHelp", "A field out of the screen that turns every moving charge, F = q v × B, without changing its speed."),
    QT_TRANSLATE_NOOP("ParameterHelp", "How fast a 10 px ball of charge 1 turns: ω = q B m(10 px) / m; negative turns the other way."),
    QT_TRANSLATE_NOOP("ParameterHelp", "A force law written as formulas of x, y, vx, vy, m, r, q, t, W, H and named constants (the Force editor)."),
    QT_TRANSLATE_NOOP("ParameterHelp", "On: the formulas are the acceleration (px/s²), the same for every mass; off: the force, divided by m."),
    QT_TRANSLATE_NOOP("ParameterHelp", "No ball moves faster than the limit (a stand-in for terminal velocity)."),
    QT_TRANSLATE_NOOP("ParameterHelp", "The limit."),
    QT_TRANSLATE_NOOP("ParameterHelp", "How touching pairs are found: brute, halved, sweep or grid."),
    QT_TRANSLATE_NOOP("ParameterHelp", "What a touching pair does: none, flag, 1d-reverse, 1d-elastic, 2d-axis or 2d-impulse."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Share of the approach speed a collision gives back."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Find the moment of impact inside the step."),
    QT_TRANSLATE_NOOP("ParameterHelp", "Under gravity, solve a pile's contacts several times per step so it stands."),
};

} // namespace

QString parameterLabel(const sim::Parameter& p)
{
    const QByteArray english(p.label.data(), static_cast<qsizetype>(p.label.size()));
    return QCoreApplication::translate("Parameter", english.constData());
}

QString parameterHelp(const sim::Parameter& p)
{
    const QByteArray english(p.help.data(), static_cast<qsizetype>(p.help.size()));
    return QCoreApplication::translate("ParameterHelp", english.constData());
}

QStringList listedParameterHelp()
{
    QStringList out;
    for (const char* help : kHelp)
        out << QString::fromUtf8(help);
    return out;
}

QStringList listedParameterLabels()
{
    QStringList out;
    for (const char* label : kLabels)
        out << QString::fromUtf8(label);
    return out;
}

} // namespace forcelab
