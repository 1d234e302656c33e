// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/machine/machinecontroller.h"

#include <cmath>

#include "model/numberformat.h"

namespace Toffee {

namespace {

// A tolerance as the operator typed it: "0.02", not "0.020"; in their own decimal mark.
QString toleranceText(double tolerance)
{
    return formatNumber(tolerance, NumberFormat::upTo(3).inLocale());
}

} // namespace

MachineController::~MachineController() = default;

Result<void> MachineController::validateTolerance(double tolerance)
{
    if (!std::isfinite(tolerance))
        return Error { tr("The break-test tolerance is not a number; enter a value such as 0.1 mm.") };
    if (tolerance < kMinTolerance)
        return Error {
            tr("A break-test tolerance of %1 mm is too small: the machine halts below %2 mm. Use %2 mm "
               "or more (%3 mm is the default).")
                .arg(toleranceText(tolerance), toleranceText(kMinTolerance), toleranceText(kDefaultTolerance))
        };
    if (tolerance > kMaxOffset)
        return Error {
            tr("A break-test tolerance of %1 mm is larger than any tool.").arg(toleranceText(tolerance))
        };
    return {};
}

Result<void> MachineController::validateOffset(const QString &what, double value)
{
    if (!std::isfinite(value) || std::fabs(value) > kMaxOffset)
        return Error { tr("%1 must be a number from -%2 to %2 mm.").arg(what).arg(kMaxOffset) };
    return {};
}

Result<void> MachineController::validateToolNumber(int tool)
{
    if (tool < Limits::kEmptySpindle || tool > Limits::kMaxToolNumber)
        return Error { tr("Tool %1 is not a tool number; use %2 to %3 (%4 for an empty spindle).")
                           .arg(tool)
                           .arg(Limits::kMinToolNumber)
                           .arg(Limits::kMaxToolNumber)
                           .arg(Limits::kEmptySpindle) };
    return {};
}

} // namespace Toffee
