// SPDX-License-Identifier: GPL-3.0-or-later
// What may stand where a table file is expected: a FIFO, a device, a folder, a link that loops or leads
// nowhere. The rows and the makers for the tests that check each is refused by name, at once.
#pragma once

#include <sys/stat.h>

#include <QDir>
#include <QFile>
#include <QTest>

namespace Toffee::Test {

// Columns "kind" (for makeSpecialFile) and "expected" (what the refusal must say).
inline void addSpecialFileRows()
{
    using namespace Qt::StringLiterals;
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("expected");
    QTest::newRow("FIFO") << u"fifo"_s << u"named pipe (FIFO)"_s;
    QTest::newRow("link to /dev/zero") << u"zero"_s << u"device"_s;
    QTest::newRow("link to /dev/urandom") << u"urandom"_s << u"device"_s;
    QTest::newRow("folder") << u"folder"_s << u"folder"_s;
    QTest::newRow("symbolic link loop") << u"loop"_s << u"symbolic links"_s;
    QTest::newRow("dangling link") << u"dangling"_s << u"No such file"_s;
}

inline bool makeSpecialFile(const QString &kind, const QString &path)
{
    using namespace Qt::StringLiterals;
    if (kind == u"fifo")
        return ::mkfifo(QFile::encodeName(path).constData(), 0600) == 0;
    if (kind == u"zero" || kind == u"urandom")
        return QFile::link(u"/dev/"_s + kind, path);
    if (kind == u"folder")
        return QDir().mkpath(path);
    if (kind == u"loop")
        return QFile::link(path, path);
    return QFile::link(path + u".nothing-here"_s, path);
}

} // namespace Toffee::Test
