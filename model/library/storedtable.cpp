// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/storedtable.h"

#include <functional>

#include "model/formats/tablefile.h"
#include "model/library/historyevent.h"

namespace Toffee {

ToolTable StoredTable::table() const
{
    QList<Tool> tools;
    for (const StoredTool &row : rows) {
        if (row.tool)
            tools.append(*row.tool);
    }
    // The rows were each checked as they were read: a table of them holds.
    auto table = ToolTable::fromTools(tools, units, nullptr, ToolTable::Validated::Already);
    return table ? table.value() : ToolTable(units);
}

const StoredTool *StoredTable::row(int number) const
{
    for (const StoredTool &r : rows) {
        if (r.number == number)
            return &r;
    }
    return nullptr;
}

QByteArray toolData(const Tool &tool, Units units)
{
    ToolTable table(units);
    (void)table.insert(tool);
    return writeJsonTable(table);
}

Result<Tool> toolFromData(const QByteArray &data, Units units)
{
    auto table = readJsonTable(data);
    if (!table)
        return table.error();
    if (table.value().size() != 1 || table.value().units() != units)
        return Error { QCoreApplication::translate("Toffee::Library",
            "A tool's row does not hold one tool in "
            "its table's units.") };
    return table.value().at(0);
}

std::optional<Recording> recordingOf(const HistoryEvent &event)
{
    Recording r;
    r.tool = event.tool;
    r.at = event.at;
    r.referenceMz = event.referenceMz;
    switch (event.kind) {
    case EventKind::Probe:
    case EventKind::ManualSet:
        if (!event.tlo)
            return std::nullopt;
        r.tlo = event.tlo;
        r.source = event.kind == EventKind::ManualSet ? TloSource::Manual : TloSource::Probe;
        r.kind = event.kind == EventKind::ManualSet ? RecordingKind::ManualSet : RecordingKind::Probe;
        return r;
    case EventKind::Import:
        if (!event.tlo)
            return std::nullopt;
        r.tlo = event.tlo;
        r.source = TloSource::Pulled; // set on the controller, not measured by Toffee
        r.kind = RecordingKind::Pulled;
        return r;
    case EventKind::BreakTest:
        if (!event.failed)
            return std::nullopt;
        r.breakTestFailed = event.failed;
        r.kind = RecordingKind::BreakTest;
        return r;
    case EventKind::Restore:
        return std::nullopt; // the table already holds what was restored
    case EventKind::NewCutter:
        r.kind = RecordingKind::NewCutter;
        r.oldTlo = event.oldTlo;
        return r;
    }
    return std::nullopt;
}

namespace {

// Each field a station edits on its own; a merge takes each from the side that changed it.
using Field = std::function<bool(Tool &into, const Tool &from, const Tool &base)>;

template<typename Member> Field field(Member member)
{
    return [member](Tool &into, const Tool &from, const Tool &base) {
        if (from.*member == base.*member)
            return false;
        into.*member = from.*member;
        return true;
    };
}

const QList<Field> &fields()
{
    // A TLO goes with when and against what it was measured, and whether it was probed: one field.
    static const QList<Field> all = { field(&Tool::pocket), field(&Tool::description),
        field(&Tool::lengthGeometry), field(&Tool::lengthWear), field(&Tool::radiusGeometry),
        field(&Tool::radiusWear), field(&Tool::notes), field(&Tool::linuxCncExtra),
        field(&Tool::breakTestFailed), field(&Tool::cutterType), field(&Tool::overallLength),
        field(&Tool::lifeLimitMinutes), field(&Tool::lifeLimitUses), field(&Tool::flutes),
        field(&Tool::probing), [](Tool &into, const Tool &from, const Tool &base) {
            const auto tlo = [](const Tool &t) {
                return std::tuple(t.measuredTlo, t.measuredAt, t.tloSource, t.referenceMz);
            };
            if (tlo(from) == tlo(base))
                return false;
            std::tie(into.measuredTlo, into.measuredAt, into.tloSource, into.referenceMz) = tlo(from);
            return true;
        } };
    return all;
}

} // namespace

std::optional<std::optional<Tool>> mergeTool(
    const std::optional<Tool> &base, const std::optional<Tool> &theirs, const std::optional<Tool> &mine)
{
    if (theirs == mine)
        return theirs;
    if (theirs == base)
        return mine;
    if (mine == base)
        return theirs;
    if (!base || !theirs || !mine)
        return std::nullopt; // added twice differently, or removed on one side and changed on the other
    Tool merged = *base;
    for (const Field &f : fields()) {
        Tool mineOnly = *base;
        const bool mineChanged = f(mineOnly, *mine, *base);
        Tool theirsOnly = *base;
        const bool theirsChanged = f(theirsOnly, *theirs, *base);
        if (mineChanged && theirsChanged && !(mineOnly == theirsOnly))
            return std::nullopt;
        f(merged, mineChanged ? *mine : *theirs, *base);
    }
    return std::optional<Tool>(merged);
}

} // namespace Toffee
