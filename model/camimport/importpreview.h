// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QStringList>

#include "model/camimport/camtool.h"
#include "model/result.h"
#include "model/tooltable.h"

namespace Toffee {

// What an import does to one tool of the library.
enum class ImportChange { New, Changed, Unchanged };

struct ImportedTool
{
    int number = 0;
    QString description; // as the table will have it
    ImportChange change = ImportChange::New;
    QStringList fields; // for a changed tool: each change in words, "radius 3.000 → 3.175 mm"
    // What the operator should know besides: a new tool's pocket and that it has no length yet, a length
    // offset (H) in the library that Toffee does not take.
    QStringList notes;
    // The library describes another cutter than the table's (type, diameter or overall length): the import
    // puts a new cutter in the pocket, as ToolTable::newCutter does, ending the old one's TLO (endedTlo),
    // length, wear and break mark. `fields` says why, first.
    bool newCutter = false;
    std::optional<double> endedTlo = std::nullopt; // in millimetres, as the history keeps it
    std::optional<double> endedReferenceMz = std::nullopt; // what that TLO was measured against
};

// A CAM library merged into a table, before anything is applied: what happens to each of the library's tools,
// and the table it makes. Only what the CAM owns changes: the description, the radius geometry (half the
// diameter), the cutter's type and overall length, and the CAM's own line in the notes; except that a tool
// whose cutter is another (its type, its diameter beyond 0.01 mm or its overall length beyond 0.1 mm) is a
// new cutter, whose TLO, length, wear and break mark end. The measured TLO, its time, source and reference,
// the break-test mark, the wear, the pocket, the length geometry and the operator's notes stay as they are,
// and a library tool without a description keeps the table's. A new tool gets the pocket the table gives a
// tool of its number, or the lowest pocket no other tool has when that one is taken; it has no length until
// measured.
class ImportPreview
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::ImportPreview)

public:
    // Converts the library's units into the table's; refuses the whole library when one tool would not be a
    // valid tool of the table, naming it.
    // A library's tools that give no unit are read in `assumed`, the operator's answer; without one they are
    // refused by name, with what the file needs.
    [[nodiscard]] static Result<ImportPreview> build(
        const ToolTable &current, const CamLibrary &library, std::optional<Units> assumed = std::nullopt);
    // The numbers of the library's tools that give no unit.
    [[nodiscard]] static QList<int> toolsWithoutUnit(const CamLibrary &library);
    // The same named for people: "T3, T5", the first ten and "…" after them; empty when none.
    [[nodiscard]] static QString toolsWithoutUnitNamed(const CamLibrary &library);

    [[nodiscard]] const QList<ImportedTool> &tools() const { return m_tools; }
    [[nodiscard]] const ToolTable &merged() const { return m_merged; }
    [[nodiscard]] qsizetype count(ImportChange change) const;
    [[nodiscard]] bool changesAnything() const { return count(ImportChange::Unchanged) < m_tools.size(); }
    // "2 new, 1 changed, 3 unchanged", and how many are new cutters
    [[nodiscard]] QString summary() const;
    // The tools the import puts a new cutter in: each needs its history's NewCutter event.
    [[nodiscard]] QList<ImportedTool> newCutters() const;

    // The notes line an import owns starts with this (never translated, so that it is found again in any
    // language); the operator's other lines are never touched.
    static constexpr QStringView kNotesMarker = u"From CAM:";

private:
    QList<ImportedTool> m_tools;
    ToolTable m_merged;
};

} // namespace Toffee
