// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/common/appearance.h"

#include <algorithm>

#include <QApplication>
#include <QEvent>
#include <QLabel>
#include <QLocale>
#include <QPalette>
#include <QStyle>
#include <QStyleFactory>
#include <QWidget>

using namespace Qt::StringLiterals;

namespace Toffee {

QIcon themeIcon(const QString &name)
{
    if (name.isEmpty())
        return {};
    return QIcon(u":/icons/"_s + name + u".svg"_s);
}

void applyPalette(bool dark)
{
    if (!dark) {
        QApplication::setPalette(QApplication::style()->standardPalette());
        return;
    }
    QApplication::setStyle(QStyleFactory::create(u"Fusion"_s));
    QPalette p;
    const QColor window(0x30, 0x30, 0x33);
    const QColor base(0x24, 0x24, 0x26);
    const QColor text(0xee, 0xee, 0xec);
    p.setColor(QPalette::Window, window);
    p.setColor(QPalette::WindowText, text);
    p.setColor(QPalette::Base, base);
    p.setColor(QPalette::AlternateBase, window);
    p.setColor(QPalette::ToolTipBase, base);
    p.setColor(QPalette::ToolTipText, text);
    p.setColor(QPalette::PlaceholderText, QColor(0x9a, 0x99, 0x96));
    p.setColor(QPalette::Text, text);
    p.setColor(QPalette::Button, window);
    p.setColor(QPalette::ButtonText, text);
    p.setColor(QPalette::BrightText, Qt::white);
    p.setColor(QPalette::Link, QColor(0x78, 0xae, 0xed));
    p.setColor(QPalette::Highlight, QColor(0x35, 0x84, 0xe4));
    p.setColor(QPalette::HighlightedText, Qt::white);
    for (auto role : { QPalette::WindowText, QPalette::Text, QPalette::ButtonText })
        p.setColor(QPalette::Disabled, role, QColor(0x77, 0x76, 0x7b));
    QApplication::setPalette(p);
}

namespace {

class WheelGuard final : public QObject
{
public:
    using QObject::QObject;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (event->type() == QEvent::Wheel) {
            auto *widget = qobject_cast<QWidget *>(watched);
            if (widget && !widget->hasFocus()) {
                event->ignore(); // the scroll area behind takes it and scrolls
                return true;
            }
        }
        return false;
    }
};

} // namespace

void takeWheelOnlyWhenFocused(QWidget *field)
{
    field->setFocusPolicy(Qt::StrongFocus); // a wheel no longer gives it focus
    static auto *guard = new WheelGuard(qApp);
    field->installEventFilter(guard);
}

void useMonospace(QWidget *widget)
{
    QFont font = widget->font();
    font.setFamily(u"monospace"_s);
    font.setStyleHint(QFont::Monospace);
    widget->setFont(font);
}

QColor alarmColor(const QPalette &palette)
{
    return palette.color(QPalette::Window).lightness() < 128 ? QColor(0xff, 0x7b, 0x63)
                                                             : QColor(0xc0, 0x1c, 0x28);
}

void explainDisabled(QWidget *widget, const QString &why)
{
    static const char *const kOwn = "toffeeOwnToolTip";
    if (!widget->property(kOwn).isValid())
        widget->setProperty(kOwn, widget->toolTip());
    widget->setToolTip(why.isEmpty() ? widget->property(kOwn).toString() : why);
}

void fitWrappedLabel(QLabel *label, int width)
{
    if (label->isHidden())
        return;
    const int height = label->text().isEmpty() ? 0 : label->heightForWidth(std::max(200, width));
    if (height >= 0 && height != label->height())
        label->setFixedHeight(height);
}

} // namespace Toffee
