// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/toolsetterdialog.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "model/limits.h"

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

ToolSetterDialog::ToolSetterDialog(const QString &machine, const ToolSetter &setter, QWidget *parent)
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

void ToolSetterDialog::check()
{
    const auto valid = setter().validate();
    m_problem->setText(valid ? QString() : valid.error().message);
    m_problem->setVisible(!valid);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(valid.ok());
}

} // namespace Toffee
