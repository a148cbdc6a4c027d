#include "ball_sprites.h"

#include <QColor>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace forcelab {

namespace {
// A cap on the cache so that a scene of many distinct sizes cannot grow it
// without bound; refilling costs one antialiased ellipse per sprite.
constexpr std::size_t kMaxSprites = 4096;
} // namespace

const QImage* BallSprites::sprite(double deviceRadius, sim::Rgb color, bool marked, qreal devicePixelRatio)
{
    if (!(deviceRadius <= kMaxDeviceRadius))
        return nullptr;
    if (devicePixelRatio != m_devicePixelRatio) {
        clear();
        m_devicePixelRatio = devicePixelRatio;
    }
    const auto bucket = static_cast<std::uint64_t>(std::lround(std::max(deviceRadius, 0.25) * kBucketsPerPixel));
    const sim::Rgb shown = (marked ? m_markedColor : color) & 0xffffffu;
    const std::uint64_t key = (bucket << 25) | (std::uint64_t{marked} << 24) | shown;
    if (key == m_lastKey)
        return m_last;
    auto it = m_cache.find(key);
    if (it == m_cache.end()) {
        if (m_cache.size() >= kMaxSprites)
            clear();
        const double r = static_cast<double>(bucket) / kBucketsPerPixel;
        it = m_cache.emplace(key, render(r, shown, devicePixelRatio)).first;
    }
    m_lastKey = key;
    m_last = &it->second;
    return m_last;
}

void BallSprites::setMarkedColor(sim::Rgb color)
{
    if (color == m_markedColor)
        return;
    m_markedColor = color;
    clear();
}

void BallSprites::clear()
{
    m_cache.clear();
    m_lastKey = ~std::uint64_t{0};
    m_last = nullptr;
}

QImage BallSprites::render(double deviceRadius, sim::Rgb color, qreal devicePixelRatio)
{
    // Odd-sized square with the disc centred on the middle pixel's centre,
    // so blitting at (centre - half size) puts the disc where the ball is.
    // The pixel k columns from the middle spans [k - ½, k + ½], so it touches
    // the disc only for k < r + ½: m = ceil(r + ½) columns each side suffice.
    const int side = 2 * static_cast<int>(std::ceil(deviceRadius + 0.5)) + 1;
    QImage image(side, side, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    const QColor fill = QColor::fromRgb(color);
    const QPointF centre(0.5 * side, 0.5 * side);
    p.setPen(Qt::NoPen);
    if (deviceRadius >= 3.0) {
        // A darker rim (about 8% of the radius, at least one pixel) keeps
        // touching balls of one colour apart.
        const double rim = std::max(1.0, 0.08 * deviceRadius);
        p.setBrush(fill.darker(150));
        p.drawEllipse(centre, deviceRadius, deviceRadius);
        p.setBrush(fill);
        p.drawEllipse(centre, deviceRadius - rim, deviceRadius - rim);
    } else {
        p.setBrush(fill);
        p.drawEllipse(centre, deviceRadius, deviceRadius);
    }
    p.end();
    image.setDevicePixelRatio(devicePixelRatio);
    return image;
}

} // namespace forcelab
