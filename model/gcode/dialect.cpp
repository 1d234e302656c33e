// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/gcode/dialect.h"

#include <cmath>

#include <QCoreApplication>

#include "model/limits.h"
#include "model/numberformat.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

constexpr int kMaxOffsetNumber = Limits::kMaxOffsetNumber; // FANUC offset counts go from 32 to 999

QString value(double v, Units units)
{
    return formatNumber(v, NumberFormat::fixed(resolutionDecimals(units)));
}

// The header says how many tools the program writes, which is not always how many the table holds.
QString header(qsizetype count, Units units, const QString &controller)
{
    return u"(Tool offsets for %1, written by Toffee: %2, %3)\n"_s.arg(controller)
        .arg(count == 1 ? u"1 tool"_s : u"%1 tools"_s.arg(count))
        .arg(unitsSymbol(units));
}

Result<QString> g10Table(const QList<Tool> &tools, Units units, const QString &controller)
{
    QString out = u"%\n"_s + header(tools.size(), units, controller)
        + (units == Units::Inch ? u"G20\n"_s : u"G21\n"_s) + u"G90\n"_s;
    for (const Tool &tool : tools) {
        if (tool.number < 1 || tool.number > kMaxOffsetNumber)
            return Error { tr("T%1 cannot be written: %2 offset numbers go from 1 to %3.")
                               .arg(tool.number)
                               .arg(controller)
                               .arg(kMaxOffsetNumber) };
        const QString p = QString::number(tool.number);
        out += u"G10 L10 P"_s + p + u" R"_s + value(tool.lengthGeometry, units) + u'\n';
        out += u"G10 L11 P"_s + p + u" R"_s + value(tool.lengthWear, units) + u'\n';
        out += u"G10 L12 P"_s + p + u" R"_s + value(tool.radiusGeometry, units) + u'\n';
        out += u"G10 L13 P"_s + p + u" R"_s + value(tool.radiusWear, units) + u'\n';
    }
    return QString(out + u"M30\n%\n"_s);
}

} // namespace

const QList<DialectInfo> &dialects()
{
    static const QList<DialectInfo> all = {
        { Dialect::Carvera, u"carvera"_s, u"Carvera"_s, u"M493.2 T, M493.3 Z per tool"_s, false },
        { Dialect::Fanuc, u"fanuc"_s, u"FANUC"_s, u"G10 L10-L13, G90"_s, true },
        { Dialect::Fagor8055M, u"fagor"_s, u"FAGOR 8055M"_s, {}, false },
        { Dialect::AllenBradley9, u"ab9"_s, u"Allen-Bradley 9/Series"_s, u"G10 L10-L13, G90"_s, true },
        { Dialect::Aerotech, u"aerotech"_s, u"Aerotech Automation1"_s,
            u"G44 axes, CutterCompensationSetOffsets for one tool"_s, false },
        { Dialect::LinuxCnc, u"linuxcnc"_s, u"LinuxCNC"_s, u"G10 L1"_s, true },
        { Dialect::GrblHal, u"grblhal"_s, u"grblHAL"_s, u"G10 L1 with the measured TLOs"_s, true },
    };
    return all;
}

const DialectInfo &dialectInfo(Dialect dialect)
{
    for (const DialectInfo &info : dialects()) {
        if (info.dialect == dialect)
            return info;
    }
    return dialects().front();
}

std::optional<Dialect> dialectFromKey(QStringView key)
{
    for (const DialectInfo &info : dialects()) {
        if (key.compare(info.key, Qt::CaseInsensitive) == 0)
            return info.dialect;
    }
    return std::nullopt;
}

bool usesG43(Dialect dialect)
{
    return dialect == Dialect::Fanuc || dialect == Dialect::Fagor8055M || dialect == Dialect::AllenBradley9
        || usesToolTableWords(dialect);
}

bool measuresTlos(Dialect dialect)
{
    return dialect == Dialect::Carvera || dialect == Dialect::GrblHal;
}

bool usesToolTableWords(Dialect dialect)
{
    return dialect == Dialect::LinuxCnc || dialect == Dialect::GrblHal;
}

Result<QString> exportProgram(const ToolTable &table, Dialect dialect, std::optional<int> tool)
{
    const Units u = table.units();
    // One tool asked for is one tool written: a program for one tool must never overwrite a controller's
    // whole offset table.
    QList<Tool> tools;
    if (tool) {
        const Tool *found = table.find(*tool);
        if (!found)
            return Error { tr("There is no tool %1 in the table.").arg(*tool) };
        tools << *found;
    } else {
        tools = table.tools();
    }
    switch (dialect) {
    case Dialect::Fanuc:
        return g10Table(tools, u, u"FANUC"_s);
    case Dialect::AllenBradley9:
        return g10Table(tools, u, u"Allen-Bradley 9/Series"_s);
    case Dialect::LinuxCnc: {
        // G10 L1 writes the tool table; LinuxCNC keeps no wear, so the totals go in.
        QString out = header(tools.size(), u, u"LinuxCNC"_s) + (u == Units::Inch ? u"G20\n"_s : u"G21\n"_s);
        for (const Tool &t : tools) {
            if (t.number < 1)
                return Error { tr("T%1 cannot be written: LinuxCNC's G10 L1 needs a tool number from 1 up.")
                                   .arg(t.number) };
            out += u"G10 L1 P"_s + QString::number(t.number) + u" Z"_s + value(t.totalLength(), u) + u" R"_s
                + value(t.totalRadius(), u) + u'\n';
        }
        return QString(out + u"M2\n"_s);
    }
    case Dialect::GrblHal: {
        // Toffee's measured TLOs (against the machine's reference tool) into grblHAL's table; a tool without
        // one is left out, as its entry would be a guess.
        QString body;
        int written = 0;
        for (const Tool &t : tools) {
            if (!t.measuredTlo)
                continue;
            if (t.number < 1)
                return Error {
                    tr("T%1 cannot be written: grblHAL's G10 L1 needs a tool number from 1 up.").arg(t.number)
                };
            body += u"G10 L1 P"_s + QString::number(t.number) + u" Z"_s + value(*t.measuredTlo, u) + u" R"_s
                + value(t.totalRadius(), u) + u'\n';
            ++written;
        }
        if (written == 0)
            return Error { tool ? tr("T%1 has no measured TLO to write; probe it first.").arg(*tool)
                                : tr("No tool has a measured TLO to write; probe the tools first.") };
        return QString(header(written, u, u"grblHAL"_s) + (u == Units::Inch ? u"G20\n"_s : u"G21\n"_s) + body
            + u"M2\n"_s);
    }
    case Dialect::Carvera: {
        QString body;
        int written = 0;
        for (const Tool &t : tools) {
            if (!t.measuredTlo)
                continue;
            body += u"M493.2 T"_s + QString::number(t.number) + u"\nM493.3 Z"_s + value(*t.measuredTlo, u)
                + u'\n';
            ++written;
        }
        if (written == 0)
            return Error { tool ? tr("T%1 has no measured TLO to write; probe it first.").arg(*tool)
                                : tr("No tool has a measured TLO to write; probe the tools first.") };
        return QString(header(written, u, u"the Carvera"_s) + body);
    }
    case Dialect::Aerotech: {
        // CutterCompensationSetOffsets sets the offsets of the tool in use: one tool, chosen, never "all".
        if (tools.isEmpty())
            return Error { tr("The table is empty.") };
        if (tools.size() > 1)
            return Error { tr(
                "An Aerotech program sets the offsets of one tool at a time: choose the tool.") };
        const Tool &t = tools.front();
        return QString(header(1, u, u"Aerotech Automation1"_s)
            + u"// T%1 %2\nG44 X Y Z\nCutterCompensationSetOffsets([0, 0, %3])\n"_s.arg(t.number).arg(
                t.description, value(t.totalLength(), u)));
    }
    case Dialect::Fagor8055M:
        return Error { tr(
            "Toffee does not know how the FAGOR 8055M programs its offset table; enter the offsets at the "
            "control, or export for another dialect.") };
    }
    return Error { tr("Unknown controller.") };
}

} // namespace Toffee
