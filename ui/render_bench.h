#pragma once
// The render benchmark: draws worlds of N balls into a QImage with the
// canvas's own painter and reports the median time per frame. Needs a
// QGuiApplication (fonts); the offscreen platform is enough.

#include <QList>
#include <QSize>
#include <QString>

namespace forcelab {

enum class BallDrawing {
    Sprites,  ///< cached ball images blitted (what the canvas does)
    Ellipses, ///< one antialiased drawEllipse per ball (the baseline)
};

struct RenderBenchOptions {
    QList<int> ballCounts{1000, 10000, 50000};
    QSize size{1280, 800};    ///< px of the image (device px, ratio 1)
    int frames = 30;          ///< timed frames per count (after two warm-up frames)
    double minRadius = 2.0;   ///< px, world radius range of the balls
    double maxRadius = 6.0;
    bool withEllipses = true; ///< also time the drawEllipse baseline
};

struct RenderBenchRow {
    int balls = 0;
    BallDrawing drawing = BallDrawing::Sprites;
    double medianMs = 0.0; ///< per frame
    double minMs = 0.0;
    double nsPerBall = 0.0; ///< median / balls
};

/// Times whole frames (box, grid, balls) of a 1200 × 800 px box filled with
/// random balls, every ball moved between frames so nothing is cached but the sprites.
QList<RenderBenchRow> runRenderBench(const RenderBenchOptions& options = {});

/// A fixed-width table of the rows, with a header naming the image size.
QString formatRenderBench(const QList<RenderBenchRow>& rows, const RenderBenchOptions& options);

} // namespace forcelab
