// SPDX-License-Identifier: GPL-3.0-or-later
// How a table cell looks, apart from its text: alignment, colours and the tooltips that explain them.
#include "model/document/tooltablemodel.h"

#include <algorithm>
#include <cmath>

#include <QColor>
#include <QLocale>

#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/timetext.h"
#include "model/toolvalidation.h"

using namespace Qt::StringLiterals;

namespace Toffee {

// How a cell looks, apart from its text: alignment, colours and the tooltips that explain them.
QVariant ToolTableModel::decoration(const Tool &tool, int column, int role) const
{
    if (role == Qt::TextAlignmentRole) {
        const bool text = column == DescriptionColumn || column == NotesColumn || column == ProbingColumn;
        return QVariant::fromValue(Qt::AlignVCenter | (text ? Qt::AlignLeft : Qt::AlignRight));
    }
    // A tool that failed its break test stands out on every column until it is probed again; a TLO never
    // measured reads as such, greyed, and not as an empty cell that could pass for zero.
    // A translucent red reads on the light and the dark palette alike, under the palette's own text colour.
    if (role == Qt::BackgroundRole && tool.breakTestFailed)
        return QColor(0xe0, 0x1b, 0x24, 0x60);
    if (role == Qt::ForegroundRole && column == MeasuredTloColumn && !tool.measuredTlo)
        return QColor(0x80, 0x80, 0x80);
    if (role == Qt::ForegroundRole && column == MeasuredAtColumn && isStale(tool))
        return QColor(0xb0, 0x50, 0x00); // stale: measure it again before trusting it
    if (role == Qt::ToolTipRole && column == MeasuredTloColumn)
        return tloToolTip(tool);
    if (role == Qt::ToolTipRole && column == ProbingColumn) {
        const ProbePlan plan = ProbePlan::of(tool.probing, tool.flutes, m_table.units());
        return plan.isPlain()
            ? tr("T%1 is touched once at the setter's centre. Type \"X 20, 4 edges, spread 0.03\" "
                 "for a face mill touched on each edge, off-centre.")
                  .arg(tool.number)
            : tr("T%1 is probed so: %2.").arg(tool.number).arg(plan.summary());
    }
    if (column == ToolLifeColumn && (role == Qt::ForegroundRole || role == Qt::ToolTipRole)) {
        const UsedLife used = m_usedLife.value(tool.number);
        const LifeState state = ToolLife::state(tool, used);
        if (role == Qt::ForegroundRole)
            return state == LifeState::Exceeded ? QColor(0xc0, 0x1c, 0x28)
                : state == LifeState::Near      ? QColor(0xb0, 0x50, 0x00)
                                                : QVariant();
        const QString done = tr("T%1's cutter has cut %2 in %3 recorded program runs since it went in.")
                                 .arg(tool.number)
                                 .arg(durationText(used.seconds))
                                 .arg(used.uses);
        const QString limit = ToolLife::limitText(tool).isEmpty()
            ? tr("It has no life limit: type one here, as \"90 min\", \"40 uses\" or both.")
            : tr("Its life limit is %1.").arg(ToolLife::limitText(tool));
        const QString what = state == LifeState::Exceeded
            ? tr("It is past its limit: put in a new cutter (Edit ▸ New Cutter…).")
            : state == LifeState::Near ? tr("It is near its limit: have a new cutter ready.")
                                       : QString();
        return QStringList { done, limit, what }.join(u' ').trimmed();
    }
    if (column == PocketColumn && (role == Qt::ForegroundRole || role == Qt::ToolTipRole)
        && pocketCount(tool.pocket) > 1) {
        if (role == Qt::ForegroundRole)
            return QColor(0xb0, 0x50, 0x00);
        QStringList others;
        for (int n : toolsSharingPocket(tool.pocket, tool.number))
            others << u"T"_s + QString::number(n);
        return tr(
            "Pocket %1 also holds %2. LinuxCNC's random tool changer needs each tool in its own pocket.")
            .arg(tool.pocket)
            .arg(others.join(u", "_s));
    }
    if (role == Qt::ToolTipRole && column == NumberColumn && tool.breakTestFailed)
        return tloToolTip(tool);
    return {};
}

QString ToolTableModel::tloToolTip(const Tool &tool) const
{
    QStringList lines;
    if (!tool.measuredTlo)
        lines << tr("T%1 has not been measured on the tool setter.").arg(tool.number);
    else if (tool.tloSource == TloSource::Manual)
        lines << tr("T%1's TLO %2 was set on the machine by hand, not measured. A break test compares "
                    "against it.")
                     .arg(tool.number)
                     .arg(formatLength(*tool.measuredTlo));
    else if (tool.tloSource == TloSource::Pulled)
        lines << tr("T%1's TLO %2 was read from the controller's own table (Pull Offsets), not measured by "
                    "Toffee. A break test compares against it.")
                     .arg(tool.number)
                     .arg(formatLength(*tool.measuredTlo));
    else
        lines << tr("T%1's TLO %2 was measured on the tool setter.")
                     .arg(tool.number)
                     .arg(formatLength(*tool.measuredTlo));
    if (tool.breakTestFailed)
        lines << tr("T%1 failed its last break test: check it, replace it if it is damaged, then probe it "
                    "again. It stays marked until it is probed.")
                     .arg(tool.number);
    return lines.join(u'\n');
}

} // namespace Toffee
