// SPDX-License-Identifier: GPL-3.0-or-later
// The Rack panel driven as an operator drives it, in the real window, against the built-in emulator: what the
// panel shows, what the table holds and what the history keeps after each step.
#include <algorithm>
#include <cmath>

#include <QCheckBox>
#include <QGroupBox>
#include <QLineEdit>
#include <QProgressBar>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>

#include "model/numberformat.h"
#include "tests/support/rackstation.h"
#include "ui/common/appsettings.h"
#include "ui/rack/rackpanel.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Toffee::Test::answerBoxNamed;
using Toffee::Test::answerNextBox;
using Toffee::Test::RackStation;

namespace {

constexpr int kLongWaitMs = 30000; // sequences of six tool changes; generous for sanitizer builds

} // namespace

class TestRackPanel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(u"ToffeeTest"_s);
        QApplication::setApplicationName(u"tst_rackpanel"_s);
    }

    void init()
    {
        QSettings().clear(); // each story starts from the defaults: rack 1-6, tolerance 0.1, option off
    }

    void anOperatorMeasuresChecksAndLoadsThroughTheRack()
    {
        RackStation s;
        QCOMPARE(s.text(u"rackSpindleLabel"_s), u"Spindle: unknown"_s);
        QVERIFY(!s.find<QPushButton>(u"rackMeasureButton"_s)->isEnabled());
        QVERIFY(!s.find<QAction>(u"actionMeasureRack"_s)->isEnabled()); // Machine ▸ Rack follows the panel
        QVERIFY(!s.find<QAction>(u"actionCheckRack"_s)->isEnabled());
        s.connect();
        QVERIFY(s.find<QAction>(u"actionMeasureRack"_s)->isEnabled());
        QCOMPARE(s.text(u"rackSpindleLabel"_s), u"Spindle: T1"_s);
        QCOMPARE(s.text(u"rackFirmwareLabel"_s), u"Community firmware 2.1.0c-emulator"_s);
        QCOMPARE(s.find<QLineEdit>(u"rackHoldsEdit"_s)->text(), u"1-6"_s);
        QCOMPARE(s.column(RackPanel::ToolColumn),
            QStringList({ u"T1 · in spindle"_s, u"T2"_s, u"T3"_s, u"T4"_s, u"T5"_s, u"T6"_s }));
        QCOMPARE(s.column(RackPanel::MeasuredColumn), QStringList(6, u"never"_s)); // a new table
        // Nothing to compare with yet: Check Rack says so instead of running.
        QVERIFY(!s.find<QPushButton>(u"rackCheckButton"_s)->isEnabled());
        QVERIFY(s.find<QPushButton>(u"rackCheckButton"_s)->toolTip().contains(u"Measure Rack"_s));

        // Each step asserts what the operator sees; a failed one ends the story there.
        for (auto step : { &TestRackPanel::measureTheRack, &TestRackPanel::checkTheRackWithABrokenTool,
                 &TestRackPanel::replaceTheBrokenToolAndLoadIt,
                 &TestRackPanel::loadAManualToolWithItsStoredTlo, &TestRackPanel::emptyTheSpindle }) {
            (this->*step)(s);
            if (QTest::currentTestFailed())
                return;
        }
    }

    void aRackThatDoesNotParseSaysWhyAndOffersNothing()
    {
        RackStation s;
        s.connect();
        auto *holds = s.find<QLineEdit>(u"rackHoldsEdit"_s);
        holds->selectAll();
        QTest::keyClicks(holds, u"1-x"_s);
        QTest::keyClick(holds, Qt::Key_Tab);
        QVERIFY(!s.text(u"rackHoldsError"_s).isEmpty());
        QCOMPARE(s.rackTable()->rowCount(), 0);
        for (const auto &button : { u"rackLoadButton"_s, u"rackMeasureButton"_s, u"rackCheckButton"_s })
            QVERIFY(!s.find<QPushButton>(button)->isEnabled());
        QCOMPARE(AppSettings().jobRack(), u"1-6"_s); // not remembered
        holds->selectAll();
        QTest::keyClicks(holds, u"1,2,5-6"_s);
        QTest::keyClick(holds, Qt::Key_Return);
        QCOMPARE(s.column(RackPanel::ToolColumn),
            QStringList({ u"T1 · in spindle"_s, u"T2"_s, u"T5"_s, u"T6"_s }));
        QCOMPARE(AppSettings().jobRack(), u"1,2,5-6"_s); // the job check's rack too
    }

    void theStockFirmwareHidesWhatItCannotDo()
    {
        RackStation s;
        ConnectionTarget stock;
        stock.emulatorStock = true;
        s.window.connection()->connectTo(stock);
        QVERIFY(QTest::qWaitFor(
            [&s] { return s.window.connection()->state() == MachineConnection::State::Connected; }));
        QVERIFY(s.find<QGroupBox>(u"breakTestGroup"_s)->isHidden());
        QVERIFY(s.find<QGroupBox>(u"offsetsGroup"_s)->isHidden());
        QVERIFY(!s.find<QLabel>(u"firmwareLimitsLabel"_s)->isHidden());
        QCOMPARE(s.text(u"firmwareLimitsLabel"_s),
            u"Makera stock firmware 1.0.1: no break test (its M491.1 only re-measures) and no manual offset "
            u"(it "
            "ignores M493.3)."_s);
        QCOMPARE(s.text(u"rackFirmwareLabel"_s), u"Makera stock firmware 1.0.1 — no break test"_s);
        QVERIFY(!s.find<QAction>(u"actionBreakTest"_s)->isEnabled());
        auto *check = s.find<QPushButton>(u"rackCheckButton"_s);
        QVERIFY(!check->isEnabled());
        QVERIFY2(check->toolTip().contains(u"would pass a broken tool"_s), qPrintable(check->toolTip()));
        QVERIFY(s.find<QPushButton>(u"rackMeasureButton"_s)->isEnabled()); // measuring is the same on both
        QVERIFY(!s.find<QAction>(u"actionCheckRack"_s)->isEnabled());
        // Measured there (from the Machine menu, as from the panel), the TLO comes from the status report
        // alone: the strip claims no MCS Z.
        answerNextBox(QMessageBox::Yes);
        s.trigger(u"actionMeasureRack"_s);
        QVERIFY(QTest::qWaitFor([&s] { return s.idle(); }, kLongWaitMs));
        QCOMPARE(s.rackCell(1, RackPanel::StoredColumn), u"9.652"_s);
        QVERIFY(!s.table().find(2)->referenceMz);
        QCOMPARE(s.text(u"referenceMzLabel"_s), u"not reported"_s);
        QCOMPARE(s.text(u"currentMzLabel"_s), u"not reported"_s);
        QCOMPARE(s.text(u"tloLabel"_s), u"20.340 mm"_s); // T6's, the last measured

        s.window.connection()->disconnectFromMachine();
        QVERIFY(!s.find<QGroupBox>(u"breakTestGroup"_s)->isHidden());
        QVERIFY(!s.find<QGroupBox>(u"offsetsGroup"_s)->isHidden());
        QVERIFY(s.find<QLabel>(u"firmwareLimitsLabel"_s)->isHidden());
        QCOMPARE(s.text(u"rackSpindleLabel"_s), u"Spindle: unknown"_s);
    }

private:
    void measureTheRack(RackStation &s)
    {
        QString question;
        answerNextBox(QMessageBox::Yes, &question);
        s.click(u"rackMeasureButton"_s);
        QVERIFY2(question.contains(u"T1, T2, T3, T4, T5, T6"_s) && question.contains(u"Keep clear"_s),
            qPrintable(question));
        // The machine's reference is its calibration: no tool "becomes" it, and the question says nothing of
        // it.
        QVERIFY2(!question.contains(u"reference"_s), qPrintable(question));
        QVERIFY(s.find<QProgressBar>(u"rackProgress"_s)->isVisible());
        QCOMPARE(s.find<QProgressBar>(u"rackProgress"_s)->maximum(), 6);
        QVERIFY(s.find<QPushButton>(u"rackCancelButton"_s)->isVisible());
        QVERIFY(QTest::qWaitFor([&s] { return s.idle(); }, kLongWaitMs));
        QTRY_VERIFY(!s.find<QProgressBar>(u"rackProgress"_s)->isVisible());
        const QStringList results = s.column(RackPanel::ResultColumn);
        QVERIFY2(std::all_of(results.cbegin(), results.cend(),
                     [](const QString &r) { return r.startsWith(u"Measured: "_s) && !r.endsWith(u": "_s); }),
            qPrintable(results.join(u" | "_s)));
        QCOMPARE(s.column(RackPanel::MeasuredColumn), QStringList(6, u"just now"_s));
        QCOMPARE(s.text(u"rackResultLabel"_s), u"Rack measured: 6 tools, each TLO recorded in the table."_s);
        for (int tool = 1; tool <= 6; ++tool) {
            const Tool *t = s.table().find(tool);
            QVERIFY2(t && t->measuredTlo, qPrintable(u"T%1"_s.arg(tool)));
            QCOMPARE(t->tloSource, TloSource::Probe);
            // Against the machine's reference: where the nose would touch, plus the tool's length, less it.
            QVERIFY(std::fabs(*t->measuredTlo
                        - (CarveraEmulator::kNoseTriggerZ + s.machine()->toolLength(tool)
                            - CarveraEmulator::kFactoryReferenceMz))
                < 0.0015);
            QCOMPARE(s.rackCell(tool - 1, RackPanel::StoredColumn), millimetres(*t->measuredTlo, false));
        }
        QCOMPARE(s.events(EventKind::Probe).size(), 6);
        QCOMPARE(s.text(u"rackSpindleLabel"_s), u"Spindle: T6"_s); // the last one stays in
        QVERIFY(s.find<QPushButton>(u"rackCheckButton"_s)->isEnabled());
    }

    void checkTheRackWithABrokenTool(RackStation &s)
    {
        const double t1 = *s.table().find(1)->measuredTlo;
        const double t2 = *s.table().find(2)->measuredTlo;
        s.machine()->breakTool(3, 0.5);
        QString question;
        QString warning;
        answerNextBox(QMessageBox::Yes, &question);
        answerBoxNamed(u"rackBrokenWarning"_s, QMessageBox::Ok, &warning);
        s.click(u"rackCheckButton"_s);
        QVERIFY2(
            question.contains(u"break-tests"_s) && question.contains(u"0.100 mm"_s), qPrintable(question));
        QVERIFY(QTest::qWaitFor([&s, &warning] { return s.idle() && !warning.isEmpty(); }, kLongWaitMs));
        QVERIFY2(
            warning.contains(u"T3 may be broken"_s) && warning.contains(u"Unlock"_s), qPrintable(warning));
        QVERIFY2(warning.contains(u"Not run: T4, T5, T6."_s), qPrintable(warning));
        const QStringList results = s.column(RackPanel::ResultColumn);
        QVERIFY2(results.at(0).startsWith(u"Passed"_s) && results.at(1).startsWith(u"Passed"_s),
            qPrintable(results.join(u" | "_s)));
        QVERIFY2(results.at(2).startsWith(u"BROKEN"_s), qPrintable(results.at(2)));
        QCOMPARE(results.mid(3), QStringList(3, u"Not run"_s));
        QVERIFY(s.rackTable()->item(2, RackPanel::ResultColumn)->background().style() != Qt::NoBrush);
        QVERIFY(s.rackTable()->item(1, RackPanel::ResultColumn)->background().style() == Qt::NoBrush);
        QCOMPARE(s.rackCell(2, RackPanel::MeasuredColumn), u"failed break test"_s);
        // The machine halted on T3: nothing that moves is offered until Unlock.
        QVERIFY(s.machine()->isHalted());
        QVERIFY(s.window.connection()->isHalted());
        QVERIFY(!s.find<QPushButton>(u"rackLoadButton"_s)->isEnabled());
        QVERIFY(!s.find<QPushButton>(u"rackMeasureButton"_s)->isEnabled());
        // The table marks T3 and keeps every TLO as measured; the history holds each verdict.
        QVERIFY(s.table().find(3)->breakTestFailed);
        QCOMPARE(*s.table().find(1)->measuredTlo, t1);
        QCOMPARE(*s.table().find(2)->measuredTlo, t2);
        const QList<HistoryEvent> tests = s.events(EventKind::BreakTest);
        QCOMPARE(tests.size(), 3);
        QCOMPARE(
            std::count_if(tests.cbegin(), tests.cend(), [](const HistoryEvent &e) { return *e.failed; }), 1);
    }

    void replaceTheBrokenToolAndLoadIt(RackStation &s)
    {
        s.machine()->breakTool(3, -0.5); // a new T3, as long as the old one was
        QString unlock;
        answerNextBox(QMessageBox::NoButton, &unlock, u"unlockBrokenButton"_s); // the tool was replaced
        s.trigger(u"actionUnlock"_s);
        QVERIFY2(unlock.contains(u"T3 failed its break test"_s), qPrintable(unlock));
        QVERIFY(QTest::qWaitFor([&s] { return !s.window.connection()->isHalted() && s.idle(); }, 10000));
        QCOMPARE(s.text(u"rackSpindleLabel"_s), u"Spindle: T3"_s);
        s.rackTable()->selectRow(2);
        QCOMPARE(s.find<QSpinBox>(u"rackToolSpin"_s)->value(), 3);
        QCOMPARE(s.find<QPushButton>(u"rackLoadButton"_s)->text(), u"Load T3…"_s);
        QString question;
        answerNextBox(QMessageBox::Yes, &question);
        s.click(u"rackLoadButton"_s);
        QVERIFY2(question.contains(u"measures it again"_s), qPrintable(question));
        QVERIFY(QTest::qWaitFor([&s] { return s.idle(); }, kLongWaitMs));
        QVERIFY2(s.text(u"rackResultLabel"_s).startsWith(u"T3 measured: TLO "_s)
                && s.text(u"rackResultLabel"_s).endsWith(u"recorded in the table."_s),
            qPrintable(s.text(u"rackResultLabel"_s)));
        QVERIFY(!s.table().find(3)->breakTestFailed); // measured again: the mark goes
        QCOMPARE(s.rackCell(2, RackPanel::MeasuredColumn), u"just now"_s);
        QCOMPARE(s.rackCell(2, RackPanel::ResultColumn), QString()); // the check's BROKEN no longer holds
        QCOMPARE(s.events(EventKind::Probe).size(), 7);
    }

    void loadAManualToolWithItsStoredTlo(RackStation &s)
    {
        // T8 lives outside the rack; it was measured this morning against the machine's reference.
        const double reference = *s.window.connection()->lastOffsets()->referenceMz;
        QVERIFY(s.window.document()->recordMeasurement(
            8, -5.25, QDateTime::currentDateTimeUtc().addSecs(-3700), TloSource::Probe, reference));
        s.find<QCheckBox>(u"rackUseStoredCheck"_s)->setChecked(true);
        QVERIFY(AppSettings().rackUsesStoredTlo()); // remembered
        auto *spin = s.find<QSpinBox>(u"rackToolSpin"_s);
        spin->selectAll();
        QTest::keyClicks(spin, u"8"_s);
        QCOMPARE(spin->value(), 8);
        const qsizetype sentBefore = s.sent.size();
        QString question;
        answerNextBox(QMessageBox::Yes, &question);
        s.click(u"rackLoadButton"_s);
        QVERIFY2(question.contains(u"puts T3 back in the rack"_s) && question.contains(u"does not probe"_s),
            qPrintable(question));
        QVERIFY(QTest::qWaitFor([&s] { return s.idle(); }, kLongWaitMs));
        const QList<QByteArray> sent = s.sent.mid(sentBefore);
        QVERIFY2(sent.contains("M6 T8 H-5.25"), sent.join(" | ").constData());
        QVERIFY(std::none_of(
            sent.cbegin(), sent.cend(), [](const QByteArray &l) { return l.startsWith("M491"); }));
        QCOMPARE(s.machine()->tool(), 8);
        QVERIFY(std::fabs(s.machine()->tlo() + 5.25) < 1e-9);
        QCOMPARE(s.text(u"rackResultLabel"_s),
            u"T8 takes its stored TLO -5.250 mm (measured 1 h ago); not probed."_s);
        QCOMPARE(s.text(u"rackSpindleLabel"_s), u"Spindle: T8"_s);
        QCOMPARE(*s.table().find(8)->measuredTlo, -5.25);
        QCOMPARE(s.events(EventKind::Restore).size(), 1);
    }

    void emptyTheSpindle(RackStation &s)
    {
        // The end of the day: T8, a manual tool, comes out; nothing is probed or recorded.
        auto *spin = s.find<QSpinBox>(u"rackToolSpin"_s);
        spin->setValue(spin->minimum());
        QCOMPARE(spin->text(), u"Empty"_s);
        QCOMPARE(s.find<QPushButton>(u"rackLoadButton"_s)->text(), u"Empty the Spindle…"_s);
        const int probes = int(s.events(EventKind::Probe).size());
        QString question;
        answerNextBox(QMessageBox::Yes, &question);
        s.click(u"rackLoadButton"_s);
        QVERIFY2(question.contains(u"Take the tool out of the spindle"_s), qPrintable(question));
        QVERIFY(QTest::qWaitFor([&s] { return s.idle(); }, kLongWaitMs));
        QVERIFY(s.sent.contains("M6 T-1"));
        QCOMPARE(s.machine()->tool(), -1);
        QCOMPARE(s.text(u"rackResultLabel"_s), u"The spindle is empty."_s);
        QTRY_COMPARE(s.text(u"rackSpindleLabel"_s), u"Spindle: empty"_s);
        QCOMPARE(int(s.events(EventKind::Probe).size()), probes);
        // Nothing to probe, restore or break-test in an empty spindle: the Machine dock says so.
        for (const QString &button : { u"probeButton"_s, u"restoreButton"_s, u"runBreakTestButton"_s }) {
            QVERIFY2(!s.find<QPushButton>(button)->isEnabled(), qPrintable(button));
            QVERIFY(s.find<QPushButton>(button)->toolTip().startsWith(u"The spindle is empty"_s));
        }
    }
};

QTEST_MAIN(TestRackPanel)
#include "tst_rackpanel.moc"
