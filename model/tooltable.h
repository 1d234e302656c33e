// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>

#include <QList>

#include "model/recording.h"
#include "model/result.h"
#include "model/tool.h"
#include "model/units.h"

namespace Toffee {

// The tool table as a value: tools kept sorted by number, numbers unique, every value valid.
// Every mutator validates first; a refused change leaves the table exactly as it was.
// A tool's stored TLO in millimetres, as a machine takes it (ToolTable::storedTlo).
struct StoredTlo
{
    double tlo = 0.0; // at the machine's 0.001 mm
    std::optional<double> referenceMz;
    // How far a machine's value may lie from these and still be them (sameLengthWithin the table's units).
    double sameWithin = 0.0005;
    TloSource source = TloSource::Probe;
    QDateTime measuredAt;
    bool breakTestFailed = false;
};

class ToolTable
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::ToolTable)

public:
    ToolTable() = default;
    explicit ToolTable(Units units)
        : m_units(units)
    { }

    // Which of the tools given to fromTools was refused, so a reader can name its line.
    struct Problem
    {
        qsizetype index = -1; // the refused tool
        qsizetype duplicateOf = -1; // for a repeated number: the earlier tool with it
        int number = 0; // the refused tool's number
    };

    // Whether each tool was already validated in these units (a reader checks each as it reads it).
    enum class Validated { No, Already };

    // Builds a table from tools in any order; the first invalid or duplicate tool refuses the lot.
    [[nodiscard]] static Result<ToolTable> fromTools(
        QList<Tool> tools, Units units, Problem *problem = nullptr, Validated validated = Validated::No);

    [[nodiscard]] Units units() const { return m_units; }
    [[nodiscard]] const QList<Tool> &tools() const { return m_tools; }
    [[nodiscard]] qsizetype size() const { return m_tools.size(); }
    [[nodiscard]] bool isEmpty() const { return m_tools.isEmpty(); }
    [[nodiscard]] const Tool &at(qsizetype index) const { return m_tools.at(index); }

    // Index of the tool with this number, or -1.
    [[nodiscard]] qsizetype indexOf(int number) const;
    [[nodiscard]] bool contains(int number) const { return indexOf(number) >= 0; }
    [[nodiscard]] const Tool *find(int number) const;
    // The index a tool with this number has, or would have once inserted.
    [[nodiscard]] qsizetype insertionIndex(int number) const;
    // The lowest unused tool number from `from` up, or -1 when the range is full.
    [[nodiscard]] int nextFreeNumber(int from = 1) const;

    // Whether insert / replace would succeed, without changing anything.
    [[nodiscard]] Result<void> checkInsert(const Tool &tool) const;
    [[nodiscard]] Result<void> checkReplace(int number, const Tool &tool) const;

    Result<void> insert(const Tool &tool);
    // Replaces the tool numbered `number` by `tool` (which may carry a new, unused number).
    Result<void> replace(int number, const Tool &tool);
    bool remove(int number);
    // Stores a TLO from the machine into tool `number`, adding the tool when the table has none. A probe
    // clears a failed break test's mark; an offset set by hand does not (the tool was not measured). The TLO
    // and its reference are the machine's, in millimetres: here they become the table's units (the one place
    // a length crosses from a machine into a table).
    Result<void> recordMeasurement(int number, double tloMm, const QDateTime &at,
        TloSource source = TloSource::Probe, std::optional<double> referenceMzMm = std::nullopt);
    // Tool `number`'s stored TLO as a machine takes it: in millimetres, with its reference, whatever the
    // table's units (the one place a length crosses from a table to a machine). Nothing when the tool is not
    // in the table or has no TLO.
    [[nodiscard]] std::optional<StoredTlo> storedTlo(int number) const;
    // How tool `number` is probed, in millimetres as a machine takes it (ProbePlan::of); the plain plan for a
    // tool the table lacks.
    [[nodiscard]] ProbePlan probePlan(int number) const;
    // Marks tool `number` as failed (or passed) by a break test, adding the tool when the table has none.
    Result<void> recordBreakTest(int number, bool failed);
    // Another cutter in tool `number`'s pocket: the old cutter's TLO (with its time, source and reference),
    // its wear and its break mark no longer hold, and the tool must be measured before it cuts. Its number,
    // pocket, description, geometry, notes and life limits stay.
    Result<void> newCutter(int number);
    // What a new cutter in tool `number` means for the history: the old cutter's TLO and reference, in
    // millimetres (Recording::newCutter).
    [[nodiscard]] Recording newCutterRecording(int number) const;
    // What an operation on the machine carries (a TLO, or a break test's verdict), recorded as the two above
    // do.
    Result<void> record(const Recording &recording);
    // Several at once (a pull of a controller's table): all of them, or none and why not, naming the tool.
    Result<void> recordAll(const QList<Recording> &recordings);

    friend bool operator==(const ToolTable &, const ToolTable &) = default;

private:
    // Tool `number` as the table has it, or a new one with its default pocket.
    [[nodiscard]] Tool toolOrNew(int number) const;

    Units m_units = Units::Millimetre;
    QList<Tool> m_tools;
};

} // namespace Toffee

Q_DECLARE_METATYPE(Toffee::ToolTable)
