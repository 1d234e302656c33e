// SPDX-License-Identifier: GPL-3.0-or-later
// The conformance suite: one row for every statement of the seeds and every worked example of docs/DIALECTS.md,
// each naming the document and the sentence it checks, run through the interpreter the emulator and the CLI
// share.
#include <cmath>
#include <limits>

#include <QTest>

#include "model/gcode/gcodeinterpreter.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

constexpr double kAny = std::numeric_limits<double>::quiet_NaN();

// "1:100/-0.1;2:30" -> H1 geometry 100 wear -0.1, H2 geometry 30.
OffsetTable offsets(const QString &spec)
{
    OffsetTable table;
    for (const QString &entry : spec.split(u';', Qt::SkipEmptyParts)) {
        const QStringList parts = entry.split(u':');
        const QStringList values = parts.at(1).split(u'/');
        OffsetEntry e;
        e.lengthGeometry = values.at(0).toDouble();
        if (values.size() > 1)
            e.lengthWear = values.at(1).toDouble();
        table[parts.at(0).toInt()] = e;
    }
    return table;
}

void row(const char *source, Dialect dialect, const QString &table, const QByteArray &program, int line,
    double x, double y, double z, const QString &error = {}, const QString &offsetAfter = {})
{
    QTest::newRow(source) << int(dialect) << table << program << line << x << y << z << error << offsetAfter;
}

} // namespace

class TestConformance : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void followsTheDocuments_data()
    {
        QTest::addColumn<int>("dialect");
        QTest::addColumn<QString>("table");
        QTest::addColumn<QByteArray>("program");
        QTest::addColumn<int>("line"); // the move to check (its line); 0: the last move
        QTest::addColumn<double>("x");
        QTest::addColumn<double>("y");
        QTest::addColumn<double>("z");
        QTest::addColumn<QString>("error"); // a fragment of the expected error, which stops the program
        QTest::addColumn<QString>("offsetAfter"); // "n:geometry/wear" the table must hold after

        const auto F = Dialect::Fanuc, G = Dialect::Fagor8055M, A = Dialect::AllenBradley9,
                   L = Dialect::LinuxCnc, R = Dialect::Aerotech, C = Dialect::Carvera;
        const QString h = u"1:20;2:30"_s;

        // seeds/003 (FANUC G43/G44/G49, FAGOR 8055M)
        row("003: 'When executing G43: Z actual value = Z command value + (Hxx)'", F, h, "G90 G43 G0 Z100 H1",
            0, kAny, kAny, 120);
        row("003: 'When executing G44: Z actual value = Z command value - (Hxx)'", F, h, "G90 G44 G0 Z100 H1",
            0, kAny, kAny, 80);
        row("003: 'G49 is the undo tool length compensation command' (G00 G49 Z_)", F, h,
            "G90 G43 G0 Z100 H1\nG0 G49 Z100", 2, kAny, kAny, 100);
        row("003: 'Or G00(G01)G43/G44Z_H00' cancels", F, h, "G90 G43 G0 Z100 H1\nG0 G43 Z100 H00", 2, kAny,
            kAny, 100);
        row("003: 'can only take effect under the movement command' (no Z yet)", F, h,
            "G90 G0 Z100\nG43 H1\nG0 X5", 3, kAny, kAny, 100);
        row("003: 'can only take effect under the movement command' (next Z)", F, h,
            "G90 G0 Z100\nG43 H1\nG0 X5\nG0 Z100", 4, kAny, kAny, 120);
        row("003: 'G43 and G44 are modal codes'", F, h, "G90 G43 G0 Z100 H1\nG0 Z50", 2, kAny, kAny, 70);
        row("003: FAGOR 'use G43 to activate tool length compensation'", G, u"1:10;2:-4"_s, "D1 G43\nG0 Z50",
            0, kAny, kAny, 60);
        row("003: FAGOR 'addition/subtraction depends on the positive and negative offsets'", G,
            u"1:10;2:-4"_s, "D2 G43\nG0 Z50", 0, kAny, kAny, 46);
        row("003: FAGOR 'G44 cancels tool length compensation'", G, u"1:10"_s, "D1 G43\nG0 Z50\nG44\nG0 Z50",
            4, kAny, kAny, 50);

        // docs/DIALECTS.md: FANUC
        row("DIALECTS FANUC: 'The stored value's sign flips the direction'", F, u"3:-5"_s,
            "G90 G43 G0 Z100 H3", 0, kAny, kAny, 95);
        row("DIALECTS FANUC: 'OFS[n] = length geometry + length wear'", F, u"1:100/-0.1"_s,
            "G90 G43 G0 Z0 H1", 0, kAny, kAny, 99.9);
        row("DIALECTS FANUC: 'Changing H replaces the active value' (H1=20, H2=30: 120 then 130)", F, h,
            "G90 G43 Z100 H1\nG90 G43 Z100 H2", 2, kAny, kAny, 130);
        row("DIALECTS FANUC: 'G49 or H0 cancels' (H0 is always 0)", F, h, "G90 G43 G0 Z10 H2\nH0 G0 Z10", 2,
            kAny, kAny, 10);
        row("DIALECTS FANUC: 'with no Z move it applies on the next Z command'", F, h, "G43 H1 G0 X10\nG0 Z0",
            1, 10, kAny, 0);
        row("DIALECTS FANUC worked: G91 G10 L11 twice -> wear -0.100, total 99.900", F, u"1:100"_s,
            "G91 G10 L11 P1 R-0.05\nG10 L11 P1 R-0.05", 0, kAny, kAny, kAny, {}, u"1:100/-0.1"_s);
        row("DIALECTS FANUC worked: G54 Z-300, G43 G0 Z10 H1 -> -190.1", F, u"1:100"_s,
            "G10 L2 P1 Z-300\nG91 G10 L11 P1 R-0.05\nG10 L11 P1 R-0.05\nG90 G43 G0 Z10 H1", 4, kAny, kAny,
            -190.1);
        row("DIALECTS FANUC worked: with G44 -> -389.9", F, u"1:100"_s,
            "G10 L2 P1 Z-300\nG91 G10 L11 P1 R-0.05\nG10 L11 P1 R-0.05\nG90 G44 G0 Z10 H1", 4, kAny, kAny,
            -389.9);
        row("DIALECTS FANUC: 'G90 replaces'", F, {}, "G90 G10 L10 P1 R50\nG10 L10 P1 R60", 0, kAny, kAny,
            kAny, {}, u"1:60/0"_s);
        row("DIALECTS FANUC: 'G91 adds'", F, {}, "G90 G10 L10 P1 R50\nG91 G10 L10 P1 R60", 0, kAny, kAny,
            kAny, {}, u"1:110/0"_s);
        row("DIALECTS FANUC: 'L12 D geometry (radius), L13 D wear' are written", F, {},
            "G90 G10 L12 P4 R3\nG10 L13 P4 R-0.01", 0, kAny, kAny, kAny, {}, u"4:0/0"_s);
        row("DIALECTS FANUC: 'PS0030 ILLEGAL OFFSET NUMBER (H beyond the offset count)'", F, h,
            "G43 G0 Z0 H1000", 0, kAny, kAny, kAny, u"PS0030"_s);
        row("DIALECTS FANUC: 'PS0031 ... (unknown L)'", F, {}, "G10 L15 P1 R1", 0, kAny, kAny, kAny,
            u"PS0031"_s);
        row("DIALECTS FANUC: 'PS0031 ... (missing P)'", F, {}, "G10 L10 R1", 0, kAny, kAny, kAny,
            u"PS0031"_s);
        row("DIALECTS FANUC: 'PS0031 ... (missing R)'", F, {}, "G10 L10 P1", 0, kAny, kAny, kAny,
            u"PS0031"_s);
        row("DIALECTS FANUC: 'H0 ... cannot be written' (P0: PS0031)", F, {}, "G10 L10 P0 R5", 0, kAny, kAny,
            kAny, u"PS0031"_s);
        row("DIALECTS FANUC: 'PS0032 ILLEGAL OFFSET VALUE IN G10' (wear over 99.999)", F, {},
            "G10 L11 P1 R150", 0, kAny, kAny, kAny, u"PS0032"_s);
        row("DIALECTS FANUC: 'geometry +-999.999' is accepted", F, {}, "G10 L10 P1 R-999.999", 0, kAny, kAny,
            kAny, {}, u"1:-999.999/0"_s);
        row("DIALECTS FANUC: 'geometry +-999.999' beyond it: PS0032", F, {}, "G10 L10 P1 R1000", 0, kAny,
            kAny, kAny, u"PS0032"_s);

        // docs/DIALECTS.md: FAGOR 8055M
        row("DIALECTS FAGOR: 'Applied value = L + K (length + length wear)'", G, u"1:10/-0.5"_s,
            "D1 G43\nG0 Z0", 0, kAny, kAny, 9.5);
        row("DIALECTS FAGOR: 'from D, else from the offset linked to the tool'", G, u"1:10;2:-4"_s,
            "T1 G43\nG0 Z50", 0, kAny, kAny, 60);
        row("DIALECTS FAGOR: 'with none selected, D0 (all zero)'", G, u"1:10"_s, "G43\nG0 Z50", 0, kAny, kAny,
            50);
        row("DIALECTS FAGOR: 'G43 only arms ... applies when the longitudinal axis next moves'", G, u"1:10"_s,
            "D1 G43\nG0 X10", 0, 10, kAny, 0);
        row("DIALECTS FAGOR: '... Z for G17'", G, u"1:10"_s, "D1 G43\nG0 X10\nG0 Z50", 3, kAny, kAny, 60);
        row("DIALECTS FAGOR: longitudinal axis in G18 is Y", G, u"1:10"_s, "G18 D1 G43\nG0 Y20", 0, kAny, 30,
            kAny);
        row("DIALECTS FAGOR: 'cancelled by G44 and by G74 (home search)'", G, u"1:10"_s,
            "D1 G43\nG0 Z50\nG74\nG0 Z50", 4, kAny, kAny, 50);

        // seeds/004 and docs/DIALECTS.md: Allen-Bradley 9/Series
        const QString ab = u"1:5;2:7"_s;
        const QByteArray sequence = "G43 H01 G0 Z0\nH02 G0 Z0\nG44 G0 Z0\nG49 G0 Z0\nG43 G0 Z0\nH0 G0 Z0";
        row("DIALECTS AB sequence: 'G43 H01'", A, ab, sequence, 1, kAny, kAny, 5);
        row("DIALECTS AB sequence: '-> H02 (G43, H02)'", A, ab, sequence, 2, kAny, kAny, 7);
        row("DIALECTS AB sequence: '-> G44 (G44, H02)'", A, ab, sequence, 3, kAny, kAny, -7);
        row("DIALECTS AB sequence: '-> G49 (off, H02 kept)'", A, ab, sequence, 4, kAny, kAny, 0);
        row("DIALECTS AB sequence: '-> G43 (G43, H02)'", A, ab, sequence, 5, kAny, kAny, 7);
        row("DIALECTS AB sequence: '-> H0 (G43, value 0)'", A, ab, sequence, 6, kAny, kAny, 0);
        row("DIALECTS AB worked: 'geometry +3.0000 and wear -0.1000 -> +2.9000'", A, {},
            "G90 G10 L10 P3 R3.0\nG10 L11 P3 R-0.1\nG43 G0 Z0 H3", 0, kAny, kAny, 2.9);
        row("004: 'G10 blocks may not be programmed when cutter compensation is active'", A, ab,
            "G41\nG10 L10 P1 R9", 0, kAny, kAny, kAny, u"cutter compensation"_s);
        row("004: '... and nothing written'", A, ab, "G10 L10 P2 R8\nG41\nG10 L10 P1 R9", 0, kAny, kAny, kAny,
            u"nothing was written"_s);
        row("004: 'the active offset value will not be updated until ... called again'", A, ab,
            "G43 H1 G0 Z0\nG10 L10 P1 R9\nG0 Z0", 3, kAny, kAny, 5);
        row("004: '... called again from the table using a D or an H-word'", A, ab,
            "G43 H1 G0 Z0\nG10 L10 P1 R9\nH1 G0 Z0", 3, kAny, kAny, 9);
        row("004: 'in incremental mode (G91), are added'", A, ab, "G91 G10 L10 P1 R1\nG90 G43 G0 Z0 H1", 2,
            kAny, kAny, 6);
        row("004: 'in absolute mode (G90), are used to replace'", A, ab, "G90 G10 L10 P1 R1\nG43 G0 Z0 H1", 2,
            kAny, kAny, 1);
        row("004: 'R can be replaced with the name of the axis'", A, ab, "G90 G10 L10 P1 Z8\nG43 G0 Z0 H1", 2,
            kAny, kAny, 8);
        row("004: 'L10 Geometry table, L11 Wear table'", A, {}, "G90 G10 L10 P1 R4\nG10 L11 P1 R-0.2", 0,
            kAny, kAny, kAny, {}, u"1:4/-0.2"_s);

        // docs/DIALECTS.md: LinuxCNC worked example (T100 Z+1, T200 Z+0.1, T300 Z+0.01)
        const QString lc = u"100:1;200:0.1;300:0.01"_s;
        row("DIALECTS LinuxCNC worked: 'T100 M6 -> 0'", L, lc, "T100 M6\nG0 Z0", 0, kAny, kAny, 0);
        row("DIALECTS LinuxCNC worked: 'G43 -> 1'", L, lc, "T100 M6\nG43\nG0 Z0", 0, kAny, kAny, 1);
        row("DIALECTS LinuxCNC worked: 'G43 H200 -> 0.1'", L, lc, "T100 M6\nG43 H200\nG0 Z0", 0, kAny, kAny,
            0.1);
        row("DIALECTS LinuxCNC worked: 'G43.2 H100 -> 1.1'", L, lc, "T100 M6\nG43 H200\nG43.2 H100\nG0 Z0", 0,
            kAny, kAny, 1.1);
        row("DIALECTS LinuxCNC worked: 'G43.2 H300 -> 1.11'", L, lc,
            "T100 M6\nG43 H200\nG43.2 H100\nG43.2 H300\nG0 Z0", 0, kAny, kAny, 1.11);
        row("DIALECTS LinuxCNC: 'G49 zeroes'", L, lc, "T100 M6\nG43\nG49\nG0 Z0", 0, kAny, kAny, 0);
        row("DIALECTS LinuxCNC: 'G43.1 Z.. replaces'", L, lc, "T100 M6\nG43\nG43.1 Z2.5\nG0 Z0", 0, kAny,
            kAny, 2.5);
        row("DIALECTS LinuxCNC: 'M6/M61 do not change the offset'", L, lc,
            "T100 M6\nG43\nT200 M6\nM61 Q300\nG0 Z0", 0, kAny, kAny, 1);
        row("DIALECTS LinuxCNC: 'None move the machine'", L, lc, "G0 Z0\nT100 M6\nG43\nG0 X5", 4, 5, kAny, 0);
        row("DIALECTS LinuxCNC: 'Cannot change tool offset with cutter radius compensation on'", L, lc,
            "G41\nG43 H100", 0, kAny, kAny, kAny,
            u"Cannot change tool offset with cutter radius compensation on"_s);
        row("DIALECTS LinuxCNC: 'G10 L1 P Z writes the table, not the active offset'", L, lc,
            "T100 M6\nG43\nG10 L1 P100 Z5\nG0 Z0", 0, kAny, kAny, 1, {}, u"100:5/0"_s);
        row("DIALECTS LinuxCNC: '(it changes on the next G43)'", L, lc,
            "T100 M6\nG43\nG10 L1 P100 Z5\nG43\nG0 Z0", 0, kAny, kAny, 5);
        row("DIALECTS LinuxCNC: 'P missing ... -> error'", L, lc, "G10 L1 Z5", 0, kAny, kAny, kAny,
            u"needs P"_s);
        row("DIALECTS LinuxCNC: 'P ... 0 ... -> error'", L, lc, "G10 L1 P0 Z5", 0, kAny, kAny, kAny,
            u"needs P"_s);
        row("DIALECTS LinuxCNC: 'P ... not in the table -> error'", L, lc, "G10 L1 P7 Z5", 0, kAny, kAny,
            kAny, u"not in the tool table"_s);

        // seeds/001 and docs/DIALECTS.md: Aerotech Automation1 cutter offset compensation
        const QByteArray setup = "G44 X Y Z\nCutterCompensationSetOffsets([1, -2, 3])\nG90 G1 X0 Y0 Z0\n";
        row("DIALECTS Aerotech worked: 'G143 G1 X10 Y10 ends at (11, 8, 3)'", R, {},
            setup + "G143 G1 X10 Y10", 4, 11, 8, 3);
        row("DIALECTS Aerotech worked: 'then G1 X20 -> (21, 8, 3)'", R, {}, setup + "G143 G1 X10 Y10\nG1 X20",
            5, 21, 8, 3);
        row("DIALECTS Aerotech worked: 'G149 G1 X30 Y10 ends at (30, 10, 0)'", R, {},
            setup + "G143 G1 X10 Y10\nG1 X20\nG149 G1 X30 Y10", 6, 30, 10, 0);
        row("001: 'The G144 command ... subtracts the tool offsets'", R, {}, setup + "G144 G1 X10 Y10", 4, 9,
            12, -3);
        row("001: 'will occur on all axes specified ... even if that axis is not explicitly included'", R, {},
            setup + "G143 G1 X10", 4, 11, -2, 3);
        row("001: 'If you do not specify the third axis, ... configured for two axes'", R, {},
            "G44 X Y\nCutterCompensationSetOffsets([1, -2])\nG143 G1 X10 Y10 Z5", 3, 11, 8, 5);
        row("001: 'CutterCompensationSetAxes([X, Y, Z])' is the same as 'G44 X Y Z'", R, {},
            "CutterCompensationSetAxes([X, Y, Z])\nCutterCompensationSetOffsets([1, -2, 3])\nG143 G1 X10 Y10",
            3, 11, 8, 3);
        row("001: 'You must specify either 2 or 3 axes'", R, {}, "G44 X", 0, kAny, kAny, kAny,
            u"2 or 3 axes"_s);
        row("001: 'The number of offsets ... must be the same as the number of axes'", R, {},
            "G44 X Y Z\nCutterCompensationSetOffsets([1, 2])", 0, kAny, kAny, kAny, u"needs 3 offsets"_s);
        row("001: 'Use this command only when cutter offset compensation is disabled'", R, {},
            setup + "G143 G1 X10\nCutterCompensationSetOffsets([0, 0, 0])", 0, kAny, kAny, kAny,
            u"only while cutter offset compensation is off"_s);
        row("001: 'If you do not [put the lead-on on the same line], the controller uses the next "
            "coordinated move'",
            R, {}, setup + "G143\nG1 X10 Y10", 5, 11, 8, 3);
        row("001: 'Home() ... immediately disables cutter offset compensation'", R, {},
            setup + "G143 G1 X10 Y10\nHome(Z)\nG1 X20", 6, 20, 10, 0);
        row("DIALECTS Aerotech: 'In Automation1, G43/G44 are not tool length'", R, {}, "G43 H1", 0, kAny,
            kAny, kAny, u"not tool length"_s);

        // seeds/000 and docs/DIALECTS.md: Carvera
        row("DIALECTS Carvera: 'No G43/G49: the TLO is always applied'", C, {}, "M493.3 Z-33.388\nG0 Z0", 0,
            kAny, kAny, -33.388);
        row("000: 'M493.3 Z-30.488' (adding 2.9 mm)", C, {}, "M493.3 Z-33.388\nM493.3 Z-30.488\nG0 Z10", 0,
            kAny, kAny, -20.488);
        row("DIALECTS Carvera: 'No G43/G49'", C, {}, "G43 H1", 0, kAny, kAny, kAny, u"no G43"_s);
    }
    void followsTheDocuments()
    {
        QFETCH(int, dialect);
        QFETCH(QString, table);
        QFETCH(QByteArray, program);
        QFETCH(int, line);
        QFETCH(double, x);
        QFETCH(double, y);
        QFETCH(double, z);
        QFETCH(QString, error);
        QFETCH(QString, offsetAfter);

        GCodeInterpreter interpreter(Dialect(dialect), offsets(table));
        const auto result = interpreter.run(program);
        if (!error.isEmpty()) {
            QVERIFY2(!result.ok(), "the program should have been refused");
            QVERIFY2(result.error().message.contains(error), qPrintable(result.error().message));
            QCOMPARE(result.error().line, int(program.count('\n')) + 1); // the failing block is the last
            if (error == u"nothing was written")
                QCOMPARE(interpreter.offsets().at(1).lengthGeometry, 5.0);
            return;
        }
        QVERIFY2(result.ok(), qPrintable(result.error().text()));
        if (!std::isnan(x) || !std::isnan(y) || !std::isnan(z)) {
            QVERIFY(!interpreter.moves().isEmpty());
            const SimulatedMove *move = &interpreter.moves().last();
            if (line > 0) {
                move = nullptr;
                for (const SimulatedMove &m : interpreter.moves())
                    move = m.line == line ? &m : move;
                QVERIFY2(move, "no move on that line");
            }
            const double expected[] = { x, y, z };
            for (size_t i = 0; i < 3; ++i) {
                if (!std::isnan(expected[i]))
                    QVERIFY2(std::fabs(move->end[i] - expected[i]) < 1e-9,
                        qPrintable(u"axis %1: %2, expected %3"_s.arg(i).arg(move->end[i]).arg(expected[i])));
            }
        }
        if (!offsetAfter.isEmpty()) {
            const auto expected = offsets(offsetAfter);
            for (const auto &[number, entry] : expected) {
                QVERIFY(interpreter.offsets().count(number));
                QVERIFY(
                    std::fabs(interpreter.offsets().at(number).lengthGeometry - entry.lengthGeometry) < 1e-9);
                QVERIFY(std::fabs(interpreter.offsets().at(number).lengthWear - entry.lengthWear) < 1e-9);
            }
        }
    }

    // Programs no controller would run, each found or suggested by fuzz-gcode: refused with a message on
    // their line, the offset table left exactly as it was, and the machine somewhere real.
    void refusesWhatNoControllerTakes_data()
    {
        QTest::addColumn<int>("dialect");
        QTest::addColumn<QByteArray>("program");
        QTest::addColumn<QString>("error");
        const QByteArray huge(308, '9'); // about 1e308: a finite double, twice of it is not
        const auto F = Dialect::Fanuc, G = Dialect::Fagor8055M, L = Dialect::LinuxCnc, R = Dialect::Aerotech;
        QTest::newRow("T beyond an int (found by fuzzing)")
            << int(L) << QByteArray("G0 X0\nT77777777772") << u"T77777777772 is too large"_s;
        QTest::newRow("T beyond any tool") << int(L) << QByteArray("T1000000 M6") << u"from 0 to 999999"_s;
        QTest::newRow("T beyond any tool, in eight digits")
            << int(L) << QByteArray("T99999999") << u"T99999999 must be a whole number from 0 to 999999"_s;
        QTest::newRow("T not whole") << int(L) << QByteArray("T1.5 M6") << u"T1.5 must be a whole number"_s;
        QTest::newRow("M61 Q beyond any tool") << int(L) << QByteArray("M61 Q-2") << u"Q-2 must be"_s;
        QTest::newRow("G43 H beyond any tool") << int(L) << QByteArray("G43 H99999999") << u"H99999999"_s;
        QTest::newRow("G43.2 H not whole") << int(L) << QByteArray("G43.2 H1.25") << u"H1.25"_s;
        QTest::newRow("G10 L1 P beyond any tool")
            << int(L) << QByteArray("G10 L1 P9999999 Z1") << u"needs P, a tool number"_s;
        QTest::newRow("FAGOR D beyond the offsets")
            << int(G) << QByteArray("G43 D1000") << u"from 0 to 999"_s;
        QTest::newRow("FAGOR T beyond an int") << int(G) << QByteArray("T12345678.5") << u"T12345678.5"_s;
        QTest::newRow("a word beyond eight digits")
            << int(F) << QByteArray("G0 X123456789") << u"too large"_s;
        QTest::newRow("G91 towards infinity, at its first step")
            << int(F) << QByteArray("G91 G0 X" + huge) << u"too large"_s;
        QTest::newRow("Aerotech offset beyond eight digits")
            << int(R) << QByteArray("G44 X Y\nCutterCompensationSetOffsets([1, 1000000000])")
            << u"too large"_s;
        QTest::newRow("a refused G10 creates no register")
            << int(F) << QByteArray("G10 L11 P5 R150") << u"PS0032"_s;
        QTest::newRow("a refused G91 G10 changes no register")
            << int(F) << QByteArray("G91 G10 L10 P1 R999") << u"PS0032"_s;
    }
    void refusesWhatNoControllerTakes()
    {
        QFETCH(int, dialect);
        QFETCH(QByteArray, program);
        QFETCH(QString, error);
        const OffsetTable before = offsets(u"1:10/-0.5;2:-190.1"_s);
        GCodeInterpreter interpreter(Dialect(dialect), before);
        const auto result = interpreter.run(program);
        QVERIFY2(!result.ok(), "the program should have been refused");
        QVERIFY2(result.error().message.contains(error), qPrintable(result.error().message));
        QCOMPARE(result.error().line, int(program.count('\n')) + 1);
        QCOMPARE(interpreter.offsets(), before);
        for (double v : interpreter.position())
            QVERIFY(std::isfinite(v));
    }

    void leadsOnGraduallyOverTheMove()
    {
        // DIALECTS Aerotech worked: 'halfway through the lead-on at (5.5, 4, 1.5)'; 001: 'gradually applies
        // the offsets during a lead-on move', 'gradually removes the offsets during a lead-off move'.
        GCodeInterpreter interpreter(Dialect::Aerotech, {}, 3);
        QVERIFY(interpreter
                    .run("G44 X Y Z\nCutterCompensationSetOffsets([1, -2, 3])\nG143 G1 X10 Y10\nG1 X20\n"
                         "G149 G1 X30 Y10")
                    .ok());
        const QList<SimulatedMove> &moves = interpreter.moves();
        QCOMPARE(moves.size(), 3);
        QCOMPARE(moves.at(0).points.at(1), (Position { 5.5, 4, 1.5 }));
        QCOMPARE(moves.at(0).points.at(0), (Position { 0, 0, 0 }));
        QCOMPARE(moves.at(2).points.at(1), (Position { 25.5, 9, 1.5 }));
    }

    void withoutANextMoveNothingIsApplied()
    {
        // 001: 'If the controller cannot find the next coordinated move, it does not use cutter offset
        // compensation.'
        GCodeInterpreter interpreter(Dialect::Aerotech);
        QVERIFY(interpreter.run("G44 X Y Z\nCutterCompensationSetOffsets([1, -2, 3])\nG143").ok());
        QVERIFY(interpreter.moves().isEmpty());
        QCOMPARE(interpreter.position(), (Position { 0, 0, 0 }));
    }
};

QTEST_GUILESS_MAIN(TestConformance)
#include "tst_conformance.moc"
