// SPDX-License-Identifier: GPL-3.0-or-later
// The Rack panel's table: a row per rack tool, with what the table knows of it and this session's result.
#include "ui/rack/rackpanel.h"

#include <QFont>
#include <QHeaderView>
#include <QTableWidget>

#include "model/document/tooldocument.h"
#include "model/numberformat.h"
#include "model/timetext.h"

using namespace Qt::StringLiterals;

namespace Toffee {

void RackPanel::setupTable()
{
    m_table->setHorizontalHeaderLabels(
        { tr("Slot"), tr("Tool"), tr("Stored TLO"), tr("Measured"), tr("Result") });
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    // The dock shares its width with the machine panel's 400 px: long cells wrap onto a second line rather
    // than push the result out of sight.
    m_table->setWordWrap(true);
    m_table->setTextElideMode(Qt::ElideNone);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(SlotColumn, QHeaderView::ResizeToContents);
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // Every row as tall as a wrapped one, so that the rows line up whichever cells wrap.
    m_table->verticalHeader()->setMinimumSectionSize(2 * m_table->fontMetrics().lineSpacing() + 8);
    m_table->horizontalHeaderItem(StoredColumn)->setToolTip(tr("In millimetres"));
    m_table->horizontalHeaderItem(ResultColumn)
        ->setToolTip(tr("This session's Measure Rack or Check Rack, with the TLO measured (mm)"));
}

void RackPanel::refreshTable()
{
    const QList<int> tools = m_rack.value_or(QList<int> {});
    m_table->setRowCount(int(tools.size()));
    for (int row = 0; row < tools.size(); ++row)
        fillRow(row, tools.at(row));
    updateState();
}

QString RackPanel::measuredText(int tool) const
{
    const Tool *t = m_document->table().find(tool);
    if (!t || !t->measuredTlo)
        return tr("never");
    if (t->breakTestFailed)
        return tr("failed break test");
    if (t->tloSource == TloSource::Manual)
        return tr("set by hand");
    if (t->tloSource == TloSource::Pulled)
        return tr("read from the controller");
    return t->measuredAt.isValid() ? ageText(t->measuredAt) : tr("measured");
}

void RackPanel::fillRow(int row, int tool)
{
    const Tool *t = m_document->table().find(tool);
    const auto stored = m_document->table().storedTlo(tool); // in millimetres, as the machine's
    const auto step = m_results.constFind(tool);
    const bool inSpindle = m_shownSpindle == tool;
    const bool broken
        = (step != m_results.cend() && step->state == RackStep::State::Broken) || (t && t->breakTestFailed);
    const QStringList texts { QString::number(row + 1),
        inSpindle ? tr("T%1 · in spindle").arg(tool) : u"T"_s + QString::number(tool),
        stored ? millimetres(stored->tlo, false) : u"—"_s, measuredText(tool),
        step != m_results.cend() ? resultText(*step) : QString() };
    for (int column = 0; column < ColumnCount; ++column) {
        QTableWidgetItem *item = m_table->item(row, column);
        if (!item) {
            item = new QTableWidgetItem;
            item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
            m_table->setItem(row, column, item);
        }
        item->setText(texts.at(column));
        QFont font = m_table->font();
        font.setBold(inSpindle || (column == ResultColumn && broken));
        item->setFont(font);
        item->setBackground(broken ? QBrush(QColor(0xe0, 0x1b, 0x24, 0x60)) : QBrush());
        item->setToolTip(column == ResultColumn && step != m_results.cend() ? step->message
                : t                                                         ? t->description
                                                                            : tr("Not in the table"));
        if (column == StoredColumn)
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    }
}

QString RackPanel::resultText(const RackStep &step) const
{
    // In millimetres, as the column next to it; the unit would only widen a narrow dock.
    const QString tlo = step.measuredTlo ? millimetres(*step.measuredTlo, false) : QString();
    switch (step.state) {
    case RackStep::State::Waiting:
        return tr("Waiting");
    case RackStep::State::Running:
        return m_sequence && m_sequence->mode() == RackSequence::Mode::Check ? tr("Checking…")
                                                                             : tr("Measuring…");
    case RackStep::State::Measured:
        return tr("Measured: %1").arg(tlo);
    case RackStep::State::Passed:
        return tlo.isEmpty() ? tr("Passed") : tr("Passed: %1").arg(tlo);
    case RackStep::State::Broken:
        return tlo.isEmpty() ? tr("BROKEN") : tr("BROKEN: %1").arg(tlo);
    case RackStep::State::Failed:
        return tr("Failed");
    case RackStep::State::NotRun:
        return tr("Not run");
    case RackStep::State::Skipped:
        return tr("Skipped");
    }
    return {};
}

} // namespace Toffee
