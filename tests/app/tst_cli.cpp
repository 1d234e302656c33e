// SPDX-License-Identifier: GPL-3.0-or-later
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

#include "model/library/library.h"
#include "tests/support/processes.h"

using Toffee::Test::cli;
using Toffee::Test::Run;

namespace {

const QString kExample = QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json");

void write(const QString &path, const QByteArray &data)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(data);
}

} // namespace

class TestCli : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void theWindowAnswersHelpWithoutADisplay()
    {
        // `toffee --help` once aborted where there was no display (a server, ssh, a script).
        for (const QString &flag : { u"--help"_s, u"--version"_s }) {
            QProcess process;
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.remove(u"DISPLAY"_s);
            env.remove(u"WAYLAND_DISPLAY"_s);
            env.remove(u"QT_QPA_PLATFORM"_s);
            process.setProcessEnvironment(env);
            process.start(QStringLiteral(TOFFEE_BIN_DIR "/toffee"), { flag });
            QVERIFY(process.waitForFinished(20000));
            QCOMPARE(process.exitStatus(), QProcess::NormalExit);
            QCOMPARE(process.exitCode(), 0);
            const QByteArray out = process.readAllStandardOutput();
            QVERIFY2(out.contains(flag == u"--help" ? QByteArray("--self-test") : QByteArray("Toffee ")),
                out.constData());
        }
    }

    // The link's own latency, on the built-in emulator: every round trip counted, and a clean exit (the loop
    // that sent them once destroyed itself while it ran, and the CLI crashed after printing).
    void measuresTheLinkAndExitsCleanly()
    {
        const Run run = cli({ u"--json"_s, u"--emulator"_s, u"link-test"_s, u"--count"_s, u"200"_s });
        QCOMPARE(run.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(run.out).object();
        QCOMPARE(o.value(u"count"_s).toInt(), 200);
        QVERIFY(o.value(u"median_ms"_s).toDouble() > 0.0);
        QVERIFY(o.value(u"max_ms"_s).toDouble() >= o.value(u"p99_ms"_s).toDouble());
        QVERIFY(run.err.isEmpty());
    }

    // The operator says a program ran: each tool's cutting time and feed path go into the library.
    void recordsWhatAProgramMadeEachToolDo()
    {
        QTemporaryDir dir;
        const QString program = dir.filePath(u"pocket.nc"_s);
        write(program, "T1 M6\nG0 X0 Y0 Z5\nG1 Z0 F300\nX60 F600\nT4 M6\nG1 X0 F1200\nM30\n");
        const QString library = dir.filePath(u"library.sqlite"_s);
        const Run run = cli({ u"--json"_s, u"--library"_s, library, u"history"_s, u"add-use"_s,
            u"--machine"_s, u"Mill 2"_s, u"--program"_s, program, u"--dialect"_s, u"fanuc"_s });
        QCOMPARE(run.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(run.out).object();
        QCOMPARE(o[u"tools"_s].toArray().size(), 2);
        QCOMPARE(
            o[u"tools"_s].toArray().at(0)[u"cutting_seconds"_s].toDouble(), 7.0); // 5 mm at 300, 60 at 600
        QCOMPARE(o[u"tools"_s].toArray().at(1)[u"feed_path_mm"_s].toDouble(), 60.0);
        QCOMPARE(o[u"rapid_mm"_s].toDouble(), 5.0);
        auto opened = Toffee::Library::open({ library });
        QVERIFY(opened);
        const auto uses = opened.value()->uses(u"Mill 2"_s, 4);
        QCOMPARE(uses.value().size(), 1);
        QCOMPARE(uses.value().front().cuttingSeconds, 3.0);
        QCOMPARE(uses.value().front().program, u"pocket.nc"_s);

        // A program the interpreter refuses records nothing, and says where it stopped.
        write(program, "T1 M6\nG1 X10 F100\nG2 X50 Y0 R10\n");
        const Run bad = cli({ u"--library"_s, library, u"history"_s, u"add-use"_s, u"--machine"_s,
            u"Mill 2"_s, u"--program"_s, program, u"--dialect"_s, u"fanuc"_s });
        QCOMPARE(bad.exitCode, 4);
        QVERIFY2(bad.err.contains("line 3") && bad.err.contains("Nothing was recorded"), bad.err.constData());
        QCOMPARE(opened.value()->uses(u"Mill 2"_s, 1).value().size(), 1);
    }

    void showsATable()
    {
        const Run run = cli({ u"show"_s, kExample });
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.out.contains("6 tools, mm"));
        QVERIFY(run.out.contains("9.652"));
        QVERIFY(run.out.contains("6 mm flat end mill, 3 flutes"));
        QVERIFY(run.err.isEmpty());
    }

    void showsATableAsOneJsonObject()
    {
        const Run run = cli({ u"--json"_s, u"show"_s, kExample });
        QCOMPARE(run.exitCode, 0);
        QJsonParseError error;
        const QJsonObject o = QJsonDocument::fromJson(run.out, &error).object();
        QCOMPARE(error.error, QJsonParseError::NoError);
        QCOMPARE(o.value(u"units"_s).toString(), u"mm"_s);
        const QJsonArray tools = o.value(u"tools"_s).toArray();
        QCOMPARE(tools.size(), 6);
        QCOMPARE(tools.at(1).toObject().value(u"measured_tlo"_s).toDouble(), 9.652);
        QCOMPARE(tools.at(2).toObject().value(u"total_length"_s).toDouble(), 41.23);
    }

    void convertsAndWarnsWhatIsLost()
    {
        QTemporaryDir dir;
        const QString tbl = dir.filePath(u"tool.tbl"_s);
        Run run = cli({ u"convert"_s, kExample, tbl });
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.err.contains("warning: A LinuxCNC table has no place for measured TLOs"));
        QFile f(tbl);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.readAll().startsWith("T1 P1 Z38.1 D3.175 ;3.175 mm flat end mill, 2 flutes\n"));

        const QString csv = dir.filePath(u"out.txt"_s);
        run = cli({ u"--json"_s, u"convert"_s, tbl, csv, u"--to"_s, u"csv"_s });
        QCOMPARE(run.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(run.out).object();
        QCOMPARE(o.value(u"tools"_s).toInt(), 6);
        QCOMPARE(o.value(u"format"_s).toString(), u"csv"_s);
        run = cli({ u"show"_s, csv });
        QCOMPARE(run.exitCode, 2); // .txt: the format cannot be told from the name
        QVERIFY(run.err.contains("unknown file type"));
    }

    void refusesBadInputWithExitCode2AndAMessage_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QByteArray>("message");
        QTest::newRow("no command") << QStringList() << QByteArray("no command given");
        QTest::newRow("unknown command")
            << QStringList { u"explode"_s } << QByteArray("unknown command \"explode\"");
        QTest::newRow("unknown option")
            << QStringList { u"--frobnicate"_s, u"show"_s } << QByteArray("--frobnicate");
        QTest::newRow("missing file")
            << QStringList { u"show"_s, u"/nonexistent/t.json"_s } << QByteArray("cannot open");
        QTest::newRow("show without a file")
            << QStringList { u"show"_s } << QByteArray("usage: toffee-cli show");
        QTest::newRow("bad --to") << QStringList { u"convert"_s, kExample, u"x"_s, u"--to"_s, u"xml"_s }
                                  << QByteArray("--to must be json, tbl or csv");
        QTest::newRow("--to without value")
            << QStringList { u"convert"_s, kExample, u"x"_s, u"--to"_s } << QByteArray("--to needs a value");
        QTest::newRow("bad --units") << QStringList { u"show"_s, kExample, u"--units"_s, u"cm"_s }
                                     << QByteArray("--units must be mm or in");
    }
    void refusesBadInputWithExitCode2AndAMessage()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QByteArray, message);
        const Run run = cli(arguments);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(message), run.err.constData());
    }

    void simulatesAProgramAsJson()
    {
        QTemporaryDir dir;
        const QString program = dir.filePath(u"aerotech.pgm"_s);
        write(program,
            "G44 X Y Z\nCutterCompensationSetOffsets([1, -2, 3])\nG143 G1 X10 Y10\nG1 X20\n"
            "G149 G1 X30 Y10\n");
        const Run run = cli(
            { u"--json"_s, u"simulate"_s, u"--dialect"_s, u"aerotech"_s, u"--samples"_s, u"3"_s, program });
        QCOMPARE(run.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(run.out).object();
        QCOMPARE(o.value(u"dialect"_s).toString(), u"aerotech"_s);
        QVERIFY(o.value(u"error"_s).isNull());
        const QJsonArray moves = o.value(u"moves"_s).toArray();
        QCOMPARE(moves.size(), 3);
        const QJsonObject leadOn = moves.at(0).toObject();
        QCOMPARE(leadOn.value(u"line"_s).toInt(), 3);
        QCOMPARE(leadOn.value(u"x"_s).toDouble(), 11.0);
        QCOMPARE(leadOn.value(u"y"_s).toDouble(), 8.0);
        QCOMPARE(leadOn.value(u"z"_s).toDouble(), 3.0);
        const QJsonArray half = leadOn.value(u"points"_s).toArray().at(1).toArray();
        QCOMPARE(half.at(0).toDouble(), 5.5);
        QCOMPARE(half.at(2).toDouble(), 1.5);
    }

    void aProgramErrorNamesTheLineAndExits4()
    {
        QTemporaryDir dir;
        const QString program = dir.filePath(u"bad.nc"_s);
        write(program, "G90 G10 L10 P1 R100\nG43 G0 Z10 H1\nG43 G0 Z10 H1000\n");
        const Run run = cli({ u"--json"_s, u"simulate"_s, u"--dialect"_s, u"fanuc"_s, program });
        QCOMPARE(run.exitCode, 4);
        const QJsonObject o = QJsonDocument::fromJson(run.out).object();
        QCOMPARE(o.value(u"error"_s).toObject().value(u"line"_s).toInt(), 3);
        QVERIFY(o.value(u"error"_s).toObject().value(u"message"_s).toString().startsWith(u"PS0030"_s));
        QCOMPARE(o.value(u"moves"_s).toArray().size(), 1); // what ran before the error
        QCOMPARE(
            o.value(u"offsets"_s).toArray().at(0).toObject().value(u"length_geometry"_s).toDouble(), 100.0);
        QVERIFY(run.err.contains("line 3: PS0030"));
    }

    void exportsAndTheExportSimulatesBack()
    {
        QTemporaryDir dir;
        Run run = cli({ u"export"_s, u"--dialect"_s, u"fanuc"_s, kExample });
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.out.contains("G10 L10 P2 R71.488\n"));
        const QString program = dir.filePath(u"offsets.nc"_s);
        write(program, run.out);
        run = cli({ u"--json"_s, u"simulate"_s, u"--dialect"_s, u"fanuc"_s, program });
        QCOMPARE(run.exitCode, 0);
        const QJsonArray offsets = QJsonDocument::fromJson(run.out).object().value(u"offsets"_s).toArray();
        QCOMPARE(offsets.size(), 6);
        QCOMPARE(offsets.at(2).toObject().value(u"length_wear"_s).toDouble(), -0.02);
        run = cli({ u"export"_s, u"--dialect"_s, u"fagor"_s, kExample });
        QCOMPARE(run.exitCode, 2);
        run = cli({ u"export"_s, u"--dialect"_s, u"heidenhain"_s, kExample });
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("--dialect must be one of carvera, fanuc"));
    }

    void namesTheLineOfAMalformedFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"bad.tbl"_s);
        write(path, "T1 P1 Z1\n; fine\nT2 P2 Z1 Z2\n");
        const QString out = dir.filePath(u"out.json"_s);
        const Run run = cli({ u"--json"_s, u"convert"_s, path, out });
        QCOMPARE(run.exitCode, 2);
        const QString error = QJsonDocument::fromJson(run.out).object().value(u"error"_s).toString();
        QVERIFY2(error.contains(u"line 3"_s), qPrintable(error));
        QVERIFY(run.err.contains("line 3"));
        QVERIFY(!QFile::exists(out)); // nothing half-written
    }
};

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
