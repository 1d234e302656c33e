// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/controllerdetection.h"

#include "serial/carvera/carverareplies.h"
#include "serial/grblhal/grblhalreplies.h"
#include "serial/linuxcnc/linuxcncreplies.h"
#include "serial/machine/machinelink.h"
#include "serial/transport/linetransport.h"
#include "serial/transport/streamtransport.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// A reply's words for a message: its first lines, printable, short.
QString said(const CommandReply &reply)
{
    QStringList lines;
    for (const QByteArray &line : reply.lines) {
        QString text;
        for (const char c : line.left(80))
            text += c >= 0x20 && c < 0x7f ? QChar::fromLatin1(c) : u'·';
        if (!text.trimmed().isEmpty())
            lines << text.trimmed();
        if (lines.size() == 3)
            break;
    }
    if (lines.isEmpty() && !reply.ok() && !reply.message.isEmpty())
        return reply.message;
    return lines.isEmpty() ? ControllerDetector::tr("nothing") : u"\""_s + lines.join(u" / "_s) + u'"';
}

} // namespace

QString controllerKindName(ControllerKind kind)
{
    switch (kind) {
    case ControllerKind::Auto:
        return u"auto"_s;
    case ControllerKind::Carvera:
        return u"carvera"_s;
    case ControllerKind::GrblHal:
        return u"grblhal"_s;
    case ControllerKind::LinuxCnc:
        return u"linuxcnc"_s;
    }
    return {};
}

QString controllerKindTitle(ControllerKind kind)
{
    switch (kind) {
    case ControllerKind::Auto:
        return ControllerDetector::tr("Automatic");
    case ControllerKind::Carvera:
        return u"Carvera"_s;
    case ControllerKind::GrblHal:
        return u"grblHAL"_s;
    case ControllerKind::LinuxCnc:
        return u"LinuxCNC"_s;
    }
    return {};
}

QList<ControllerKind> controllerKinds()
{
    return { ControllerKind::Auto, ControllerKind::Carvera, ControllerKind::GrblHal,
        ControllerKind::LinuxCnc };
}

bool keepsOwnReference(ControllerKind kind)
{
    return kind == ControllerKind::Carvera;
}

QString dialectKeyOf(ControllerKind kind)
{
    return kind == ControllerKind::Auto ? u"carvera"_s : controllerKindName(kind);
}

ControllerDetector::ControllerDetector(MachineLink *link, QObject *parent)
    : QObject(parent)
    , m_link(link)
{
    m_openGuard.setSingleShot(true);
    m_openGuard.setTimerType(Qt::PreciseTimer);
}

void ControllerDetector::detect(Done done)
{
    m_done = std::move(done);
    if (m_link->isOpen())
        return ask();
    auto fail = [this](const QString &message) {
        finish(Error { message });
    };
    m_opening << connect(m_link, &MachineLink::opened, this, &ControllerDetector::ask);
    m_opening << connect(m_link->transport(), &LineTransport::errorOccurred, this, fail);
    m_opening << connect(m_link, &MachineLink::closed, this, fail);
    // A backstop: the transport says itself why it did not open, within its own limit.
    const int limitMs = m_link->transport()->openLimitMs() + 1000;
    connect(&m_openGuard, &QTimer::timeout, this, [this, fail, limitMs] {
        fail(tr("The link to %1 did not open within %2 s. Check the machine and the connection, then try "
                "again.")
                 .arg(m_link->transport()->description())
                 .arg(limitMs / 1000));
    });
    m_openGuard.start(limitMs);
    m_link->open();
}

void ControllerDetector::ask()
{
    m_openGuard.stop();
    for (const QMetaObject::Connection &c : std::as_const(m_opening))
        disconnect(c);
    m_opening.clear();
    // Makera's frames are the Carvera's alone; its firmware said which version it runs then, and says it
    // again to the Carvera's own connect.
    const auto *stream = qobject_cast<const StreamTransport *>(m_link->transport());
    if (stream && stream->mode() == ConsoleStream::Mode::Framed)
        return finish(DetectedController { ControllerKind::Carvera, {}, {} });
    // Nothing answered the transport's first question: a Carvera and grblHAL always do; LinuxCNC's console
    // answers only after its hello.
    if (stream && stream->openedSilent())
        return askHello();
    m_link->send(
        "version", MachineLink::kDefaultTimeoutMs,
        [this](const CommandReply &reply) {
            if (reply.status == CommandReply::Status::Timeout
                || reply.status == CommandReply::Status::LinkLost)
                return finish(Error { tr("%1 The controller was asked which it is (\"version\") and did not "
                                         "answer; nothing else was sent.")
                                          .arg(reply.message) });
            for (const QByteArray &line : reply.lines) {
                if (auto firmware = parseVersion(line))
                    return finish(DetectedController { ControllerKind::Carvera, *firmware, {} });
            }
            askBuild(said(reply));
        },
        ReplyEnd::Line);
}

void ControllerDetector::askBuild(const QString &versionAnswer)
{
    m_link->send("$I", MachineLink::kDefaultTimeoutMs, [this, versionAnswer](const CommandReply &reply) {
        GrblHal::BuildInfoBuilder build;
        for (const QByteArray &line : reply.lines)
            build.addLine(line);
        if (build.info().isGrblHal()) {
            FirmwareInfo firmware;
            firmware.kind = FirmwareInfo::Kind::GrblHal;
            firmware.version = build.info().version;
            firmware.toolTableSize = build.info().toolTableSize;
            return finish(DetectedController { ControllerKind::GrblHal, firmware, build.info().buildName });
        }
        if (build.hasVersionAndOptions())
            return finish(
                Error { tr("The controller answered $I as Grbl does but did not say it is grblHAL "
                           "([FIRMWARE:grblHAL]): it may be classic Grbl, which keeps no tool table. "
                           "Toffee manages Carvera and grblHAL machines; nothing else was sent.") });
        finish(Error {
            tr("The controller is not a Carvera, grblHAL or LinuxCNC, the controllers Toffee manages: it "
               "answered \"version\" with %1 and \"$I\" with %2. Nothing else was sent. If it is "
               "one of them, choose it (Carvera, grblHAL or LinuxCNC; toffee-cli --controller) and connect "
               "again.")
                .arg(versionAnswer, said(reply)) });
    });
}

void ControllerDetector::askHello()
{
    m_link->send(
        LinuxCnc::kHello, MachineLink::kDefaultTimeoutMs,
        [this](const CommandReply &reply) {
            for (const QByteArray &line : reply.lines) {
                if (LinuxCnc::isHelloAck(line) || LinuxCnc::isHelloNak(line)) {
                    FirmwareInfo firmware;
                    firmware.kind = FirmwareInfo::Kind::LinuxCnc;
                    return finish(DetectedController { ControllerKind::LinuxCnc, firmware, {} });
                }
            }
            if (reply.status == CommandReply::Status::Timeout
                || reply.status == CommandReply::Status::LinkLost)
                return finish(
                    Error { tr("%1 The machine answered nothing: not to the Carvera's and grblHAL's "
                               "first question, nor to LinuxCNC's hello. Check that it is switched on "
                               "and has started, and the address and port.")
                                .arg(reply.message) });
            finish(Error {
                tr("The controller is none of those Toffee manages: it answered LinuxCNC's hello with "
                   "%1. Nothing else was sent.")
                    .arg(said(reply)) });
        },
        ReplyEnd::Line);
}

void ControllerDetector::finish(const Result<DetectedController> &result)
{
    m_openGuard.stop();
    for (const QMetaObject::Connection &c : std::as_const(m_opening))
        disconnect(c);
    m_opening.clear();
    if (Done done = std::exchange(m_done, nullptr))
        done(result);
}

} // namespace Toffee
