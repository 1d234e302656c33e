// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/library/conflictdialog.h"

#include <algorithm>

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QScreen>
#include <QTableWidget>
#include <QVBoxLayout>

#include "model/numberformat.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QString length(double value, Units units)
{
    return formatNumber(value, NumberFormat::display(units).inLocale()) + u' ' + unitsSymbol(units);
}

QString tloText(const Tool &tool, Units units)
{
    if (!tool.measuredTlo)
        return ConflictDialog::tr("not measured");
    const QString source = tool.tloSource == TloSource::Manual ? ConflictDialog::tr("set by hand")
        : tool.tloSource == TloSource::Pulled ? ConflictDialog::tr("read from the controller")
                                              : ConflictDialog::tr("probed");
    const QString when = tool.measuredAt.isValid()
        ? QLocale().toString(tool.measuredAt.toLocalTime(), QLocale::ShortFormat)
        : ConflictDialog::tr("time unknown");
    return ConflictDialog::tr("%1 (%2, %3)").arg(length(*tool.measuredTlo, units), source, when);
}

// Each field as "name: value", in the order the table shows them.
QList<std::pair<QString, QString>> fields(const Tool &tool, Units units)
{
    return {
        { ConflictDialog::tr("Description"),
            tool.description.isEmpty() ? ConflictDialog::tr("(none)") : tool.description },
        { ConflictDialog::tr("Pocket"), QString::number(tool.pocket) },
        { ConflictDialog::tr("TLO"), tloText(tool, units) },
        { ConflictDialog::tr("Length"), length(tool.lengthGeometry, units) },
        { ConflictDialog::tr("Length wear"), length(tool.lengthWear, units) },
        { ConflictDialog::tr("Radius"), length(tool.radiusGeometry, units) },
        { ConflictDialog::tr("Radius wear"), length(tool.radiusWear, units) },
        { ConflictDialog::tr("Break test"),
            tool.breakTestFailed ? ConflictDialog::tr("failed") : ConflictDialog::tr("passed or not run") },
        { ConflictDialog::tr("Reference MCS Z"),
            tool.referenceMz ? length(*tool.referenceMz, units) : ConflictDialog::tr("unknown") },
        { ConflictDialog::tr("Notes"), tool.notes.isEmpty() ? ConflictDialog::tr("(none)") : tool.notes },
        { ConflictDialog::tr("LinuxCNC fields"),
            tool.linuxCncExtra.isEmpty() ? ConflictDialog::tr("(none)") : tool.linuxCncExtra },
    };
}

} // namespace

QString ConflictDialog::describe(
    const std::optional<Tool> &tool, const std::optional<Tool> &other, Units units)
{
    if (!tool)
        return tr("Removed from the table");
    const auto mine = fields(*tool, units);
    const auto theirs = other ? fields(*other, units) : QList<std::pair<QString, QString>> {};
    QStringList lines;
    for (qsizetype i = 0; i < mine.size(); ++i) {
        // The description always, so that the tool is recognised; then what differs.
        if (i == 0 || theirs.isEmpty() || theirs.at(i).second != mine.at(i).second)
            lines << mine.at(i).first + u": "_s + mine.at(i).second;
    }
    return lines.join(u'\n');
}

ConflictDialog::ConflictDialog(const QList<ToolConflict> &conflicts, Units units, QWidget *parent)
    : QDialog(parent)
    , m_conflicts(conflicts)
    , m_table(new QTableWidget(this))
{
    setObjectName(u"conflictDialog"_s);
    setAccessibleName(tr("Tools changed on another station"));
    setWindowTitle(tr("Changed on Another Station"));
    auto *intro = new QLabel(this);
    intro->setObjectName(u"conflictIntro"_s);
    intro->setAccessibleName(tr("What happened"));
    intro->setWordWrap(true);
    intro->setText(conflicts.size() == 1
            ? tr("Another station changed this tool since you opened the table, and so did you. Choose which "
                 "version the library keeps. Everything else is saved.")
            : tr("Another station changed these %1 tools since you opened the table, and so did you. Choose, "
                 "for each, which version the library keeps. Everything else is saved.")
                  .arg(conflicts.size()));
    m_table->setObjectName(u"conflictTable"_s);
    m_table->setAccessibleName(tr("Their version and yours, per tool"));
    m_table->setColumnCount(ColumnCount);
    m_table->setHorizontalHeaderLabels({ tr("Tool"), tr("Theirs"), tr("Mine"), tr("Keep") });
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    // Tab goes from one tool's choice to the next and on to the buttons: the table's own Tab would move
    // its (invisible) current cell instead, and the keyboard would never leave the first choice.
    m_table->setTabKeyNavigation(false);
    m_table->setWordWrap(true);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(TheirsColumn, QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(MineColumn, QHeaderView::Stretch);
    fill(units);

    auto *buttons = new QDialogButtonBox(this);
    buttons->setObjectName(u"conflictButtons"_s);
    buttons->setAccessibleName(tr("Apply the choices or decide later"));
    QPushButton *apply = buttons->addButton(tr("&Apply Choices"), QDialogButtonBox::AcceptRole);
    apply->setObjectName(u"conflictApplyButton"_s);
    apply->setAccessibleName(tr("Apply the choices"));
    apply->setDefault(true);
    QPushButton *later = buttons->addButton(tr("Decide &Later"), QDialogButtonBox::RejectRole);
    later->setObjectName(u"conflictLaterButton"_s);
    later->setAccessibleName(tr("Decide later; your edits stay unsaved"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addWidget(m_table, 1);
    layout->addWidget(buttons);
    // Wrapped text is as tall as its column is narrow: the rows follow the columns' widths.
    connect(m_table->horizontalHeader(), &QHeaderView::sectionResized, m_table,
        &QTableWidget::resizeRowsToContents);
    // A choice reached with Tab is scrolled into view, however many tools there are.
    m_scrollToFocus = connect(qApp, &QApplication::focusChanged, this, [this](QWidget *, QWidget *now) {
        if (const auto row = m_choices.indexOf(now); row >= 0)
            m_table->scrollTo(m_table->model()->index(int(row), ChoiceColumn));
    });
    if (!m_choices.isEmpty())
        m_choices.front()->setFocus();
    resize(800, 400);
}

// Its widgets lose their focus as they go: the rows are not scrolled to then.
ConflictDialog::~ConflictDialog()
{
    disconnect(m_scrollToFocus);
}

// As tall as the rows need once they are laid out at the dialog's width, within the screen.
void ConflictDialog::showEvent(QShowEvent *event)
{
    QDialog::showEvent(event);
    m_table->resizeRowsToContents();
    const int rows = m_table->verticalHeader()->length() + m_table->horizontalHeader()->height()
        + 2 * m_table->frameWidth();
    const int available = screen() ? screen()->availableGeometry().height() * 4 / 5 : 600;
    resize(width(), std::min(available, height() - m_table->height() + rows));
}

void ConflictDialog::fill(Units units)
{
    m_table->setRowCount(int(m_conflicts.size()));
    for (int row = 0; row < m_conflicts.size(); ++row) {
        const ToolConflict &c = m_conflicts.at(row);
        auto *tool = new QTableWidgetItem(u"T"_s + QString::number(c.number));
        tool->setTextAlignment(Qt::AlignLeft | Qt::AlignTop);
        m_table->setItem(row, ToolColumn, tool);
        const QString station = c.theirStation.isEmpty() ? tr("another station") : c.theirStation;
        auto *theirs
            = new QTableWidgetItem(tr("From %1:").arg(station) + u'\n' + describe(c.theirs, c.mine, units));
        theirs->setTextAlignment(Qt::AlignLeft | Qt::AlignTop);
        m_table->setItem(row, TheirsColumn, theirs);
        auto *mine
            = new QTableWidgetItem(tr("From this station:") + u'\n' + describe(c.mine, c.theirs, units));
        mine->setTextAlignment(Qt::AlignLeft | Qt::AlignTop);
        m_table->setItem(row, MineColumn, mine);
        // At the top of its cell, beside the tool's first line, not stretched over the row's height.
        auto *cell = new QWidget(m_table);
        auto *choice = new QComboBox(cell);
        auto *top = new QVBoxLayout(cell);
        top->setContentsMargins(4, 2, 4, 2);
        top->addWidget(choice);
        top->addStretch(1);
        choice->setObjectName(u"conflictChoice%1"_s.arg(c.number));
        choice->setAccessibleName(tr("Version of T%1 to keep").arg(c.number));
        choice->addItem(tr("Keep mine"));
        choice->addItem(tr("Take theirs (%1)").arg(station));
        m_table->setCellWidget(row, ChoiceColumn, cell);
        m_choices.append(choice);
    }
    m_table->resizeRowsToContents();
}

bool ConflictDialog::keepsMine(int number) const
{
    for (qsizetype i = 0; i < m_conflicts.size(); ++i) {
        if (m_conflicts.at(i).number == number)
            return m_choices.at(i)->currentIndex() == 0;
    }
    return true;
}

void ConflictDialog::setKeepsMine(int number, bool keep)
{
    for (qsizetype i = 0; i < m_conflicts.size(); ++i) {
        if (m_conflicts.at(i).number == number)
            m_choices.at(i)->setCurrentIndex(keep ? 0 : 1);
    }
}

} // namespace Toffee
