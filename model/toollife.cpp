// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/toollife.h"

#include <algorithm>
#include <cmath>

#include <QRegularExpression>

#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/timetext.h"

using namespace Qt::StringLiterals;

namespace Toffee {

std::optional<double> ToolLife::fraction(const Tool &tool, const UsedLife &used)
{
    std::optional<double> out;
    if (tool.lifeLimitMinutes && *tool.lifeLimitMinutes > 0.0)
        out = used.seconds / 60.0 / *tool.lifeLimitMinutes;
    if (tool.lifeLimitUses && *tool.lifeLimitUses > 0)
        out = std::max(out.value_or(0.0), double(used.uses) / double(*tool.lifeLimitUses));
    return out;
}

LifeState ToolLife::state(const Tool &tool, const UsedLife &used)
{
    const auto f = fraction(tool, used);
    if (!f)
        return LifeState::NoLimit;
    // Exactly at the limit is used up, not beyond it: the next cut takes it past.
    if (*f > 1.0 + 1e-9)
        return LifeState::Exceeded;
    return *f >= kNearFraction - 1e-9 ? LifeState::Near : LifeState::Fine;
}

QString ToolLife::limitText(const Tool &tool)
{
    QStringList parts;
    if (tool.lifeLimitMinutes)
        parts << tr("%1 min").arg(formatNumber(*tool.lifeLimitMinutes, NumberFormat::upTo(3)));
    if (tool.lifeLimitUses)
        parts << tr("%1 uses").arg(*tool.lifeLimitUses);
    return parts.join(u", "_s);
}

Result<void> ToolLife::parseLimit(const QString &text, Tool &tool)
{
    const QString how
        = tr("Type the tool's life as minutes of cutting, uses (programs), or both: \"90 min\", "
             "\"40 uses\", \"90 min, 40 uses\"; leave it empty for no limit.");
    std::optional<double> minutes;
    std::optional<int> uses;
    const QString minWord = tr("min");
    const QString usesWord = tr("uses");
    static const QRegularExpression part(u"^\\s*([0-9]+(?:[.,][0-9]+)?)\\s*([^\\s0-9.,]*)\\s*$"_s);
    const QStringList pieces
        = text.split(QRegularExpression(u"[;/]|,(?=\\s)|\\band\\b"_s), Qt::SkipEmptyParts);
    for (const QString &piece : pieces) {
        if (piece.trimmed().isEmpty())
            continue;
        const auto m = part.match(piece);
        if (!m.hasMatch())
            return Error { tr("\"%1\" is not a tool life. %2").arg(excerpt(text, 40), how) };
        QByteArray digits = m.captured(1).toUtf8();
        digits.replace(',', '.');
        const QString unit = m.captured(2).toLower();
        const bool isUses = unit == usesWord.toLower() || unit == u"uses"_s || unit == u"use"_s
            || unit == u"x"_s || unit == u"runs"_s;
        const bool isMinutes
            = unit.isEmpty() || unit == minWord.toLower() || unit == u"min"_s || unit == u"minutes"_s;
        if (isUses) {
            const auto n = parseInteger(digits);
            if (!n || *n < 1 || *n > 1000000 || uses)
                return Error { tr("\"%1\" is not a tool life. %2").arg(excerpt(text, 40), how) };
            uses = int(*n);
        } else if (isMinutes) {
            const auto v = parseDecimal(digits);
            if (!v || *v <= 0.0 || *v > 100000.0 || minutes)
                return Error { tr("\"%1\" is not a tool life. %2").arg(excerpt(text, 40), how) };
            minutes = *v;
        } else {
            return Error { tr("\"%1\" is not a tool life. %2").arg(excerpt(text, 40), how) };
        }
    }
    tool.lifeLimitMinutes = minutes;
    tool.lifeLimitUses = uses;
    return {};
}

QString ToolLife::usedText(const Tool &tool, const UsedLife &used)
{
    QStringList parts;
    const QString time = durationText(used.seconds);
    if (tool.lifeLimitMinutes)
        parts << tr("%1 of %2 min").arg(time, formatNumber(*tool.lifeLimitMinutes, NumberFormat::upTo(3)));
    else if (used.seconds > 0.0 || !tool.lifeLimitUses)
        parts << time;
    if (tool.lifeLimitUses)
        parts << tr("%1 of %2 uses").arg(used.uses).arg(*tool.lifeLimitUses);
    return parts.join(u" · "_s);
}

} // namespace Toffee
