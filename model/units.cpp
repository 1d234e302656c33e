// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/units.h"

using namespace Qt::StringLiterals;

namespace Toffee {

QString unitsSymbol(Units units)
{
    return units == Units::Inch ? u"in"_s : u"mm"_s;
}

std::optional<Units> unitsFromSymbol(QStringView symbol)
{
    const QString s = symbol.trimmed().toString().toLower();
    if (s == u"mm" || s == u"millimetre" || s == u"millimeter")
        return Units::Millimetre;
    if (s == u"in" || s == u"inch")
        return Units::Inch;
    return std::nullopt;
}

} // namespace Toffee
