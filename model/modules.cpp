// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/modules.h"

#include <QDir>
#include <QFileInfo>
#include <QLibrary>
#include <QMutex>

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QMutex directoryLock;
QString &directoryOverride()
{
    static QString directory;
    return directory;
}

} // namespace

QString modulePath(QLatin1StringView file)
{
    QString directory;
    {
        const QMutexLocker lock(&directoryLock);
        directory = directoryOverride();
    }
    if (directory.isEmpty()) // beside the program: /proc/self/exe, also where there is no QCoreApplication
        directory
            = QFileInfo(u"/proc/self/exe"_s).canonicalPath() + QStringLiteral("/" TOFFEE_MODULE_RELATIVE_DIR);
    return QDir::cleanPath(directory + u'/' + file);
}

QString guidePath()
{
    return QDir::cleanPath(QFileInfo(u"/proc/self/exe"_s).canonicalPath()
        + QStringLiteral("/" TOFFEE_GUIDE_RELATIVE_DIR "/GUIDE.md"));
}

Result<QFunctionPointer> resolveInModule(QLatin1StringView file, const char *symbol)
{
    const QString path = modulePath(file);
    if (!QFileInfo::exists(path)) {
        Error missing(QString(), 0, path);
        missing.code = kModuleMissing;
        return missing;
    }
    QLibrary module(path);
    // Kept loaded: QLibrary's object going out of scope does not unload the library.
    if (QFunctionPointer function = module.resolve(symbol))
        return function;
    return Error(module.errorString(), 0, path);
}

void setModuleDirectory(const QString &directory)
{
    const QMutexLocker lock(&directoryLock);
    directoryOverride() = directory;
}

} // namespace Toffee
