// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/machine/machinereplies.h"

#include <cmath>

using namespace Qt::StringLiterals;

namespace Toffee {

TloReading TloReading::from(double tloInForce, const std::optional<OffsetReport> &report)
{
    TloReading reading { tloInForce, std::nullopt, std::nullopt };
    if (report) {
        reading.referenceMz = report->referenceMz;
        // At the report's resolution: 0.001 mm either way.
        if (std::fabs(report->currentMz - report->referenceMz - tloInForce) < 0.0015)
            reading.currentMz = report->currentMz;
    }
    return reading;
}

QString FirmwareInfo::description() const
{
    switch (kind) {
    case Kind::Community:
        return tr("Community firmware %1").arg(version);
    case Kind::Stock:
        return tr("Makera stock firmware %1").arg(version);
    case Kind::GrblHal:
        return tr("grblHAL %1").arg(version);
    case Kind::LinuxCnc:
        return version.isEmpty() ? u"LinuxCNC"_s : tr("LinuxCNC %1").arg(version);
    case Kind::Unknown:
        break;
    }
    return version.isEmpty() ? tr("Unknown firmware (it did not answer \"version\")")
                             : tr("Unknown firmware %1").arg(version);
}

} // namespace Toffee
