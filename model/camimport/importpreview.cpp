// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/camimport/importpreview.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <QHash>
#include <QSet>

#include "model/limits.h"
#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/toolvalidation.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// A converted value keeps one decimal more than a machine resolves (0.0001 mm, 0.00001 in): the conversion's
// floating-point noise goes, and importing the same library again finds nothing changed.
double converted(double value, Units from, Units to)
{
    if (from == to)
        return value;
    const double v = convertLength(value, from, to);
    const double scale = std::pow(10.0, resolutionDecimals(to) + 1);
    return std::round(v * scale) / scale;
}

QString lengthText(double value, Units units)
{
    return formatNumber(value, NumberFormat::upTo(resolutionDecimals(units) + 1)) + u' ' + unitsSymbol(units);
}

// The CAM's lengths of a cutter are not the machine's tool length offset: they go into the notes, on a line
// of their own, never into the length geometry a controller would apply.
QString camLine(const CamTool &cam, Units units)
{
    QStringList parts;
    auto add = [&](const QString &what, const std::optional<double> &value) {
        if (value)
            parts << what + u' ' + lengthText(converted(*value, cam.units, units), units);
    };
    add(ImportPreview::tr("flute length"), cam.fluteLength);
    add(ImportPreview::tr("below the holder"), cam.stickOut);
    add(ImportPreview::tr("overall length"), cam.overallLength);
    if (parts.isEmpty())
        return {};
    return ImportPreview::kNotesMarker + u' ' + parts.join(u", "_s);
}

qsizetype camLineIndex(const QStringList &lines)
{
    for (qsizetype i = 0; i < lines.size(); ++i) {
        if (lines.at(i).startsWith(ImportPreview::kNotesMarker))
            return i;
    }
    return -1;
}

QString camLineOf(const QString &notes)
{
    const QStringList lines = notes.split(u'\n');
    const qsizetype at = camLineIndex(lines);
    return at < 0 ? QString() : lines.at(at).mid(ImportPreview::kNotesMarker.size()).trimmed();
}

// The notes with the CAM's line put in place of the old one, or added after the operator's lines.
QString notesWith(const QString &notes, const QString &line)
{
    if (line.isEmpty())
        return notes;
    if (notes.isEmpty())
        return line;
    QStringList lines = notes.split(u'\n');
    if (const qsizetype at = camLineIndex(lines); at >= 0)
        lines[at] = line;
    else
        lines.append(line);
    return lines.join(u'\n');
}

QStringList changes(const Tool &before, const Tool &after, Units units)
{
    QStringList fields;
    if (before.description != after.description)
        fields << ImportPreview::tr("description “%1” → “%2”")
                      .arg(excerpt(before.description, Limits::kMaxDescriptionLength),
                          excerpt(after.description, Limits::kMaxDescriptionLength));
    if (before.radiusGeometry != after.radiusGeometry)
        fields << ImportPreview::tr("radius %1 → %2 %3")
                      .arg(displayNumber(before.radiusGeometry, units),
                          displayNumber(after.radiusGeometry, units), unitsSymbol(units));
    const QString wasLine = camLineOf(before.notes);
    const QString isLine = camLineOf(after.notes);
    if (wasLine != isLine)
        fields << (wasLine.isEmpty()
                ? ImportPreview::tr("CAM lengths added to the notes (%1)").arg(isLine)
                : ImportPreview::tr("CAM lengths in the notes: %1 → %2").arg(wasLine, isLine));
    return fields;
}

// Why the library's cutter is not the one the table's tool describes, in words; nothing when it is the same,
// or when the table knows too little to tell (a tool never imported has no type or overall length; a radius
// of 0 is none given).
QStringList cutterChanges(const Tool &before, const Tool &after, Units units)
{
    QStringList why;
    const QString was = before.cutterType.simplified();
    const QString is = after.cutterType.simplified();
    if (!was.isEmpty() && !is.isEmpty() && was.compare(is, Qt::CaseInsensitive) != 0)
        why << ImportPreview::tr("type “%1” → “%2”")
                   .arg(excerpt(was, Limits::kMaxDescriptionLength),
                       excerpt(is, Limits::kMaxDescriptionLength));
    const double diameterTolerance = units == Units::Inch ? 0.0005 : 0.01;
    if (before.radiusGeometry > 0.0
        && std::fabs(before.radiusGeometry - after.radiusGeometry) * 2.0 > diameterTolerance + 1e-9)
        why << ImportPreview::tr("diameter %1 → %2 %3")
                   .arg(displayNumber(before.radiusGeometry * 2.0, units),
                       displayNumber(after.radiusGeometry * 2.0, units), unitsSymbol(units));
    const double lengthTolerance = units == Units::Inch ? 0.004 : 0.1;
    if (before.overallLength && after.overallLength
        && std::fabs(*before.overallLength - *after.overallLength) > lengthTolerance + 1e-9)
        why << ImportPreview::tr("overall length %1 → %2 %3")
                   .arg(displayNumber(*before.overallLength, units),
                       displayNumber(*after.overallLength, units), unitsSymbol(units));
    return why;
}

// "flat end mill, 6 mm": a new tool's description when the library gives none.
QString fallbackDescription(const CamTool &tool)
{
    const QString type = tool.type.simplified();
    if (!tool.diameter)
        return type;
    const QString size = formatNumber(*tool.diameter) + u' ' + unitsSymbol(tool.units);
    return type.isEmpty() ? size : type + u", "_s + size;
}

// The pocket of each of the library's new tools: the one the table gives its number (defaultPocket) when no
// other tool has it, else the lowest one from 1 up that none has. A tool numbered as a pocket is served
// first, so that T0 (the probe) does not take T2's pocket. Only when every pocket is taken do two share one.
QHash<int, int> newPockets(const ToolTable &current, const QList<CamTool> &library)
{
    std::vector<bool> used(std::size_t(Limits::kMaxPocket) + 1, false);
    auto claim = [&used](int pocket) {
        if (pocket >= 0 && pocket <= Limits::kMaxPocket)
            used[std::size_t(pocket)] = true;
    };
    for (const Tool &tool : current.tools())
        claim(tool.pocket);
    QHash<int, int> pockets;
    QList<int> waiting;
    QSet<int> seen;
    for (const CamTool &cam : library) {
        if (current.contains(cam.number) || seen.contains(cam.number))
            continue;
        seen.insert(cam.number);
        const int own = defaultPocket(cam.number);
        if (own == cam.number && !used[std::size_t(own)]) {
            pockets.insert(cam.number, own);
            claim(own);
        } else {
            waiting.append(cam.number);
        }
    }
    int lowest = 1;
    for (const int number : std::as_const(waiting)) {
        int pocket = defaultPocket(number);
        if (used[std::size_t(pocket)]) {
            while (lowest <= Limits::kMaxPocket && used[std::size_t(lowest)])
                ++lowest;
            if (lowest <= Limits::kMaxPocket)
                pocket = lowest;
        }
        pockets.insert(number, pocket);
        claim(pocket);
    }
    return pockets;
}

// The table's tool with the CAM's fields put in, or a new tool in `pocket`. A library without a description
// never replaces the operator's.
Tool mergedTool(const CamTool &cam, const Tool *existing, Units units, int pocket)
{
    Tool tool;
    if (existing) {
        tool = *existing;
    } else {
        tool.number = cam.number;
        tool.pocket = pocket;
        tool.description = fallbackDescription(cam);
    }
    if (!cam.description.isEmpty())
        tool.description = cam.description;
    if (cam.diameter)
        tool.radiusGeometry = converted(*cam.diameter / 2.0, cam.units, units);
    if (!cam.type.simplified().isEmpty())
        tool.cutterType = excerpt(cam.type.simplified(), Limits::kMaxDescriptionLength);
    if (cam.overallLength)
        tool.overallLength = converted(*cam.overallLength, cam.units, units);
    tool.notes = notesWith(tool.notes, camLine(cam, units));
    return tool;
}

} // namespace

QList<int> ImportPreview::toolsWithoutUnit(const CamLibrary &library)
{
    QList<int> out;
    for (const CamTool &cam : library.tools) {
        if (!cam.unitGiven)
            out << cam.number;
    }
    return out;
}

QString ImportPreview::toolsWithoutUnitNamed(const CamLibrary &library)
{
    const QList<int> without = toolsWithoutUnit(library);
    QStringList names;
    for (int n : without.first(std::min<qsizetype>(without.size(), 10)))
        names << u"T"_s + QString::number(n);
    if (without.size() > 10)
        names << u"…"_s;
    return names.join(u", "_s);
}

Result<ImportPreview> ImportPreview::build(
    const ToolTable &current, const CamLibrary &library, std::optional<Units> assumed)
{
    if (const QString names = toolsWithoutUnitNamed(library); !names.isEmpty() && !assumed) {
        return Error {
            tr("Tools in this library without \"unit\" (millimeters or inches): %1. Their diameters and "
               "lengths cannot be read. Fusion writes one on every tool: export the library from Fusion "
               "again, or add \"unit\": \"millimeters\" (or \"inches\") to each, or say which unit they "
               "are in (the window asks; toffee-cli import --cam-units mm|in).")
                .arg(names),
            0, library.path
        };
    }
    ImportPreview preview;
    const Units units = current.units();
    // The table's tools, replaced in place or added after, and sorted once at the end: a library of a hundred
    // thousand tools merges in well under a second.
    QList<Tool> tools = current.tools();
    QSet<int> seen;
    const QHash<int, int> pockets = newPockets(current, library.tools);
    preview.m_tools.reserve(library.tools.size());
    for (CamTool cam : library.tools) {
        if (!cam.unitGiven)
            cam.units = *assumed;
        auto refuse = [&cam, &library](const QString &message) {
            return Error { cam.place.isEmpty() ? message : cam.place + u": "_s + message, cam.line,
                library.path };
        };
        if (seen.contains(cam.number))
            return refuse(tr("T%1 is in the library twice.").arg(cam.number));
        seen.insert(cam.number);
        const qsizetype at = current.indexOf(cam.number);
        const Tool *existing = at >= 0 ? &current.at(at) : nullptr;
        Tool tool = mergedTool(cam, existing, units, pockets.value(cam.number));
        const QStringList cutter = existing ? cutterChanges(*existing, tool, units) : QStringList();
        if (!cutter.isEmpty()) {
            tool.endCutter(); // as ToolTable::newCutter
        }
        if (auto r = validateTool(tool, units); !r)
            return refuse(r.error().message);
        ImportedTool item { cam.number, tool.description, ImportChange::New, {}, {} };
        if (!cutter.isEmpty()) {
            item.newCutter = true;
            // For the history: in millimetres, as a machine has them.
            if (existing->measuredTlo)
                item.endedTlo = toMillimetres(*existing->measuredTlo, units);
            if (existing->referenceMz)
                item.endedReferenceMz = toMillimetres(*existing->referenceMz, units);
            item.notes << (existing->measuredTlo
                    ? tr("a new cutter (%1): the old cutter's TLO %2 %3, its length, wear and break mark "
                         "end; measure it before it cuts")
                          .arg(cutter.join(u", "_s), displayNumber(*existing->measuredTlo, units),
                              unitsSymbol(units))
                    : tr("a new cutter (%1): the old cutter's length, wear and break mark end; measure it "
                         "before it cuts")
                          .arg(cutter.join(u", "_s)));
        }
        if (!existing)
            item.notes << tr("pocket %1; no tool length yet (0 in the table): measure it before use")
                              .arg(tool.pocket);
        if (!cam.unitGiven)
            item.notes << tr("the library gives no unit: its lengths are read in %1, as you said")
                              .arg(cam.units == Units::Inch ? tr("inches") : tr("millimetres"));
        if (cam.lengthOffset && *cam.lengthOffset != cam.number)
            item.notes << tr("the library gives length offset H%1; Toffee always uses H = T (H%2), so it is "
                             "not imported")
                              .arg(*cam.lengthOffset)
                              .arg(cam.number);
        if (existing) {
            item.fields = changes(*existing, tool, units);
            // The cutter's type and overall length, taken the first time, are the CAM's own facts kept for
            // the next import: not a change the operator needs to look at.
            Tool seen = tool;
            if (existing->cutterType.isEmpty())
                seen.cutterType.clear();
            if (!existing->overallLength)
                seen.overallLength.reset();
            item.change = *existing == seen ? ImportChange::Unchanged : ImportChange::Changed;
            if (item.change == ImportChange::Changed && item.fields.isEmpty())
                item.fields << tr("the CAM lengths line in the notes");
            tools[at] = tool;
        } else {
            tools.append(tool);
        }
        preview.m_tools.append(std::move(item));
    }
    auto merged = ToolTable::fromTools(std::move(tools), units, nullptr, ToolTable::Validated::Already);
    if (!merged)
        return Error { merged.error().message, 0, library.path };
    preview.m_merged = merged.takeValue();
    return preview;
}

qsizetype ImportPreview::count(ImportChange change) const
{
    return std::count_if(m_tools.cbegin(), m_tools.cend(),
        [change](const ImportedTool &tool) { return tool.change == change; });
}

QString ImportPreview::summary() const
{
    const auto cutters
        = std::count_if(m_tools.cbegin(), m_tools.cend(), [](const ImportedTool &t) { return t.newCutter; });
    const QString counts = tr("%1 new, %2 changed, %3 unchanged")
                               .arg(count(ImportChange::New))
                               .arg(count(ImportChange::Changed))
                               .arg(count(ImportChange::Unchanged));
    return cutters == 0 ? counts : tr("%1; a new cutter in %2 (measure before use)").arg(counts).arg(cutters);
}

QList<ImportedTool> ImportPreview::newCutters() const
{
    QList<ImportedTool> out;
    std::copy_if(m_tools.cbegin(), m_tools.cend(), std::back_inserter(out),
        [](const ImportedTool &t) { return t.newCutter; });
    return out;
}

} // namespace Toffee
