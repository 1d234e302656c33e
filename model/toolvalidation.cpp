// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/toolvalidation.h"

#include <cmath>

#include <QCoreApplication>
#include <QLocale>

#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QString shown(double value, Units units)
{
    return formatNumber(value, NumberFormat::fixed(resolutionDecimals(units)));
}

} // namespace

double maxGeometry(Units units)
{
    return units == Units::Inch ? Limits::kMaxGeometryInch : Limits::kMaxGeometryMm;
}

int defaultPocket(int toolNumber)
{
    return toolNumber >= 1 && toolNumber <= Limits::kMaxPocket ? toolNumber : 1;
}

double maxWear(Units units)
{
    return units == Units::Inch ? Limits::kMaxWearInch : Limits::kMaxWearMm;
}

Result<void> validateToolNumber(int number)
{
    if (number < Limits::kMinToolNumber || number > Limits::kMaxToolNumber)
        return Error { tr("tool number %1 is out of range; use %2 to %3.")
                           .arg(number)
                           .arg(Limits::kMinToolNumber)
                           .arg(Limits::kMaxToolNumber) };
    return {};
}

Result<void> validatePocket(int pocket)
{
    if (pocket < Limits::kMinPocket || pocket > Limits::kMaxPocket)
        return Error { tr("pocket %1 is out of range; use %2 to %3.")
                           .arg(pocket)
                           .arg(Limits::kMinPocket)
                           .arg(Limits::kMaxPocket) };
    return {};
}

Result<void> validateLength(const QString &what, double value, double limit, Units units)
{
    if (!std::isfinite(value))
        return Error { tr("%1 is not a number; enter a value from %2 to %3 %4.")
                           .arg(what, shown(-limit, units), shown(limit, units), unitsSymbol(units)) };
    if (std::fabs(value) > limit)
        return Error { tr("%1 %2 %3 is out of range; a controller takes %4 to %5 %3.")
                           .arg(what, quotedNumber(value), unitsSymbol(units), shown(-limit, units),
                               shown(limit, units)) };
    return {};
}

bool isMachineTlo(double millimetres)
{
    return std::isfinite(millimetres) && std::fabs(millimetres) <= Limits::kMaxMachineOffsetMm;
}

Result<void> validateLinuxCncExtra(const QString &extra)
{
    static const QString kLetters = u"XYABCUVWIJQ"_s;
    const auto tokens = QStringView(extra).split(u' ', Qt::SkipEmptyParts);
    for (QStringView token : tokens) {
        bool isNumber = false;
        const QChar letter = token.isEmpty() ? QChar() : token.front().toUpper();
        if (kLetters.contains(letter)) {
            if (letter == u'Q') {
                const int q = token.mid(1).toInt(&isNumber);
                isNumber = isNumber && q >= 0 && q <= 9;
            } else {
                isNumber = std::isfinite(token.mid(1).toDouble(&isNumber)) && isNumber;
            }
        }
        if (!isNumber)
            return Error { tr("\"%1\" is not a LinuxCNC tool field (X, Y, A, B, C, U, V, W, I, J or Q0-Q9).")
                               .arg(excerpt(token)) };
    }
    return {};
}

namespace {

// A cutter lasts hours, not years: a limit beyond these is a typing slip.
constexpr double kMaxLifeMinutes = 100000.0;
constexpr int kMaxLifeUses = 1000000;

bool withinLimit(double value, double limit)
{
    return std::isfinite(value) && std::fabs(value) <= limit;
}

// The common case, without building a single message: loading 100,000 tools validates each one.
bool isPlainlyValid(const Tool &tool, Units units)
{
    const double geometry = maxGeometry(units);
    const double wear = maxWear(units);
    if (tool.number < Limits::kMinToolNumber || tool.number > Limits::kMaxToolNumber
        || tool.pocket < Limits::kMinPocket || tool.pocket > Limits::kMaxPocket
        || tool.description.size() > Limits::kMaxDescriptionLength
        || tool.notes.size() > Limits::kMaxNotesLength || !tool.linuxCncExtra.isEmpty()
        || !withinLimit(tool.lengthGeometry, geometry) || !withinLimit(tool.lengthWear, wear)
        || !withinLimit(tool.radiusGeometry, geometry) || !withinLimit(tool.radiusWear, wear)
        || (tool.measuredTlo && !withinLimit(*tool.measuredTlo, geometry))
        || (!tool.measuredTlo && tool.tloSource != TloSource::Probe)
        || (tool.referenceMz && !withinLimit(*tool.referenceMz, geometry))
        || tool.cutterType.size() > Limits::kMaxDescriptionLength
        || (tool.overallLength && (!withinLimit(*tool.overallLength, geometry) || *tool.overallLength < 0.0))
        || (tool.lifeLimitMinutes
            && (!std::isfinite(*tool.lifeLimitMinutes) || *tool.lifeLimitMinutes <= 0.0
                || *tool.lifeLimitMinutes > kMaxLifeMinutes))
        || (tool.lifeLimitUses && (*tool.lifeLimitUses < 1 || *tool.lifeLimitUses > kMaxLifeUses))
        || tool.flutes || !tool.probing.isDefault())
        return false;
    for (QChar c : tool.description) {
        if (c.unicode() < 0x20 || (c.unicode() >= 0x7f && c.category() == QChar::Other_Control))
            return false;
    }
    return true;
}

} // namespace

Result<void> validateTool(const Tool &tool, Units units)
{
    if (isPlainlyValid(tool, units))
        return {};
    const QString prefix = u"T"_s + QString::number(tool.number) + u": "_s;
    auto withPrefix = [&](const Result<void> &r) -> Result<void> {
        if (r.ok())
            return r;
        return Error { prefix + r.error().message };
    };

    if (auto r = validateToolNumber(tool.number); !r)
        return r;
    if (auto r = validatePocket(tool.pocket); !r)
        return withPrefix(r);
    if (tool.description.size() > Limits::kMaxDescriptionLength)
        return Error { prefix
            + tr("the description is %1 characters long; keep it to %2.")
                  .arg(tool.description.size())
                  .arg(Limits::kMaxDescriptionLength) };
    for (QChar c : tool.description) {
        if (c.category() == QChar::Other_Control)
            return Error { prefix
                + tr("the description must be one line of text, without tabs or line breaks.") };
    }
    if (tool.notes.size() > Limits::kMaxNotesLength)
        return Error { prefix
            + tr("the notes are %1 characters long; keep them to %2.")
                  .arg(tool.notes.size())
                  .arg(Limits::kMaxNotesLength) };

    const double geometry = maxGeometry(units);
    const double wear = maxWear(units);
    if (auto r = validateLength(tr("length geometry"), tool.lengthGeometry, geometry, units); !r)
        return withPrefix(r);
    if (auto r = validateLength(tr("length wear"), tool.lengthWear, wear, units); !r)
        return withPrefix(r);
    if (auto r = validateLength(tr("radius geometry"), tool.radiusGeometry, geometry, units); !r)
        return withPrefix(r);
    if (auto r = validateLength(tr("radius wear"), tool.radiusWear, wear, units); !r)
        return withPrefix(r);
    if (tool.measuredTlo) {
        if (auto r = validateLength(tr("measured TLO"), *tool.measuredTlo, geometry, units); !r)
            return withPrefix(r);
    } else if (tool.tloSource != TloSource::Probe) {
        return Error { prefix + tr("a TLO set by hand needs its value; the measured TLO is empty.") };
    }
    if (tool.referenceMz) {
        if (auto r = validateLength(tr("reference MCS Z"), *tool.referenceMz, geometry, units); !r)
            return withPrefix(r);
    }
    if (auto r = validateLinuxCncExtra(tool.linuxCncExtra); !r)
        return withPrefix(r);
    if (tool.cutterType.size() > Limits::kMaxDescriptionLength)
        return Error { prefix
            + tr("the cutter type is %1 characters long; keep it to %2.")
                  .arg(tool.cutterType.size())
                  .arg(Limits::kMaxDescriptionLength) };
    if (tool.overallLength) {
        if (auto r = validateLength(tr("overall length"), *tool.overallLength, geometry, units); !r)
            return withPrefix(r);
        if (*tool.overallLength < 0.0)
            return Error { prefix + tr("the overall length cannot be negative.") };
    }
    if (tool.lifeLimitMinutes
        && (!std::isfinite(*tool.lifeLimitMinutes) || *tool.lifeLimitMinutes <= 0.0
            || *tool.lifeLimitMinutes > kMaxLifeMinutes))
        return Error { prefix
            + tr("a life limit in minutes must be more than 0 and at most %1; leave it empty for none.")
                  .arg(kMaxLifeMinutes) };
    if (tool.lifeLimitUses && (*tool.lifeLimitUses < 1 || *tool.lifeLimitUses > kMaxLifeUses))
        return Error { prefix
            + tr("a life limit in uses must be a whole number from 1 to %1; leave it empty for none.")
                  .arg(kMaxLifeUses) };
    if (tool.flutes && (*tool.flutes < 1 || *tool.flutes > ProbeSettings::kMaxFlutes))
        return Error { prefix
            + tr("a cutter has 1 to %1 cutting edges; leave it empty when unknown.")
                  .arg(ProbeSettings::kMaxFlutes) };
    if (auto r = tool.probing.validate(units); !r)
        return Error { prefix + r.error().message };
    return {};
}

} // namespace Toffee
