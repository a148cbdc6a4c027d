#pragma once
// The render benchmark: draws worlds of N balls into a QImage with the
// canvas's own painter and reports the median time per frame. Needs a
// QGuiApplication (fonts); the offscreen platform is enough.

#include <QList>
#include <QSize>
#include <QString>
#include <QStringList>

namespace forcelab {

enum class BallDrawing {
    Sprites,  ///< cached ball images blitted with drawImage (what the canvas does)
    Ellipses, ///< one antialiased drawEllipse per ball (the baseline)
};

struct RenderBenchOptions {
    QList<int> ballCounts{1000, 10000, 50000};
    QSize size{1280, 800};    ///< px of the image (device px, ratio 1)
    int frames = 30;          ///< timed frames per count (after two warm-up frames)
    double fill = 0.3;        ///< share of the box's area covered by balls (radii follow from N)
    bool withBaseline = true; ///< also time the drawEllipse baseline
    /// Lessons drawn as the canvas shows them with paths (trails) on, at
    /// `lessonSize`, after `lessonWarmUp` frames (one step each) so the paths
    /// are long; built-in ids.
    QStringList pathLessons{QStringLiteral("bounce-at-the-right-moment")};
    QSize lessonSize{1280, 720};
    int lessonWarmUp = 300;
};

struct RenderBenchRow {
    int balls = 0;
    double meanRadius = 0.0; ///< px (world; the image shows the box at scale 0.975)
    BallDrawing drawing = BallDrawing::Sprites;
    double medianMs = 0.0; ///< per frame, wall clock
    double minMs = 0.0;
    double cpuMedianMs = 0.0; ///< per frame, this thread's CPU time (what a busy machine does not inflate)
    double nsPerBall = 0.0; ///< median / balls
    double maxMs = 0.0;     ///< the slowest timed frame
    QString lesson;         ///< the lesson id of a lesson row, empty for a row of random balls
    bool incremental = true; ///< a lesson row: paths appended to a layer (true) or redrawn whole each frame
};

/// Times whole frames (box, grid, balls) of a 1200 × 800 px box with N
/// random balls covering `fill` of its area (radii 0.7 … 1.3 × the mean, as
/// in a box about 30% full), every ball moved between frames so nothing is
/// cached but the sprites.
QList<RenderBenchRow> runRenderBench(const RenderBenchOptions& options = {});

/// Then one row per options.pathLessons: the lesson's own overlays plus
/// paths, stepped once per frame (the step is not timed, the paths are
/// recorded as the canvas records them).
///
/// A fixed-width table of the rows, with a header naming the image size.
QString formatRenderBench(const QList<RenderBenchRow>& rows, const RenderBenchOptions& options);

} // namespace forcelab
