#pragma once
// Draws a world with QPainter: the box, the balls (cached sprites), and the
// teaching overlays. The canvas calls it from paintEvent; the render benchmark
// and offscreen renders call it on a QImage, so every picture of a world comes
// from the same code.

#include "ball_sprites.h"
#include "view_transform.h"

#include "sim/world.h"

#include <QColor>
#include <QStringList>

class QPainter;

namespace forcelab {

/// The overlays a lesson can switch on (its "overlays" names in brackets).
struct Overlays {
    bool grid = true;          ///< [grid] faint lines every 50 px, labelled every 100 px
    bool velocity = false;     ///< [velocity] velocity arrows
    bool acceleration = false; ///< [acceleration] acceleration arrows
    bool readout = false;      ///< [readout] position, velocity, acceleration of the selected ball
    bool colliding = false;    ///< [colliding] balls touching another ball drawn in the marked colour
    bool markers = true;       ///< [markers] point-force centre and spring anchor

    /// From a lesson's overlay names; unknown names are ignored (the loader has checked them).
    static Overlays fromNames(const QStringList& names);
    friend bool operator==(const Overlays&, const Overlays&) = default;
};

struct PaintOptions {
    Overlays overlays;
    int selected = -1;              ///< the selected ball, -1 for none (the readout then shows ball 0)
    double velocityScale = 0.25;    ///< s: a velocity arrow is as long as the path covered in this time
    double accelerationScale = 0.05; ///< s²: an acceleration arrow is a × this
    double lineScale = 1.0;         ///< thicker lines and larger text for a projector
    bool sprites = true;            ///< false: one antialiased drawEllipse per ball (the render benchmark's baseline)
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
} // namespace canvas_colors

class WorldPainter {
public:
    /// Paints the whole `area` (letterbox, box, balls, overlays).
    /// `devicePixelRatio` must be the paint device's, for sharp sprites.
    void paint(QPainter& painter, const QRectF& area, const sim::World& world, const PaintOptions& options,
               qreal devicePixelRatio);

    /// The view used for `area` and this world's box.
    static ViewTransform view(const sim::World& world, const QRectF& area);

    void setMarkedColor(sim::Rgb color) { m_sprites.setMarkedColor(color); }
    sim::Rgb markedColor() const { return m_sprites.markedColor(); }
    const BallSprites& sprites() const { return m_sprites; }

    /// Above this many balls, arrows are drawn for the selected ball only.
    static constexpr int kMaxArrowBalls = 2000;

private:
    void paintBox(QPainter& p, const ViewTransform& view, const sim::World& world, const PaintOptions& options);
    void paintBalls(QPainter& p, const QRectF& area, const ViewTransform& view, const sim::World& world,
                    const PaintOptions& options, qreal dpr);
    void paintMarkers(QPainter& p, const ViewTransform& view, const sim::World& world, const PaintOptions& options);
    void paintArrows(QPainter& p, const ViewTransform& view, const sim::World& world, const PaintOptions& options,
                     const sim::Matrix2X* accelerations);
    void paintReadout(QPainter& p, const QRectF& area, const ViewTransform& view, const sim::World& world,
                      const PaintOptions& options, const sim::Matrix2X* accelerations);

    BallSprites m_sprites;
};

} // namespace forcelab
