#include "atomic_file.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

namespace forcelab::lessons {

AtomicFile::AtomicFile(const QString& path)
    : m_path(path)
{
}

AtomicFile::~AtomicFile()
{
    if (auto* save = qobject_cast<QSaveFile*>(m_file.get()); save && save->isOpen())
        save->cancelWriting(); // the temporary file goes; the target is untouched
}

bool AtomicFile::fail(const QString& reason)
{
    if (m_error.isEmpty())
        m_error = QStringLiteral("%1: cannot write: %2").arg(m_path, reason);
    if (auto* save = qobject_cast<QSaveFile*>(m_file.get()); save && save->isOpen())
        save->cancelWriting();
    return false;
}

bool AtomicFile::open()
{
    if (m_file)
        return m_error.isEmpty();
    const QFileInfo info(m_path);
    if (m_path.isEmpty())
        return fail(QStringLiteral("no file name"));
    if (info.exists() && info.isDir())
        return fail(QStringLiteral("it is a folder"));
    m_inPlace = info.exists() && !info.isFile();
    if (m_inPlace) {
        auto file = std::make_unique<QFile>(m_path);
        if (!file->open(QIODevice::WriteOnly))
            return fail(file->errorString());
        m_file = std::move(file);
    } else {
        auto file = std::make_unique<QSaveFile>(m_path);
        if (!file->open(QIODevice::WriteOnly))
            return fail(file->errorString());
        m_file = std::move(file);
    }
    return true;
}

bool AtomicFile::write(const QByteArray& bytes)
{
    if (!open())
        return false;
    if (!m_error.isEmpty())
        return false;
    if (m_file->write(bytes) != bytes.size())
        return fail(m_file->errorString());
    return true;
}

bool AtomicFile::commit()
{
    if (!open() || !m_error.isEmpty())
        return false;
    if (m_inPlace) {
        auto* file = static_cast<QFile*>(m_file.get());
        if (!file->flush())
            return fail(file->errorString());
        file->close();
        if (file->error() != QFileDevice::NoError)
            return fail(file->errorString());
        return true;
    }
    auto* save = static_cast<QSaveFile*>(m_file.get());
    if (!save->commit())
        return fail(save->errorString());
    return true;
}

bool writeFileAtomically(const QString& path, const QByteArray& bytes, QString* error)
{
    AtomicFile file(path);
    const bool ok = file.write(bytes) && file.commit();
    if (!ok && error)
        *error = file.error();
    return ok;
}

} // namespace forcelab::lessons
