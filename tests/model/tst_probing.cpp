// SPDX-License-Identifier: GPL-3.0-or-later
// How a tool is probed: typed and shown as text, kept in the JSON and CSV tables (a LinuxCNC save says it
// loses them), checked, and turned into millimetres for the machine; the touches' highest and spread.
#include <QTest>

#include "model/formats/tablefile.h"
#include "model/probing.h"
#include "model/tooltable.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

Tool faceMill()
{
    Tool t;
    t.number = 3;
    t.pocket = 3;
    t.description = u"50 mm face mill"_s;
    t.flutes = 4;
    t.probing.offsetX = 20.0;
    t.probing.offsetY = -2.5;
    t.probing.latchFeed = 20.0;
    t.probing.spreadLimit = 0.03;
    return t;
}

} // namespace

class TestProbing : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void typedSettingsAreReadBackAsShown()
    {
        const auto parsed
            = ProbeSettings::parse(u"X 20, y -2.5, 4 edges, latch 20, spread 0.03"_s, Units::Millimetre);
        QVERIFY2(parsed, qPrintable(parsed ? QString() : parsed.error().message));
        QCOMPARE(parsed.value().flutes, 4);
        QCOMPARE(parsed.value().settings, faceMill().probing);
        const QString shown
            = ProbeSettings::text(parsed.value().settings, parsed.value().flutes, Units::Millimetre);
        QCOMPARE(shown, u"X 20, Y -2.5, 4 edges, latch 20, spread 0.03"_s);
        const auto again = ProbeSettings::parse(shown, Units::Millimetre);
        QVERIFY(again);
        QCOMPARE(again.value().settings, parsed.value().settings);
        // Touches set apart from the edges, on the same edge; the number either side of its word.
        const auto other = ProbeSettings::parse(u"touches 5, same edge, 2 flutes"_s, Units::Millimetre);
        QVERIFY(other);
        QCOMPARE(other.value().settings.touches, 5);
        QVERIFY(!other.value().settings.turn);
        QCOMPARE(ProbeSettings::text(other.value().settings, other.value().flutes, Units::Millimetre),
            u"2 edges, 5 touches, same edge"_s);
        // Empty: the defaults.
        const auto none = ProbeSettings::parse(u"  "_s, Units::Millimetre);
        QVERIFY(none && none.value().settings.isDefault() && !none.value().flutes);
        QCOMPARE(ProbeSettings::text({}, std::nullopt, Units::Millimetre), QString());
    }

    void whatIsNoSettingIsRefusedSayingHow()
    {
        const QStringList bad { u"X"_s, u"4 wobbles"_s, u"X 1, X 2"_s, u"0 touches"_s, u"17 touches"_s,
            u"2.5 touches"_s, u"X 150"_s, u"latch 0"_s, u"latch 30000"_s, u"spread -1"_s, u"spread 6"_s,
            u"100 edges"_s, u"X nan"_s };
        for (const QString &text : bad) {
            const auto parsed = ProbeSettings::parse(text, Units::Millimetre);
            QVERIFY2(!parsed, qPrintable(text));
            QVERIFY2(!parsed.error().message.isEmpty(), qPrintable(text));
        }
        QVERIFY(ProbeSettings::parse(u"4 wobbles"_s, Units::Millimetre)
                    .error()
                    .message.contains(u"\"4 touches\""_s));
        // An inch table's limits are its own: 150 mm is 5.9 in.
        QVERIFY(ProbeSettings::parse(u"X 3.9"_s, Units::Inch));
        QVERIFY(!ProbeSettings::parse(u"X 4"_s, Units::Inch));
    }

    void touchesDefaultToOnePerEdge()
    {
        ProbeSettings s;
        QCOMPARE(s.touchesFor(std::nullopt), 1);
        QCOMPARE(s.touchesFor(4), 4);
        QCOMPARE(s.touchesFor(40), 1); // more edges than touches a tool takes: once, as before
        s.touches = 2;
        QCOMPARE(s.touchesFor(4), 2);
    }

    // The one place a tool's settings cross from the table's units to the machine's.
    void aPlanIsInMillimetresWhateverTheTable()
    {
        ToolTable inches(Units::Inch);
        Tool t = faceMill();
        t.probing.offsetX = 1.0;
        t.probing.offsetY = 0.0;
        t.probing.latchFeed = 2.0;
        t.probing.spreadLimit = 0.001;
        QVERIFY(inches.insert(t));
        const ProbePlan plan = inches.probePlan(3);
        QCOMPARE(plan.offsetX, 25.4);
        QCOMPARE(plan.latchFeed, 50.8);
        QVERIFY(std::fabs(*plan.spreadLimit - 0.0254) < 1e-12);
        QCOMPARE(plan.touches, 4);
        QVERIFY(!plan.isPlain());
        QVERIFY(inches.probePlan(9).isPlain());
        QCOMPARE(
            plan.summary(), u"4 touches, X 25.4 Y 0 mm from the setter's centre, latch at 50.8 mm/min"_s);
    }

    void theLongestEdgeAndTheSpread()
    {
        const QList<double> touches { -80.0, -79.972, -79.94, -80.004 };
        QCOMPARE(highestTouch(touches), -79.94);
        QCOMPARE(spreadOf(touches), 0.064);
        QCOMPARE(spreadOf({ -75.0 }), 0.0);
    }

    void theSettingsLiveInJsonAndCsvAndALinuxCncSaveSaysItLosesThem()
    {
        ToolTable table(Units::Millimetre);
        QVERIFY(table.insert(faceMill()));
        Tool plain;
        plain.number = 1;
        plain.pocket = 1;
        QVERIFY(table.insert(plain));
        Tool sameEdge = plain;
        sameEdge.number = 2;
        sameEdge.pocket = 2;
        sameEdge.probing.touches = 3;
        sameEdge.probing.turn = false;
        QVERIFY(table.insert(sameEdge));
        for (TableFormat format : { TableFormat::Json, TableFormat::Csv }) {
            const QByteArray data = writeTable(table, format);
            const auto back = readTable(data, format);
            QVERIFY2(back, qPrintable(back ? QString() : back.error().message));
            QCOMPARE(back.value().tools(), table.tools());
        }
        const QByteArray json = writeTable(table, TableFormat::Json);
        QVERIFY2(json.contains("\"version\": 5"), json.constData());
        QVERIFY(json.contains("\"flutes\": 4, \"probe_x\": 20, \"probe_y\": -2.5"));
        QVERIFY(json.contains("\"probe_touches\": 3, \"probe_turn\": false"));
        // A table without settings stays the version an older Toffee reads.
        ToolTable older(Units::Millimetre);
        QVERIFY(older.insert(plain));
        QVERIFY(writeTable(older, TableFormat::Json).contains("\"version\": 1"));
        QVERIFY(formatLosses(older, TableFormat::LinuxCnc).isEmpty());
        const QStringList losses = formatLosses(table, TableFormat::LinuxCnc);
        QVERIFY2(losses.join(u' ').contains(u"how a tool is probed"_s), qPrintable(losses.join(u' ')));
        // Out of range in a file: refused with the tool and the reason.
        QByteArray wrong = json;
        wrong.replace("\"probe_touches\": 3", "\"probe_touches\": 30");
        const auto refused = readTable(wrong, TableFormat::Json);
        QVERIFY(!refused);
        QVERIFY2(refused.error().message.contains(u"T2"_s), qPrintable(refused.error().message));
        const QByteArray csv = writeTable(table, TableFormat::Csv);
        QByteArray badTurn = csv;
        badTurn.replace(",3,no,", ",3,maybe,");
        const auto turn = readTable(badTurn, TableFormat::Csv);
        QVERIFY(!turn);
        QVERIFY2(turn.error().message.contains(u"probe_turn"_s), qPrintable(turn.error().message));
    }
};

QTEST_GUILESS_MAIN(TestProbing)
#include "tst_probing.moc"
