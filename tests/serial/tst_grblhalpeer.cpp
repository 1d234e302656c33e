// SPDX-License-Identifier: GPL-3.0-or-later
// grblHAL itself (TOFFEE_GRBLHAL_PEER, set by .ci/run) read by Toffee's parsers: each step sends what a tool
// manager sends over a raw TCP socket and asserts what the parsers conclude from the real answers. The steps
// run in order on one controller, as an operator's session would. Skipped, and says so, without the peer.
#include <memory>

#include <QElapsedTimer>
#include <QHostAddress>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

#include "serial/grblhal/grblhalreplies.h"
#include "tests/support/grblhalpeer.h"

using namespace Toffee;
using namespace Toffee::GrblHal;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

// A blocking line client: a line out, the lines back until "ok" or "error:N" (ALARM:N does not end a line's
// answer: the probe that raised it is still answered with "ok").
class LineClient
{
public:
    bool connectTo(quint16 port)
    {
        m_socket.connectToHost(QHostAddress::LocalHost, port);
        return m_socket.waitForConnected(5000);
    }
    void close() { m_socket.abort(); }

    QByteArrayList command(const QByteArray &line, int limitMs = 10000)
    {
        m_socket.write(line + '\n');
        QByteArrayList answer;
        while (auto next = readLine(limitMs)) {
            answer << *next;
            if (endsCommand(*next))
                break;
        }
        return answer;
    }

    // "?" is a real-time byte: no line end, answered by one status report.
    std::optional<StatusReport> status(int limitMs = 5000)
    {
        m_socket.write("?");
        while (auto next = readLine(limitMs)) {
            if (classifyReply(*next).kind == ReplyKind::Status)
                return parseStatusReport(*next);
        }
        return std::nullopt;
    }

private:
    std::optional<QByteArray> readLine(int limitMs)
    {
        QElapsedTimer clock;
        clock.start();
        while (!m_socket.canReadLine()) {
            const qint64 left = limitMs - clock.elapsed();
            if (left <= 0 || !m_socket.waitForReadyRead(int(left)))
                return std::nullopt;
        }
        return m_socket.readLine().trimmed();
    }

    QTcpSocket m_socket;
};

std::optional<Reply> findKind(const QByteArrayList &lines, ReplyKind kind)
{
    for (const QByteArray &line : lines) {
        if (const Reply reply = classifyReply(line); reply.kind == kind)
            return reply;
    }
    return std::nullopt;
}

ParameterReport parameters(const QByteArrayList &lines)
{
    ParameterReport report;
    for (const QByteArray &line : lines)
        report.addLine(line);
    return report;
}

std::optional<ProbeReport> probeIn(const QByteArrayList &lines)
{
    for (const QByteArray &line : lines) {
        if (const auto probe = parseProbeReport(line))
            return probe;
    }
    return std::nullopt;
}

QByteArray joined(const QByteArrayList &lines)
{
    return lines.join(" / ");
}

} // namespace

class TestGrblHalPeer : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        if (GrblHalPeer::script().isEmpty())
            QSKIP(qPrintable(GrblHalPeer::skipReason()));
        QVERIFY(m_state.isValid());
        m_peer = std::make_unique<GrblHalPeer>(m_state.path());
        QVERIFY2(m_peer->started(), qPrintable(m_peer->errors()));
        qInfo("grblHAL answered %lld ms after its start", m_peer->startupMs());
        QVERIFY(m_client.connectTo(m_peer->port()));
    }

    void detectsGrblHalWithItsToolTable()
    {
        const QByteArrayList answer = m_client.command("$I");
        QVERIFY2(!answer.isEmpty() && answer.back() == "ok", joined(answer));
        BuildInfoBuilder builder;
        for (const QByteArray &line : answer)
            builder.addLine(line);
        QCOMPARE(builder.refusedLines(), 0);
        QVERIFY(builder.hasVersionAndOptions());
        QVERIFY(builder.info().isGrblHal());
        QCOMPARE(builder.info().toolTableSize, 16);
        QVERIFY(builder.info().toolChange);
        QCOMPARE(builder.info().axes, u"XYZ"_s);
    }

    void writesAToolIntoTheControllersTable()
    {
        QCOMPARE(m_client.command("G10 L1 P3 Z-12.345 R1.5"), QByteArrayList { "ok" });
        const QByteArrayList answer = m_client.command("$#");
        const ParameterReport report = parameters(answer);
        QCOMPARE(report.refusedLines, 0);
        QCOMPARE(report.tools.size(), size_t(16));
        QVERIFY2(report.tools.count(3), joined(answer));
        QCOMPARE(report.tools.at(3).offset.z(), -12.345);
        QCOMPARE(report.tools.at(3).radius, 1.5);
        QCOMPARE(report.workOffsets.size(), 12);
        QVERIFY(report.toolLengthOffset);
        QVERIFY(report.probe);
    }

    void probesAToolOnTheSetter()
    {
        QVERIFY(m_peer->writeSetter(-100.0, { { 1, 30.0 } }));
        QCOMPARE(m_client.command("M61 Q1"), QByteArrayList { "ok" });
        const QByteArrayList answer = m_client.command("G38.2 Z-120 F3000");
        QVERIFY2(!answer.isEmpty() && answer.back() == "ok", joined(answer));
        QVERIFY(!findKind(answer, ReplyKind::Alarm));
        const auto probe = probeIn(answer);
        QVERIFY2(probe, joined(answer));
        QVERIFY(probe->touched);
        QCOMPARE(probe->position.z(), -70.0); // the setter at -100, the tool 30 long
        const auto status = m_client.status();
        QVERIFY(status);
        QCOMPARE(status->state, State::Idle);
        QVERIFY(status->probeTriggered); // it stopped on the setter, a little past the contact
    }

    void aProbeThatMeetsNothingAlarmsUntilUnlocked()
    {
        QCOMPARE(m_client.command("G53 G0 Z0"), QByteArrayList { "ok" });
        QCOMPARE(m_client.command("M61 Q2"), QByteArrayList { "ok" }); // not in the setter file: length 0
        const QByteArrayList answer = m_client.command("G38.2 Z-50 F3000"); // the setter is at -100
        const auto alarm = findKind(answer, ReplyKind::Alarm);
        QVERIFY2(alarm, joined(answer));
        QCOMPARE(alarm->code, std::optional<int>(5));
        QVERIFY(alarmMeaning(*alarm->code).startsWith(u"Probe found nothing"_s));
        const auto probe = probeIn(answer);
        QVERIFY2(probe && !probe->touched, joined(answer));
        QCOMPARE(answer.back(), QByteArray("ok")); // the probing line is answered after its alarm

        const auto halted = m_client.status();
        QVERIFY(halted);
        QVERIFY(halted->isAlarm());

        const QByteArrayList refused = m_client.command("G53 G0 Z0");
        QCOMPARE(refused.size(), 1);
        const Reply error = classifyReply(refused.front());
        QCOMPARE(error.kind, ReplyKind::Error);
        QCOMPARE(error.code, std::optional<int>(9));
        QVERIFY(errorMeaning(9).contains(u"alarm"_s));

        const QByteArrayList unlocked = m_client.command("$X");
        QCOMPARE(unlocked.back(), QByteArray("ok"));
        const auto message = findKind(unlocked, ReplyKind::Message);
        QVERIFY2(message, joined(unlocked));
        QCOMPARE(parseMessage(unlocked.front()), std::optional<QString>(u"Caution: Unlocked"_s));
        const auto free = m_client.status();
        QVERIFY(free);
        QCOMPARE(free->state, State::Idle);
        QCOMPARE(m_client.command("G53 G0 Z0"), QByteArrayList { "ok" });
    }

    // grblHAL reports WCO and T when they change (and every few reports): the first report after G43 H3 has
    // them.
    void theStatusReportShowsTheToolAndItsOffset()
    {
        QCOMPARE(m_client.command("M61 Q3"), QByteArrayList { "ok" });
        QCOMPARE(m_client.command("G43 H3"), QByteArrayList { "ok" });
        std::optional<int> tool;
        std::optional<AxisValues> wco;
        for (int i = 0; i < 40 && (!tool || !wco); ++i) {
            const auto status = m_client.status();
            QVERIFY(status);
            if (status->tool)
                tool = status->tool;
            if (status->workCoordinateOffset)
                wco = status->workCoordinateOffset;
        }
        QCOMPARE(tool, std::optional<int>(3));
        QVERIFY(wco);
        QCOMPARE(wco->z(), -12.345);
        const ParameterReport report = parameters(m_client.command("$#"));
        QVERIFY(report.toolLengthOffset);
        QCOMPARE(report.toolLengthOffset->z(), -12.345);
    }

    // Switched off and on with its EEPROM kept: the controller forgets the tool in the spindle and its offset
    // in force, and keeps its tool table (and work offsets) as the machine does: what `restore` is for. The
    // restore is M61 and G43 H from the table grblHAL kept, nothing probed.
    void aRestartWithItsStateKeepsTheTableAndARestorePutsTheToolBackInForce()
    {
        QCOMPARE(m_client.command("G10 L2 P1 X1.5 Y2.5 Z-3.25"), QByteArrayList { "ok" });
        m_client.close();
        m_peer.reset();
        m_peer = std::make_unique<GrblHalPeer>(m_state.path());
        QVERIFY2(m_peer->started(), qPrintable(m_peer->errors()));
        QVERIFY(m_client.connectTo(m_peer->port()));
        const QByteArrayList answer = m_client.command("$#");
        const ParameterReport report = parameters(answer);
        QCOMPARE(report.refusedLines, 0);
        QVERIFY(report.toolLengthOffset);
        QCOMPARE(report.toolLengthOffset->z(), 0.0); // nothing in force
        QVERIFY2(report.tools.count(3), joined(answer));
        QCOMPARE(report.tools.at(3).offset.z(), -12.345); // the table kept
        QCOMPARE(report.tools.at(3).radius, 1.5);
        QVERIFY2(answer.contains("[G54:1.500,2.500,-3.250]"), joined(answer));
        QVERIFY(m_client.command("$G").front().contains(" T0 ")); // no tool in the spindle

        QCOMPARE(m_client.command("M61 Q3"), QByteArrayList { "ok" });
        QCOMPARE(m_client.command("G43 H3"), QByteArrayList { "ok" });
        const ParameterReport restored = parameters(m_client.command("$#"));
        QVERIFY(restored.toolLengthOffset);
        QCOMPARE(restored.toolLengthOffset->z(), -12.345);
        QVERIFY(m_client.command("$G").front().contains(" T3 "));
    }

    void cleanupTestCase()
    {
        m_client.close();
        m_peer.reset();
    }

private:
    QTemporaryDir m_state;
    std::unique_ptr<GrblHalPeer> m_peer;
    LineClient m_client;
};

QTEST_GUILESS_MAIN(TestGrblHalPeer)
#include "tst_grblhalpeer.moc"
