// SPDX-License-Identifier: GPL-3.0-or-later
// What LinuxCNC is doing, asked with linuxcncrsh's gets: its state, whether it can take an operation now (and
// what to do when not), the offset in force, values printed through (DEBUG,…), and its table file.
#include "serial/linuxcnc/linuxcnccontroller.h"

#include <QFile>
#include <QFileInfo>
#include <QHostAddress>

#include "model/formats/tablefile.h"
#include "serial/transport/tcptransport.h"

using namespace Qt::StringLiterals;

namespace Toffee {

void LinuxCncController::readState(Done done, std::function<void(const LinuxCnc::State &)> next)
{
    auto state = std::make_shared<LinuxCnc::State>();
    get("estop", "ESTOP", done, [=, this](const QByteArray &estop) {
        state->estop = estop != "OFF";
        get("machine", "MACHINE", done, [=, this](const QByteArray &machine) {
            state->machineOn = machine == "ON";
            get("mode", "MODE", done, [=, this](const QByteArray &mode) {
                state->mode = mode;
                get("program_status", "PROGRAM_STATUS", done, [=, this](const QByteArray &program) {
                    state->program = program;
                    get("joint_homed", "JOINT_HOMED", done, [=, this](const QByteArray &homed) {
                        state->homedJoints = LinuxCnc::homedJoints(homed);
                        get("enable", "ENABLE", done, [=, this](const QByteArray &enable) {
                            state->enabled = enable == "ON";
                            get("tool", "TOOL", done, [=, this](const QByteArray &tool) {
                                state->tool = std::max(0, tool.toInt());
                                m_tool = state->tool > 0 ? state->tool : Limits::kEmptySpindle;
                                get("program_codes", "PROGRAM_CODES", done,
                                    [=, this](const QByteArray &codes) {
                                        state->programCodes = codes;
                                        state->millimetres = !LinuxCnc::inInches(codes);
                                        get("abs_act_pos", "ABS_ACT_POS", done,
                                            [=, this](const QByteArray &pos) {
                                                if (const auto xyz = LinuxCnc::position(pos))
                                                    state->machinePosition = *xyz;
                                                m_link->reportStatus(statusOf(*state));
                                                next(*state);
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

MachineStatus LinuxCncController::statusOf(const LinuxCnc::State &state) const
{
    MachineStatus s;
    s.state = state.word();
    s.mpos = state.machinePosition;
    s.wpos = state.machinePosition;
    s.tool = state.tool > 0 ? state.tool : Limits::kEmptySpindle;
    s.tlo = m_tloInForce;
    return s;
}

std::optional<QString> LinuxCncController::notReady(const LinuxCnc::State &state, const QString &what) const
{
    const QString before = what.isEmpty() ? QString() : tr("Toffee cannot %1 now: ").arg(what);
    const QString nothing = u' ' + tr("Nothing was sent.");
    if (state.estop)
        return before
            + tr(
                "LinuxCNC is in estop. Release it at the machine (in AXIS: F1), then try again; Toffee never "
                "releases an estop itself.")
            + nothing;
    if (!state.machineOn)
        return before + tr("LinuxCNC's machine is off. Switch it on (in AXIS: F2), then try again.")
            + nothing;
    if (!state.homed())
        return before + tr("LinuxCNC is not homed. Home every axis (in AXIS: Ctrl-Home), then try again.")
            + nothing;
    if (!state.idle())
        return before
            + tr("LinuxCNC is running a program or a line (%1). Wait until it is idle, then try again.")
                  .arg(QString::fromUtf8(state.program))
            + nothing;
    if (state.mode != "MDI")
        return before
            + tr(
                "LinuxCNC is in %1 mode; Toffee works through MDI and does not switch modes itself (a switch "
                "aborts whatever runs). Switch it to MDI (in AXIS: F5), then try again.")
                  .arg(QString::fromUtf8(state.mode).toLower())
            + nothing;
    if (!state.enabled && !m_abortedHere)
        return before
            + tr("Another program took control of LinuxCNC (linuxcncrsh's enable) since Toffee connected. "
                 "Make sure nobody else is driving it, then connect again.")
            + nothing;
    if (!state.millimetres)
        return before
            + tr("LinuxCNC is in inches (G20), where G10 and G38.2 take inches. Toffee works in millimetres: "
                 "send G21, then try again.")
            + nothing;
    return std::nullopt;
}

void LinuxCncController::ready(
    Done done, const QString &what, std::function<void(const LinuxCnc::State &)> next)
{
    readState(done, [this, done, what, next](const LinuxCnc::State &state) {
        if (const auto why = notReady(state, what))
            return done(SessionResult::failed(SessionResult::Outcome::Refused, *why));
        if (state.enabled) {
            m_abortedHere = false;
            return next(state);
        }
        // Toffee's own abort took the enable to a second connection: take it back.
        sendEnable(MachineLink::kDefaultTimeoutMs, [this, done, state, next](const CommandReply &reply) {
            if (!reply.ok())
                return done(failure(reply));
            m_abortedHere = false;
            next(state);
        });
    });
}

void LinuxCncController::printFields(
    const QByteArray &name, const QByteArray &fields, Done done, std::function<void(const Fields &)> next)
{
    // Numbered: a line of an earlier question left in the queue is never taken for this one's.
    const QByteArray marker = name + '-' + m_session + '-' + QByteArray::number(++m_printed);
    mdi("(DEBUG," + marker + ' ' + fields + ')', MachineLink::kDefaultTimeoutMs, done,
        [this, marker, done, next](const CommandReply &) {
            // The queue is shared by every kind of message and every client: each get takes one message of
            // any kind, so an error or another program's text may come first (then the display says OK).
            auto read = std::make_shared<std::function<void(int)>>();
            *read = [this, marker, done, next, self = std::weak_ptr(read)](int left) {
                get("operator_display", "OPERATOR_DISPLAY", done,
                    [marker, done, next, left, again = self.lock()](const QByteArray &value) {
                        if (const auto f = LinuxCnc::displayFields(value, marker))
                            return next(*f);
                        if (left > 0)
                            return (*again)(left - 1);
                        done(SessionResult::failed(SessionResult::Outcome::MachineError,
                            tr("LinuxCNC did not print what Toffee asked of it (%1); it said \"%2\". Nothing "
                               "was recorded.")
                                .arg(QString::fromUtf8(marker), QString::fromUtf8(value.left(80)))));
                    });
            };
            (*read)(kMaxDisplayReads);
        });
}

void LinuxCncController::readOffsetInForce(Done done, std::function<void()> next)
{
    // #<_abs_z> − #<_z> is every offset in force; less the coordinate system's Z and G92's, the tool's.
    mdi("#<_toffee_w>=[#[5203+20*#5220]+#5213*#5210]", MachineLink::kDefaultTimeoutMs, done,
        [this, done, next](const CommandReply &) {
            printFields("TOFFEE-TLO", "t=#5400 a=#<_abs_z> z=#<_z> w=#<_toffee_w>", done,
                [this, next](const Fields &f) {
                    m_tloInForce = atResolution(f.at("a") - f.at("z") - f.at("w"));
                    const int tool = int(f.at("t"));
                    m_tool = tool > 0 ? tool : Limits::kEmptySpindle;
                    next();
                });
        });
}

void LinuxCncController::locateTable(Done done, std::function<void()> next)
{
    if (!m_iniPath.isEmpty()) {
        m_tablePath.clear();
        QFile ini(m_iniPath);
        if (!ini.open(QIODevice::ReadOnly))
            return done(SessionResult::failed(SessionResult::Outcome::Refused,
                tr("Cannot read LinuxCNC's INI %1: %2").arg(m_iniPath, ini.errorString())));
        m_tablePath = LinuxCnc::toolTableOfIni(ini.readAll(), m_iniPath);
        return readTableFile([next](const QString &) { next(); });
    }
    // The INI LinuxCNC runs, when it runs on this computer: its path means the same here.
    const auto *tcp = qobject_cast<const TcpTransport *>(m_link->transport());
    const bool local = tcp && QHostAddress(tcp->address().host).isLoopback();
    if (!local)
        return next();
    get("inifile", "INIFILE", done, [this, next](const QByteArray &path) {
        QFile ini(QString::fromUtf8(path));
        if (ini.open(QIODevice::ReadOnly))
            m_tablePath = LinuxCnc::toolTableOfIni(ini.readAll(), ini.fileName());
        readTableFile([next](const QString &) { next(); });
    });
}

void LinuxCncController::readTableFile(std::function<void(const QString &)> next)
{
    if (m_tablePath.isEmpty()) {
        m_table.reset();
        return next(
            tr("linuxcncrsh cannot read LinuxCNC's tool table, so Toffee reads its file: give the INI "
               "LinuxCNC runs (toffee-cli --ini FILE) on the computer LinuxCNC runs on."));
    }
    QFile file(m_tablePath);
    if (!file.open(QIODevice::ReadOnly)) {
        m_table.reset();
        return next(tr("Cannot read LinuxCNC's tool table %1: %2").arg(m_tablePath, file.errorString()));
    }
    const auto table = readLinuxCncTable(file.readAll(), Units::Millimetre);
    if (!table) {
        m_table.reset();
        return next(
            tr("LinuxCNC's tool table %1 could not be read: %2").arg(m_tablePath, table.error().message));
    }
    QList<ControllerTool> tools;
    // A row's Z is its length (lengthGeometry, as Toffee reads a tool.tbl offline): here, the TLO in it.
    for (const Tool &tool : table.value().tools())
        tools.append({ tool.number, atResolution(tool.lengthGeometry), std::max(0.0, tool.totalRadius()) });
    m_table = tools;
    next({});
}

void LinuxCncController::readToolTable(Done done)
{
    readTableFile([this, done](const QString &why) {
        if (!why.isEmpty())
            return refuse(done, why);
        report(done);
    });
}

} // namespace Toffee
