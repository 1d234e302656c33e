// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli and a shared library it cannot reach: a measurement is kept in this computer's outbox (its own
// SQLite library) instead of being lost, and what waits there is sent the next time the library answers.
#include <QFileInfo>

#include "app/cli/machineoptions.h"
#include "model/library/outbox.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

void sendWaiting(Library &library, QTextStream &err)
{
    const LibraryLocation own = LibraryLocation::standard();
    if (!library.location().isShared() || !QFileInfo::exists(own.path))
        return;
    auto outbox = Library::open(own);
    if (!outbox)
        return;
    int events = 0;
    auto sent = Outbox::send(
        *outbox.value(), library,
        [&events](const QList<HistoryEvent> &written) { events += int(written.size()); },
        [&err](const QString &machine, const WriteOutcome &outcome) {
            for (const ToolConflict &c : outcome.conflicts)
                err << "toffee-cli: T" << c.number << " of " << machine << " was kept from before but "
                    << c.theirStation << " changed it since: open the table in the window to choose."
                    << Qt::endl;
        });
    if (events > 0)
        err << "toffee-cli: sent " << events << (events == 1 ? " measurement" : " measurements")
            << " kept in " << own.path << " while the library was out of reach" << Qt::endl;
    if (!sent)
        err << "toffee-cli: what waits in " << own.path << " is not sent yet: " << sent.error().message
            << Qt::endl;
}

Result<QString> keepForLater(const Library &library, const HistoryEvent &event)
{
    const LibraryLocation own = LibraryLocation::standard();
    auto outbox = Library::open(own);
    if (!outbox)
        return outbox.error();
    if (auto kept = Outbox::keep(*outbox.value(), library.location(), u"events"_s, eventsPayload({ event }));
        !kept)
        return kept.error();
    return own.path;
}

} // namespace Toffee::Cli
