// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/rowreader.h"

#include <cmath>

#include "model/limits.h"
#include "model/textparsing.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

constexpr qsizetype kMaxIdChars = 64; // a UUID is 36, in braces 38
constexpr qsizetype kMaxMachineChars = 1000;
constexpr qsizetype kMaxProgramChars = 4096; // a file name with its path
constexpr double kMaxSeconds = 1e9; // 30 years of cutting
constexpr double kMaxPathMm = 1e12;

bool isText(const QVariant &value)
{
    return value.typeId() == QMetaType::QString;
}

std::optional<QString> text(const QVariant &value, qsizetype maxChars)
{
    if (!isText(value))
        return std::nullopt;
    QString s = value.toString();
    if (s.size() > maxChars)
        return std::nullopt;
    return s;
}

QDateTime timeFrom(const QVariant &value)
{
    if (!isText(value))
        return {};
    return QDateTime::fromString(value.toString(), Qt::ISODateWithMs).toUTC();
}

} // namespace

std::optional<qint64> RowReader::wholeNumber(const QVariant &value)
{
    switch (value.typeId()) {
    case QMetaType::Int:
    case QMetaType::LongLong:
    case QMetaType::Short:
    case QMetaType::Char:
    case QMetaType::SChar:
    case QMetaType::UChar:
    case QMetaType::UShort:
        return value.toLongLong();
    case QMetaType::UInt:
    case QMetaType::ULongLong: {
        const qulonglong v = value.toULongLong();
        return v > qulonglong(std::numeric_limits<qint64>::max()) ? std::nullopt : std::optional(qint64(v));
    }
    case QMetaType::Double:
    case QMetaType::Float: {
        const double v = value.toDouble();
        if (!std::isfinite(v) || v != std::floor(v) || std::fabs(v) > 9e15)
            return std::nullopt;
        return qint64(v);
    }
    default:
        return std::nullopt; // NULL, text (even "3": an integer column that holds text was not written so)
    }
}

std::optional<double> RowReader::finiteNumber(const QVariant &value)
{
    switch (value.typeId()) {
    case QMetaType::Int:
    case QMetaType::LongLong:
    case QMetaType::UInt:
    case QMetaType::ULongLong:
    case QMetaType::Short:
    case QMetaType::UShort:
    case QMetaType::Double:
    case QMetaType::Float: {
        const double v = value.toDouble();
        return std::isfinite(v) ? std::optional(v) : std::nullopt;
    }
    default:
        return std::nullopt;
    }
}

QString RowReader::shown(const QVariant &value)
{
    if (value.isNull())
        return u"NULL"_s;
    switch (value.typeId()) {
    case QMetaType::QString:
        return u'"' + excerpt(value.toString()) + u'"';
    case QMetaType::QByteArray:
        return tr("a blob of %1 bytes").arg(value.toByteArray().size());
    default:
        return excerpt(value.toString());
    }
}

Result<StoredTool> RowReader::tool(const ToolRow &row, Units units)
{
    const auto number = wholeNumber(row.number);
    if (!number || *number < Limits::kMinToolNumber || *number > Limits::kMaxToolNumber)
        return Error { tr("a row's tool number is %1, not a tool number (%2 to %3)")
                           .arg(shown(row.number))
                           .arg(Limits::kMinToolNumber)
                           .arg(Limits::kMaxToolNumber) };
    const QString who = tr("T%1's row").arg(*number);
    auto refuse = [&who](const QString &why) {
        return Error { who + u": "_s + why };
    };
    const auto version = wholeNumber(row.version);
    if (!version || *version < 1 || *version > (qint64(1) << 62))
        return refuse(tr("its version is %1, not a whole number from 1 up").arg(shown(row.version)));
    const auto deleted = wholeNumber(row.deleted);
    if (!deleted || (*deleted != 0 && *deleted != 1))
        return refuse(tr("\"deleted\" is %1, not 0 or 1").arg(shown(row.deleted)));
    StoredTool out { int(*number), std::nullopt, *version,
        excerpt(isText(row.updatedBy) ? row.updatedBy.toString() : QString(), 255), timeFrom(row.updatedAt) };
    if (*deleted == 1)
        return out;
    const auto chars = wholeNumber(row.dataChars);
    if (chars && *chars > kMaxToolDataChars)
        return refuse(tr("its data is %1 characters long; no tool's is longer than %2 KB")
                          .arg(*chars)
                          .arg(kMaxToolDataChars / 1024));
    if (!isText(row.data))
        return refuse(tr("its data is %1, not a tool").arg(shown(row.data)));
    auto tool = toolFromData(row.data.toString().toUtf8(), units);
    if (!tool)
        return refuse(tool.error().text());
    if (tool.value().number != *number)
        return refuse(tr("its data is T%1's, not T%2's").arg(tool.value().number).arg(*number));
    out.tool = tool.takeValue();
    return out;
}

Result<void> RowReader::checkEvent(const HistoryEvent &e)
{
    auto refuse = [&e](const QString &why) {
        return Error { tr("event %1: %2").arg(excerpt(e.id, kMaxIdChars), why) };
    };
    if (e.id.isEmpty() || e.id.size() > kMaxIdChars)
        return refuse(tr("its id is not an event's"));
    if (e.machine.isEmpty() || e.machine.size() > kMaxMachineChars)
        return refuse(tr("it names no machine"));
    if (e.tool < Limits::kMinToolNumber || e.tool > Limits::kMaxToolNumber)
        return refuse(tr("its tool %1 is not a tool number").arg(e.tool));
    if (!e.at.isValid())
        return refuse(tr("it has no valid time"));
    for (const auto &[value, name] : { std::pair(e.tlo, "tlo"), std::pair(e.referenceMz, "reference_mz"),
             std::pair(e.currentMz, "current_mz"), std::pair(e.oldTlo, "old_tlo"),
             std::pair(e.newTlo, "new_tlo"), std::pair(e.tolerance, "tolerance") }) {
        if (value && (!std::isfinite(*value) || std::fabs(*value) > kMaxMachineMillimetres))
            return refuse(tr("its %1 is %2, which no machine measures")
                              .arg(QLatin1StringView(name))
                              .arg(*value, 0, 'g', 6));
    }
    if (e.tolerance && *e.tolerance < 0)
        return refuse(tr("its tolerance is negative"));
    if (e.touches.size() == 1 || e.touches.size() > ProbeSettings::kMaxTouches
        || !touchesFromText(touchesText(e.touches)))
        return refuse(tr("its touches are not 2 to %1 machine positions").arg(ProbeSettings::kMaxTouches));
    return {};
}

Result<HistoryEvent> RowReader::event(const QVariantList &row)
{
    if (row.size() != kEventColumns)
        return Error { tr("an event's row has %1 columns, not %2").arg(row.size()).arg(kEventColumns) };
    HistoryEvent e;
    const auto id = text(row.at(0), kMaxIdChars);
    e.id = id.value_or(QString());
    auto refuse = [&row, &id](const QString &why) {
        return Error { tr("event %1: %2").arg(id ? *id : shown(row.at(0)), why) };
    };
    if (!id || id->isEmpty())
        return refuse(tr("its id is not text of up to %1 characters").arg(kMaxIdChars));
    const auto machine = text(row.at(1), kMaxMachineChars);
    if (!machine || machine->isEmpty())
        return refuse(tr("its machine is %1, not a machine's name").arg(shown(row.at(1))));
    e.machine = *machine;
    const auto tool = wholeNumber(row.at(2));
    if (!tool || *tool < Limits::kMinToolNumber || *tool > Limits::kMaxToolNumber)
        return refuse(tr("its tool is %1, not a tool number (%2 to %3)")
                          .arg(shown(row.at(2)))
                          .arg(Limits::kMinToolNumber)
                          .arg(Limits::kMaxToolNumber));
    e.tool = int(*tool);
    e.at = timeFrom(row.at(3));
    if (!e.at.isValid())
        return refuse(
            tr("its time is %1, not a time in UTC (2026-11-23T08:10:00.125Z)").arg(shown(row.at(3))));
    const auto kind = isText(row.at(4)) ? eventKindFromName(row.at(4).toString()) : std::nullopt;
    if (!kind)
        return refuse(tr("its kind is %1, not one Toffee records").arg(shown(row.at(4))));
    e.kind = *kind;
    constexpr const char *kNumbers[]
        = { "tlo", "reference_mz", "current_mz", "tolerance", "old_tlo", "new_tlo" };
    std::optional<double> *into[]
        = { &e.tlo, &e.referenceMz, &e.currentMz, &e.tolerance, &e.oldTlo, &e.newTlo };
    for (int i = 0; i < 6; ++i) {
        const QVariant &v = row.at(5 + i);
        if (v.isNull())
            continue;
        const auto n = finiteNumber(v);
        if (!n)
            return refuse(tr("its %1 is %2, not a number").arg(QLatin1StringView(kNumbers[i]), shown(v)));
        *into[i] = *n;
    }
    if (!row.at(11).isNull()) {
        const auto failed = wholeNumber(row.at(11));
        if (!failed || (*failed != 0 && *failed != 1))
            return refuse(tr("\"failed\" is %1, not 0 or 1").arg(shown(row.at(11))));
        e.failed = *failed == 1;
    }
    // The spread (column 13) is the touches' own, kept for whoever reads the library with SQL.
    if (!row.at(12).isNull() && !row.at(12).toString().isEmpty()) {
        const auto touches = isText(row.at(12)) ? touchesFromText(row.at(12).toString()) : std::nullopt;
        if (!touches)
            return refuse(tr("its touches are %1, not machine positions").arg(shown(row.at(12))));
        e.touches = *touches;
    }
    if (auto checked = checkEvent(e); !checked)
        return checked.error();
    return e;
}

Result<ToolUse> RowReader::use(const QVariantList &row)
{
    if (row.size() != 7)
        return Error { tr("a tool use's row has %1 columns, not 7").arg(row.size()) };
    const auto id = text(row.at(0), kMaxIdChars);
    auto refuse = [&row, &id](const QString &why) {
        return Error { tr("tool use %1: %2").arg(id ? *id : shown(row.at(0)), why) };
    };
    const auto machine = text(row.at(1), kMaxMachineChars);
    const auto tool = wholeNumber(row.at(2));
    const QDateTime at = timeFrom(row.at(3));
    const auto program = row.at(4).isNull() ? std::optional(QString()) : text(row.at(4), kMaxProgramChars);
    const auto seconds = finiteNumber(row.at(5));
    const auto path = finiteNumber(row.at(6));
    if (!id || id->isEmpty())
        return refuse(tr("its id is not text of up to %1 characters").arg(kMaxIdChars));
    if (!machine || machine->isEmpty())
        return refuse(tr("its machine is %1, not a machine's name").arg(shown(row.at(1))));
    if (!tool || *tool < Limits::kMinToolNumber || *tool > Limits::kMaxToolNumber)
        return refuse(tr("its tool is %1, not a tool number").arg(shown(row.at(2))));
    if (!at.isValid())
        return refuse(tr("its time is %1, not a time in UTC").arg(shown(row.at(3))));
    if (!program)
        return refuse(tr("its program is %1, not a file name").arg(shown(row.at(4))));
    if (!seconds || *seconds < 0 || *seconds > kMaxSeconds)
        return refuse(tr("its cutting time is %1, not a number of seconds").arg(shown(row.at(5))));
    if (!path || *path < 0 || *path > kMaxPathMm)
        return refuse(tr("its feed path is %1, not a length").arg(shown(row.at(6))));
    return ToolUse { *id, *machine, int(*tool), at, *program, *seconds, *path };
}

} // namespace Toffee
