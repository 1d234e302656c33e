// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDateTime>
#include <QString>

#include "model/clock.h"

namespace Toffee {

// How long ago a measurement was, as the table and the job check show it: "just now", "12 min ago",
// "5 h ago", "9 days ago"; "dated in the future (2100-01-01 00:00 UTC)" beyond the clocks' skew.
[[nodiscard]] QString ageText(const QDateTime &at, const QDateTime &now = Clock::now());
// A cutting time: "42 s", "25 min", "3 h 05 min".
[[nodiscard]] QString durationText(double seconds);

} // namespace Toffee
