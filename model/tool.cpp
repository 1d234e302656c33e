// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/tool.h"

using namespace Qt::StringLiterals;

namespace Toffee {

QLatin1StringView tloSourceName(TloSource source)
{
    switch (source) {
    case TloSource::Manual:
        return "manual"_L1;
    case TloSource::Pulled:
        return "pulled"_L1;
    case TloSource::Probe:
        break;
    }
    return "probe"_L1;
}

std::optional<TloSource> tloSourceFromName(QByteArrayView name)
{
    for (TloSource s : { TloSource::Probe, TloSource::Manual, TloSource::Pulled }) {
        if (name == QByteArrayView(tloSourceName(s).data(), tloSourceName(s).size()))
            return s;
    }
    return std::nullopt;
}

} // namespace Toffee
