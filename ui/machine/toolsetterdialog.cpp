// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/machine/toolsetterdialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QVBoxLayout>

#include "model/limits.h"
#include "model/numberformat.h"
#include "serial/machineconnection.h"
#include "ui/common/askfirst.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QDoubleSpinBox *spin(QWidget *parent, const QString &name, double low, double high, const QString &suffix)
{
    auto *box = new QDoubleSpinBox(parent);
    box->setObjectName(name);
    box->setRange(low, high);
    box->setDecimals(3);
    box->setSuffix(suffix);
    box->setAccelerated(true);
    return box;
}

} // namespace

ToolSetterDialog::ToolSetterDialog(
    const QString &machine, const ToolSetter &setter, MachineConnection *connection, QWidget *parent)
    : QDialog(parent)
    , m_x(spin(this, u"setterX"_s, -Limits::kMaxMachineOffsetMm, Limits::kMaxMachineOffsetMm, tr(" mm")))
    , m_y(spin(this, u"setterY"_s, -Limits::kMaxMachineOffsetMm, Limits::kMaxMachineOffsetMm, tr(" mm")))
    , m_zMin(
          spin(this, u"setterZMin"_s, -Limits::kMaxMachineOffsetMm, Limits::kMaxMachineOffsetMm, tr(" mm")))
    , m_safeZ(
          spin(this, u"setterSafeZ"_s, -Limits::kMaxMachineOffsetMm, Limits::kMaxMachineOffsetMm, tr(" mm")))
    , m_seek(spin(this, u"setterSeekFeed"_s, 1.0, ToolSetter::kMaxFeed, tr(" mm/min")))
    , m_latch(spin(this, u"setterLatchFeed"_s, 1.0, ToolSetter::kMaxFeed, tr(" mm/min")))
    , m_backoff(spin(this, u"setterBackoff"_s, 0.1, ToolSetter::kMaxBackoff, tr(" mm")))
    , m_problem(new QLabel(this))
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    setObjectName(u"toolSetterDialog"_s);
    setWindowTitle(tr("Tool Setter of %1").arg(machine));
    auto *intro
        = new QLabel(tr("Where the tool setter is, in machine coordinates, and how Toffee touches it: "
                        "it lifts to the safe Z, moves over the setter, searches down to the lowest "
                        "Z at the search feed, backs off, and touches again at the latch feed."),
            this);
    intro->setWordWrap(true);
    m_x->setValue(setter.x);
    m_y->setValue(setter.y);
    m_zMin->setValue(setter.zMin);
    m_safeZ->setValue(setter.safeZ);
    m_seek->setValue(setter.seekFeed);
    m_latch->setValue(setter.latchFeed);
    m_backoff->setValue(setter.backoff);
    m_problem->setObjectName(u"setterProblem"_s);
    m_problem->setWordWrap(true);
    auto *form = new QFormLayout;
    form->addRow(tr("Setter &X:"), m_x);
    form->addRow(tr("Setter &Y:"), m_y);
    form->addRow(tr("&Lowest Z to search to:"), m_zMin);
    form->addRow(tr("Safe Z to &lift to:"), m_safeZ);
    form->addRow(tr("&Search feed:"), m_seek);
    form->addRow(tr("L&atch feed:"), m_latch);
    form->addRow(tr("&Back-off between touches:"), m_backoff);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(form);
    // Only a controller whose setter cycle is Toffee's is jogged from here; the others keep their own.
    if (connection && connection->state() == MachineConnection::State::Connected && connection->session()
        && connection->session()->needsToolSetter())
        layout->addWidget(machineBox(connection));
    layout->addWidget(m_problem);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    for (QDoubleSpinBox *box : { m_x, m_y, m_zMin, m_safeZ, m_seek, m_latch, m_backoff })
        connect(box, &QDoubleSpinBox::valueChanged, this, &ToolSetterDialog::check);
    check();
}

ToolSetter ToolSetterDialog::setter() const
{
    ToolSetter s;
    s.x = m_x->value();
    s.y = m_y->value();
    s.zMin = m_zMin->value();
    s.safeZ = m_safeZ->value();
    s.seekFeed = m_seek->value();
    s.latchFeed = m_latch->value();
    s.backoff = m_backoff->value();
    return s;
}

QWidget *ToolSetterDialog::machineBox(MachineConnection *connection)
{
    m_connection = connection;
    auto *box = new QGroupBox(tr("From the machine"), this);
    box->setObjectName(u"setterMachineBox"_s);
    auto *help
        = new QLabel(tr("Jog the spindle over the setter's centre, then take its X and Y from where the "
                        "machine stands."),
            box);
    help->setWordWrap(true);
    m_position = new QLabel(tr("Where the machine stands: waiting for its report…"), box);
    m_position->setObjectName(u"setterMachinePosition"_s);
    m_step = new QComboBox(box);
    m_step->setObjectName(u"setterJogStep"_s);
    for (double step : { 0.1, 1.0, 10.0 })
        m_step->addItem(tr("%1 mm").arg(formatNumber(step, NumberFormat::upTo(3).inLocale())), step);
    m_step->setCurrentIndex(1);
    auto *stepLabel = new QLabel(tr("Jog s&tep:"), box);
    stepLabel->setBuddy(m_step);
    auto *pad = new QGridLayout;
    struct Jog
    {
        int axis;
        double direction;
        QString text;
        QString name;
        int row;
        int column;
    };
    const Jog jogs[] = { { 1, 1.0, tr("Y+"), u"setterJogYPlus"_s, 0, 1 },
        { 0, -1.0, tr("X−"), u"setterJogXMinus"_s, 1, 0 }, { 0, 1.0, tr("X+"), u"setterJogXPlus"_s, 1, 2 },
        { 1, -1.0, tr("Y−"), u"setterJogYMinus"_s, 2, 1 }, { 2, 1.0, tr("Z+"), u"setterJogZPlus"_s, 0, 3 },
        { 2, -1.0, tr("Z−"), u"setterJogZMinus"_s, 2, 3 } };
    for (const Jog &j : jogs) {
        auto *button = new QPushButton(j.text, box);
        button->setObjectName(j.name);
        button->setAutoDefault(false);
        button->setToolTip(tr("Moves the machine by the jog step along %1.").arg(j.text));
        connect(button, &QPushButton::clicked, this, [this, j] { jog(j.axis, j.direction); });
        pad->addWidget(button, j.row, j.column);
        m_jogButtons << button;
    }
    m_stop = new QPushButton(tr("Sto&p"), box);
    m_stop->setObjectName(u"setterJogStop"_s);
    m_stop->setAutoDefault(false);
    m_stop->setToolTip(tr("Stops the jog at once where the machine stands."));
    connect(m_stop, &QPushButton::clicked, m_connection, &MachineConnection::stopJog);
    pad->addWidget(m_stop, 1, 3);
    m_useHere = new QPushButton(tr("&Use X and Y Where It Stands"), box);
    m_useHere->setObjectName(u"setterUseHere"_s);
    m_useHere->setAutoDefault(false);
    connect(m_useHere, &QPushButton::clicked, this, &ToolSetterDialog::useWhereItStands);
    m_jogResult = new QLabel(box);
    m_jogResult->setObjectName(u"setterJogResult"_s);
    m_jogResult->setWordWrap(true);
    auto *steps = new QHBoxLayout;
    steps->addWidget(stepLabel);
    steps->addWidget(m_step);
    steps->addStretch();
    auto *layout = new QVBoxLayout(box);
    layout->addWidget(help);
    layout->addWidget(m_position);
    layout->addLayout(steps);
    layout->addLayout(pad);
    layout->addWidget(m_useHere);
    layout->addWidget(m_jogResult);
    connect(m_connection, &MachineConnection::statusChanged, this, [this](const MachineStatus &status) {
        m_here = status.mpos;
        m_position->setText(tr("Where the machine stands: X %1, Y %2, Z %3 mm (machine coordinates).")
                                .arg(millimetres(status.mpos[0], false), millimetres(status.mpos[1], false),
                                    millimetres(status.mpos[2], false)));
        updateMachine();
    });
    connect(m_connection, &MachineConnection::busyChanged, this, &ToolSetterDialog::updateMachine);
    connect(m_connection, &MachineConnection::stateChanged, this, &ToolSetterDialog::updateMachine);
    updateMachine();
    return box;
}

void ToolSetterDialog::updateMachine()
{
    const bool ready = m_connection->canOperate();
    for (QPushButton *b : std::as_const(m_jogButtons))
        b->setEnabled(ready);
    m_stop->setEnabled(m_connection->isBusy());
    m_useHere->setEnabled(ready && m_here.has_value());
}

void ToolSetterDialog::jog(int axis, double direction)
{
    if (!m_connection->canOperate())
        return;
    if (!m_jogAsked) {
        m_jogAsked = askFirst(this,
            { QMessageBox::Question, tr("Jog the machine?"),
                tr("The machine moves each time you press a jog button."),
                tr("Each press moves it by the jog step, at %1 mm/min, and Stop stops it. Keep hands clear.")
                    .arg(formatNumber(kJogFeed, NumberFormat::upTo(0).inLocale())),
                tr("Jog"), u"setterJogYesButton"_s, u"setterJogQuestion"_s });
        if (!m_jogAsked)
            return;
    }
    std::array<double, 3> step { 0, 0, 0 };
    step[std::size_t(axis)] = direction * m_step->currentData().toDouble();
    m_jogResult->clear();
    QPointer<ToolSetterDialog> self(this);
    m_connection->jog(step, kJogFeed, [self](const SessionResult &r) {
        if (self) // a refusal or a failure, or a jog stopped: said; a jog that ran its step says nothing
            self->m_jogResult->setText(r.message);
    });
}

void ToolSetterDialog::useWhereItStands()
{
    if (!m_here)
        return;
    m_x->setValue((*m_here)[0]);
    m_y->setValue((*m_here)[1]);
    m_jogResult->setText(tr("The setter's X and Y are where the machine stands: X %1, Y %2 mm.")
                             .arg(millimetres((*m_here)[0], false), millimetres((*m_here)[1], false)));
}

void ToolSetterDialog::check()
{
    const auto valid = setter().validate();
    m_problem->setText(valid ? QString() : valid.error().message);
    m_problem->setVisible(!valid);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(valid.ok());
}

} // namespace Toffee
