// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/machine/offsetsyncdialog.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include "model/numberformat.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QString cell(std::optional<double> v)
{
    return v ? formatNumber(*v, NumberFormat::fixed(3).inLocale()) : QString(u'—');
}

} // namespace

OffsetSyncDialog::OffsetSyncDialog(Direction direction, const QString &controller,
    const QList<OffsetDifference> &rows, const QString &refusal, QWidget *parent)
    : QDialog(parent)
    , m_table(new QTableWidget(int(rows.size()), 4, this))
    , m_summary(new QLabel(this))
{
    const bool push = direction == Direction::Push;
    setObjectName(push ? u"pushOffsetsDialog"_s : u"pullOffsetsDialog"_s);
    setWindowTitle(
        push ? tr("Push Offsets to %1").arg(controller) : tr("Pull Offsets from %1").arg(controller));
    m_table->setObjectName(u"offsetsPreviewTable"_s);
    m_table->setHorizontalHeaderLabels({ tr("Tool"), tr("TLO in the file"), tr("TLO in %1").arg(controller),
        push ? tr("Pushing") : tr("Pulling") });
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    int changing = 0;
    for (int i = 0; i < rows.size(); ++i) {
        const OffsetDifference &r = rows.at(i);
        const QStringList texts { u"T%1"_s.arg(r.tool), cell(r.inFile), cell(r.inController), r.what };
        for (int c = 0; c < texts.size(); ++c) {
            auto *item = new QTableWidgetItem(texts.at(c));
            if (c == 1 || c == 2)
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            if (r.changes) {
                QFont bold = item->font();
                bold.setBold(true);
                item->setFont(bold);
            }
            m_table->setItem(i, c, item);
        }
        changing += r.changes ? 1 : 0;
    }
    m_table->resizeColumnsToContents();
    m_summary->setObjectName(u"offsetsPreviewSummary"_s);
    m_summary->setWordWrap(true);
    if (!refusal.isEmpty())
        m_summary->setText(refusal);
    else if (changing == 0)
        m_summary->setText(tr("Nothing to change: the file and %1 agree.").arg(controller));
    else if (push)
        m_summary->setText(tr("The TLOs in bold (%1) will be written into %2's own table and read back. The "
                              "file does not change.")
                               .arg(changing)
                               .arg(controller));
    else
        m_summary->setText(
            tr("The TLOs in bold (%1) will be taken into the file as set on %2, not measured by "
               "Toffee, each with a history event. %2 does not change.")
                .arg(changing)
                .arg(controller));
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    QPushButton *go = buttons->addButton(push ? tr("&Push") : tr("P&ull"), QDialogButtonBox::AcceptRole);
    go->setObjectName(u"offsetsGoButton"_s);
    go->setEnabled(changing > 0 && refusal.isEmpty());
    (go->isEnabled() ? go : buttons->button(QDialogButtonBox::Cancel))->setDefault(true);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_table);
    layout->addWidget(m_summary);
    layout->addWidget(buttons);
    resize(560, 380);
}

} // namespace Toffee
