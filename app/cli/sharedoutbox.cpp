// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli and a library that could not take a measurement (busy, locked, damaged, out of reach): what this
// computer kept for it is sent the next time the library opens.
#include <QFileInfo>

#include "app/cli/machineoptions.h"
#include "model/library/outbox.h"
#include "model/library/spool.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

void sendWaiting(Library &library, QTextStream &err)
{
    if (library.isReadOnly())
        return; // nothing can be written: what waits stays where it is
    int events = 0;
    const auto count = [&events](const QList<HistoryEvent> &written) {
        events += int(written.size());
    };
    // What this computer kept in its outbox folder (any library), then, for a shared library, in the outbox
    // table of its own SQLite library (the window's recorder keeps it there).
    const Spool spool;
    auto fromSpool = spool.send(library, count);
    if (fromSpool) {
        for (const QString &why : fromSpool.value().quarantined)
            err << "toffee-cli: " << why << Qt::endl;
    }
    Result<void> fromOutbox;
    const LibraryLocation own = LibraryLocation::standard();
    if (fromSpool && library.location().isShared() && QFileInfo::exists(own.path)) {
        if (auto outbox = Library::open(own, Library::Options { .busyTimeoutMs = library.waitLimitMs() })) {
            fromOutbox = Outbox::send(
                *outbox.value(), library, count, [&err](const QString &machine, const WriteOutcome &outcome) {
                    for (const ToolConflict &c : outcome.conflicts)
                        err << "toffee-cli: T" << c.number << " of " << machine
                            << " was kept from before but " << c.theirStation
                            << " changed it since: open the table in the window to choose." << Qt::endl;
                });
        }
    }
    if (events > 0)
        err << "toffee-cli: sent " << events << (events == 1 ? " measurement" : " measurements")
            << " kept on this computer while the library could not take them" << Qt::endl;
    const Error *failed = !fromSpool ? &fromSpool.error() : !fromOutbox ? &fromOutbox.error() : nullptr;
    if (failed)
        err << "toffee-cli: what this computer keeps for the library is not sent yet: " << failed->message
            << Qt::endl;
}

} // namespace Toffee::Cli
