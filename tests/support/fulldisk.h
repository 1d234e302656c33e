// SPDX-License-Identifier: GPL-3.0-or-later
// A real full disk for the tests: a small tmpfs mounted in a temporary folder where the test runs as root (as
// CI does), filled to its last byte once the test's files are in place. Where no file system can be mounted,
// the process's file-size limit (RLIMIT_FSIZE, inherited by the programs a test starts) stands in, and
// writes then fail with "File too large" instead of "No space left on device".
#pragma once

#include <csignal>
#include <sys/resource.h>
#include <unistd.h>

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

namespace Toffee::Test {

class FullDisk
{
    Q_DISABLE_COPY_MOVE(FullDisk)

public:
    // `bytes`: the size of the file system (a tmpfs rounds it up to whole pages).
    explicit FullDisk(qint64 bytes = 256 * 1024)
    {
        std::signal(SIGXFSZ, SIG_IGN); // the limit fails a write instead of killing the test
        m_mounted = ::geteuid() == 0
            && QProcess::execute(QStringLiteral("mount"),
                   { QStringLiteral("-t"), QStringLiteral("tmpfs"), QStringLiteral("-o"),
                       QStringLiteral("size=%1").arg(bytes), QStringLiteral("tmpfs"), m_dir.path() })
                == 0;
    }
    ~FullDisk()
    {
        if (m_limited) {
            ::setrlimit(RLIMIT_FSIZE, &m_oldLimit);
        }
        if (m_mounted)
            QProcess::execute(QStringLiteral("umount"), { m_dir.path() });
    }

    [[nodiscard]] bool isMounted() const { return m_mounted; }
    [[nodiscard]] QString path(const QString &name) const { return m_dir.filePath(name); }
    // What the system says when a write no longer fits.
    [[nodiscard]] QString reason() const
    {
        return m_mounted ? QStringLiteral("No space left on device") : QStringLiteral("File too large");
    }

    // Fills the disk but for `spare` bytes. Without a mount, no file may grow beyond `limit` bytes from now
    // on (the files already there stay as they are).
    void fill(qint64 spare = 0, qint64 limit = 512)
    {
        if (!m_mounted) {
            ::getrlimit(RLIMIT_FSIZE, &m_oldLimit);
            rlimit lower = m_oldLimit;
            lower.rlim_cur = rlim_t(limit);
            m_limited = ::setrlimit(RLIMIT_FSIZE, &lower) == 0;
            return;
        }
        QFile filler(path(QStringLiteral(".filler")));
        if (!filler.open(QIODevice::WriteOnly | QIODevice::Unbuffered))
            return;
        const QByteArray block(4096, 'x');
        while (filler.write(block) == block.size()) { }
        while (filler.write("x", 1) == 1) { }
        filler.close();
        // Give back what was asked for, a page at a time.
        if (spare > 0)
            filler.resize(std::max<qint64>(0, filler.size() - spare));
    }

    // Makes room again: the filler goes, the file-size limit is lifted.
    void free()
    {
        QFile::remove(path(QStringLiteral(".filler")));
        if (m_limited) {
            ::setrlimit(RLIMIT_FSIZE, &m_oldLimit);
            m_limited = false;
        }
    }

private:
    QTemporaryDir m_dir;
    bool m_mounted = false;
    bool m_limited = false;
    rlimit m_oldLimit {};
};

} // namespace Toffee::Test
