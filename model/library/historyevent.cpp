// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/historyevent.h"

#include <QUuid>

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

HistoryEvent historyEvent(const Recording &r, const QString &machine)
{
    HistoryEvent e;
    e.id = HistoryEvent::newId();
    e.machine = machine;
    e.tool = r.tool;
    e.at = r.at.isValid() ? r.at.toUTC() : QDateTime::currentDateTimeUtc();
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
    }
    // A break test leaves the tool at the TLO it measured when it passed; a failed one changes nothing.
    e.tlo = r.kind == RecordingKind::BreakTest ? (r.breakTestFailed.value_or(false) ? r.oldTlo : r.newTlo) : r.tlo;
    e.referenceMz = r.referenceMz;
    e.currentMz = r.currentMz;
    e.tolerance = r.tolerance;
    e.oldTlo = r.oldTlo;
    e.newTlo = r.newTlo;
    e.failed = r.breakTestFailed;
    return e;
}

QString HistoryEvent::newId()
{
    return QUuid::createUuid().toString(QUuid::WithoutBraces);
}

} // namespace Toffee
