// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/linuxcnc/linuxcncreplies.h"

#include <cmath>

#include <QDir>
#include <QFileInfo>
#include <QList>

using namespace Qt::StringLiterals;

namespace Toffee::LinuxCnc {

bool isHelloAck(QByteArrayView line)
{
    return line.trimmed().startsWith("HELLO ACK");
}

bool isHelloNak(QByteArrayView line)
{
    return line.trimmed() == "HELLO NAK";
}

ReplyKind classify(QByteArrayView line)
{
    const QByteArrayView t = line.trimmed();
    if (isHelloAck(t) || (t.startsWith("SET ") && t.endsWith(" ACK")))
        return ReplyKind::Ok;
    if (isHelloNak(t) || t == "SET NAK" || t == "GET NAK"
        || ((t.startsWith("SET ") || t.startsWith("GET ")) && t.endsWith(" NAK")))
        return ReplyKind::Error;
    return ReplyKind::Other;
}

std::optional<QByteArray> valueOf(QByteArrayView line, QByteArrayView keyword)
{
    const QByteArrayView t = line.trimmed();
    if (!t.startsWith(keyword) || (t.size() > keyword.size() && t[keyword.size()] != ' '))
        return std::nullopt;
    return t.sliced(keyword.size()).trimmed().toByteArray();
}

QString State::word() const
{
    if (estop)
        return u"Estop"_s;
    if (!machineOn)
        return u"Off"_s;
    return idle() ? u"Idle"_s : u"Run"_s;
}

int homedJoints(QByteArrayView value)
{
    int homed = 0;
    const QList<QByteArray> words = value.toByteArray().simplified().split(' ');
    for (qsizetype i = 0; i < words.size() && i < 3; ++i)
        homed += words[i] == "YES" ? 1 : 0;
    return homed;
}

std::optional<std::array<double, 3>> position(QByteArrayView value)
{
    const QList<QByteArray> words = value.toByteArray().simplified().split(' ');
    if (words.size() < 3)
        return std::nullopt;
    std::array<double, 3> xyz {};
    for (int i = 0; i < 3; ++i) {
        bool ok = false;
        xyz[i] = words[i].toDouble(&ok);
        if (!ok || !std::isfinite(xyz[i]))
            return std::nullopt;
    }
    return xyz;
}

bool inInches(QByteArrayView codes)
{
    return codes.toByteArray().simplified().split(' ').contains("G20");
}

std::optional<std::map<QByteArray, double>> displayFields(QByteArrayView display, QByteArrayView marker)
{
    const QList<QByteArray> words = display.toByteArray().simplified().split(' ');
    if (words.isEmpty() || words.first() != marker)
        return std::nullopt;
    std::map<QByteArray, double> fields;
    for (qsizetype i = 1; i < words.size(); ++i) {
        const qsizetype eq = words[i].indexOf('=');
        if (eq <= 0)
            return std::nullopt;
        bool ok = false;
        const double value = words[i].mid(eq + 1).toDouble(&ok);
        if (!ok || !std::isfinite(value)) // "######": a parameter LinuxCNC does not know
            return std::nullopt;
        fields[words[i].left(eq)] = value;
    }
    return fields;
}

QString toolTableOfIni(const QByteArray &iniText, const QString &iniPath)
{
    bool inSection = false;
    for (const QByteArray &raw : iniText.split('\n')) {
        const QByteArray line = raw.trimmed();
        if (line.startsWith('[')) {
            inSection = line == "[EMCIO]";
            continue;
        }
        if (!inSection || line.startsWith('#') || line.startsWith(';'))
            continue;
        const qsizetype eq = line.indexOf('=');
        if (eq < 0 || line.left(eq).trimmed() != "TOOL_TABLE")
            continue;
        const QString file = QString::fromUtf8(line.mid(eq + 1).trimmed());
        if (file.isEmpty())
            return {};
        return QDir::cleanPath(
            QFileInfo(file).isAbsolute() ? file : QFileInfo(iniPath).absoluteDir().filePath(file));
    }
    return {};
}

} // namespace Toffee::LinuxCnc
