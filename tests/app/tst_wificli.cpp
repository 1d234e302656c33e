// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli over Wi-Fi, as an operator or a script runs it: against toffee-emulator's TCP console in plain
// text (the community firmware) and in Makera's frames (community and stock), the protocol found or forced,
// the story of a tool (status, select-tool, probe, report, set-tlo, a passing break test) with the table file
// read after each step; a forced protocol the machine does not speak, a bad address, nothing listening and a
// machine that never answers the connect. `discover`: tst_wifidiscover; what both share:
// tests/app/wificlirun.h.
#include <memory>

#include <QElapsedTimer>
#include <QHostAddress>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QUdpSocket>

#include "tests/app/wificlirun.h"

using namespace Toffee::Test;
using namespace Qt::StringLiterals;
using namespace Toffee::Test;

class TestWifiCli : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // Nothing of the user's own: the standard library lives under XDG_DATA_HOME.
        qputenv("XDG_DATA_HOME", m_dir.filePath(u"data"_s).toLocal8Bit());
    }

    // The same story in every wire and protocol a Carvera serves over Wi-Fi, found (--protocol auto) or
    // forced: what the machine says, what the exit code says, and what the table file holds after each step.
    void anOperatorsStoryOverWifi_data()
    {
        QTest::addColumn<QStringList>("emulatorArguments");
        QTest::addColumn<QString>("protocol");
        QTest::addColumn<bool>("stock");
        const QStringList plain;
        const QStringList framed { u"--framed"_s };
        const QStringList stock { u"--framed"_s, u"--firmware"_s, u"stock"_s };
        QTest::newRow("plain text, found") << plain << u"auto"_s << false;
        QTest::newRow("plain text, forced") << plain << u"text"_s << false;
        QTest::newRow("framed community, found") << framed << u"auto"_s << false;
        QTest::newRow("framed community, forced") << framed << u"framed"_s << false;
        QTest::newRow("framed stock, found") << stock << u"auto"_s << true;
        QTest::newRow("framed stock, forced") << stock << u"framed"_s << true;
    }
    void anOperatorsStoryOverWifi()
    {
        QFETCH(QStringList, emulatorArguments);
        QFETCH(QString, protocol);
        QFETCH(bool, stock);
        QTemporaryDir dir;
        Emulator emulator(
            dir.filePath(u"tty"_s), emulatorArguments + QStringList { u"--listen"_s, u"127.0.0.1:0"_s });
        QVERIFY(emulator.started());
        QVERIFY(!emulator.tcp().isEmpty());
        const QString table = dir.filePath(u"tools.json"_s);
        QVERIFY(QFile::copy(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json"), table));
        QFile(table).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
        const auto machine = [&](const QStringList &arguments) {
            return cli(QStringList { u"--json"_s, u"--library"_s, dir.filePath(u"library.sqlite"_s),
                           u"--table"_s, table, u"--host"_s, emulator.tcp(), u"--protocol"_s, protocol }
                    + arguments,
                30000);
        };
        const auto tool = [&table](int number) {
            for (const QJsonValue &t :
                QJsonDocument::fromJson(readFile(table)).object()[u"tools"_s].toArray()) {
                if (t[u"number"_s].toInt() == number)
                    return t.toObject();
            }
            return QJsonObject();
        };
        const bool framed = emulatorArguments.contains(u"--framed"_s);

        // Connected, in the protocol the machine speaks: the link says so (found, or as forced).
        Run run = machine({ u"link-test"_s, u"--count"_s, u"20"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"count"_s].toInt(), 20);
        QCOMPARE(json(run)[u"link"_s].toString(),
            emulator.tcp() + u" over the network"_s + (framed ? u" (framed)"_s : QString()));

        QByteArray before = readFile(table);
        run = machine({ u"status"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"state"_s].toString(), u"Idle"_s);
        QCOMPARE(json(run)[u"tool"_s].toInt(), 1);
        QCOMPARE(json(run)[u"firmware"_s][u"kind"_s].toString(), stock ? u"stock"_s : u"community"_s);
        QCOMPARE(
            json(run)[u"firmware"_s][u"version"_s].toString(), stock ? u"1.0.5"_s : u"2.1.0c-emulator"_s);
        QCOMPARE(json(run)[u"firmware"_s][u"break_test"_s].toBool(), !stock);
        QCOMPARE(readFile(table), before); // reading writes nothing

        run = machine({ u"select-tool"_s, u"3"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"tool"_s].toInt(), 3);
        QVERIFY(json(run)[u"warning"_s].toString().contains(u"another tool's"_s));
        QCOMPARE(readFile(table), before);
        QCOMPARE(json(machine({ u"status"_s }))[u"tool"_s].toInt(), 3);

        // T3 had no TLO in the table; now it has the one measured, against the machine's reference where the
        // firmware reports one (the stock firmware does not).
        run = machine({ u"probe"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(fixed3(json(run)[u"tlo"_s]), u"12.840"_s);
        QCOMPARE(json(run)[u"history"_s].toString(), u"recorded"_s);
        QCOMPARE(fixed3(tool(3)[u"measured_tlo"_s]), u"12.840"_s);
        QVERIFY(!tool(3).contains(u"tlo_source"_s));
        if (stock) {
            QVERIFY(json(run)[u"reference_mz"_s].isNull());
            QVERIFY(!tool(3).contains(u"reference_mz"_s));
        } else {
            QCOMPARE(fixed3(json(run)[u"reference_mz"_s]), u"-115.340"_s);
            QCOMPARE(fixed3(tool(3)[u"reference_mz"_s]), u"-115.340"_s);
        }
        QCOMPARE(fixed3(tool(2)[u"measured_tlo"_s]), u"9.652"_s); // another tool's is left as it was

        before = readFile(table);
        run = machine({ u"report"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(fixed3(json(run)[u"tlo"_s]), u"12.840"_s);
        QCOMPARE(json(run)[u"tool"_s].toInt(), 3);
        QCOMPARE(readFile(table), before);

        run = machine({ u"set-tlo"_s, u"--z"_s, u"12.8"_s });
        if (stock) {
            // The stock firmware ignores M493.3 without a word: refused before anything is sent or written.
            QCOMPARE(run.exitCode, 2);
            QVERIFY2(json(run)[u"error"_s].toString().contains(u"ignores M493.3"_s), run.out.constData());
            QCOMPARE(readFile(table), before);
            run = machine({ u"break-test"_s, u"--tolerance"_s, u"0.1"_s });
            QCOMPARE(run.exitCode, 2);
            QVERIFY2(json(run)[u"error"_s].toString().contains(u"M491.1 only measures the tool again"_s),
                run.out.constData());
            QCOMPARE(readFile(table), before);
            QCOMPARE(fixed3(json(machine({ u"status"_s }))[u"tlo"_s]), u"12.840"_s); // nothing reached it
            return;
        }
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(fixed3(json(run)[u"tlo"_s]), u"12.800"_s);
        QCOMPARE(fixed3(tool(3)[u"measured_tlo"_s]), u"12.800"_s);
        QCOMPARE(tool(3)[u"tlo_source"_s].toString(), u"manual"_s);
        QCOMPARE(fixed3(json(machine({ u"status"_s }))[u"tlo"_s]), u"12.800"_s);

        // Measured again, 0.04 mm off the 12.800 set: within 0.1, not broken, and the table keeps its TLO.
        before = readFile(table);
        run = machine({ u"break-test"_s, u"--tolerance"_s, u"0.1"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"broken"_s].toBool(), false);
        QCOMPARE(fixed3(json(run)[u"old_tlo"_s]), u"12.800"_s);
        QCOMPARE(fixed3(json(run)[u"new_tlo"_s]), u"12.840"_s);
        QVERIFY(!tool(3)[u"break_test_failed"_s].toBool());
        QCOMPARE(fixed3(tool(3)[u"measured_tlo"_s]), u"12.800"_s);
        QCOMPARE(json(machine({ u"status"_s }))[u"state"_s].toString(), u"Idle"_s);
    }

    // A protocol forced that the machine does not speak: it fails within the command's limit (the connect's
    // 2 s status wait and its first command's 5 s), exit 5, and says what the bytes say: nothing came back to
    // plain text (a framed machine over TCP falls silent after plain bytes), or plain text came to frames.
    // Beside them, a machine that never answers the connect: the limit, and --timeout shortening it.
    void saysWhatIsWrongWhenTheLinkIsNot()
    {
        QTemporaryDir dir;
        Emulator framed(dir.filePath(u"framed"_s), { u"--framed"_s, u"--listen"_s, u"127.0.0.1:0"_s });
        Emulator stock(dir.filePath(u"stock"_s),
            { u"--framed"_s, u"--firmware"_s, u"stock"_s, u"--listen"_s, u"127.0.0.1:0"_s });
        Emulator plain(dir.filePath(u"plain"_s), { u"--listen"_s, u"127.0.0.1:0"_s });
        QVERIFY(!framed.tcp().isEmpty() && !stock.tcp().isEmpty() && !plain.tcp().isEmpty());
        SilentListener silent;
        QVERIFY(silent.full);
        const QString hanging = u"127.0.0.1:%1"_s.arg(silent.port);
        const QStringList status { u"--json"_s, u"--no-history"_s, u"status"_s };

        QElapsedTimer clock;
        clock.start();
        const auto textToFramed
            = startCli(QStringList { u"--host"_s, framed.tcp(), u"--protocol"_s, u"text"_s } + status);
        const auto textToStock
            = startCli(QStringList { u"--host"_s, stock.tcp(), u"--protocol"_s, u"text"_s } + status);
        const auto framedToPlain
            = startCli(QStringList { u"--host"_s, plain.tcp(), u"--protocol"_s, u"framed"_s } + status);
        const auto unanswered = startCli(QStringList { u"--host"_s, hanging } + status);
        const auto unansweredShort
            = startCli(QStringList { u"--host"_s, hanging, u"--timeout"_s, u"1"_s } + status);

        qint64 ms = 0;
        Run run = finish(*unansweredShort, &ms, &clock);
        QCOMPARE(run.exitCode, 5);
        QVERIFY2(ms >= 1000 && ms < 2500, qPrintable(QString::number(ms)));
        QVERIFY2(
            json(run)[u"error"_s].toString().contains(u"did not answer within 1 s"_s), run.out.constData());

        // The words here are the session's own 5 s guard on opening, which fires a moment before the
        // transport's worded "did not answer within 5 s" (reported with issue 28); what is sure is the limit.
        run = finish(*unanswered, &ms, &clock);
        QCOMPARE(run.exitCode, 5);
        QVERIFY2(ms >= 5000 && ms < 6500, qPrintable(QString::number(ms)));
        QVERIFY(!json(run)[u"error"_s].toString().isEmpty());

        // A protocol chosen is checked by the first question, harmless to every machine: plain text chosen
        // for a framed machine is refused before a plain byte reaches it (it would fall deaf until
        // restarted).
        for (QProcess *process : { textToFramed.get(), textToStock.get() }) {
            run = finish(*process, &ms, &clock);
            QCOMPARE(run.exitCode, 5);
            QVERIFY2(ms < 10000, qPrintable(QString::number(ms)));
            const QString said = json(run)[u"error"_s].toString();
            QVERIFY2(said.contains(u"speaks Makera's frames (its firmware from 1.0.4 on), not the plain text "
                                   "chosen. Plain text would leave it deaf until it is restarted, so nothing "
                                   "more was sent"_s),
                qPrintable(said));
            QVERIFY2(said.contains(u"or framed"_s), qPrintable(said));
        }
        run = finish(*framedToPlain, &ms, &clock);
        QCOMPARE(run.exitCode, 5);
        QVERIFY2(ms < 10000, qPrintable(QString::number(ms)));
        const QString said = json(run)[u"error"_s].toString();
        QVERIFY2(said.contains(u"speaks plain text, not Makera's frames as chosen"_s), qPrintable(said));
        QVERIFY2(said.contains(u"or text"_s), qPrintable(said));

        // Found rather than forced, each connects: the framed ones were never made deaf.
        for (const Emulator *machine : { &plain, &framed, &stock }) {
            run = cli({ u"--json"_s, u"--no-history"_s, u"--host"_s, machine->tcp(), u"status"_s });
            QVERIFY2(run.exitCode == 0, run.err.constData());
            QCOMPARE(json(run)[u"controller"_s].toString(), u"carvera"_s);
        }
    }

    // An address that is none: refused before anything is tried, exit 2, in words that name it; nothing
    // listening: refused at once, exit 5, said so.
    void refusesABadAddressAndSaysWhenNothingListens_data()
    {
        QTest::addColumn<QString>("host");
        QTest::addColumn<QString>("says");
        QTest::addColumn<QString>("hint");
        QTest::newRow("a:b:c") << u"a:b:c"_s
                               << u"\"a:b:c\" is not a machine's address: give HOST or HOST:PORT"_s
                               << QString();
        QTest::newRow("port 0") << u"carvera.local:0"_s << u"\"carvera.local:0\" is not a machine's address"_s
                                << QString();
        QTest::newRow("port 70000") << u"192.168.1.57:70000"_s
                                    << u"\"192.168.1.57:70000\" is not a machine's address"_s << QString();
        QTest::newRow("no port") << u"192.168.1.57:"_s << u"\"192.168.1.57:\" is not a machine's address"_s
                                 << QString();
        // Its last group could be a port: how to write it is said too.
        QTest::newRow("IPv6 bare")
            << u"::1"_s << u"\"::1\" is not a machine's address"_s
            << u"An IPv6 address goes in brackets: [::1], or [::1]:PORT with a port."_s;
    }
    void refusesABadAddressAndSaysWhenNothingListens()
    {
        QFETCH(QString, host);
        QFETCH(QString, says);
        QFETCH(QString, hint);
        const QString library = m_dir.filePath(u"untouched.sqlite"_s);
        Run run = cli({ u"--json"_s, u"--library"_s, library, u"--host"_s, host, u"probe"_s });
        QCOMPARE(run.exitCode, 2);
        const QString said = json(run)[u"error"_s].toString();
        QVERIFY2(said.startsWith(says), qPrintable(said));
        QVERIFY2(said.endsWith(hint), qPrintable(said));
        QCOMPARE(said.contains(u"brackets"_s), !hint.isEmpty()); // not said of an address that is no IPv6
        QVERIFY(!QFile::exists(library)); // refused before anything was opened
        run = cli({ u"--host"_s, host, u"status"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.startsWith(QByteArray("toffee-cli: " + says.toUtf8())), run.err.constData());
        QVERIFY(run.out.isEmpty());

        const quint16 closed = closedTcpPort();
        QElapsedTimer clock;
        clock.start();
        run = cli(
            { u"--json"_s, u"--no-history"_s, u"--host"_s, u"127.0.0.1:%1"_s.arg(closed), u"status"_s });
        QVERIFY2(clock.elapsed() < 2000, qPrintable(QString::number(clock.elapsed())));
        QCOMPARE(run.exitCode, 5);
        QVERIFY2(json(run)[u"error"_s].toString().startsWith(
                     u"Nothing answers at 127.0.0.1:%1 (the connection was refused)"_s.arg(closed)),
            run.out.constData());
    }

private:
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TestWifiCli)
#include "tst_wificli.moc"
