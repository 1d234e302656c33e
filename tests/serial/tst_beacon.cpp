// SPDX-License-Identifier: GPL-3.0-or-later
// The Wi-Fi beacon: what the firmware sends is read, anything else is refused; and the listener's memory
// stays bounded however many names arrive.
#include <QSignalSpy>
#include <QTest>

#include "serial/transport/beaconlistener.h"
#include "serial/wire/beacon.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

class TestBeacon : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void readsWhatTheFirmwareSends_data()
    {
        QTest::addColumn<QByteArray>("datagram");
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("address");
        QTest::addColumn<int>("port");
        QTest::addColumn<bool>("busy");
        QTest::newRow("the peer") << QByteArray("CARVERA_C1_SIM,127.0.0.1,38663,0") << u"CARVERA_C1_SIM"_s
                                  << u"127.0.0.1"_s << 38663 << false;
        QTest::newRow("busy") << QByteArray("Carvera_01234,192.168.1.57,2222,1") << u"Carvera_01234"_s
                              << u"192.168.1.57"_s << 2222 << true;
        QTest::newRow("a line end") << QByteArray("C,10.0.0.1,1,0\r\n") << u"C"_s << u"10.0.0.1"_s << 1
                                    << false;
        QTest::newRow("a NUL") << QByteArray("C,10.0.0.1,65535,0\0", 19) << u"C"_s << u"10.0.0.1"_s << 65535
                               << false;
        QTest::newRow("spaces in the name")
            << QByteArray("Shop C1 #2,10.0.0.2,2222,0") << u"Shop C1 #2"_s << u"10.0.0.2"_s << 2222 << false;
    }
    void readsWhatTheFirmwareSends()
    {
        QFETCH(QByteArray, datagram);
        QFETCH(QString, name);
        QFETCH(QString, address);
        QFETCH(int, port);
        QFETCH(bool, busy);
        const auto beacon = Beacon::parse(datagram);
        QVERIFY(beacon);
        QCOMPARE(beacon->name, name);
        QCOMPARE(beacon->address, address);
        QCOMPARE(int(beacon->port), port);
        QCOMPARE(beacon->busy, busy);
        QCOMPARE(Beacon::parse(beacon->format()), beacon);
    }

    void refusesWhatIsNoBeacon_data()
    {
        QTest::addColumn<QByteArray>("datagram");
        QTest::newRow("empty") << QByteArray();
        QTest::newRow("three fields") << QByteArray("C,10.0.0.1,2222");
        QTest::newRow("five fields") << QByteArray("C,10.0.0.1,2222,0,1");
        QTest::newRow("no name") << QByteArray(",10.0.0.1,2222,0");
        QTest::newRow("a control character") << QByteArray("C\x1b[2J,10.0.0.1,2222,0");
        QTest::newRow("UTF-8 name") << QByteArray("Fräse,10.0.0.1,2222,0");
        QTest::newRow("a long name") << QByteArray(65, 'n') + ",10.0.0.1,2222,0";
        QTest::newRow("octet 256") << QByteArray("C,10.0.0.256,2222,0");
        QTest::newRow("three octets") << QByteArray("C,10.0.1,2222,0");
        QTest::newRow("a host name") << QByteArray("C,carvera.local,2222,0");
        QTest::newRow("port 0") << QByteArray("C,10.0.0.1,0,0");
        QTest::newRow("port 65536") << QByteArray("C,10.0.0.1,65536,0");
        QTest::newRow("port -1") << QByteArray("C,10.0.0.1,-1,0");
        QTest::newRow("port 1e3") << QByteArray("C,10.0.0.1,1e3,0");
        QTest::newRow("busy 2") << QByteArray("C,10.0.0.1,2222,2");
        QTest::newRow("busy empty") << QByteArray("C,10.0.0.1,2222,");
        QTest::newRow("a NUL inside") << QByteArray("C,10.0.0.1\0,2222,0", 18);
        QTest::newRow("too long") << QByteArray("C,10.0.0.1,2222,0") + QByteArray(300, '\n');
    }
    void refusesWhatIsNoBeacon()
    {
        QFETCH(QByteArray, datagram);
        QVERIFY(!Beacon::parse(datagram));
    }

    // One entry per name, the last beacon's; malformed ones counted; a flood of names holds at most
    // kMaxMachines of them.
    void listenerKeepsOneEntryPerMachineAndStaysBounded()
    {
        BeaconListener listener;
        QSignalSpy changed(&listener, &BeaconListener::machinesChanged);
        listener.take("B,10.0.0.2,2222,0", u"10.0.0.2"_s);
        listener.take("A,10.0.0.1,2222,0", u"10.0.0.1"_s);
        listener.take("A,10.0.0.1,2222,0", u"10.0.0.1"_s); // the same again: no change
        QCOMPARE(changed.size(), 2);
        listener.take("A,10.0.0.1,2222,1", u"10.0.0.1"_s); // busy now
        QCOMPARE(changed.size(), 3);
        listener.take("garbage", u"10.0.0.9"_s);
        QCOMPARE(listener.ignored(), 1);
        auto machines = listener.machines();
        QCOMPARE(machines.size(), 2);
        QCOMPARE(machines.at(0).beacon.name, u"A"_s); // by name
        QVERIFY(machines.at(0).beacon.busy);
        // A flood of names from one sender holds only its share: A and B stay listed, and the dropped names
        // are counted.
        for (int i = 0; i < 100000; ++i)
            listener.take(
                u"M%1,10.0.%2.%3,2222,0"_s.arg(i).arg(i / 256 % 256).arg(i % 256).toLatin1(), u"x"_s);
        machines = listener.machines();
        QCOMPARE(machines.size(), 2 + BeaconListener::kMaxNamesPerSender);
        QCOMPARE(machines.at(0).beacon.name, u"A"_s);
        QCOMPARE(machines.at(1).beacon.name, u"B"_s);
        QCOMPARE(listener.dropped(), 100000 - BeaconListener::kMaxNamesPerSender);
        // Many senders: at most kMaxMachines names in all, the rest counted; the first heard keep theirs.
        for (int i = 0; i < 5000; ++i)
            listener.take(u"N%1,10.1.%2.%3,2222,0"_s.arg(i).arg(i / 256).arg(i % 256).toLatin1(),
                u"10.1.%1.%2"_s.arg(i / 256).arg(i % 256));
        QCOMPARE(listener.machines().size(), BeaconListener::kMaxMachines);
        QCOMPARE(listener.machines().at(0).beacon.name, u"A"_s);
    }
};

QTEST_GUILESS_MAIN(TestBeacon)
#include "tst_beacon.moc"
