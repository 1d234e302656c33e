// SPDX-License-Identifier: GPL-3.0-or-later
// Makera CAM's tool header in a G-code program (model/camimport/makeraheader.cpp).
#include <csignal>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <QFile>
#include <QTest>

#include "model/camimport/camreaders.h"
#include "tests/support/camfiles.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

// AddressSanitizer reserves terabytes of address space and keeps what is freed a while: the limit is left out
// under it.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kLimitMemory = false;
#else
constexpr bool kLimitMemory = true;
#endif

// The address space this process has now (VmSize), in bytes.
qint64 addressSpace()
{
    QFile status(u"/proc/self/status"_s);
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n')) {
        if (line.startsWith("VmSize:"))
            return line.mid(7).trimmed().split(' ').value(0).toLongLong() * 1024;
    }
    return -1;
}

} // namespace

class TestMakeraHeader : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void readsEachToolLineOfTheHeader()
    {
        const QByteArray program = Test::makeraProgram(
            { Test::makeraTool(3), Test::makeraTool(1, "diameter=6|flutelength=22|colour=blue|oddfield") });
        const auto read = readMakeraHeader(program);
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().size(), 2);
        const CamTool &t3 = read.value().at(0);
        QCOMPARE(t3.number, 3);
        QCOMPARE(t3.description, u"Flat 3"_s);
        QCOMPARE(t3.type, u"flat end mill"_s);
        QCOMPARE(t3.units, Units::Millimetre);
        QCOMPARE(t3.diameter, 3.175);
        QCOMPARE(t3.fluteLength, 12.0);
        QCOMPARE(t3.stickOut, 18.0);
        QCOMPARE(t3.overallLength, std::nullopt);
        QCOMPARE(t3.line, 3);
        QCOMPARE(read.value().at(1).diameter, 6.0);
        QCOMPARE(read.value().at(1).line, 4);
    }

    void readsOnlyTheHeader()
    {
        // A tool line after the first G-code line is part of the program, not of its header.
        QByteArray program
            = Test::makeraProgram({ Test::makeraTool(3) }, "G21\n" + Test::makeraTool(9) + "\n");
        program.replace('\n', "\r\n");
        const auto read = readMakeraHeader(program);
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().size(), 1);
        QCOMPARE(read.value().front().number, 3);
        QCOMPARE(read.value().front().description, u"Flat 3"_s);
    }

    void refusesAMalformedHeaderWhole_data()
    {
        QTest::addColumn<QByteArray>("program");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("message");
        QTest::newRow("number=abc") << Test::makeraProgram(
            { Test::makeraTool(3), ";@MKR|TOOL|number=abc|name=x|diameter=3" })
                                    << 4 << u"number=abc is not a tool number."_s;
        QTest::newRow("diameter=abc") << Test::makeraProgram({ Test::makeraTool(3, "diameter=abc") }) << 3
                                      << u"diameter=abc is not a number."_s;
        QTest::newRow("diameter=nan") << Test::makeraProgram({ Test::makeraTool(3, "diameter=nan") }) << 3
                                      << u"diameter=nan is not a number."_s;
        QTest::newRow("negative") << Test::makeraProgram({ Test::makeraTool(3, "diameter=-1") }) << 3
                                  << u"T3: the diameter is -1 mm; it cannot be negative."_s;
        QTest::newRow("no number") << Test::makeraProgram({ ";@MKR|TOOL|name=x|diameter=3" }) << 3
                                   << u"no number="_s;
        QTest::newRow("number out of range") << Test::makeraProgram({ Test::makeraTool(1234567) }) << 3
                                             << u"tool number 1234567 is out of range"_s;
        QTest::newRow("repeated") << Test::makeraProgram({ Test::makeraTool(3), Test::makeraTool(3) }) << 4
                                  << u"number 3 is taken already (line 3)"_s;
        QTest::newRow("no header") << "G21\nG0 X0 Y0\n"_ba << 0 << u"no Makera CAM tool header"_s;
        QTest::newRow("empty") << QByteArray() << 0 << u"no Makera CAM tool header"_s;
        QTest::newRow("binary") << QByteArray("\x7f"
                                              "ELF\x02\x01\x01\0\0\0",
            10) << 1 << u"this is not a text program"_s;
        QTest::newRow("NUL bytes") << QByteArray(1000, '\0') << 1 << u"this is not a text program"_s;
        QTest::newRow("NUL after the header") << Test::makeraProgram({ Test::makeraTool(3) },
            QByteArray(64, '\0')) << 5 << u"this is not a text program"_s;
        QTest::newRow("number twice") << Test::makeraProgram({ ";@MKR|TOOL|number=9|number=10|diameter=2" })
                                      << 3 << u"number is in this tool line twice (number=9 and number=10)"_s;
        QTest::newRow("diameter twice")
            << Test::makeraProgram({ Test::makeraTool(3), Test::makeraTool(4, "diameter=2|diameter=3") }) << 4
            << u"diameter is in this tool line twice (diameter=2 and diameter=3)"_s;
    }
    void refusesAMalformedHeaderWhole()
    {
        QFETCH(QByteArray, program);
        QFETCH(int, line);
        QFETCH(QString, message);
        const auto read = readMakeraHeader(program);
        QVERIFY2(!read.ok(), "the header was read");
        QVERIFY2(read.error().message.contains(message), qPrintable(read.error().message));
        QCOMPARE(read.error().line, line);
    }

    void anUnknownFieldMayRepeat()
    {
        const auto read
            = readMakeraHeader(Test::makeraProgram({ Test::makeraTool(3, "x=1|x=2|diameter=2") }));
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().front().diameter, 2.0);
    }

    void zerosPastWhatWasReadAreNoTextProgram()
    {
        // Four megabytes of NUL bytes have no line end, but they are not "all comments" either.
        const auto read = readMakeraHeader(QByteArray(4096, '\0'), false);
        QVERIFY(!read.ok());
        QVERIFY2(read.error().message.startsWith(u"this is not a text program"_s),
            qPrintable(read.error().message));
        QCOMPARE(read.error().line, 1);
    }

    // A tool line is read a field at a time: a line of 4 MB of empty fields is read in a child whose address
    // space may grow by 16 MB (split into a list first, it took 64 MB).
    void readsALineOfManyFieldsInBoundedMemory()
    {
        const QByteArray program
            = Test::makeraProgram({ ";@MKR|TOOL|number=1" + QByteArray(kMaxProgramHeaderBytes - 1024, '|') });
        const qint64 limit = addressSpace() + 16LL * 1024 * 1024;
        const pid_t child = fork();
        QVERIFY(child >= 0);
        if (child == 0) {
            std::signal(SIGABRT, SIG_DFL); // an abort ends the child quietly, not through QTest's handler
            const rlimit rl { rlim_t(limit), rlim_t(limit) };
            if (kLimitMemory && setrlimit(RLIMIT_AS, &rl) != 0)
                _exit(3);
            try {
                const auto read = readMakeraHeader(program);
                _exit(read.ok() && read.value().size() == 1 ? 0 : 1);
            } catch (...) { // std::bad_alloc: QTest would catch it, and the child would run on as a test
                _exit(4);
            }
        }
        int status = 0;
        QCOMPARE(waitpid(child, &status, 0), child);
        QVERIFY2(WIFEXITED(status), "the reader crashed");
        QVERIFY2(WEXITSTATUS(status) != 4, "the reader ran out of memory");
        QCOMPARE(WEXITSTATUS(status), 0);
    }

    void refusesAHeaderThatRunsPastWhatWasRead()
    {
        const QByteArray head = Test::makeraProgram({ Test::makeraTool(3) }, ";" + QByteArray(100, 'x'));
        const auto read = readMakeraHeader(head, false);
        QVERIFY(!read.ok());
        QVERIFY2(read.error().message.contains(u"all comments"_s), qPrintable(read.error().message));
    }
};

QTEST_GUILESS_MAIN(TestMakeraHeader)
#include "tst_makeraheader.moc"
