// SPDX-License-Identifier: GPL-3.0-or-later
#include <QSignalSpy>
#include <QTest>

#include "linetransport.h"
#include "machinelink.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

// A transport the test speaks for: every line the link writes is recorded; the test answers by hand.
class ScriptedTransport final : public LineTransport
{
public:
    QList<QByteArray> written;
    QByteArray realtime;
    bool open_ = false;

    void open() override
    {
        open_ = true;
        QMetaObject::invokeMethod(this, &LineTransport::opened, Qt::QueuedConnection);
    }
    void close() override
    {
        if (!open_)
            return;
        open_ = false;
        Q_EMIT closed();
    }
    bool isOpen() const override { return open_; }
    void writeLine(const QByteArray &line) override { written.append(line); }
    void writeRealtime(char c) override { realtime += c; }
    QString description() const override { return u"scripted"_s; }
    void reply(const QByteArray &line) { Q_EMIT lineReceived(line); }
};

struct Fixture
{
    ScriptedTransport transport;
    MachineLink link { &transport };
    QList<CommandReply> replies;

    Fixture()
    {
        link.setPollInterval(0);
        link.open();
        if (!QTest::qWaitFor([this] { return link.isOpen(); }))
            qFatal("the scripted link did not open");
    }
    void send(const QByteArray &line, int timeoutMs = 5000)
    {
        link.send(line, timeoutMs, [this](const CommandReply &r) { replies.append(r); });
    }
};

} // namespace

class TestMachineLink : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void matchesTheTerminatorByExactToken()
    {
        Fixture f;
        f.send("M493.4");
        QCOMPARE(f.transport.written, QList<QByteArray> { "M493.4" });
        f.transport.reply("okay then");
        f.transport.reply("Probe ok");
        f.transport.reply("current tool offset [1] , reference tool offset [0]");
        QVERIFY(f.replies.isEmpty()); // none of those ended the command
        f.transport.reply("ok");
        QCOMPARE(f.replies.size(), 1);
        QVERIFY(f.replies.front().ok());
        QCOMPARE(f.replies.front().lines.size(), 3);
    }

    void sendsOneCommandAtATime()
    {
        Fixture f;
        f.send("G90");
        f.send("M493.4");
        QCOMPARE(f.transport.written.size(), 1);
        f.transport.reply("ok");
        QTRY_COMPARE(f.transport.written.size(), 2);
        f.transport.reply("error:Alarm lock");
        QCOMPARE(f.replies.size(), 2);
        QCOMPARE(f.replies.at(1).status, CommandReply::Status::Refused);
        QVERIFY(f.replies.at(1).message.contains(u"\"M493.4\": Alarm lock"_s));
    }

    void aStatusReportIsNotPartOfTheCommand()
    {
        Fixture f;
        QSignalSpy status(&f.link, &MachineLink::statusChanged);
        f.send("G90");
        f.transport.reply("<Idle|MPos:0,0,-2,0,0|WPos:0,0,57,0,0|T:2,-33.388,-1,0>");
        f.transport.reply("ok");
        QCOMPARE(status.size(), 1);
        QVERIFY(f.replies.front().lines.isEmpty());
        QCOMPARE(f.link.lastStatus()->tlo.value_or(0), -33.388);
        QVERIFY(f.link.statusAgeMs() >= 0);
    }

    void anAlarmFailsTheCommandEvenWithOk()
    {
        Fixture f;
        f.send("M491");
        f.transport.reply("ALARM: Probe failed to trigger within safety margin (135.00mm)");
        f.transport.reply("ok");
        QCOMPARE(f.replies.size(), 1);
        QCOMPARE(f.replies.front().status, CommandReply::Status::Halted);
        QVERIFY(f.replies.front().message.contains(u"Probe failed to trigger"_s));
    }

    void anAlarmWithoutTerminatorEndsTheCommandAfterAGrace()
    {
        Fixture f;
        f.link.setTimeoutScale(0.05);
        f.send("M491", 60000);
        f.transport.reply("ALARM: Abort during cycle");
        QTRY_COMPARE_WITH_TIMEOUT(f.replies.size(), 1, 2000);
        QCOMPARE(f.replies.front().status, CommandReply::Status::Halted);
        QVERIFY(f.link.isOpen());
    }

    void aTimeoutFailsEverythingAndClosesTheLink()
    {
        Fixture f;
        QSignalSpy closed(&f.link, &MachineLink::closed);
        f.send("G90", 50);
        f.send("M493.4", 50);
        QTRY_COMPARE_WITH_TIMEOUT(f.replies.size(), 2, 2000);
        QCOMPARE(f.replies.at(0).status, CommandReply::Status::Timeout);
        QVERIFY(f.replies.at(0).message.contains(u"did not answer \"G90\""_s));
        QCOMPARE(f.replies.at(1).status, CommandReply::Status::Timeout);
        QVERIFY(!f.link.isOpen());
        QCOMPARE(closed.size(), 1);
        f.transport.reply("ok"); // a late answer is matched to nothing
        QCOMPARE(f.replies.size(), 2);
    }

    void aLostPortFailsThePendingCommands()
    {
        Fixture f;
        f.send("M491", 60000);
        f.send("M493.4");
        Q_EMIT f.transport.errorOccurred(u"The port /dev/ttyACM0 went away"_s);
        f.transport.close();
        QCOMPARE(f.replies.size(), 2);
        QCOMPARE(f.replies.at(0).status, CommandReply::Status::LinkLost);
        QVERIFY(f.replies.at(0).message.contains(u"went away"_s));
        QCOMPARE(f.replies.at(1).status, CommandReply::Status::LinkLost);
    }

    void sendingWhileClosedFailsAtOnce()
    {
        ScriptedTransport transport;
        MachineLink link(&transport);
        std::optional<CommandReply> reply;
        link.send("G90", 1000, [&](const CommandReply &r) { reply = r; });
        QTRY_VERIFY(reply.has_value());
        QCOMPARE(reply->status, CommandReply::Status::LinkLost);
        QVERIFY(transport.written.isEmpty());
    }

    void pollsTheStatusAsRealtimeTraffic()
    {
        ScriptedTransport transport;
        MachineLink link(&transport);
        link.open();
        QTRY_VERIFY(transport.realtime.count('?') >= 2); // about every 200 ms
        QVERIFY(transport.written.isEmpty()); // never as a command line
    }
};

QTEST_GUILESS_MAIN(TestMachineLink)
#include "tst_machinelink.moc"
