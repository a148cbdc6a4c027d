#pragma once
// Ball images drawn once (antialiased) and then blitted: one QImage per
// (radius bucket, colour, marked), in device pixels, tagged with the device
// pixel ratio so QPainter places it in logical coordinates. Drawing a cached
// image costs a small copy; an antialiased drawEllipse per ball costs an order
// of magnitude more at large counts.

#include "sim/world/types.h"

#include <QImage>
#include <QtGlobal>

#include <cstdint>
#include <unordered_map>

namespace forcelab {

class BallSprites {
public:
    /// Radii above this (device px) are not cached: few such balls fit on
    /// screen, so they are drawn directly.
    static constexpr double kMaxDeviceRadius = 96.0;
    /// Sprites are made for radii rounded to this many buckets per device px.
    static constexpr int kBucketsPerPixel = 4;

    /// The sprite of a ball of `deviceRadius` (device px), or nullptr when
    /// the ball is too large to cache. `marked` draws it in `markedColor`.
    const QImage* sprite(double deviceRadius, sim::Rgb color, bool marked, qreal devicePixelRatio);

    void setMarkedColor(sim::Rgb color);
    sim::Rgb markedColor() const { return m_markedColor; }

    int size() const { return static_cast<int>(m_cache.size()); }
    void clear();

    /// Draws one ball image: a flat disc of the colour with a darker rim, so
    /// the centre pixel is exactly the ball's colour.
    static QImage render(double deviceRadius, sim::Rgb color, qreal devicePixelRatio);

private:
    std::unordered_map<std::uint64_t, QImage> m_cache;
    std::uint64_t m_lastKey = ~std::uint64_t{0}; // consecutive balls often share a sprite
    const QImage* m_last = nullptr;
    qreal m_devicePixelRatio = 0.0;
    sim::Rgb m_markedColor = 0xff2a2a;
};

} // namespace forcelab
