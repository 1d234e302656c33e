// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/machine/offseteditor.h"

#include <cmath>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>

#include "model/document/tooldocument.h"
#include "serial/machineconnection.h"
#include "ui/common/appearance.h"
#include "ui/machine/brokentool.h"

using namespace Qt::StringLiterals;

namespace Toffee {

OffsetEditor::OffsetEditor(MachineConnection *connection, ToolDocument *document, QWidget *parent)
    : QWidget(parent)
    , m_connection(connection)
    , m_document(document)
    , m_mode(new QComboBox(this))
    , m_value(new QDoubleSpinBox(this))
    , m_command(new QLabel(this))
    , m_result(new QLabel(this))
    , m_send(new QPushButton(tr("Send"), this))
{
    m_mode->setObjectName(u"offsetModeCombo"_s);
    m_mode->setAccessibleName(tr("How to set the offset"));
    m_mode->addItem(tr("Set TLO to"), SetTlo);
    m_mode->addItem(tr("Change TLO by"), ChangeTlo);
    m_mode->addItem(tr("Gauge height above Z0"), AboveZ0);
    m_value->setObjectName(u"offsetValueSpin"_s);
    m_value->setAccessibleName(tr("Offset value in millimetres"));
    m_value->setRange(-MachineController::kMaxOffset, MachineController::kMaxOffset);
    m_value->setDecimals(3);
    m_value->setSingleStep(0.01);
    m_value->setSuffix(u" mm"_s);
    m_value->setKeyboardTracking(true);
    takeWheelOnlyWhenFocused(m_value);
    takeWheelOnlyWhenFocused(m_mode);
    m_command->setObjectName(u"offsetCommandPreview"_s);
    m_command->setAccessibleName(tr("Command that will be sent"));
    m_command->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_command->setWordWrap(true); // grblHAL's G10 L1 and G43 H are longer than the Carvera's M493.3
    useMonospace(m_command);
    m_result->setObjectName(u"offsetResultPreview"_s);
    m_result->setWordWrap(true); // "set by the machine from the spindle's position" must not widen the panel
    m_mode->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_mode->setMinimumContentsLength(17);
    m_result->setAccessibleName(tr("Resulting tool length offset"));
    m_send->setObjectName(u"sendOffsetButton"_s);
    m_send->setAccessibleName(tr("Send the offset to the machine"));
    m_send->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Return));
    m_send->setToolTip(tr("Send the command above — Ctrl+Enter"));

    auto *form = new QFormLayout(this);
    form->addRow(m_mode, m_value);
    form->addRow(tr("Sends:"), m_command);
    form->addRow(tr("TLO:"), m_result);
    form->addRow(m_send);

    // The same number means something else in each mode: switching starts from a value that changes nothing
    // (the current TLO to set, 0 to add), and a gauge height is never below Z0.
    connect(m_mode, &QComboBox::currentIndexChanged, this, [this] {
        const Mode mode = Mode(m_mode->currentData().toInt());
        m_value->setMinimum(mode == AboveZ0 ? 0.0 : -MachineController::kMaxOffset);
        m_value->setValue(mode == SetTlo && m_currentTlo ? *m_currentTlo : 0.0);
        updatePreview();
    });
    connect(m_value, &QDoubleSpinBox::valueChanged, this, &OffsetEditor::updatePreview);
    connect(m_send, &QPushButton::clicked, this, [this] { send(); });
    connect(m_connection, &MachineConnection::offsetsChanged, this, [this](const TloReading &offsets) {
        m_currentTlo = offsets.tlo();
        updatePreview();
    });
    connect(m_connection, &MachineConnection::statusChanged, this, [this](const MachineStatus &status) {
        if (status.tlo && !m_connection->isBusy()) {
            m_currentTlo = status.tlo;
            updatePreview();
        }
    });
    connect(m_connection, &MachineConnection::stateChanged, this, &OffsetEditor::updatePreview);
    connect(m_connection, &MachineConnection::busyChanged, this, &OffsetEditor::updatePreview);
    connect(m_connection, &MachineConnection::haltedChanged, this, &OffsetEditor::updatePreview);
    updatePreview();
}

void OffsetEditor::setMode(Mode mode)
{
    m_mode->setCurrentIndex(m_mode->findData(mode));
}

void OffsetEditor::setValue(double value)
{
    m_value->setValue(value);
}

std::optional<double> OffsetEditor::targetTlo() const
{
    switch (Mode(m_mode->currentData().toInt())) {
    case SetTlo:
        return m_value->value();
    case ChangeTlo:
        if (!m_currentTlo)
            return std::nullopt;
        return std::round((*m_currentTlo + m_value->value()) * 1000.0) / 1000.0;
    case AboveZ0:
        return std::nullopt; // the machine works it out from where the spindle is
    }
    return std::nullopt;
}

QString OffsetEditor::commandPreview() const
{
    // The connected controller's own words; the Carvera's while none is connected.
    const MachineController *controller = m_connection->session();
    if (Mode(m_mode->currentData().toInt()) == AboveZ0)
        return controller ? controller->aboveZ0Command(m_value->value())
                          : u"M493.3 H"_s + formatNumber(m_value->value(), NumberFormat::command());
    const auto target = targetTlo();
    if (!target)
        return tr("(the current TLO is not known yet)");
    return controller ? controller->setTloCommand(*target)
                      : u"M493.3 Z"_s + formatNumber(*target, NumberFormat::command());
}

QString OffsetEditor::resultPreview() const
{
    const QString now = m_currentTlo ? millimetres(*m_currentTlo, false) : u"?"_s;
    const auto target = targetTlo();
    if (!target)
        return tr("%1 → set by the machine from the spindle's position").arg(now);
    return now + u" → "_s + millimetres(*target, false) + u" mm"_s;
}

void OffsetEditor::updatePreview()
{
    // One command a line: grblHAL's "G10 L1 P2 Z15.5, G43 H2" was cut to "…, G43" in the dock at 1280 px.
    m_command->setText(commandPreview().replace(u", G43"_s, u"\nG43"_s));
    m_result->setText(resultPreview());
    const Mode mode = Mode(m_mode->currentData().toInt());
    const bool known = mode != ChangeTlo || m_currentTlo.has_value();
    // Nothing to send when nothing would change (and a measured TLO must not become "set by hand" for it).
    const auto target = targetTlo();
    const bool changes
        = mode == AboveZ0 || !target || !m_currentTlo || std::fabs(*target - *m_currentTlo) > 0.0005;
    m_send->setEnabled(known && changes && m_connection->canOperate());
}

void OffsetEditor::send(bool confirm)
{
    if (!m_connection->canOperate())
        return;
    const Mode mode = Mode(m_mode->currentData().toInt());
    const auto target = targetTlo();
    if (mode != AboveZ0 && !target)
        return;
    const QString name = m_connection->activeToolName();
    if (confirm
        && QMessageBox::question(this, tr("Change %1's tool length offset?").arg(name),
               tr("Send %1 for %2?\nTLO %3\n\nThe next cut uses the new offset. The table records it as "
                  "set by hand, not measured.")
                       .arg(commandPreview(), name, resultPreview())
                   + brokenParagraph(
                       brokenToolWarning(m_document, m_connection, BrokenToolAction::SetByHand)),
               QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel)
            != QMessageBox::Yes)
        return;
    auto done = [this, mode](const SessionResult &r) {
        if (!r.ok()) {
            if (m_connection->linkLostDuringOperation())
                return; // the window says so, and offers to reconnect
            QMessageBox::warning(this, tr("The offset was not set"),
                r.message + u"\n\n"_s + tr("Nothing was written to the tool table."));
            return;
        }
        // A change is applied once: a second Send must not add it again.
        if (mode == ChangeTlo)
            m_value->setValue(0.0);
        auto recorded = r.recording
            ? m_document->record(*r.recording)
            : Result<void>(Error { tr("the machine reports no tool in the spindle.") });
        if (!recorded)
            QMessageBox::warning(this, tr("The offset is set but not recorded"),
                tr("The machine now has TLO %1, but the table could not record it: %2")
                    .arg(r.tlo ? millimetres(r.tlo->tlo()) : u"?"_s, recorded.error().message));
    };
    if (mode == AboveZ0)
        m_connection->setTloAboveZ0(m_value->value(), done);
    else
        m_connection->setTlo(*target, done);
}

void OffsetEditor::focusValue()
{
    m_value->setFocus(Qt::ShortcutFocusReason);
    m_value->selectAll();
}

} // namespace Toffee
