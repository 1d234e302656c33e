// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/historyevent.h"

#include <cmath>

#include <QUuid>

#include "model/clock.h"
#include "model/library/rowreader.h"
#include "model/limits.h"
#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/toolvalidation.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

struct KindName
{
    EventKind kind;
    QStringView name;
};
constexpr KindName kKindNames[] = {
    { EventKind::Probe, u"probe" },
    { EventKind::BreakTest, u"break_test" },
    { EventKind::ManualSet, u"manual_set" },
    { EventKind::Restore, u"restore" },
    { EventKind::Import, u"import" },
    { EventKind::NewCutter, u"new_cutter" },
};

} // namespace

QString eventKindName(EventKind kind)
{
    for (const KindName &k : kKindNames) {
        if (k.kind == kind)
            return k.name.toString();
    }
    return {};
}

std::optional<EventKind> eventKindFromName(QStringView name)
{
    for (const KindName &k : kKindNames) {
        if (k.name == name)
            return k.kind;
    }
    return std::nullopt;
}

QDateTime cutterSince(const QList<HistoryEvent> &events)
{
    // A new cutter dated in the future (a clock set wrong) ends nothing: every real use would fall before it.
    const QDateTime now = Clock::now();
    QDateTime since;
    for (const HistoryEvent &e : events) {
        if (e.kind == EventKind::NewCutter && !Clock::isInFuture(e.at, now)
            && (!since.isValid() || e.at > since))
            since = e.at;
    }
    return since;
}

Result<void> validateEvent(const HistoryEvent &e)
{
    // What any row of the history must be (an id, a machine, a tool, a time, numbers a machine reads) ...
    if (auto row = RowReader::checkEvent(e); !row)
        return row;
    // ... and the one TLO range.
    for (const auto &tlo : { e.tlo, e.oldTlo, e.newTlo }) {
        if (tlo && !isMachineTlo(*tlo))
            return Error { tr("T%1's %2 event %3 holds a TLO of %4 mm, beyond any tool (%5 mm at most).")
                               .arg(e.tool)
                               .arg(eventKindName(e.kind), e.id, formatNumber(*tlo, NumberFormat::fixed(3)))
                               .arg(Limits::kMaxMachineOffsetMm) };
    }
    return {};
}

HistoryEvent historyEvent(const Recording &r, const QString &machine)
{
    HistoryEvent e;
    e.id = HistoryEvent::newId();
    e.machine = machine;
    e.tool = r.tool;
    e.at = r.at.isValid() ? r.at.toUTC() : Clock::now();
    switch (r.kind) {
    case RecordingKind::Probe:
        e.kind = EventKind::Probe;
        break;
    case RecordingKind::ManualSet:
        e.kind = EventKind::ManualSet;
        break;
    case RecordingKind::Restore:
        e.kind = EventKind::Restore;
        break;
    case RecordingKind::BreakTest:
        e.kind = EventKind::BreakTest;
        break;
    case RecordingKind::Pulled:
        e.kind = EventKind::Import; // read in from the controller's own table
        break;
    case RecordingKind::NewCutter:
        e.kind = EventKind::NewCutter;
        break;
    }
    // A break test leaves the tool at the TLO it measured when it passed; a failed one changes nothing.
    e.tlo = r.kind == RecordingKind::BreakTest ? (r.breakTestFailed.value_or(false) ? r.oldTlo : r.newTlo)
                                               : r.tlo;
    e.referenceMz = r.referenceMz;
    e.currentMz = r.currentMz;
    e.tolerance = r.tolerance;
    e.oldTlo = r.oldTlo;
    e.newTlo = r.newTlo;
    e.failed = r.breakTestFailed;
    if (r.touches.size() > 1)
        e.touches = r.touches;
    return e;
}

QByteArray eventsAsCsv(const QList<HistoryEvent> &events)
{
    QByteArray out
        = "id,machine,tool,measured_at,kind,tlo,reference_mz,current_mz,tolerance,old_tlo,new_tlo,failed,"
          "touches,spread\n";
    auto number = [&out](std::optional<double> v) {
        out += ',';
        if (v)
            appendNumber(out, *v);
    };
    for (const HistoryEvent &e : events) {
        out += e.id.toLatin1();
        out += ',';
        QString machine = e.machine;
        if (machine.contains(u',') || machine.contains(u'"') || machine.contains(u'\n'))
            machine = u'"' + machine.replace(u'"', u"\"\""_s) + u'"';
        out += machine.toUtf8() + ',' + QByteArray::number(e.tool) + ','
            + e.at.toString(Qt::ISODateWithMs).toLatin1() + ',' + eventKindName(e.kind).toLatin1();
        for (const auto &v : { e.tlo, e.referenceMz, e.currentMz, e.tolerance, e.oldTlo, e.newTlo })
            number(v);
        out += ',';
        if (e.failed)
            out += *e.failed ? '1' : '0';
        out += ',' + touchesText(e.touches).toLatin1();
        number(e.spread());
        out += '\n';
    }
    return out;
}

std::optional<double> HistoryEvent::spread() const
{
    return touches.size() > 1 ? std::optional<double>(spreadOf(touches)) : std::nullopt;
}

QString touchesText(const QList<double> &touches)
{
    QByteArray out;
    for (double z : touches) {
        if (!out.isEmpty())
            out += ' ';
        appendNumber(out, z);
    }
    return out.isEmpty() ? u""_s : QString::fromLatin1(out); // never null: the column is NOT NULL
}

std::optional<QList<double>> touchesFromText(const QString &text)
{
    QList<double> out;
    const QStringList parts = text.split(u' ', Qt::SkipEmptyParts);
    if (parts.size() > ProbeSettings::kMaxTouches || parts.size() == 1)
        return std::nullopt;
    for (const QString &part : parts) {
        const auto z = parseDecimal(QByteArrayView(part.toLatin1()));
        if (!z || !std::isfinite(*z) || std::fabs(*z) > kMaxMachineMillimetres)
            return std::nullopt;
        out << *z;
    }
    return out;
}

QString HistoryEvent::newId()
{
    return QUuid::createUuid().toString(QUuid::WithoutBraces);
}

} // namespace Toffee
