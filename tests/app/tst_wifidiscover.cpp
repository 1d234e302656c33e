// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli discover, as an operator or a script runs it: it hears the machines' beacons (toffee-emulator's)
// and which is busy, says when nothing is heard, ignores what is no beacon, and keeps the real machine
// visible under a flood sent by the test.
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

class TestWifiDiscover : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // Nothing of the user's own: the standard library lives under XDG_DATA_HOME.
        qputenv("XDG_DATA_HOME", m_dir.filePath(u"data"_s).toLocal8Bit());
    }

    // Two machines announce themselves: both heard, with the address and port to connect to; a client
    // connected to one makes it busy, in JSON and in words.
    void discoverHearsTheMachinesAndWhichIsBusy()
    {
        const quint16 udp = freeUdpPort();
        QVERIFY(udp > 0);
        QTemporaryDir dir;
        Emulator one(dir.filePath(u"one"_s),
            { u"--listen"_s, u"127.0.0.1:0"_s, u"--announce"_s, QString::number(udp), u"--name"_s,
                u"Mill_One"_s });
        Emulator two(dir.filePath(u"two"_s),
            { u"--listen"_s, u"127.0.0.1:0"_s, u"--announce"_s, QString::number(udp), u"--name"_s,
                u"Mill_Two"_s });
        QVERIFY(!one.tcp().isEmpty() && !two.tcp().isEmpty());
        const QStringList discover { u"discover"_s, u"--seconds"_s, u"2"_s, u"--discovery-port"_s,
            QString::number(udp) };
        const auto verify = [&](const Run &run, bool oneBusy) {
            QVERIFY2(run.exitCode == 0, run.err.constData());
            const QJsonArray heard = machines(run);
            QCOMPARE(heard.size(), 2);
            int i = 0;
            for (const Emulator *e : { &one, &two }) {
                const QJsonObject m = heard.at(i++).toObject();
                QCOMPARE(m[u"name"_s].toString(), i == 1 ? u"Mill_One"_s : u"Mill_Two"_s);
                QCOMPARE(m[u"address"_s].toString(), u"127.0.0.1"_s);
                QCOMPARE(m[u"port"_s].toInt(), e->tcp().section(u':', -1).toInt());
                QCOMPARE(m[u"busy"_s].toBool(), i == 1 && oneBusy);
            }
        };
        verify(cli(QStringList { u"--json"_s } + discover), false);

        QTcpSocket client; // another program, connected to Mill_One
        client.connectToHost(QHostAddress::LocalHost, quint16(one.tcp().section(u':', -1).toUInt()));
        QVERIFY(client.waitForConnected(3000));
        verify(cli(QStringList { u"--json"_s } + discover), true);

        const Run words = cli(discover);
        QCOMPARE(words.exitCode, 0);
        QCOMPARE(words.out,
            "Mill_One  " + one.tcp().toUtf8() + "  busy: another program is connected to it\nMill_Two  "
                + two.tcp().toUtf8() + "  free\n");
        QVERIFY(words.err.isEmpty());
    }

    // Nothing heard is no failure of the command: an empty list and exit 0 (a script reads the list), and in
    // words what to check.
    void discoverSaysWhenNothingIsHeard()
    {
        const quint16 udp = freeUdpPort();
        const QStringList discover { u"discover"_s, u"--seconds"_s, u"1"_s, u"--discovery-port"_s,
            QString::number(udp) };
        QElapsedTimer clock;
        clock.start();
        const auto inJson = startCli(QStringList { u"--json"_s } + discover);
        const auto inWords = startCli(discover);
        qint64 ms = 0;
        Run run = finish(*inJson, &ms, &clock);
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(ms >= 1000 && ms < 3000, qPrintable(QString::number(ms)));
        QCOMPARE(run.out.trimmed(), QByteArray(R"({"dropped":0,"machines":[]})"));
        run = finish(*inWords);
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.startsWith(
                     QByteArray("No Carvera heard on UDP port " + QByteArray::number(udp) + " in 1 s.")),
            run.out.constData());
        QVERIFY(run.out.contains(QByteArray("no firewall blocks UDP port " + QByteArray::number(udp))));
    }

    // What is no beacon (noise, a forged field, an escape sequence for the terminal, an oversized datagram)
    // is counted, said on stderr and ignored; the machine beside it is heard.
    void discoverIgnoresWhatIsNoBeacon()
    {
        const quint16 udp = freeUdpPort();
        const auto process = startCli({ u"--json"_s, u"discover"_s, u"--seconds"_s, u"2"_s,
            u"--discovery-port"_s, QString::number(udp) });
        const QList<QByteArray> malformed { "garbage", "Evil,127.0.0.1,0,0", "Evil,127.0.0.1,2222,0,1",
            "Evil\x1b[2J,127.0.0.1,2222,0", "Evil,localhost,2222,0", "Evil,127.0.0.1,2222,busy",
            QByteArray(300, 'E'), QByteArray("Evil,127.0.0.1\0,2222,0", 22) };
        QUdpSocket sender;
        // Sent all the while it listens, since when it starts listening is its own affair.
        while (!process->waitForFinished(100)) {
            for (const QByteArray &datagram : malformed)
                sender.writeDatagram(datagram, QHostAddress::LocalHost, udp);
            sender.writeDatagram("Good_Mill,127.0.0.1,2222,0", QHostAddress::LocalHost, udp);
        }
        const Run run = finish(*process);
        QCOMPARE(run.exitCode, 0);
        const QJsonArray heard = machines(run);
        QCOMPARE(heard.size(), 1);
        QCOMPARE(heard.at(0)[u"name"_s].toString(), u"Good_Mill"_s);
        QCOMPARE(heard.at(0)[u"port"_s].toInt(), 2222);
        QVERIFY2(run.err.contains("were no Carvera's beacon and were ignored"), run.err.constData());
    }

    // A flood of 1000 names from one sender (a broken or hostile device, here 127.0.0.2) holds only that
    // sender's share of the list: the real machine, announcing itself from its own address (127.0.0.1), is
    // listed all the same, the dropped names are said, and the command still ends on time. 64 such names once
    // filled the list and hid the machine, without a word.
    void discoverKeepsTheRealMachineVisibleUnderAFlood()
    {
        const quint16 udp = freeUdpPort();
        QElapsedTimer clock;
        clock.start();
        const auto process = startCli({ u"--json"_s, u"discover"_s, u"--seconds"_s, u"2"_s,
            u"--discovery-port"_s, QString::number(udp) });
        QUdpSocket flood;
        QVERIFY(flood.bind(QHostAddress(u"127.0.0.2"_s), 0));
        QUdpSocket machine;
        int sent = 0;
        QElapsedTimer beacon;
        beacon.start();
        while (!process->waitForFinished(20)) {
            // 100 names at a turn, the 1000 over and over: whichever arrive once it listens are plenty.
            for (int i = 0; i < 100; ++i, ++sent) {
                const int n = sent % 1000;
                flood.writeDatagram(u"Flood_%1,10.0.%2.%3,2222,0"_s.arg(n, 4, 10, QChar(u'0'))
                                        .arg(n / 250)
                                        .arg(n % 250)
                                        .toLatin1(),
                    QHostAddress::LocalHost, udp);
            }
            if (beacon.elapsed() > 200) { // a machine announces itself once a second; here more often
                machine.writeDatagram("Good_Mill,127.0.0.1,2222,0", QHostAddress::LocalHost, udp);
                beacon.restart();
            }
        }
        qint64 ms = clock.elapsed();
        const Run run = finish(*process);
        QVERIFY2(sent >= 1000, qPrintable(QString::number(sent)));
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(ms < 4000, qPrintable(QString::number(ms)));
        const QJsonArray heard = machines(run);
        QStringList names;
        for (const QJsonValue &m : heard)
            names << m[u"name"_s].toString();
        QVERIFY2(names.contains(u"Good_Mill"_s), qPrintable(names.join(u' ')));
        QCOMPARE(heard.size(), 1 + Toffee::BeaconListener::kMaxNamesPerSender);
        QVERIFY(QJsonDocument::fromJson(run.out.trimmed()).object()[u"dropped"_s].toInt() > 900);
        QVERIFY2(run.err.contains("announcement(s) were not listed"), run.err.constData());
    }

private:
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TestWifiDiscover)
#include "tst_wifidiscover.moc"
