#pragma once
// The trails overlay's memory: the paths drawn as a layer the size of the box.
// Each frame draws only the segments recorded since the last one; the layer is
// drawn afresh when the view, the recorder or the window of records shown
// changes.

#include "sim/world/types.h"

#include <QImage>
#include <QPointF>
#include <QRectF>
#include <QtGlobal>

#include <vector>

namespace forcelab {

struct PathLayer {
    QImage image;
    quint64 generation = 0;
    qint64 start = -1;   ///< first record shown (TrailRecorder::recorded() numbering)
    qint64 drawnTo = -1; ///< last record drawn
    QRectF box;          ///< widget px the layer covers
    double scale = 0.0;
    QPointF origin;      ///< widget px of the world origin (a pan or a followed ball moves it)
    qreal dpr = 0.0;
    double lineScale = 0.0;
    std::vector<int> balls;
    std::vector<sim::Rgb> colors;
};

} // namespace forcelab
