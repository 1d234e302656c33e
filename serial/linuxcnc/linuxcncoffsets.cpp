// SPDX-License-Identifier: GPL-3.0-or-later
// What Toffee writes into LinuxCNC: a TLO (G10 L1, which rewrites tool.tbl, and G43 H for the tool in the
// spindle) read back before it counts, set by hand or restored, and its whole table (push), each refused
// before anything is sent when it cannot be right (beyond the one range, in inches, a tool LinuxCNC lacks).
#include "serial/linuxcnc/linuxcnccontroller.h"

#include <cmath>

#include <QStringList>

#include "model/numberformat.h"

using namespace Qt::StringLiterals;

namespace Toffee {

void LinuxCncController::writeOffset(int tool, double tlo, Done done, std::function<void()> next)
{
    if (auto valid = validateOffset(tr("T%1's TLO").arg(tool), tlo); !valid) {
        done(SessionResult::failed(SessionResult::Outcome::MachineError,
            valid.error().message + u' ' + tr("Nothing was written to LinuxCNC or recorded.")));
        return;
    }
    const QByteArray p = QByteArray::number(tool);
    mdiChain({ "G10 L1 P" + p + " Z" + number(tlo), "G43 H" + p }, MachineLink::kDefaultTimeoutMs, done,
        [this, done, next, tool, tlo] {
            readOffsetInForce(done, [this, done, next, tool, tlo] {
                QStringList wrong;
                if (!m_tloInForce || std::fabs(*m_tloInForce - tlo) > kReadBackTolerance)
                    wrong << tr("the offset in force reads %1 mm")
                                 .arg(m_tloInForce ? mm(*m_tloInForce) : tr("nothing"));
                readTableFile([this, done, next, tool, tlo, wrong](const QString &) mutable {
                    if (m_table) {
                        const auto it = std::find_if(m_table->cbegin(), m_table->cend(),
                            [tool](const ControllerTool &t) { return t.tool == tool; });
                        if (it == m_table->cend() || std::fabs(it->tlo - tlo) > kReadBackTolerance)
                            wrong << tr("%1 holds %2 for T%3")
                                         .arg(
                                             m_tablePath, it == m_table->cend() ? tr("nothing") : mm(it->tlo))
                                         .arg(tool);
                    }
                    if (!wrong.isEmpty())
                        return done(SessionResult::failed(SessionResult::Outcome::MachineError,
                            tr("LinuxCNC was given T%1's TLO %2 mm, but read back %3. Nothing was recorded; "
                               "check LinuxCNC's tool table before you cut.")
                                .arg(tool)
                                .arg(mm(tlo), wrong.join(u", "_s))));
                    next();
                });
            });
        });
}

void LinuxCncController::setTlo(double tlo, Done done)
{
    done = recording(std::move(done), RecordingKind::ManualSet);
    if (auto valid = validateOffset(tr("The TLO"), tlo); !valid) {
        refuse(done, valid.error().message);
        return;
    }
    const auto tool = spindleTool(done, tr("set a TLO for"));
    if (!tool)
        return;
    const double value = atResolution(tlo);
    ready(done, tr("set a TLO"), [this, done, tool = *tool, value](const LinuxCnc::State &) {
        writeOffset(
            tool, value, done, [this, done, tool, value] { done(tloResult(tool, value, std::nullopt)); });
    });
}

void LinuxCncController::setTloAboveZ0(double height, Done done)
{
    if (auto valid = validateOffset(tr("The height above Z0"), height); !valid) {
        refuse(done, valid.error().message);
        return;
    }
    ready(done, tr("set a TLO"), [this, done, height](const LinuxCnc::State &) {
        printFields("TOFFEE-Z", "z=#<_z>", done, [this, done, height](const Fields &f) {
            // The work Z grows by what the TLO shrinks: the tip is `height` above Z0 when #<_z> reads it.
            setTlo(m_tloInForce.value_or(0.0) + f.at("z") - height, done);
        });
    });
}

void LinuxCncController::restoreTlo(int tool, double tlo, Done done)
{
    done = recording(std::move(done), RecordingKind::Restore);
    if (auto valid = validateToolNumber(tool); !valid || tool <= 0) {
        refuse(done,
            valid ? tr("A TLO is restored for a tool, not for an empty spindle.") : valid.error().message);
        return;
    }
    if (auto valid = validateOffset(tr("The TLO"), tlo); !valid) {
        refuse(done, valid.error().message);
        return;
    }
    const double value = atResolution(tlo);
    ready(done, tr("restore a TLO"), [this, done, tool, value](const LinuxCnc::State &) {
        mdi("M61 Q" + QByteArray::number(tool), MachineLink::kDefaultTimeoutMs, done,
            [this, done, tool, value](const CommandReply &) {
                m_tool = tool;
                writeOffset(tool, value, done,
                    [this, done, tool, value] { done(tloResult(tool, value, std::nullopt)); });
            });
    });
}

QString LinuxCncController::setTloCommand(double tlo) const
{
    const int tool = m_tool.value_or(0);
    return u"G10 L1 P%1 Z%2, G43 H%1"_s.arg(tool).arg(QString::fromLatin1(number(atResolution(tlo))));
}

QString LinuxCncController::aboveZ0Command(double height) const
{
    return tr("%1 (the TLO that puts the tip %2 mm above Z0, from where it is)")
        .arg(setTloCommand(0.0).replace(u"Z0"_s, u"Z…"_s), QString::fromLatin1(number(height)));
}

QString LinuxCncController::restoreCommand(int tool, double tlo) const
{
    return u"M61 Q%1, G10 L1 P%1 Z%2, G43 H%1"_s.arg(tool).arg(
        QString::fromLatin1(number(atResolution(tlo))));
}

void LinuxCncController::writeToolTable(const QList<ControllerTool> &tools, Done done)
{
    readTableFile([this, done, tools](const QString &why) {
        if (!why.isEmpty())
            return refuse(done, why);
        QStringList missing;
        for (const ControllerTool &t : tools) {
            if (auto valid = validateOffset(tr("T%1's TLO").arg(t.tool), t.tlo); !valid)
                return refuse(done, valid.error().message);
            const bool held = std::any_of(m_table->cbegin(), m_table->cend(),
                [&t](const ControllerTool &h) { return h.tool == t.tool; });
            if (!held)
                missing << u"T%1"_s.arg(t.tool);
        }
        if (!missing.isEmpty())
            return refuse(done,
                tr("LinuxCNC's tool table (%1) has no %2: G10 L1 cannot add a tool. Nothing was written: add "
                   "them to LinuxCNC's table, or leave them out.")
                    .arg(m_tablePath, missing.join(u", "_s)));
        ready(done, tr("write LinuxCNC's table"),
            [this, done, tools](const LinuxCnc::State &) { writeEntries(tools, done); });
    });
}

void LinuxCncController::writeEntries(const QList<ControllerTool> &tools, Done finished)
{
    const WriteOne writeOne = [this](const ControllerTool &t, Done done, std::function<void()> next) {
        mdi("G10 L1 P" + QByteArray::number(t.tool) + " Z" + number(atResolution(t.tlo)),
            MachineLink::kDefaultTimeoutMs, done, [next](const CommandReply &) { next(); });
    };
    const auto verify = [this, tools](Done done) {
        readTableFile([this, done, tools](const QString &why) {
            QStringList differ;
            for (const ControllerTool &t : tools) {
                const auto held = m_table ? std::find_if(m_table->cbegin(), m_table->cend(),
                                      [&t](const ControllerTool &h) { return h.tool == t.tool; })
                                          : QList<ControllerTool>::const_iterator {};
                if (!m_table || held == m_table->cend() || std::fabs(held->tlo - t.tlo) > kReadBackTolerance)
                    differ << tr("T%1 reads %2, not %3 mm")
                                  .arg(t.tool)
                                  .arg(m_table && held != m_table->cend() ? mm(held->tlo) : tr("nothing"),
                                      mm(t.tlo));
            }
            SessionResult result
                = tloResult(m_tool.value_or(Limits::kEmptySpindle), m_tloInForce.value_or(0.0), std::nullopt);
            result.controllerTools = m_table;
            if (!differ.isEmpty()) {
                result.outcome = SessionResult::Outcome::MachineError;
                result.message = tr("LinuxCNC's table does not read back as written: %1. %2")
                                     .arg(differ.join(u"; "_s), why);
            }
            done(result);
        });
    };
    writeEach(tools, writeOne, verify, std::move(finished));
}

} // namespace Toffee
