// SPDX-License-Identifier: GPL-3.0-or-later
// The Rack panel stopped part-way, in the real window against the built-in emulator: Cancel lets the tool in
// hand finish, a Stop in the middle of a change says to look before Unlock; neither records what was not
// measured, and nothing hangs.
#include <QProgressBar>
#include <QSettings>
#include <QStandardPaths>

#include "tests/support/rackstation.h"
#include "ui/rack/rackpanel.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Toffee::Test::answerNextBox;
using Toffee::Test::RackStation;

namespace {

constexpr int kLongWaitMs = 30000; // generous for sanitizer builds

} // namespace

class TestRackPanelStops : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(u"ToffeeTest"_s);
        QApplication::setApplicationName(u"tst_rackpanelstops"_s);
    }

    void init() { QSettings().clear(); }

    void cancelLetsTheCurrentToolFinishThenStops()
    {
        RackStation s;
        s.connect();
        s.machine()->setTiming({ 300, 0, 300 });
        answerNextBox(QMessageBox::Yes);
        s.click(u"rackMeasureButton"_s);
        QVERIFY(QTest::qWaitFor(
            [&s] { return s.rackCell(1, RackPanel::ResultColumn) == u"Measuring…"_s; }, kLongWaitMs));
        s.click(u"rackCancelButton"_s);
        QCOMPARE(s.find<QPushButton>(u"rackCancelButton"_s)->text(), u"Stopping after this tool…"_s);
        QVERIFY(s.window.connection()->isBusy()); // T2 is still being measured
        QVERIFY(QTest::qWaitFor([&s] { return s.idle(); }, kLongWaitMs));
        QCOMPARE(s.column(RackPanel::ResultColumn).mid(2), QStringList(4, u"Not run"_s));
        QVERIFY(s.rackCell(0, RackPanel::ResultColumn).startsWith(u"Measured: "_s));
        QVERIFY(s.rackCell(1, RackPanel::ResultColumn).startsWith(u"Measured: "_s));
        QVERIFY2(s.text(u"rackResultLabel"_s).contains(u"Not run: T3, T4, T5, T6."_s),
            qPrintable(s.text(u"rackResultLabel"_s)));
        QVERIFY(s.table().find(2) && s.table().find(2)->measuredTlo);
        QVERIFY(!s.table().find(3));
        QVERIFY(!s.machine()->isHalted());
        QVERIFY(!s.find<QProgressBar>(u"rackProgress"_s)->isVisible());
        QVERIFY(s.find<QPushButton>(u"rackMeasureButton"_s)->isEnabled()); // nothing hangs
    }

    void aStopInTheMiddleOfAChangeSaysToLook()
    {
        RackStation s;
        s.connect();
        s.machine()->setTiming({ 300, 0, 2000 });
        answerNextBox(QMessageBox::Yes);
        s.click(u"rackMeasureButton"_s);
        // T1 is measured where it is; T2's change takes its time, and the operator stops the machine in it.
        QVERIFY(QTest::qWaitFor([&s] { return s.sent.contains("M6 T2"); }, kLongWaitMs));
        QString warning;
        answerNextBox(QMessageBox::Ok, &warning);
        s.window.connection()->stop();
        QVERIFY(QTest::qWaitFor([&s] { return s.idle(); }, kLongWaitMs));
        QVERIFY(s.machine()->isHalted());
        QVERIFY2(warning.contains(u"stopped during T2's step"_s) && warning.contains(u"before you Unlock"_s),
            qPrintable(warning));
        QCOMPARE(s.rackCell(1, RackPanel::ResultColumn).left(6), u"Failed"_s);
        QVERIFY(!s.table().find(2) || !s.table().find(2)->measuredTlo); // nothing recorded for T2
    }
};

QTEST_MAIN(TestRackPanelStops)
#include "tst_rackpanelstops.moc"
