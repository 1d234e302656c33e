// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/job/jobsources.h"

#include <QFileInfo>

#include "model/library/library.h"

namespace Toffee {

Result<void> addHistoryFacts(const JobSources &sources, QHash<int, ToolFacts> &facts, const QList<int> &tools)
{
    if (!sources.library || !QFileInfo::exists(sources.library->path))
        return {};
    auto library = Library::open(*sources.library, Library::Options { 250 });
    if (!library)
        return {}; // the check goes on with the table's facts; the window says when the library is away
    return addLibraryFacts(facts, *library.value(), sources.machine, tools);
}

} // namespace Toffee
