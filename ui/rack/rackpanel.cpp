// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/rack/rackpanel.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTimer>

#include "model/document/tooldocument.h"
#include "model/job/jobchecker.h"
#include "serial/machineconnection.h"
#include "ui/common/appearance.h"
#include "ui/common/appsettings.h"

using namespace Qt::StringLiterals;

namespace Toffee {

RackPanel::RackPanel(MachineConnection *connection, ToolDocument *document, QWidget *parent)
    : QWidget(parent)
    , m_connection(connection)
    , m_document(document)
    , m_spindle(new QLabel(this))
    , m_firmware(new QLabel(this))
    , m_holds(new QLineEdit(AppSettings().jobRack(), this))
    , m_holdsError(new QLabel(this))
    , m_table(new QTableWidget(0, ColumnCount, this))
    , m_toolSpin(new QSpinBox(this))
    , m_load(new QPushButton(this))
    , m_measure(new QPushButton(tr("Measure Rack…"), this))
    , m_check(new QPushButton(tr("Check Rack…"), this))
    , m_tolerance(new QDoubleSpinBox(this))
    , m_useStored(new QCheckBox(
          tr("After a manual change, use the tool's stored TLO\nwhen it is fresh (no probe)"), this))
    , m_progress(new QProgressBar(this))
    , m_status(new QLabel(this))
    , m_cancel(new QPushButton(tr("Cancel"), this))
    , m_result(new QLabel(this))
{
    buildLayout();
    connectSignals();
    rackEdited();
    updateSpindle();
    showProgress(false);
}

void RackPanel::buildLayout()
{
    const auto name = [](QWidget *w, const QString &object, const QString &accessible) {
        w->setObjectName(object);
        w->setAccessibleName(accessible);
    };
    name(m_spindle, u"rackSpindleLabel"_s, tr("The tool in the spindle"));
    name(m_firmware, u"rackFirmwareLabel"_s, tr("The machine's firmware"));
    name(m_holds, u"rackHoldsEdit"_s, tr("The tools the rack holds"));
    name(m_holdsError, u"rackHoldsError"_s, tr("Why the rack is not understood"));
    name(m_table, u"rackTable"_s, tr("The rack's tools"));
    name(m_toolSpin, u"rackToolSpin"_s, tr("The tool to load"));
    name(m_load, u"rackLoadButton"_s, tr("Load the tool"));
    name(m_measure, u"rackMeasureButton"_s, tr("Measure every rack tool"));
    name(m_check, u"rackCheckButton"_s, tr("Break-test every rack tool"));
    name(m_tolerance, u"rackToleranceSpin"_s, tr("Rack check tolerance in millimetres"));
    name(m_useStored, u"rackUseStoredCheck"_s, tr("Use a fresh stored TLO after a manual change"));
    name(m_progress, u"rackProgress"_s, tr("Rack progress"));
    name(m_status, u"rackStatusLabel"_s, tr("What the machine does now"));
    name(m_cancel, u"rackCancelButton"_s, tr("Cancel the rack operation"));
    name(m_result, u"rackResultLabel"_s, tr("The last rack operation's result"));
    m_holds->setToolTip(
        tr("1-6 on a Carvera C1, or tool numbers and ranges (1,2,5-8); the job check uses the "
           "same rack."));
    m_holds->setPlaceholderText(tr("1-6, or none"));
    m_holdsError->setWordWrap(true);
    m_holdsError->setStyleSheet(u"color: #c01c28;"_s);
    setupTable();
    // T-1 empties the spindle: the tool in it goes back to the rack (or out, by hand).
    m_toolSpin->setRange(Limits::kEmptySpindle, Limits::kMaxToolNumber);
    m_toolSpin->setSpecialValueText(tr("Empty"));
    m_toolSpin->setValue(1); // not T0, the Carvera's probe
    m_toolSpin->setPrefix(u"T"_s);
    m_toolSpin->setToolTip(tr("Any tool: one outside the rack is a manual change"));
    takeWheelOnlyWhenFocused(m_toolSpin);
    // Below the firmware's minimum the field still takes what is typed, so that Check Rack can say why it
    // refuses; a field that quietly turned 0.01 into 0.02 would test against a tolerance nobody chose.
    m_tolerance->setRange(0.001, 10.0);
    m_tolerance->setDecimals(3);
    m_tolerance->setSingleStep(0.01);
    m_tolerance->setSuffix(u" mm"_s);
    m_tolerance->setValue(AppSettings().rackTolerance());
    takeWheelOnlyWhenFocused(m_tolerance);
    m_useStored->setChecked(AppSettings().rackUsesStoredTlo());
    m_useStored->setToolTip(tr("A rack tool is always measured by the machine at its change."));
    m_progress->setFormat(tr("%v of %m"));
    m_status->setWordWrap(true);
    m_cancel->setIcon(themeIcon(u"stop"_s));
    m_result->setWordWrap(true);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *grid = new QGridLayout(this);
    grid->addWidget(m_spindle, 0, 0);
    grid->addWidget(m_firmware, 0, 1, 1, 2);
    auto *holdsLabel = new QLabel(tr("&Rack holds:"), this);
    holdsLabel->setBuddy(m_holds);
    grid->addWidget(holdsLabel, 1, 0);
    grid->addWidget(m_holds, 1, 1, 1, 2);
    grid->addWidget(m_holdsError, 2, 0, 1, 3);
    grid->addWidget(m_table, 3, 0, 1, 3);
    grid->addWidget(m_toolSpin, 4, 0);
    grid->addWidget(m_load, 4, 1, 1, 2);
    grid->addWidget(m_measure, 5, 0);
    grid->addWidget(m_check, 5, 1);
    grid->addWidget(m_tolerance, 5, 2);
    grid->addWidget(m_useStored, 6, 0, 1, 3);
    grid->addWidget(m_progress, 7, 0, 1, 2);
    grid->addWidget(m_cancel, 7, 2);
    grid->addWidget(m_status, 8, 0, 1, 3);
    grid->addWidget(m_result, 9, 0, 1, 3);
    grid->setRowStretch(3, 1);
}

void RackPanel::connectSignals()
{
    connect(m_holds, &QLineEdit::textChanged, this, &RackPanel::rackEdited);
    // Remembered once typed, not at each key: "1" on the way to "1-6" is not the rack.
    connect(m_holds, &QLineEdit::editingFinished, this, [this] {
        if (m_rack)
            AppSettings().setJobRack(m_holds->text().trimmed());
    });
    connect(m_toolSpin, &QSpinBox::valueChanged, this, &RackPanel::updateState);
    connect(m_load, &QPushButton::clicked, this, [this] { loadTool(m_toolSpin->value()); });
    connect(m_measure, &QPushButton::clicked, this, [this] { measureRack(); });
    connect(m_check, &QPushButton::clicked, this, [this] { checkRack(); });
    connect(m_cancel, &QPushButton::clicked, this, &RackPanel::cancel);
    connect(m_tolerance, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (MachineController::validateTolerance(v)) // only a tolerance the machine takes is remembered
            AppSettings().setRackTolerance(v);
        updateState();
    });
    connect(m_useStored, &QCheckBox::toggled, this, [](bool on) { AppSettings().setRackUsesStoredTlo(on); });
    connect(m_table, &QTableWidget::itemSelectionChanged, this, [this] {
        const QList<QTableWidgetItem *> selected = m_table->selectedItems();
        if (m_rack && !selected.isEmpty() && selected.front()->row() < m_rack->size())
            m_toolSpin->setValue(m_rack->at(selected.front()->row()));
    });
    connect(m_document->model(), &QAbstractItemModel::modelReset, this, &RackPanel::refreshTable);
    connect(m_document->model(), &QAbstractItemModel::dataChanged, this, &RackPanel::refreshTable);
    connect(m_document->model(), &QAbstractItemModel::rowsInserted, this, &RackPanel::refreshTable);
    connect(m_document->model(), &QAbstractItemModel::rowsRemoved, this, &RackPanel::refreshTable);
    connect(m_connection, &MachineConnection::stateChanged, this, &RackPanel::updateSpindle);
    connect(m_connection, &MachineConnection::stateChanged, this, &RackPanel::updateState);
    connect(m_connection, &MachineConnection::statusChanged, this, &RackPanel::updateSpindle);
    connect(m_connection, &MachineConnection::offsetsChanged, this, &RackPanel::updateSpindle);
    connect(m_connection, &MachineConnection::haltedChanged, this, &RackPanel::updateState);
    connect(m_connection, &MachineConnection::busyChanged, this, [this](bool busy, const QString &what) {
        if (busy && (m_sequence || m_loading))
            m_status->setText(what);
        updateState();
    });
    // "12 min ago" grows old while the panel is open.
    auto *ages = new QTimer(this);
    connect(ages, &QTimer::timeout, this, &RackPanel::refreshTable);
    ages->start(60 * 1000);
}

void RackPanel::rackEdited()
{
    const auto parsed = parseRack(m_holds->text());
    m_rack = parsed ? std::optional(parsed.value()) : std::nullopt;
    m_holdsError->setText(parsed ? QString() : parsed.error().message);
    m_holdsError->setVisible(!parsed);
    refreshTable();
}

std::optional<QString> RackPanel::checkRefusal() const
{
    if (!m_rack)
        return m_holdsError->text();
    if (m_connection->state() != MachineConnection::State::Connected)
        return tr("Connect to the machine first.");
    const auto plan
        = RackSequence::plan(RackSequence::Mode::Check, *m_rack, m_document->table(), m_tolerance->value());
    return RackSequence::refusal(plan, m_connection->firmware());
}

void RackPanel::updateState()
{
    const bool ours = m_sequence || m_loading;
    // The rack is the Carvera's: another controller (grblHAL) is told so, not offered it.
    const bool connected = m_connection->state() == MachineConnection::State::Connected;
    const bool rackless = connected && !m_connection->firmware().hasRack();
    const bool ready = m_connection->canOperate() && m_rack && !ours && !rackless;
    m_load->setText(m_toolSpin->value() == Limits::kEmptySpindle ? tr("Empty the Spindle…")
                                                                 : tr("Load T%1…").arg(m_toolSpin->value()));
    m_load->setEnabled(ready);
    m_measure->setEnabled(ready && !m_rack->isEmpty());
    const auto refusal = checkRefusal();
    m_check->setEnabled(ready && !refusal);
    m_check->setToolTip(refusal ? *refusal
                                : tr("Break-test every rack tool against its stored TLO; the machine halts "
                                     "on a broken one."));
    m_measure->setToolTip(tr("Change to every rack tool in turn and measure it on the tool setter."));
    m_load->setToolTip(tr("Change to the tool: the machine puts the one in the spindle back first."));
    if (rackless) {
        const QString why = tr("%1 has no tool rack: the rack is the Carvera's.")
                                .arg(m_connection->firmware().description());
        for (QWidget *w : std::initializer_list<QWidget *> { m_load, m_measure, m_check })
            w->setToolTip(why);
    }
    for (QWidget *w : std::initializer_list<QWidget *> { m_holds, m_toolSpin, m_tolerance, m_useStored })
        w->setEnabled(!ours);
    Q_EMIT stateChanged();
}

bool RackPanel::canMeasure() const
{
    return m_measure->isEnabled();
}

bool RackPanel::canCheck() const
{
    return m_check->isEnabled();
}

void RackPanel::updateSpindle()
{
    const bool connected = m_connection->state() == MachineConnection::State::Connected;
    const auto tool = connected ? m_connection->activeTool() : std::nullopt;
    m_spindle->setText(!tool                 ? tr("Spindle: unknown")
            : *tool == Limits::kEmptySpindle ? tr("Spindle: empty")
                                             : tr("Spindle: T%1").arg(*tool));
    const FirmwareInfo firmware = m_connection->firmware();
    m_firmware->setText(!connected    ? tr("Not connected")
            : firmware.hasBreakTest() ? firmware.description()
                                      : tr("%1 — no break test").arg(firmware.description()));
    if (tool != m_shownSpindle) {
        m_shownSpindle = tool;
        refreshTable();
    }
    updateState();
}

void RackPanel::showProgress(bool running)
{
    m_progress->setVisible(running);
    m_status->setVisible(running);
    m_cancel->setVisible(running);
    m_cancel->setEnabled(true);
    m_cancel->setText(tr("Cancel"));
    if (running)
        m_status->setText(m_connection->operation());
    updateState();
}

} // namespace Toffee
