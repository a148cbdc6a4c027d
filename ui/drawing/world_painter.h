#pragma once
// Draws a world with QPainter: the box, the balls (cached sprites), and the
// teaching overlays (one record each under overlays/, drawn in the order of
// overlays/overlay_table.h). The canvas calls it from paintEvent; the render
// benchmark and offscreen renders call it on a QImage, so every picture of a
// world comes from the same code.

#include "ball_sprites.h"
#include "overlays/path_layer.h"
#include "view_transform.h"

#include "sim/world/world.h"

#include <QColor>
#include <QCoreApplication>
#include <QImage>
#include <QLineF>
#include <QStringList>

#include <string_view>
#include <vector>

class QPainter;

namespace forcelab {

/// The overlays a lesson can switch on (its "overlays" names in brackets).
struct Overlays {
    bool grid = true;          ///< [grid] lines every 50 px, labelled every 100 px (zoomed: round steps)
    bool velocity = false;     ///< [velocity] velocity arrows
    bool acceleration = false; ///< [acceleration] acceleration arrows
    bool forces = false;       ///< [forces] net force arrows, F = m a
    bool forceSources = false; ///< [sources] one force arrow per force model that acts, in the model's colour, with a legend
    bool readout = false;      ///< [readout] position, velocity, acceleration of the selected ball
    bool colliding = false;    ///< [colliding] balls touching another ball drawn in the marked colour
    bool markers = true;       ///< [markers] point-force centre, spring anchor, homes, the pointer's pull or push
    bool trails = false;       ///< [trails] the path behind each ball (or the selected one)
    bool centreOfMass = false; ///< [centre-of-mass] the centre of mass of all balls and its path
    bool momenta = false;      ///< [momenta] an inset beside the box: each ball's momentum tip to tail, and their sum
    bool apexes = false;       ///< [apexes] a mark and the height at the top of each flight
    bool vanes = false;        ///< [vanes] one wind vane per wind model (the acting one and wind.compare)
    bool impact = false;       ///< [impact] the selected ball's last collision: line of impact, tangent, velocities before and after
    bool broadphase = false;   ///< [broadphase] the grid cells or the sweep's x-intervals of the collision detection
    bool histogram = false;    ///< [histogram] not drawn on the canvas: the plots dock shows the speed histogram
    bool totals = false;       ///< [totals] total energy and momentum in the box's top-right corner
    bool ghost = true;         ///< [ghost] faint outlines of the ghost world's balls, when one runs (the Accuracy dock starts it)

    /// From a lesson's overlay names; unknown names are ignored (the loader has
    /// checked them). grid and markers are on in every lesson (they hide
    /// nothing); the others are on exactly when named.
    static Overlays fromNames(const QStringList& names);
    friend bool operator==(const Overlays&, const Overlays&) = default;
};

/// The selected ball's last collision, frozen at the frame it was found:
/// where both balls were and their velocities just before and after.
struct CollisionView {
    int a = -1, b = -1;         ///< the two balls (a is the selected one)
    sim::Vec2 positionA{0, 0}, positionB{0, 0}; ///< px, centres when the contact was found
    double radiusA = 0.0, radiusB = 0.0;        ///< px
    sim::Vec2 beforeA{0, 0}, beforeB{0, 0};     ///< px/s, velocities at the end of the frame before
    sim::Vec2 afterA{0, 0}, afterB{0, 0};       ///< px/s, velocities at the end of the frame of the contact
    double time = 0.0;          ///< s, world time of the frame of the contact
    bool valid() const { return a >= 0 && b >= 0; }
};

class TrailRecorder;
struct CanvasColors;

/// The top of one flight, for the "apexes" overlay.
struct ApexMark {
    sim::Vec2 centre{0, 0}; ///< px, the ball's centre at the top
    double radius = 0.0;    ///< px
};

/// The arrows' scales kept through a run with autoArrows: each is fixed by
/// the first frame in which that quantity is not zero everywhere (the start,
/// or the first frame that moves) and kept after, through a Reset, so the
/// arrows of two moments compare. The canvas owns it and clears it for a new
/// lesson; the teacher's "from now" clears it too.
struct ArrowRun {
    double velocity = 0.0;     ///< s; 0: not fixed yet
    double acceleration = 0.0; ///< s²; 0: not fixed yet
    double force = 0.0;        ///< s² per unit of mass; 0: not fixed yet
    double factor = 1.0;       ///< the teacher's ×2 / ÷2 on top of the fixed scales
    void clear() { *this = ArrowRun(); }
};

struct PaintOptions {
    Overlays overlays;
    int selected = -1;              ///< the selected ball, -1 for none (the readout then shows ball 0)
    double velocityScale = 0.25;    ///< s: a velocity arrow is as long as the path covered in this time
    double accelerationScale = 0.05; ///< s²: an acceleration arrow is a × this
    double lineScale = 1.0;         ///< thicker lines and larger text for a projector
    double margin = 10.0;           ///< px, free space around the box (the stage view uses less)
    Camera camera;                  ///< zoom and centre of the view; the default shows the whole box
    bool sprites = true;            ///< false: one antialiased drawEllipse per ball (the render benchmark's baseline)
    bool autoArrows = false;        ///< scale the arrows so the median one is kArrowPixels long on screen (once per run, with arrowRun)
    ArrowRun* arrowRun = nullptr;   ///< with autoArrows: the scales kept through the run (filled as they are fixed); null: every frame its own; not owned
    double arrowFactor = 1.0;       ///< without autoArrows: the fixed scales are multiplied by this
    double forceScale = 0.05;       ///< s² per unit of mass: a force arrow is F × this
    bool incrementalPaths = true;   ///< false: every path is redrawn whole each frame (the reference for tests)
    bool arrowLegendCard = true;    ///< false: the arrow legend is only reported (PaintedFrame::arrowLegendRows), for the stage bar to show
    const TrailRecorder* trails = nullptr;    ///< drawn when overlays.trails; not owned
    const CollisionView* collision = nullptr; ///< drawn when overlays.impact; not owned
    const sim::World* ghost = nullptr;        ///< drawn as outlines when overlays.ghost; not owned
    const CanvasColors* colors = nullptr;     ///< the theme's colours (ui/window/theme.h); null: the plain ones; not owned
    const std::vector<ApexMark>* apexes = nullptr; ///< the tops of the flights; drawn when overlays.apexes; not owned
    const std::vector<sim::Vec2>* centreOfMassPath = nullptr; ///< world px, oldest first; drawn when overlays.centreOfMass; not owned
    /// px, where to draw the balls instead of their positions (2×N, the
    /// slow-motion interpolation between two steps); not owned
    const sim::Matrix2X* positions = nullptr;
};

/// The canvas palette (light, high contrast: readable on a projector).
namespace canvas_colors {
inline constexpr QRgb kLetterbox = 0xffd5dae1;
inline constexpr QRgb kBackground = 0xfffcfcfa;
inline constexpr QRgb kFrame = 0xff2d3340;
inline constexpr QRgb kGridMinor = 0xffeef0f3;
inline constexpr QRgb kGridMajor = 0xffdde1e7;
inline constexpr QRgb kVelocity = 0xff1f7a3a;
inline constexpr QRgb kAcceleration = 0xffb0186a;
inline constexpr QRgb kSelection = 0xff111111;
inline constexpr QRgb kTrail = 0xff5a6478;      ///< trails when too many balls for their own colours
inline constexpr QRgb kVane = 0xff1c5d99;
inline constexpr QRgb kImpactLine = 0xffd9480f;
inline constexpr QRgb kTangent = 0xff6c757d;
inline constexpr QRgb kBroadPhase = 0xff4263eb;
inline constexpr QRgb kGhost = 0xa0202020;      ///< the ghost's outlines (translucent)
inline constexpr QRgb kForce = 0xff22262e;      ///< net force arrows and the momenta inset's sum
inline constexpr QRgb kCentreOfMass = 0xff343a40;
} // namespace canvas_colors

/// The colours and marks a theme may change (ui/window/theme.h); the defaults are the plain theme.
struct CanvasColors {
    QRgb letterbox = canvas_colors::kLetterbox;
    QRgb background = canvas_colors::kBackground;
    QRgb frame = canvas_colors::kFrame;
    QRgb gridMinor = canvas_colors::kGridMinor;
    QRgb gridMajor = canvas_colors::kGridMajor;
    QRgb gridText = 0xff8a929e;
    QRgb ballOutline = 0;         ///< a dark outline round every ball; 0 (transparent): none
    double outlineWidth = 0.0;    ///< px of that outline, times the line scale
    bool colourBlindSafe = false; ///< ball colours drawn as their nearest Okabe-Ito colour
    bool ringMarked = false;      ///< balls touching another also get a thick ring (not colour alone)
};

/// One row of the arrow legend: a sample arrow and what it stands for.
struct ArrowLegendRow {
    double pixels = 0.0; ///< widget px, the sample arrow's length at the frame's scale
    QString label;       ///< "100 px/s (velocity)", in the shown units
    QRgb color = 0;      ///< the arrows' colour
    bool operator==(const ArrowLegendRow&) const = default;
};

/// What the last paint() drew, for tests: the momenta inset's numbers and
/// whether the path layer was drawn afresh.
struct PaintedFrame {
    std::vector<double> forceLengths; ///< widget px, one per net force arrow drawn
    std::vector<double> velocityLengths; ///< widget px, one per ball whose velocity arrow is drawn (0: too short to draw)
    QStringList arrowLegend;          ///< the arrow legend's lines as drawn (empty: none)
    QList<ArrowLegendRow> arrowLegendRows; ///< the legend's rows, drawn on a card or not (PaintOptions::arrowLegendCard)
    double forceScale = 0.0;          ///< s² per unit of mass, the scale the force arrows used
    std::vector<sim::Vec2> momenta;   ///< mass·px/s, each ball's momentum (the inset's arrows)
    sim::Vec2 momentumSum{0, 0};      ///< mass·px/s, their sum
    QLineF momentumSumArrow;          ///< widget px, the sum arrow from its tail to its tip
    QPointF momentumChainTip;         ///< widget px, the tip of the last ball's arrow in the chain
    double momentumScale = 0.0;       ///< widget px per mass·px/s in the inset
    bool pathLayerRebuilt = false;    ///< the path layer was drawn afresh this frame (not appended to)
    double gridStep = 0.0;            ///< world px between the grid's labelled lines (0: no grid drawn)
    QStringList gridLabelsX;          ///< the labels along the top, as drawn ("1 m", "2", …)
    QStringList gridLabelsY;          ///< the labels down the left, as drawn
    double scaleBarLength = 0.0;      ///< world px the scale bar stands for (0: no bar drawn)
    QLineF scaleBar;                  ///< widget px, the scale bar as drawn
};

class WorldPainter {
    Q_DECLARE_TR_FUNCTIONS(WorldPainter)

public:
    /// Paints the whole `area` (letterbox, box, balls, overlays).
    /// `devicePixelRatio` must be the paint device's, for sharp sprites.
    void paint(QPainter& painter, const QRectF& area, const sim::World& world, const PaintOptions& options,
               qreal devicePixelRatio);

    /// The view used for `area` and this world's box. With the readout or the
    /// totals on, a strip beside the box (or above it, in a tall area) is kept
    /// for their panels, so they never cover the physics.
    static ViewTransform view(const sim::World& world, const QRectF& area, const PaintOptions& options = {});

    /// Where the readout and the totals panels are drawn (empty rects for
    /// those that are off): in the strip that view() keeps, one after the other.
    struct Panels {
        QRectF readout;
        QRectF totals;
        QRectF sources; ///< the legend of the per-source force arrows
        QRectF momenta; ///< the momenta inset
        bool readoutWide = false; ///< in a row above the box: the readout in two long lines
        bool totalsWide = false;  ///< in a row above the box: the totals in two long lines
    };
    static Panels panels(const sim::World& world, const QRectF& area, const PaintOptions& options);

    void setMarkedColor(sim::Rgb color) { m_sprites.setMarkedColor(color); }
    sim::Rgb markedColor() const { return m_sprites.markedColor(); }
    const BallSprites& sprites() const { return m_sprites; }

    /// The on-screen length of the median arrow with autoArrows, px.
    static constexpr double kArrowPixels = 45.0;
    /// The velocity and acceleration scales the arrows are drawn with (s and
    /// s²): the options' own, or with autoArrows those that make the median
    /// arrow of the balls that move kArrowPixels long.
    struct ArrowScales {
        double velocity = 0.25;
        double acceleration = 0.05;
        double force = 0.05;
    };
    /// With options.arrowRun, a scale fixed earlier in the run is kept and one
    /// fixed now is stored there.
    static ArrowScales arrowScales(const sim::World& world, const ViewTransform& view, const PaintOptions& options,
                                   const sim::Matrix2X* accelerations);
    /// The arrow legend's sample arrow is the round quantity (1, 2, 5 × 10^k)
    /// whose arrow is at least this many widget px long.
    static constexpr double kArrowLegendPixels = 40.0;

    /// In a zoomed or moved view the grid's labelled lines are the smallest
    /// round spacing (1, 2 or 5 × 10^k world px) at least this many widget px
    /// apart (the fitted view keeps 100 px, with lines every 50 px).
    static constexpr double kGridLabelPixels = 80.0;
    /// World px between the grid's labelled lines at `scale` widget px per world px.
    static double gridStep(double scale);
    /// The scale bar, drawn when the view is zoomed or moved: the smallest
    /// round length (world px) at least kScaleBarPixels widget px long.
    static constexpr double kScaleBarPixels = 90.0;
    static double scaleBarLength(double scale);

    /// In a zoomed or moved view, a ball drawn with at least this radius (px,
    /// times the line scale) gets a cross on its centre.
    static constexpr double kCentreMarkRadius = 30.0;

    /// Above this many balls, arrows are drawn for the selected ball only.
    static constexpr int kMaxArrowBalls = 2000;
    /// Above this many balls, the broad-phase view shows the cells or rows but not each ball's share.
    static constexpr int kMaxBroadPhaseBalls = 5000;

    /// Centre and radius (widget px) of wind vane `index` (0: the acting wind, 1: the compared one).
    static QPointF vaneCentre(const ViewTransform& view, int index, double lineScale);
    static double vaneRadius(double lineScale) { return 26.0 * lineScale; }
    /// Above this many balls, the ghost is not drawn (outlines of every ball would hide the balls).
    static constexpr int kMaxGhostBalls = 5000;
    /// The lines of the totals panel: kinetic, potential and total energy, momentum.
    static QStringList totalsText(const sim::World& world, bool wide = false);
    /// The same from an energy and a momentum already worked out.
    /// `momentumScale` (mass·px/s) is the size the momentum's digits are
    /// counted from (momentumScale(world)); 0 counts them from the total.
    static QStringList totalsText(const sim::Energy& e, const sim::Vec2& momentum, bool wide = false,
                                  double momentumScale = 0.0);
    /// The sum of the balls' own momenta' sizes, Σ m|v| (mass·px/s): the
    /// scale a total momentum's rounding noise is measured against.
    static double momentumScale(const sim::World& world);
    /// The units the totals are written in: the lesson's mass unit times px and s.
    static inline const QString kEnergyUnit = QStringLiteral("mass·px²/s²");
    static inline const QString kMomentumUnit = QStringLiteral("mass·px/s");
    /// The shapes the readout's lines come in: the canvas panel's five lines,
    /// two long lines for a strip above the box, or the stage bar's short lines.
    enum class ReadoutShape { Panel, Wide, Short };
    /// The lines of the readout of ball `selected` (ball 0 when none; none at
    /// all without balls); accelerations null: shown as 0.
    static QStringList readoutText(const sim::World& world, int selected, const sim::Matrix2X* accelerations,
                                   ReadoutShape shape);
    /// The same in the Wide shape, or the Panel shape when not `wide`.
    static QStringList readoutText(const sim::World& world, int selected, const sim::Matrix2X* accelerations,
                                   bool wide = false);
    /// The same for ball `ball` at position x, velocity v and acceleration a
    /// at time t: the one place the readout's lines are written.
    static QStringList readoutText(int ball, const sim::Vec2& x, const sim::Vec2& v, const sim::Vec2& a, double time,
                                   ReadoutShape shape);
    /// The totals in the stage bar's short lines: in a `column` the energy and
    /// the momentum get head lines of their own and the momentum's x and y a
    /// line each; in a row they take fewer lines.
    static QStringList stageTotalsText(const sim::Energy& e, const sim::Vec2& momentum, bool column,
                                       double momentumScale = 0.0);
    /// Above this many balls, per-source force arrows are drawn for the selected ball only.
    static constexpr int kMaxSourceBalls = 12;
    /// Above this many balls, the momenta inset shows the sum only.
    static constexpr int kMaxMomentumChain = 60;
    /// The colour of force model `name`'s arrows (its place in sim::forceModels()).
    static QColor sourceColor(std::string_view name);

    /// What the last paint() drew (for tests).
    const PaintedFrame& lastFrame() const { return m_frame; }

private:
    // What the overlays keep from frame to frame (overlays/overlay.h).
    BallSprites m_sprites;
    PathLayer m_paths;
    PaintedFrame m_frame;
    double m_momentumScale = 0.0; // the inset's scale, kept while the arrows fit
};

} // namespace forcelab
