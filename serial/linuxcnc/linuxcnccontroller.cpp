// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/linuxcnc/linuxcnccontroller.h"

#include <cmath>

#include <QPointer>
#include <QRandomGenerator>
#include <QTcpSocket>
#include <QTimer>

#include "model/limits.h"
#include "model/numberformat.h"
#include "serial/transport/tcptransport.h"

using namespace Qt::StringLiterals;

namespace Toffee {

ReplyGrammar LinuxCncController::grammar()
{
    ReplyGrammar g = ReplyGrammar::basic();
    g.classify = LinuxCnc::classify;
    g.message = [](QByteArrayView line) {
        return QString::fromUtf8(line.trimmed());
    };
    g.refusalMeaning = [](QStringView) {
        return QString();
    };
    return g;
}

LinuxCncController::LinuxCncController(MachineLink *link, QObject *parent)
    : MachineController(parent)
    , m_link(link)
{
    m_link->setGrammar(grammar());
    // linuxcncrsh has no status report to poll: its state is asked for with gets, between commands.
    m_link->setPollInterval(0);
    m_firmware.kind = FirmwareInfo::Kind::LinuxCnc;
    m_session = QByteArray::number(QRandomGenerator::global()->generate(), 36);
    m_poll = new QTimer(this);
    m_poll->setInterval(kPollIntervalMs);
    connect(m_poll, &QTimer::timeout, this, &LinuxCncController::poll);
    connect(m_link, &MachineLink::closed, m_poll, &QTimer::stop);
}

void LinuxCncController::poll()
{
    if (!m_link->isOpen())
        return m_poll->stop();
    // Between an operation's lines too the link is busy: its next line is queued as the last one's answer
    // comes.
    if (m_link->isBusy() || m_polling)
        return;
    m_polling = true;
    readState([this](const SessionResult &) { m_polling = false; },
        [this](const LinuxCnc::State &) { m_polling = false; });
}

QString LinuxCncController::mm(double v)
{
    return formatNumber(v, NumberFormat::fixed(3));
}

double LinuxCncController::atResolution(double v)
{
    return std::round(v * 1000.0) / 1000.0;
}

QByteArray LinuxCncController::number(double value)
{
    return numberBytes(value, NumberFormat::command());
}

void LinuxCncController::set(const QByteArray &what, int timeoutMs, Done done, Next next)
{
    m_link->send("set " + what, timeoutMs, [done, next = std::move(next)](const CommandReply &reply) {
        if (!reply.ok()) {
            done(failure(reply));
            return;
        }
        next(reply);
    });
}

void LinuxCncController::sendEnable(int timeoutMs, std::function<void(const CommandReply &)> handler)
{
    // The password is never shown: not in the console (a quiet line), not in any message (named without it).
    m_link->sendQuietly(
        "set enable " + m_enablePassword, timeoutMs, std::move(handler), ReplyEnd::Ok, "set enable …");
}

void LinuxCncController::lastError(std::function<void(const QString &)> next)
{
    m_link->send(
        "get error", MachineLink::kDefaultTimeoutMs,
        [next](const CommandReply &reply) {
            for (const QByteArray &line : reply.lines) {
                if (const auto value = LinuxCnc::valueOf(line, "ERROR"))
                    return next(*value == "OK" ? QString() : QString::fromUtf8(*value));
            }
            next({});
        },
        ReplyEnd::Line);
}

void LinuxCncController::mdi(const QByteArray &line, int timeoutMs, Done done, Next next)
{
    const QByteArray command = "set mdi " + line;
    if (command.size() > LinuxCnc::kMaxLineBytes || line.contains('\n') || line.contains('\r')) {
        refuse(done,
            tr("The line \"%1\" is too long for linuxcncrsh; nothing was sent.")
                .arg(QString::fromUtf8(line)));
        return;
    }
    m_link->send(command, timeoutMs, [this, done, line, next = std::move(next)](const CommandReply &reply) {
        // Stopped here (set abort): whatever the line's answer, it did not run to its end; nothing after it
        // is sent.
        if (m_abortedHere && reply.status != CommandReply::Status::LinkLost)
            return done(SessionResult::failed(SessionResult::Outcome::MachineError,
                tr("Stopped: LinuxCNC aborted \"%1\" where the machine stood. Nothing was measured or "
                   "written; check where the spindle is before you go on.")
                    .arg(QString::fromUtf8(line))));
        if (reply.status != CommandReply::Status::Refused) {
            if (!reply.ok())
                return done(failure(reply));
            return next(reply);
        }
        // LinuxCNC says why in its error queue.
        lastError([done, line](const QString &error) {
            done(SessionResult::failed(SessionResult::Outcome::MachineError,
                error.isEmpty()
                    ? tr("LinuxCNC refused \"%1\" and did not say why (get error: OK). Check LinuxCNC's own "
                         "screen.")
                          .arg(QString::fromUtf8(line))
                    : tr("LinuxCNC refused \"%1\": %2").arg(QString::fromUtf8(line), error)));
        });
    });
}

void LinuxCncController::mdiChain(
    const QList<QByteArray> &lines, int timeoutMs, Done done, std::function<void()> next)
{
    if (lines.isEmpty())
        return next();
    mdi(lines.first(), timeoutMs, done, [this, lines, timeoutMs, done, next](const CommandReply &) {
        mdiChain(lines.mid(1), timeoutMs, done, next);
    });
}

void LinuxCncController::get(const QByteArray &what, const QByteArray &keyword, Done done,
    std::function<void(const QByteArray &)> next, bool again)
{
    auto answered = [this, done, what, keyword, next, again](const CommandReply &reply) {
        // Right after an abort linuxcncrsh may refuse a get once (GET NAK, seen under a slow, sanitized
        // build): a read changes nothing, so it is asked once more before it counts as refused.
        if (reply.status == CommandReply::Status::Refused && !again && m_link->isOpen())
            return QTimer::singleShot(kGetRetryMs, this,
                [this, what, keyword, done, next] { get(what, keyword, done, next, true); });
        if (!reply.ok())
            return done(failure(reply));
        for (const QByteArray &line : reply.lines) {
            if (const auto value = LinuxCnc::valueOf(line, keyword))
                return next(*value);
        }
        done(SessionResult::failed(SessionResult::Outcome::MachineError,
            tr("linuxcncrsh answered \"get %1\" with something else (%2); is this LinuxCNC?")
                .arg(QString::fromUtf8(what), QString::fromUtf8(reply.lines.value(0).left(80)))));
    };
    // The state asked for every half second is not said in the console.
    if (m_polling)
        m_link->sendQuietly("get " + what, MachineLink::kDefaultTimeoutMs, answered, ReplyEnd::Line);
    else
        m_link->send("get " + what, MachineLink::kDefaultTimeoutMs, answered, ReplyEnd::Line);
}

void LinuxCncController::connectToMachine(Done done)
{
    m_poll->stop();
    done = [this, done](const SessionResult &result) {
        if (result.ok())
            m_poll->start();
        done(result);
    };
    openLink(done, [this, done] {
        // Ended by HELLO ACK or NAK; a second hello (after the detector's) comes back echoed first.
        auto heard = std::make_shared<QMetaObject::Connection>();
        *heard = connect(m_link, &MachineLink::lineReceived, this, [this](const QByteArray &line) {
            // "HELLO ACK EMCNETSVR 1.1": the server's name and linuxcncrsh's protocol, not LinuxCNC's version
            // (read once it can run MDI).
            if (LinuxCnc::isHelloAck(line))
                m_firmware.version = u"(linuxcncrsh %1)"_s.arg(QString::fromUtf8(line.trimmed().mid(10)));
        });
        m_link->send(
            LinuxCnc::kHello, MachineLink::kDefaultTimeoutMs, [this, done, heard](const CommandReply &reply) {
                disconnect(*heard);
                if (reply.status == CommandReply::Status::Refused)
                    return done(SessionResult::failed(SessionResult::Outcome::Refused,
                        tr("linuxcncrsh refused Toffee's hello (HELLO NAK): it was started with a connect "
                           "password "
                           "of its own (--connectpw), which Toffee does not know. Start it with the default "
                           "(EMC), "
                           "then connect again.")));
                if (!reply.ok())
                    return done(failure(reply));
                afterHello(done);
            });
    });
}

void LinuxCncController::afterHello(Done done)
{
    const int limit = MachineLink::kDefaultTimeoutMs;
    set("verbose on", limit, done, [=, this](const CommandReply &) {
        set("echo off", limit, done, [=, this](const CommandReply &) {
            sendEnable(limit, [=, this](const CommandReply &enabled) {
                if (enabled.status == CommandReply::Status::Refused)
                    return done(SessionResult::failed(SessionResult::Outcome::Refused,
                        tr("LinuxCNC refused the enable password in this machine's settings (linuxcncrsh "
                           "--enablepw). Set the right one, then connect again. Nothing was sent.")));
                if (!enabled.ok())
                    return done(failure(enabled));
                m_abortedHere = false;
                set("set_wait done", limit, done, [=, this](const CommandReply &) {
                    get("user_linear_units", "USER_LINEAR_UNITS", done, [=, this](const QByteArray &units) {
                        if (units != "MM")
                            return done(SessionResult::failed(SessionResult::Outcome::Refused,
                                tr("This LinuxCNC's machine units are %1 ([TRAJ] LINEAR_UNITS); Toffee reads "
                                   "and writes millimetres only. Nothing was sent.")
                                    .arg(QString::fromUtf8(units))));
                        locateTable(done, [=, this] {
                            readState(done, [=, this](const LinuxCnc::State &state) {
                                SessionResult result
                                    = tloResult(state.tool > 0 ? state.tool : Limits::kEmptySpindle,
                                        m_tloInForce.value_or(0.0), std::nullopt);
                                result.status = statusOf(state);
                                result.controllerTools = m_table;
                                if (notReady(state, {}))
                                    return done(result);
                                // Ready for MDI: what is in force now, and which LinuxCNC this is.
                                printFields("TOFFEE-VER", "v=#<_vmajor> m=#<_vminor>", done,
                                    [=, this](const Fields &f) mutable {
                                        m_firmware.version = u"%1.%2"_s.arg(f.at("v")).arg(f.at("m"));
                                        readOffsetInForce(done, [=, this]() mutable {
                                            result.tlo = TloReading { m_tloInForce.value_or(0.0), m_reference,
                                                std::nullopt };
                                            result.status->tlo = m_tloInForce;
                                            done(result);
                                        });
                                    });
                            });
                        });
                    });
                });
            });
        });
    });
}

void LinuxCncController::status(Done done)
{
    readState(done, [this, done](const LinuxCnc::State &state) {
        SessionResult result;
        result.status = statusOf(state);
        result.tool = result.status->tool;
        done(result);
    });
}

void LinuxCncController::report(Done done)
{
    readState(done, [this, done](const LinuxCnc::State &state) {
        auto finish = [this, done, state] {
            SessionResult result = tloResult(state.tool > 0 ? state.tool : Limits::kEmptySpindle,
                m_tloInForce.value_or(0.0), std::nullopt);
            result.status = statusOf(state);
            result.controllerTools = m_table;
            done(result);
        };
        readTableFile([this, done, state, finish](const QString &) {
            if (notReady(state, {}))
                return finish();
            readOffsetInForce(done, finish);
        });
    });
}

void LinuxCncController::selectTool(int tool, Done done)
{
    if (auto valid = validateToolNumber(tool); !valid) {
        refuse(done, valid.error().message);
        return;
    }
    ready(done, tr("select a tool"), [this, done, tool](const LinuxCnc::State &) {
        mdi("M61 Q" + QByteArray::number(std::max(tool, 0)), MachineLink::kDefaultTimeoutMs, done,
            [this, done, tool](const CommandReply &) {
                get("tool", "TOOL", done, [this, done, tool](const QByteArray &value) {
                    const int now = value.toInt();
                    m_tool = now > 0 ? now : Limits::kEmptySpindle;
                    SessionResult result;
                    result.tool = m_tool;
                    if (now != std::max(tool, 0)) {
                        result.outcome = SessionResult::Outcome::MachineError;
                        result.message
                            = tr("LinuxCNC was told T%1 is in the spindle but says T%2.").arg(tool).arg(now);
                    }
                    done(result);
                });
            });
    });
}

QString LinuxCncController::changeByHand(int tool) const
{
    // LinuxCNC's change is its HAL's: with hal_manualtoolchange it asks at LinuxCNC's own screen, which
    // Toffee cannot see; so a person must be there to answer it.
    return tool > 0 ? tr("T%1 may be asked for at LinuxCNC's own screen (its manual tool change)").arg(tool)
                    : QString();
}

void LinuxCncController::startToolChange(int tool, Done done, std::optional<double> storedTlo)
{
    if (auto valid = validateToolNumber(tool); !valid || tool <= 0) {
        refuse(done,
            valid ? tr("LinuxCNC changes to a tool, not to an empty spindle: use Select Tool with T0.")
                  : valid.error().message);
        return;
    }
    ready(done, tr("change tools"), [this, done, tool, storedTlo](const LinuxCnc::State &) {
        // The ACK waits for the change to end (LinuxCNC's tool-changed), for as long as a person may take.
        mdi("M6 T" + QByteArray::number(tool), operatorWaitMs() + MachineLink::kMotionTimeoutMs, done,
            [this, done, tool, storedTlo](const CommandReply &) {
                get("tool", "TOOL", done, [this, done, tool, storedTlo](const QByteArray &value) {
                    if (value.toInt() != tool)
                        return done(SessionResult::failed(SessionResult::Outcome::MachineError,
                            tr("LinuxCNC ended the change to T%1 with T%2 in the spindle: nothing was "
                               "measured.")
                                .arg(tool)
                                .arg(QString::fromUtf8(value))));
                    m_tool = tool;
                    if (storedTlo)
                        restoreTlo(tool, *storedTlo, done);
                    else
                        probe(done);
                });
            });
    });
}

QString LinuxCncController::cancelledChangeNote() const
{
    return tr("LinuxCNC's change was aborted (set abort): check what is in the spindle, then select it and "
              "restore or probe its TLO before cutting.");
}

void LinuxCncController::unlock(Done done, std::optional<double> brokenToolTlo)
{
    Q_UNUSED(brokenToolTlo) // a failed break test changed nothing in LinuxCNC
    status(done);
}

void LinuxCncController::abort()
{
    if (!m_link->isOpen())
        return;
    m_abortedHere = true;
    if (!m_link->isBusy()) {
        m_link->send("set abort", MachineLink::kDefaultTimeoutMs, [](const CommandReply &) {});
        return;
    }
    abortOnSecondConnection();
}

// linuxcncrsh reads one line at a time per connection: while this one waits for its MDI line's ACK, the abort
// goes on a connection of its own, which takes the enable (this connection takes it back before its next
// set).
void LinuxCncController::abortOnSecondConnection()
{
    const auto *tcp = qobject_cast<const TcpTransport *>(m_link->transport());
    if (!tcp)
        return;
    auto *socket = new QTcpSocket(this);
    QTimer::singleShot(MachineLink::kDefaultTimeoutMs, socket, [socket] {
        socket->abort();
        socket->deleteLater();
    });
    const QByteArray lines = QByteArray("\n") + LinuxCnc::kHello + "\nset verbose on\nset enable "
        + m_enablePassword + "\nset abort\n";
    connect(socket, &QTcpSocket::connected, socket, [socket, lines] { socket->write(lines); });
    connect(socket, &QTcpSocket::readyRead, socket, [socket] {
        if (socket->readAll().contains("SET ABORT")) {
            socket->disconnectFromHost();
            socket->deleteLater();
        }
    });
    socket->connectToHost(tcp->address().host, tcp->address().port);
}

} // namespace Toffee
