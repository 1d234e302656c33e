// SPDX-License-Identifier: GPL-3.0-or-later
#include <optional>

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include "serial/carvera/carverareplies.h"
#include "serial/machine/machinelink.h"
#include "serial/transport/linetransport.h"

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
        link.setGrammar(carveraGrammar());
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

    // A quiet line (a status question; a password in it) is written as given but never said as sent, and
    // every message names it as it is shown: a timeout's, a refusal's, a reply's.
    void aQuietLineIsWrittenButNeverShown()
    {
        Fixture f;
        QSignalSpy sent(&f.link, &MachineLink::lineSent);
        std::optional<CommandReply> refused;
        f.link.sendQuietly(
            "set enable secret", 5000, [&refused](const CommandReply &r) { refused = r; }, ReplyEnd::Ok,
            "set enable …");
        QCOMPARE(f.transport.written.last(), QByteArray("set enable secret"));
        QVERIFY(f.link.isQuiet());
        f.transport.reply("error:Unsupported command");
        QTRY_VERIFY(refused.has_value());
        QCOMPARE(refused->command, QByteArray("set enable …"));
        QVERIFY2(!refused->message.contains(u"secret"_s) && refused->message.contains(u"set enable …"_s),
            qPrintable(refused->message));
        std::optional<CommandReply> late;
        f.link.sendQuietly(
            "set enable secret", 50, [&late](const CommandReply &r) { late = r; }, ReplyEnd::Ok,
            "set enable …");
        QTRY_VERIFY(late.has_value());
        QCOMPARE(late->status, CommandReply::Status::Timeout);
        QVERIFY2(!late->message.contains(u"secret"_s), qPrintable(late->message));
        QCOMPARE(sent.size(), 0);
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
        link.setGrammar(carveraGrammar());
        std::optional<CommandReply> reply;
        link.send("G90", 1000, [&](const CommandReply &r) { reply = r; });
        QTRY_VERIFY(reply.has_value());
        QCOMPARE(reply->status, CommandReply::Status::LinkLost);
        QVERIFY(transport.written.isEmpty());
    }

    // A limit is a promise to wait that long: a coarse timer fires up to 5 % early.
    void aTimedOutCommandNeverEndsBeforeItsLimit()
    {
        constexpr int kLinks = 16;
        std::vector<std::unique_ptr<Fixture>> fixtures;
        QList<int> limits;
        QList<qint64> endedAfter(kLinks, -1);
        for (int i = 0; i < kLinks; ++i) {
            fixtures.push_back(std::make_unique<Fixture>());
            limits.append(900 + 61 * i); // limits a coarse timer would round to its own boundaries
            auto clock = std::make_shared<QElapsedTimer>();
            clock->start();
            fixtures.back()->link.send("G4 P100", limits.last(),
                [&endedAfter, clock, i](const CommandReply &) { endedAfter[i] = clock->elapsed(); });
        }
        QTRY_VERIFY_WITH_TIMEOUT(!endedAfter.contains(-1), 10000);
        for (int i = 0; i < kLinks; ++i) {
            QCOMPARE(fixtures.at(i)->replies.size(), 0);
            QVERIFY2(endedAfter.at(i) >= limits.at(i),
                qPrintable(u"a %1 ms limit ended after %2 ms"_s.arg(limits.at(i)).arg(endedAfter.at(i))));
        }
    }

    // A machine that prints without end while a command runs: the reply keeps the last lines, and counts
    // the rest.
    void aReplyKeepsABoundedTail()
    {
        Fixture f;
        f.send("M491", 60000);
        constexpr int kFlood = 100000;
        for (int i = 0; i < kFlood; ++i)
            f.transport.reply("noise " + QByteArray::number(i));
        f.transport.reply("[PRB:-88.000,-9.000,-105.688:1]");
        f.transport.reply("ok");
        QCOMPARE(f.replies.size(), 1);
        const CommandReply &reply = f.replies.front();
        QVERIFY(reply.ok());
        QCOMPARE(reply.lines.size(), MachineLink::kMaxReplyLines);
        QCOMPARE(reply.droppedLines, kFlood + 1 - MachineLink::kMaxReplyLines);
        QCOMPARE(reply.lines.last(), QByteArray("[PRB:-88.000,-9.000,-105.688:1]"));
        QCOMPARE(
            reply.lines.first(), "noise " + QByteArray::number(kFlood + 1 - MachineLink::kMaxReplyLines));

        f.send("M493.4"); // the next command starts from nothing
        f.transport.reply("current tool offset [1] , reference tool offset [0]");
        f.transport.reply("ok");
        QTRY_COMPARE(f.replies.size(), 2);
        QCOMPARE(f.replies.at(1).lines.size(), 1);
        QCOMPARE(f.replies.at(1).droppedLines, 0);
    }

    void aFloodIsCountedInTheTimeoutMessage()
    {
        Fixture f;
        f.send("M491", 200);
        for (int i = 0; i < 1000; ++i)
            f.transport.reply("noise");
        QTRY_COMPARE_WITH_TIMEOUT(f.replies.size(), 1, 3000);
        QCOMPARE(f.replies.front().status, CommandReply::Status::Timeout);
        QVERIFY2(f.replies.front().message.contains(u"printed 1000 lines"_s),
            qPrintable(f.replies.front().message));
        QVERIFY(f.replies.front().message.contains(u"last 256"_s));
    }

    // 100 KB of "error:" text is a refusal; the message quotes the start of it, not all of it.
    void aLongRefusalIsQuotedShort()
    {
        Fixture f;
        f.send("M493.4");
        f.transport.reply("error:" + QByteArray(4090, 'e'));
        QCOMPARE(f.replies.size(), 1);
        QCOMPARE(f.replies.front().status, CommandReply::Status::Refused);
        QVERIFY(f.replies.front().message.size() < 300);
    }

    void pollsTheStatusAsRealtimeTraffic()
    {
        ScriptedTransport transport;
        MachineLink link(&transport);
        link.setGrammar(carveraGrammar());
        link.open();
        QTRY_VERIFY(transport.realtime.count('?') >= 2); // about every 200 ms
        QVERIFY(transport.written.isEmpty()); // never as a command line
    }
};

QTEST_GUILESS_MAIN(TestMachineLink)
#include "tst_machinelink.moc"
