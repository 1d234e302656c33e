// SPDX-License-Identifier: GPL-3.0-or-later
// What a library's machine tables must do, whichever database holds them: tst_librarytables runs these on an
// SQLite file, tst_pglibrary on a real PostgreSQL server. Two stations are two connections with their names.
#pragma once

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include "model/document/tooldocument.h"
#include "model/library/library.h"
#include "model/library/librarywatcher.h"

namespace Toffee::Test {

class SharedTableCases : public QObject
{
    Q_OBJECT

protected:
    // A library nobody used yet, for one test.
    virtual LibraryLocation freshLocation() = 0;

    std::unique_ptr<Library> station(const LibraryLocation &where, const QString &name)
    {
        auto opened = Library::open(where, Library::Options { .station = name });
        if (!opened)
            qWarning("%s", qPrintable(opened.error().message));
        return opened ? opened.takeValue() : nullptr;
    }

    static Tool tool(int number, const QString &description, double length)
    {
        Tool t;
        t.number = number;
        t.pocket = number;
        t.description = description;
        t.lengthGeometry = length;
        return t;
    }

    static ToolTable threeTools()
    {
        return ToolTable::fromTools(
            { tool(1, QStringLiteral("6 mm flat"), 30), tool(2, QStringLiteral("3 mm ball"), 25),
                tool(3, QStringLiteral("drill"), 40) },
            Units::Millimetre)
            .value();
    }

    static HistoryEvent probe(const QString &machine, int number, double tlo)
    {
        HistoryEvent e;
        e.id = HistoryEvent::newId();
        e.machine = machine;
        e.tool = number;
        e.at = QDateTime::currentDateTimeUtc();
        e.kind = EventKind::Probe;
        e.tlo = tlo;
        e.referenceMz = -72.5;
        return e;
    }

private Q_SLOTS:
    void aTableIsCreatedOnceAndReadBackWithVersions();
    void twoStationsEditingTheSameToolConflictAndDifferentToolsBothSave();
    void aRemovalAndATwiceAddedToolConflictToo();
    void aMeasurementUpdatesItsToolOnceHoweverOftenItIsWritten();
    void aLateMeasurementNeverOverwritesANewerOne();
    void documentsMergeFieldsAndAskOnlyForTheSameField();
    void anotherStationsWriteIsSeenByTheWatcher();
};

} // namespace Toffee::Test
