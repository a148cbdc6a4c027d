#pragma once
// A picture written as a PNG file all or nothing (lessons/atomic_file.h): on
// a full or read-only disk the old file stays whole and the error says so.

#include "lessons/atomic_file.h"

#include <QBuffer>
#include <QImage>

namespace forcelab {

inline bool writePngAtomically(const QString& path, const QImage& image, QString* error)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    if (!buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, "PNG")) {
        if (error)
            *error = QStringLiteral("%1: cannot write: the picture could not be made into a PNG").arg(path);
        return false;
    }
    return lessons::writeFileAtomically(path, bytes, error);
}

} // namespace forcelab
