// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/selftest.h"

#include <QImage>
#include <QPixmap>

#include "model/document/tooldocument.h"
#include "model/numberformat.h"
#include "serial/machineconnection.h"
#include "ui/machine/machinedock.h"
#include "ui/machine/probepanel.h"
#include "ui/shell/mainwindow.h"

using namespace Qt::StringLiterals;

namespace Toffee {

SelfTest::SelfTest(MainWindow *window, std::function<void(int, const QString &)> finished, QObject *parent)
    : QObject(parent)
    , m_window(window)
    , m_finished(std::move(finished))
{
    m_watchdog.setSingleShot(true);
    connect(&m_watchdog, &QTimer::timeout, this, [this] { fail(tr("no progress within 20 s")); });
}

void SelfTest::step(const QString &what)
{
    m_step = what;
    m_watchdog.start(20000);
}

void SelfTest::fail(const QString &reason)
{
    if (m_done)
        return;
    m_done = true;
    m_watchdog.stop();
    m_finished(1, tr("self-test failed while %1: %2").arg(m_step, reason));
}

void SelfTest::start(const QElapsedTimer &sinceLaunch)
{
    step(tr("showing the window"));
    m_window->show();
    const QImage frame = m_window->grab().toImage();
    m_firstFrameMs = sinceLaunch.elapsed();
    if (frame.isNull() || frame.width() < 100)
        return fail(tr("the window did not render"));

    step(tr("loading the example table"));
    if (!m_window->openFile(u":/examples/example.json"_s))
        return fail(tr("the example table did not load"));

    step(tr("connecting to the built-in emulator"));
    MachineConnection *connection = m_window->connection();
    connect(connection, &MachineConnection::connectFailed, this, [this](const QString &m) { fail(m); });
    connect(
        connection, &MachineConnection::stateChanged, this, [this, connection](MachineConnection::State s) {
            if (s != MachineConnection::State::Connected || m_done)
                return;
            step(tr("probing the current tool"));
            ProbePanel *probe = m_window->machineDock()->probePanel();
            connect(probe, &ProbePanel::finished, this, [this](const SessionResult &r) {
                if (!r.ok())
                    return fail(r.message);
                const auto tool = m_window->document()->table().storedTlo(r.tool.value_or(-1));
                if (!tool || std::fabs(tool->tlo - r.tlo->tlo()) > 1e-9)
                    return fail(tr("the measurement did not reach the table"));
                step(tr("rendering"));
                if (m_window->grab().isNull())
                    return fail(tr("the window did not render"));
                m_done = true;
                m_watchdog.stop();
                m_finished(0,
                    tr("self-test passed: first frame after %1 ms; T%2 probed, TLO %3 mm recorded")
                        .arg(m_firstFrameMs)
                        .arg(r.tool.value_or(-1))
                        .arg(millimetres(r.tlo->tlo(), false)));
            });
            probe->probe(false);
        });
    connection->connectTo(ConnectionTarget {});
}

} // namespace Toffee
