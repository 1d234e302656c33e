// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/job/jobreport.h"

#include <algorithm>

using namespace Qt::StringLiterals;

namespace Toffee {

Severity findingSeverity(FindingKind kind)
{
    switch (kind) {
    case FindingKind::MissingTool:
    case FindingKind::BrokenTool:
    case FindingKind::UnitsMismatch:
    case FindingKind::InchOnCarvera:
    case FindingKind::ProgramError:
    case FindingKind::BelowFloor:
        return Severity::Error;
    case FindingKind::NotMeasured:
    case FindingKind::StaleTlo:
    case FindingKind::ManualChange:
    case FindingKind::LengthOffsetMismatch:
    case FindingKind::NoLengthCompensation:
    case FindingKind::NoToolLoaded:
    case FindingKind::ProgramSetsTlo:
    case FindingKind::ControllerTableDiffers:
    case FindingKind::LifeExceeded:
    case FindingKind::SpreadExceeded:
        return Severity::Warning;
    }
    return Severity::Error;
}

QString findingKey(FindingKind kind)
{
    switch (kind) {
    case FindingKind::MissingTool:
        return u"missing_tool"_s;
    case FindingKind::NotMeasured:
        return u"not_measured"_s;
    case FindingKind::StaleTlo:
        return u"stale_tlo"_s;
    case FindingKind::BrokenTool:
        return u"broken_tool"_s;
    case FindingKind::ManualChange:
        return u"manual_change"_s;
    case FindingKind::LengthOffsetMismatch:
        return u"length_offset_mismatch"_s;
    case FindingKind::NoLengthCompensation:
        return u"no_length_compensation"_s;
    case FindingKind::NoToolLoaded:
        return u"no_tool_loaded"_s;
    case FindingKind::UnitsMismatch:
        return u"units_mismatch"_s;
    case FindingKind::InchOnCarvera:
        return u"inch_on_carvera"_s;
    case FindingKind::ProgramError:
        return u"program_error"_s;
    case FindingKind::BelowFloor:
        return u"below_floor"_s;
    case FindingKind::ProgramSetsTlo:
        return u"program_sets_tlo"_s;
    case FindingKind::ControllerTableDiffers:
        return u"controller_table_differs"_s;
    case FindingKind::LifeExceeded:
        return u"life_exceeded"_s;
    case FindingKind::SpreadExceeded:
        return u"spread_exceeded"_s;
    }
    return {};
}

QString severityName(Severity severity)
{
    return severity == Severity::Error ? u"error"_s : u"warning"_s;
}

QString linesListed(const QList<int> &lines, qint64 count)
{
    QStringList numbers;
    for (int at : lines)
        numbers << QString::number(at);
    QString text = numbers.join(u", "_s);
    if (count > lines.size())
        text += u", …"_s;
    return text;
}

namespace {

int countOf(const QList<Finding> &findings, Severity severity)
{
    qint64 n = 0;
    for (const Finding &f : findings) {
        if (f.severity() == severity)
            n += f.moreTools > 0 ? f.moreTools : 1;
    }
    return int(n);
}

} // namespace

int JobReport::errors() const
{
    return countOf(findings, Severity::Error);
}

int JobReport::warnings() const
{
    return countOf(findings, Severity::Warning);
}

int JobReport::exitCode() const
{
    return errors() > 0 ? 4 : warnings() > 0 ? 1 : 0;
}

const JobTool *JobReport::tool(int number) const
{
    const auto it = std::find_if(
        tools.cbegin(), tools.cend(), [number](const JobTool &t) { return t.number == number; });
    return it == tools.cend() ? nullptr : &*it;
}

QString JobReport::summary() const
{
    const int e = errors();
    const int w = warnings();
    if (e == 0 && w == 0)
        return tr("no findings");
    const QString errorText = e == 1 ? tr("1 error") : tr("%1 errors").arg(e);
    const QString warningText = w == 1 ? tr("1 warning") : tr("%1 warnings").arg(w);
    if (w == 0)
        return errorText;
    if (e == 0)
        return warningText;
    return tr("%1, %2").arg(errorText, warningText);
}

} // namespace Toffee
