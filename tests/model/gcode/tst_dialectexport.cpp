// SPDX-License-Identifier: GPL-3.0-or-later
// Export a table as a controller's program, run it through the interpreter on an empty table, get the table
// back.
#include <QTest>

#include "model/gcode/dialect.h"
#include "model/gcode/gcodeinterpreter.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

// Values at the controllers' resolution (0.001 mm), so that the program holds them exactly.
ToolTable table()
{
    QList<Tool> tools;
    const double values[][4] = { { 100.0, -0.1, 3.0, -0.01 }, { 71.488, 0.0, 1.588, 0.002 },
        { -12.345, 0.05, 0, 0 }, { 999.999, -99.999, 0.5, 0 } };
    int number = 1;
    for (const auto &v : values) {
        Tool t;
        t.number = number;
        t.pocket = number;
        number = number * 7 + 2; // 1, 9, 65, 457
        t.lengthGeometry = v[0];
        t.lengthWear = v[1];
        t.radiusGeometry = v[2];
        t.radiusWear = v[3];
        tools << t;
    }
    return ToolTable::fromTools(tools, Units::Millimetre).takeValue();
}

bool near(double a, double b)
{
    return std::fabs(a - b) < 1e-9;
}

} // namespace

class TestDialectExport : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void roundTripsThroughTheInterpreter_data()
    {
        QTest::addColumn<int>("dialect");
        for (const DialectInfo &info : dialects()) {
            if (info.holdsATable)
                QTest::newRow(qPrintable(info.key)) << int(info.dialect);
        }
    }
    void roundTripsThroughTheInterpreter()
    {
        QFETCH(int, dialect);
        ToolTable original = table();
        const bool grblHal = Dialect(dialect) == Dialect::GrblHal;
        if (grblHal) { // grblHAL's table takes the TLOs Toffee measured against the reference tool
            double tlo = -12.345;
            const QList<Tool> tools = original.tools(); // a copy: the loop changes the table
            for (const Tool &t : tools)
                QVERIFY(
                    original.recordMeasurement(t.number, tlo += 7.5, QDateTime::currentDateTimeUtc()).ok());
        }
        const auto program = exportProgram(original, Dialect(dialect));
        QVERIFY2(program.ok(), qPrintable(program.error().text()));
        OffsetTable empty;
        if (usesToolTableWords(Dialect(dialect))) {
            // LinuxCNC refuses G10 L1 for a tool its table does not list: the tools are there, with no
            // offsets.
            for (const Tool &t : original.tools())
                empty[t.number] = {};
        }
        GCodeInterpreter interpreter(Dialect(dialect), empty);
        const auto ran = interpreter.run(program.value().toUtf8());
        QVERIFY2(ran.ok(), qPrintable(ran.error().text() + u"\n"_s + program.value()));
        QCOMPARE(interpreter.offsets().size(), size_t(original.size()));
        for (const Tool &t : original.tools()) {
            const OffsetEntry &e = interpreter.offsets().at(t.number);
            if (grblHal) {
                QVERIFY(near(e.length(), *t.measuredTlo));
                QVERIFY(near(e.radiusGeometry + e.radiusWear, t.totalRadius()));
            } else if (Dialect(dialect) == Dialect::LinuxCnc) { // no wear columns: the totals
                QVERIFY(near(e.length(), t.totalLength()));
                QVERIFY(near(e.radiusGeometry + e.radiusWear, t.totalRadius()));
            } else {
                QVERIFY(near(e.lengthGeometry, t.lengthGeometry));
                QVERIFY(near(e.lengthWear, t.lengthWear));
                QVERIFY(near(e.radiusGeometry, t.radiusGeometry));
                QVERIFY(near(e.radiusWear, t.radiusWear));
            }
        }
    }

    void exportsWhatTheOtherControllersTake()
    {
        ToolTable t = table();
        QVERIFY(t.recordMeasurement(9, -33.388, QDateTime::currentDateTimeUtc()).ok());
        auto carvera = exportProgram(t, Dialect::Carvera);
        QVERIFY(carvera.ok());
        QVERIFY(carvera.value().contains(u"M493.2 T9\nM493.3 Z-33.388\n"_s));
        GCodeInterpreter machine(Dialect::Carvera);
        QVERIFY(machine.run(QByteArray(carvera.value().toUtf8() + "G0 Z0\n")).ok());
        QCOMPARE(machine.position()[2], -33.388);

        auto aerotech = exportProgram(t, Dialect::Aerotech, 9);
        QVERIFY(aerotech.ok());
        QVERIFY(aerotech.value().contains(u"G44 X Y Z\nCutterCompensationSetOffsets([0, 0, 71.488])"_s));
        GCodeInterpreter aero(Dialect::Aerotech);
        QVERIFY(aero.run(QByteArray(aerotech.value().toUtf8() + "G143 G1 X10\n")).ok());
        QCOMPARE(aero.position()[2], 71.488);
    }

    void oneToolAskedForIsOneToolWritten_data()
    {
        QTest::addColumn<int>("dialect");
        QTest::addColumn<QString>("perTool"); // what the program writes once for each tool
        QTest::newRow("FANUC") << int(Dialect::Fanuc) << u"G10 L10 P"_s;
        QTest::newRow("Allen-Bradley") << int(Dialect::AllenBradley9) << u"G10 L10 P"_s;
        QTest::newRow("LinuxCNC") << int(Dialect::LinuxCnc) << u"G10 L1 P"_s;
        QTest::newRow("Carvera") << int(Dialect::Carvera) << u"M493.2 T"_s;
        QTest::newRow("Aerotech") << int(Dialect::Aerotech) << u"// T"_s;
    }
    void oneToolAskedForIsOneToolWritten()
    {
        // Once, every tool was written whatever was chosen: a program meant for one tool would have
        // overwritten the controller's whole offset table.
        QFETCH(int, dialect);
        QFETCH(QString, perTool);
        ToolTable t = table();
        QVERIFY(t.size() > 2);
        for (const Tool &tool : t.tools())
            QVERIFY(
                t.recordMeasurement(tool.number, -30.0 - tool.number, QDateTime::currentDateTimeUtc()).ok());
        const int chosen = t.at(1).number;
        const auto program = exportProgram(t, Dialect(dialect), chosen);
        QVERIFY2(program.ok(), qPrintable(program.error().message));
        QCOMPARE(program.value().count(perTool), 1);
        QVERIFY2(program.value().contains(perTool + QString::number(chosen)), qPrintable(program.value()));
        QVERIFY2(program.value().contains(u"Toffee: 1 tool,"_s), qPrintable(program.value()));
        // All tools: each once, and the header counts what is written. Aerotech sets one tool at a time.
        const auto all = exportProgram(t, Dialect(dialect));
        if (Dialect(dialect) == Dialect::Aerotech) {
            QVERIFY(!all.ok());
            QVERIFY2(all.error().message.contains(u"one tool at a time"_s), qPrintable(all.error().message));
            return;
        }
        QVERIFY2(all.ok(), qPrintable(all.error().message));
        QCOMPARE(all.value().count(perTool), t.size());
        QVERIFY(all.value().contains(u"%1 tools"_s.arg(t.size())));
    }

    void refusesWhatAControllerCannotHold()
    {
        ToolTable t = table();
        QVERIFY(t.insert(Tool { 1200, 1, {}, 10, 0, 0, 0, {}, {}, {}, {} }).ok());
        const auto fanuc = exportProgram(t, Dialect::Fanuc);
        QVERIFY(!fanuc.ok());
        QVERIFY(fanuc.error().message.contains(u"T1200"_s));
        QVERIFY(!exportProgram(t, Dialect::Fagor8055M).ok());
        QVERIFY(!exportProgram(ToolTable(), Dialect::Carvera).ok()); // no measured TLO to write
        QVERIFY(!exportProgram(t, Dialect::Aerotech, 42).ok());
        QCOMPARE(dialectFromKey(u"AB9"), Dialect::AllenBradley9);
        QVERIFY(!dialectFromKey(u"heidenhain"));
    }
};

QTEST_GUILESS_MAIN(TestDialectExport)
#include "tst_dialectexport.moc"
