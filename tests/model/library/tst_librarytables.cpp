// SPDX-License-Identifier: GPL-3.0-or-later
// Machine tables in an SQLite library (sharedtablecases.cpp), and what a station keeps for later.
#include <QTemporaryDir>

#include "model/library/outboxpayload.h"
#include "tests/model/library/sharedtablecases.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

class TestLibraryTables : public Toffee::Test::SharedTableCases
{
    Q_OBJECT

protected:
    LibraryLocation freshLocation() override
    {
        m_dirs.emplace_back(std::make_unique<QTemporaryDir>());
        return LibraryLocation { m_dirs.back()->filePath(u"library.sqlite"_s) };
    }

private Q_SLOTS:
    void mergesEachFieldFromTheSideThatChangedIt()
    {
        const Tool base = tool(4, u"ball"_s, 20);
        Tool theirs = base;
        theirs.measuredTlo = -12.5;
        theirs.measuredAt = QDateTime::currentDateTimeUtc();
        Tool mine = base;
        mine.notes = u"chipped"_s;
        const auto merged = mergeTool(base, theirs, mine);
        QVERIFY(merged && *merged);
        QCOMPARE((*merged)->measuredTlo, -12.5);
        QCOMPARE((*merged)->notes, u"chipped"_s);
        mine.measuredTlo = -12.4;
        QVERIFY(!mergeTool(base, theirs, mine)); // both measured it
        QVERIFY(!mergeTool(base, std::nullopt, mine)); // removed there, changed here
        QCOMPARE(mergeTool(base, std::nullopt, base),
            std::optional<std::optional<Tool>>(std::in_place, std::nullopt));
    }

    void readsAPostgresqlUrlAndWritesItBack()
    {
        const auto remote = LibraryLocation::parse(u"postgresql://shop@server:5433/tools?sslmode=require"_s);
        QVERIFY(remote && remote.value().isShared());
        QCOMPARE(remote.value().host, u"server"_s);
        QCOMPARE(remote.value().port, 5433);
        QCOMPARE(remote.value().user, u"shop"_s);
        QCOMPARE(remote.value().database, u"tools"_s);
        QCOMPARE(remote.value().options, u"sslmode=require"_s);
        QCOMPARE(remote.value().text(), u"postgresql://shop@server:5433/tools?sslmode=require"_s);
        // A Unix socket's folder goes in the query, and comes back from it.
        const auto local = LibraryLocation::parse(u"postgres://shop@/tools?host=/run/pg&port=5444"_s);
        QCOMPARE(local.value().host, u"/run/pg"_s);
        QCOMPARE(LibraryLocation::parse(local.value().text()).value(), local.value());
        QCOMPARE(remote.value().displayName(), u"database tools on server:5433"_s);
        for (const QString &bad :
            { u"postgresql://shop:pw@server/tools"_s, u"postgresql://server"_s, u"postgresql://server/a/b"_s,
                u"postgresql://server/t?colour=red"_s, u"postgresql://server:99999/t"_s })
            QVERIFY2(!LibraryLocation::parse(bad), qPrintable(bad));
    }

    void outboxEntriesReadBackWhole()
    {
        HistoryEvent e = probe(u"C1"_s, 7, -18.125);
        e.currentMz = -90.625;
        QCOMPARE(eventsFromPayload(eventsPayload({ e })).value(), QList<HistoryEvent> { e });
        const ToolWrites writes { u"C1"_s, Units::Millimetre,
            { { 7, tool(7, u"x"_s, 1), 4, tool(7, u"y"_s, 2) }, { 8, std::nullopt, 2 } } };
        const auto back = toolsFromPayload(toolsPayload(writes));
        QVERIFY(back);
        QCOMPARE(back.value().writes, writes.writes);
        QVERIFY(!eventsFromPayload("[{\"id\": 1}]"));
        QVERIFY(!toolsFromPayload("{}"));
    }

private:
    std::vector<std::unique_ptr<QTemporaryDir>> m_dirs;
};

QTEST_GUILESS_MAIN(TestLibraryTables)
#include "tst_librarytables.moc"
