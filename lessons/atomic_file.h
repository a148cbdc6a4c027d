#pragma once
// Files written all or nothing. Every export (the handbook, a CSV, a PNG, a
// saved lesson) goes through here: the bytes go to a temporary file beside
// the target, every write, the flush and the close are checked, and only
// then is it renamed over the target. On any failure the old file is left
// as it was and the error says why in one line; nothing claims success over
// a half-written file.

#include <QByteArray>
#include <QString>

#include <memory>

class QFileDevice;

namespace forcelab::lessons {

class AtomicFile {
public:
    explicit AtomicFile(const QString& path);
    ~AtomicFile(); // without commit(), the temporary file goes and the target stays as it was
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// Makes the temporary file, so a command can find out that it cannot
    /// write before it does long work. False: error() says why.
    bool open();
    /// Appends `bytes`; false (and error()) once any write failed.
    bool write(const QByteArray& bytes);
    /// Checks every write and the close, then puts the file in place.
    bool commit();
    /// "PATH: cannot write: REASON", or empty.
    QString error() const { return m_error; }

private:
    bool fail(const QString& reason);

    QString m_path;
    QString m_error;
    // A target that exists and is not a regular file (a device such as
    // /dev/full, a FIFO) is written in place: renaming over it would replace
    // the device. Every write and the close are still checked.
    bool m_inPlace = false;
    std::unique_ptr<QFileDevice> m_file;
};

/// `bytes` written to `path` all or nothing; false with `error` set.
bool writeFileAtomically(const QString& path, const QByteArray& bytes, QString* error);

} // namespace forcelab::lessons
