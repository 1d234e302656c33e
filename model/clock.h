// SPDX-License-Identifier: GPL-3.0-or-later
// The one place the product reads the wall clock. Everything that stamps, ages or orders a time asks
// Clock::now(); tests set it (setForTests in the test's process, TOFFEE_TEST_CLOCK=<ISO time> in a program's
// environment), so that what they check never depends on the day they run. Time
// limits and waits are not wall time: they use QDeadlineTimer / QElapsedTimer (monotonic), which a moved
// calendar does not touch.
#pragma once

#include <QDateTime>

namespace Toffee {

namespace Clock {

// Now, in UTC.
[[nodiscard]] QDateTime now();

// A time that came from outside (a file, a row, an event, a machine) and lies beyond now by more than this
// is in the future: a clock set wrong somewhere. It is shown as such and never orders events or restarts a
// tool's life. Five minutes forgive the skew between two stations' clocks.
inline constexpr qint64 kMaxSkewSeconds = 5 * 60;
[[nodiscard]] bool isInFuture(const QDateTime &at, const QDateTime &now);
[[nodiscard]] bool isInFuture(const QDateTime &at);

// Tests only: the clock reads `at` from now on, and runs on from there (frozen: stays at `at`). An invalid
// `at` gives the real clock back.
enum class Run { Running, Frozen };
void setForTests(const QDateTime &at, Run run = Run::Running);

} // namespace Clock

} // namespace Toffee
