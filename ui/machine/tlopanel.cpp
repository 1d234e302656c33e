// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/machine/tlopanel.h"

#include <cmath>

#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

#include "model/clock.h"
#include "model/document/tooldocument.h"
#include "serial/machineconnection.h"
#include "ui/common/appearance.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QLabel *valueLabel(QWidget *parent, const QString &name, const QString &accessible)
{
    auto *label = new QLabel(parent);
    label->setObjectName(name);
    label->setAccessibleName(accessible);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

QLabel *caption(const QString &text, QWidget *parent)
{
    auto *label = new QLabel(text, parent);
    label->setForegroundRole(QPalette::PlaceholderText);
    return label;
}

QString when(const QDateTime &at)
{
    return QLocale().toString(at.toLocalTime(), QLocale::ShortFormat);
}

} // namespace

// The firmware's state words, in the window's language.
QString machineStateName(const QString &state)
{
    static const char *const names[][2] = { { "Idle", QT_TRANSLATE_NOOP("Toffee::TloPanel", "Idle") },
        { "Run", QT_TRANSLATE_NOOP("Toffee::TloPanel", "Running") },
        { "Hold", QT_TRANSLATE_NOOP("Toffee::TloPanel", "Held") },
        { "Alarm", QT_TRANSLATE_NOOP("Toffee::TloPanel", "Alarm") },
        { "Home", QT_TRANSLATE_NOOP("Toffee::TloPanel", "Homing") },
        { "Sleep", QT_TRANSLATE_NOOP("Toffee::TloPanel", "Asleep") },
        { "Pause", QT_TRANSLATE_NOOP("Toffee::TloPanel", "Paused") },
        { "Wait", QT_TRANSLATE_NOOP("Toffee::TloPanel", "Waiting") },
        { "Tool", QT_TRANSLATE_NOOP("Toffee::TloPanel", "Waiting for the operator") } };
    for (const auto &[word, name] : names) {
        if (state == QLatin1StringView(word))
            return QCoreApplication::translate("Toffee::TloPanel", name);
    }
    return state;
}

TloPanel::TloPanel(MachineConnection *connection, ToolDocument *document, QWidget *parent)
    : QWidget(parent)
    , m_connection(connection)
    , m_document(document)
    , m_state(valueLabel(this, u"machineStateLabel"_s, tr("Machine state")))
    , m_tool(valueLabel(this, u"activeToolLabel"_s, tr("Active tool")))
    , m_tlo(valueLabel(this, u"tloLabel"_s, tr("Tool length offset")))
    , m_tloNote(valueLabel(this, u"tloNoteLabel"_s, tr("Where the tool length offset came from")))
    , m_reference(valueLabel(this, u"referenceMzLabel"_s, tr("Reference tool MCS Z")))
    , m_current(valueLabel(this, u"currentMzLabel"_s, tr("Current tool MCS Z")))
    , m_halt(valueLabel(this, u"haltLabel"_s, tr("Why the machine halted and what to do")))
    , m_unlock(new QPushButton(tr("&Unlock", "the strip's button"), this))
{
    setObjectName(u"machineStrip"_s);
    QFont big = m_tlo->font();
    big.setPointSizeF(big.pointSizeF() * 1.5);
    big.setBold(true);
    m_tlo->setFont(big);
    QFont bold = m_tool->font();
    bold.setBold(true);
    m_tool->setFont(bold);
    m_state->setFont(bold);
    // Wrapped at the width the strip has (fitHalt), never widening the window: a wrapped label left to the
    // layout would ask for the height of its narrowest layout. The tooltip has it all too.
    m_halt->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_halt->setWordWrap(true);
    m_halt->setAutoFillBackground(true);
    m_halt->setMargin(4);
    m_halt->hide();
    m_unlock->setObjectName(u"unlockButton"_s);
    m_unlock->setIcon(themeIcon(u"unlock"_s));
    m_unlock->setAccessibleName(tr("Unlock the machine"));
    // Ctrl+Shift+U belongs to the Machine menu's Unlock, which runs this same unlock.
    m_unlock->setToolTip(tr("Clear the halt ($X) — Ctrl+Shift+U"));
    m_unlock->hide();

    layOut();

    connect(m_connection, &MachineConnection::statusChanged, this, &TloPanel::showStatus);
    connect(m_connection, &MachineConnection::offsetsChanged, this, &TloPanel::showOffsets);
    connect(m_connection, &MachineConnection::haltedChanged, this, &TloPanel::showHalt);
    // An operation's end may change what the halt means (a failed break test's length in force), before the
    // next status report.
    connect(m_connection, &MachineConnection::busyChanged, this, &TloPanel::showHalt);
    connect(m_connection, &MachineConnection::stateChanged, this, [this](MachineConnection::State s) {
        if (s == MachineConnection::State::Connecting)
            m_connectedAt = Clock::now();
        if (s != MachineConnection::State::Connected)
            clear();
    });
    // The note compares the machine's TLO with the table's: it follows every edit, undo and file load.
    connect(m_document->model(), &QAbstractItemModel::modelReset, this, &TloPanel::updateTlo);
    connect(m_document->model(), &QAbstractItemModel::dataChanged, this, &TloPanel::updateTlo);
    connect(m_document->model(), &QAbstractItemModel::rowsInserted, this, &TloPanel::updateTlo);
    connect(m_document->model(), &QAbstractItemModel::rowsRemoved, this, &TloPanel::updateTlo);
    connect(m_unlock, &QPushButton::clicked, this, [this] { unlock(); });
    connect(&m_staleTimer, &QTimer::timeout, this, &TloPanel::checkStale);
    m_staleTimer.start(500);
    clear();
}

// The note wraps and the two Z values stack, so that the strip fits 1280 pixels in every language.
void TloPanel::layOut()
{
    m_tloNote->setWordWrap(true);
    m_tloNote->setMinimumWidth(160);
    // Two lines, always, as the heights beside it: the strip never changes height when the note does, so
    // the table below never moves. What does not fit is in the tooltip.
    m_tloNote->setFixedHeight(2 * m_tloNote->fontMetrics().lineSpacing() + 2);
    m_tloNote->setAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    auto *row = new QHBoxLayout;
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(caption(tr("State:"), this));
    row->addWidget(m_state);
    row->addSpacing(12);
    row->addWidget(caption(tr("Tool:"), this));
    row->addWidget(m_tool);
    row->addSpacing(12);
    row->addWidget(caption(tr("TLO:"), this));
    row->addWidget(m_tlo);
    row->addSpacing(6);
    row->addWidget(m_tloNote, 1);
    row->addSpacing(12);
    auto *heights = new QGridLayout;
    heights->setVerticalSpacing(0);
    heights->addWidget(caption(tr("Reference Z:"), this), 0, 0);
    heights->addWidget(m_reference, 0, 1, Qt::AlignRight);
    heights->addWidget(caption(tr("Current Z:"), this), 1, 0);
    heights->addWidget(m_current, 1, 1, Qt::AlignRight);
    row->addLayout(heights);
    row->addSpacing(8);
    row->addWidget(m_unlock);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 2, 6, 2);
    layout->setSpacing(2);
    layout->addLayout(row);
    layout->addWidget(m_halt);
}

void TloPanel::clear()
{
    m_state->setText(m_connection->state() == MachineConnection::State::Connecting ? tr("Connecting…")
                                                                                   : tr("Not connected"));
    m_state->setStyleSheet({});
    for (QLabel *l : { m_tool, m_reference, m_current, m_tlo })
        l->setText(u"—"_s);
    m_tloNote->clear();
    m_activeTool.reset();
    m_machineTlo.reset();
    m_offsets.reset();
    m_unlock->hide();
    m_halt->hide();
    m_stale = true;
}

void TloPanel::showStatus(const MachineStatus &status)
{
    m_stale = false;
    if (status.tool)
        m_activeTool = *status.tool;
    if (status.tlo)
        m_machineTlo = *status.tlo;
    showHalt();
    updateTlo();
}

void TloPanel::showHalt()
{
    const bool halted = m_connection->isHalted();
    const auto status = m_connection->link() ? m_connection->link()->lastStatus() : std::nullopt;
    QString state = halted ? tr("HALTED") : status ? machineStateName(status->state) : tr("Connected");
    m_lastStateText = state;
    m_state->setText(state);
    // Style sheets, not palettes: a toolbar's style repaints its widgets with its own palette.
    const QString red = alarmColor(palette()).name();
    m_state->setStyleSheet(
        halted ? u"color: white; background: %1; padding: 1px 6px;"_s.arg(red) : QString());
    m_unlock->setVisible(halted);
    m_halt->setVisible(halted);
    if (halted) {
        const auto reason = m_connection->haltReason();
        const HaltWords words = reason ? m_connection->haltWords(*reason) : HaltWords {};
        const auto restore = m_connection->session() ? m_connection->session()->tloToRestore() : std::nullopt;
        // After a failed break test the firmware keeps the length it measured in force: which one that is,
        // and what Unlock does about it.
        const QString why = restore
            ? tr(
                "The break test found %1 broken, and the machine halted with the length it measured in force "
                "(%2 above).\nCheck the tool, then Unlock: Toffee sets its stored TLO, %3, back first.")
                  .arg(m_activeTool && *m_activeTool >= 0 ? u"T"_s + QString::number(*m_activeTool)
                                                          : tr("the tool"),
                      m_machineTlo ? millimetres(*m_machineTlo) : tr("its TLO"), millimetres(*restore))
            : !m_connection->haltSaid().isEmpty() ? tr("The machine said: “%1”").arg(m_connection->haltSaid())
                + u'\n' + (reason ? words.recovery : tr("Check the machine, then Unlock ($X)."))
            : reason
            ? words.meaning + u'\n' + words.recovery
            : tr("The machine reported an alarm.") + u'\n' + tr("Check the machine, then Unlock ($X).");
        m_halt->setText(
            why + u' ' + tr("Nothing that moves the machine or changes its offsets runs until then."));
        m_halt->setToolTip(m_halt->text());
        fitHalt();
        m_halt->setStyleSheet(
            u"color: white; background: %1; padding: 3px 6px; font-weight: bold;"_s.arg(red));
    }
}

void TloPanel::showOffsets(const TloReading &offsets, int tool)
{
    m_offsets = offsets;
    m_machineTlo = offsets.tlo();
    if (tool >= 0)
        m_activeTool = tool;
    updateTlo();
}

QString TloPanel::tloNote() const
{
    return m_tloNote->text();
}

void TloPanel::updateTlo()
{
    if (m_connection->state() != MachineConnection::State::Connected)
        return;
    m_tool->setText(
        m_activeTool ? (*m_activeTool < 0 ? tr("none") : u"T"_s + QString::number(*m_activeTool)) : u"—"_s);
    if (m_offsets) {
        // The stock firmware reports the TLO alone, and after a TLO set by hand the tool has no MCS Z on the
        // setter: what the machine did not report is said so, not shown as zero.
        m_reference->setText(
            m_offsets->referenceMz ? millimetres(*m_offsets->referenceMz) : tr("not reported"));
        m_current->setText(m_offsets->currentMz ? millimetres(*m_offsets->currentMz)
                : m_offsets->referenceMz        ? tr("not measured")
                                                : tr("not reported"));
    }
    // A TLO of exactly 0 that no MCS Z adds up to is the firmware's "none" (its break test says "No previous
    // TLO" to it): nothing measured or set since the machine started.
    const bool neverMeasured = m_offsets && m_offsets->tlo() == 0.0 && !m_offsets->currentMz;
    if (!m_machineTlo) {
        m_tlo->setText(u"—"_s);
        m_tloNote->clear();
        return;
    }
    m_tlo->setText(neverMeasured ? tr("not measured") : millimetres(*m_machineTlo));
    QString note;
    bool warn = false;
    // The table's TLO as the machine has it (millimetres), whatever the table's units.
    const auto tool = m_activeTool ? m_document->table().storedTlo(*m_activeTool) : std::nullopt;
    const Tool *row = m_activeTool ? m_document->table().find(*m_activeTool) : nullptr;
    if (neverMeasured) {
        note = tr("the machine has no TLO in force: probe the tool first");
        warn = true;
    } else if (!m_activeTool || *m_activeTool < 0) {
        note.clear();
    } else if (!tool) {
        note = tr("T%1 has no TLO in the table").arg(*m_activeTool);
        warn = true;
    } else if (std::fabs(tool->tlo - *m_machineTlo) > tool->sameWithin) {
        note = tr("not T%1's: the table holds %2").arg(*m_activeTool).arg(millimetres(tool->tlo));
        warn = true;
    } else if (tool->source == TloSource::Manual) {
        note = tr("set by hand %1, not measured").arg(when(tool->measuredAt));
        warn = true;
    } else if (tool->source == TloSource::Pulled) {
        note = tr("read from the controller %1, not measured").arg(when(tool->measuredAt));
        warn = true;
    } else if (tool->measuredAt.isValid() && m_connectedAt.isValid() && tool->measuredAt < m_connectedAt) {
        // The machine's value is the table's, but nothing here says the machine took it from that probe.
        note = tr("as the table's, measured %1").arg(when(tool->measuredAt));
    } else {
        note = tr("measured %1").arg(when(tool->measuredAt));
    }
    if (row && row->breakTestFailed) {
        note = tr("T%1 FAILED ITS BREAK TEST — %2").arg(*m_activeTool).arg(note);
        warn = true;
    }
    m_tloNote->setText(note);
    m_tloNote->setToolTip(note);
    m_tloNote->setStyleSheet(warn ? u"color: %1;"_s.arg(alarmColor(palette()).name()) : QString());
}

void TloPanel::checkStale()
{
    if (m_connection->state() != MachineConnection::State::Connected)
        return;
    const bool stale = m_connection->isStatusStale();
    const bool halted = m_connection->isHalted();
    if (stale) {
        // How long, in whole seconds, redrawn as it grows. A halt is what the machine last said and what it
        // stays in until unlocked: it is shown as known, not greyed as if the link were gone.
        const qint64 age = m_connection->link() ? m_connection->link()->statusAgeMs() : -1;
        const QString since = age < 0 ? tr("no status report yet")
                                      : tr("no status report for %1 s").arg(std::max<qint64>(1, age / 1000));
        m_state->setText(halted ? tr("HALTED (%1; it stays halted until unlocked)").arg(since)
                                : tr("%1 (stale: %2)").arg(m_lastStateText, since));
    } else if (m_stale) {
        showHalt();
    }
    m_stale = stale;
    m_state->setEnabled(!stale || halted);
    for (QLabel *l : { m_tool, m_reference, m_current, m_tlo, m_tloNote })
        l->setEnabled(!stale);
}

void TloPanel::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    fitHalt();
}

void TloPanel::fitHalt()
{
    // The banner spans the strip (its margins aside); its height is what its words need at that width.
    const QMargins margins = layout() ? layout()->contentsMargins() : QMargins();
    fitWrappedLabel(m_halt, this->width() - margins.left() - margins.right());
}

void TloPanel::unlock(bool confirm)
{
    // A tool the table marks broken: the failed break test left its new length in force, and its stored TLO
    // goes back first.
    const auto tool = m_connection->activeTool();
    const Tool *stored = tool ? m_document->table().find(*tool) : nullptr;
    const auto storedTlo = tool ? m_document->table().storedTlo(*tool) : std::nullopt;
    const std::optional<double> brokenTlo
        = storedTlo && storedTlo->breakTestFailed ? std::optional(storedTlo->tlo) : std::nullopt;
    // One click must not carry on with a tool that may be broken: the operator says the tool was looked at.
    if (confirm && stored && stored->breakTestFailed && window()->isVisible()) {
        QMessageBox box(QMessageBox::Warning, tr("Unlock with T%1 marked broken?").arg(stored->number),
            tr("T%1 failed its break test: it may be broken, and the machine halted so that it cuts nothing "
               "more.")
                .arg(stored->number),
            QMessageBox::Cancel, this);
        // The stored TLO goes back whatever it was (the table and the machine then agree, as on grblHAL,
        // where a failed test changes nothing); one set by hand is said to be that.
        box.setInformativeText(brokenTlo && stored->tloSource == TloSource::Manual
                ? tr("Look at the tool first, and replace it if it is broken. Unlock sets T%1's stored TLO, "
                     "%2, back before anything can move: it was set by hand, not measured, and the break "
                     "test measured %3. Probe T%1 before it cuts; the mark stays until then.")
                      .arg(stored->number)
                      .arg(millimetres(*brokenTlo),
                          m_machineTlo ? millimetres(*m_machineTlo) : tr("another length"))
                : brokenTlo
                ? tr("Look at the tool first, and replace it if it is broken. Unlock sets T%1's stored TLO, "
                     "%2, "
                     "back before anything can move; the mark stays until T%1 is measured again (Probe).")
                      .arg(stored->number)
                      .arg(millimetres(*brokenTlo))
                : tr("Look at the tool first, and replace it if it is broken. The mark stays until T%1 is "
                     "measured again (Probe).")
                      .arg(stored->number));
        QPushButton *unlock = box.addButton(tr("Unlock"), QMessageBox::AcceptRole);
        unlock->setObjectName(u"unlockBrokenButton"_s);
        box.setDefaultButton(QMessageBox::Cancel);
        box.exec();
        if (box.clickedButton() != unlock)
            return;
    }
    m_connection->unlock(
        [this](const SessionResult &r) {
            if (!r.ok())
                QMessageBox::warning(this, tr("Unlock failed"),
                    r.message + u"\n\n"_s
                        + tr("The machine is still halted: check it, then try Unlock again."));
        },
        brokenTlo);
}

} // namespace Toffee
