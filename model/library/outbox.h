// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>

#include "model/library/library.h"
#include "model/library/outboxpayload.h"

namespace Toffee {

// What a station keeps, in its own SQLite library, for a shared library it could not reach, and the sending
// of it when the library answers again: the window (HistoryRecorder) and toffee-cli do the same.
namespace Outbox {

// Keeps events, or one table's tool writes, for `target`.
[[nodiscard]] Result<void> keep(
    Library &outbox, const LibraryLocation &target, const QString &kind, const QByteArray &payload);
[[nodiscard]] Result<qsizetype> count(const Library &outbox, const LibraryLocation &target);

// Each entry sent to `target`, oldest first, and removed once written: `events` hears of events written,
// `tools` of tool writes with their outcome (the conflicts among them). A crash in between sends it again:
// its events are skipped by their ids, and its tools are found already so. Stops at the first failure.
[[nodiscard]] Result<void> send(Library &outbox, Library &target,
    const std::function<void(const QList<HistoryEvent> &)> &events,
    const std::function<void(const QString &machine, const WriteOutcome &)> &tools);

} // namespace Outbox

} // namespace Toffee
