// SPDX-License-Identifier: GPL-3.0-or-later
// What tst_wifiwindow.cpp and tst_wifilostlink.cpp share: a Carvera on the network (the emulator on TCP, its
// beacons to a port of the test's own) and what the connection panel heard.
#pragma once

#include "serial/emulator/beaconsender.h"
#include "serial/emulator/tcpserver.h"
#include "serial/transport/beaconlistener.h"
#include "tests/support/carverapeer.h"
#include "tests/support/station.h"
#include "tests/support/windowsteps.h"
#include "ui/common/appsettings.h"
#include "ui/connection/connectionpanel.h"
#include <QAbstractButton>
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>
#include <QUdpSocket>

namespace Toffee::Test {

using namespace Qt::StringLiterals;

// A UDP port nobody uses now: the test's own discovery port (never the machines' 3333).
inline quint16 freeUdpPort()
{
    QUdpSocket probe;
    if (!probe.bind(QHostAddress::LocalHost, 0))
        qFatal("cannot bind a UDP port on 127.0.0.1");
    return probe.localPort();
}

// A Carvera on the network, as this test's own: the emulator behind a TCP port, announcing itself.
struct NetworkMachine
{
    CarveraEmulator emulator;
    TcpServer server;
    std::unique_ptr<BeaconSender> beacon;

    NetworkMachine(const QString &name, quint16 discoveryPort, bool framed)
        : server(&emulator, framed)
    {
        if (!server.listen(QHostAddress::LocalHost, 0))
            qFatal("cannot listen on 127.0.0.1: %s", qPrintable(server.errorString()));
        Beacon b;
        b.name = name;
        b.address = u"127.0.0.1"_s;
        b.port = server.port();
        beacon = std::make_unique<BeaconSender>(b, QHostAddress::LocalHost, discoveryPort);
        QObject::connect(&server, &TcpServer::busyChanged, beacon.get(), &BeaconSender::setBusy);
        beacon->start();
    }
    QString address() const { return u"127.0.0.1:"_s + QString::number(server.port()); }
};

inline ConnectionPanel *panelOf(Station &s)
{
    return s.window.findChild<ConnectionPanel *>();
}

// The Wi-Fi list's entries as the operator reads them.
inline QStringList heard(Station &s)
{
    auto *combo = s.find<QComboBox>(u"wifiMachineCombo"_s);
    QStringList items;
    for (int i = 0; i < combo->count(); ++i)
        items << combo->itemText(i);
    return items;
}

inline void chooseHeard(Station &s, const QString &startsWith)
{
    auto *combo = s.find<QComboBox>(u"wifiMachineCombo"_s);
    auto isHeard = [&] {
        const QStringList items = heard(s); // one list: begin and end of the same one
        return std::any_of(
            items.cbegin(), items.cend(), [&](const QString &i) { return i.startsWith(startsWith); });
    };
    QTRY_VERIFY2_WITH_TIMEOUT(isHeard(), qPrintable(u"heard: "_s + heard(s).join(u" | "_s)), 10000);
    for (int i = 0; i < combo->count(); ++i) {
        if (combo->itemText(i).startsWith(startsWith))
            combo->setCurrentIndex(i);
    }
}

} // namespace Toffee::Test
