// SPDX-License-Identifier: GPL-3.0-or-later
// A machinist's day in the real window, offscreen (issue 30): the History chart of probes a minute apart, a
// new cutter put in from the Edit menu (asked first, undone, the history keeping the old one), a tool life
// limit typed into the table and a program run that takes the tool to it, the job check's warning, and a
// Fusion library without units imported through the question and the preview. At each step: what the
// machinist sees, what the table and the history hold. With TOFFEE_SCREENSHOTS set, the window is saved there
// at 1280×720 and 1024×700, in English and in German.
#include <QAbstractButton>
#include <QChart>
#include <QChartView>
#include <QDateTimeAxis>
#include <QDir>
#include <QLabel>
#include <QLineSeries>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableView>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>
#include <QValueAxis>

#include "model/library/historyrecorder.h"
#include "model/library/library.h"
#include "tests/support/messageboxes.h"
#include "tests/support/station.h"
#include "ui/common/translations.h"
#include "ui/history/historydock.h"
#include "ui/job/jobcheckdialog.h"
#include "ui/job/jobreportmodels.h"
#include "ui/machine/tlopanel.h"
#include "ui/table/tooltablepanel.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Toffee::Test::answerNextBox;
using Toffee::Test::Station;

namespace {

const QString kExample = QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json");

void screenshot(QWidget &widget, const QString &name)
{
    const QString folder = qEnvironmentVariable("TOFFEE_SCREENSHOTS");
    if (folder.isEmpty())
        return;
    QTest::qWait(300); // the layout settles
    QVERIFY(widget.grab().save(QDir(folder).filePath(name)));
}

QString write(const QTemporaryDir &dir, const QString &name, const QByteArray &content)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (file.open(QIODevice::WriteOnly))
        file.write(content);
    return path;
}

// Selects tool `number`'s row, as a click on it does.
void select(Station &s, int number)
{
    s.window.findChild<ToolTablePanel *>()->selectTool(number);
    QApplication::processEvents();
}

QChart *historyChart(Station &s)
{
    auto *view = qobject_cast<QChartView *>(s.window.historyDock()->chartView());
    return view ? view->chart() : nullptr;
}

qsizetype pointsOf(QChart *chart, const QString &series)
{
    for (QAbstractSeries *one : chart->series()) {
        if (one->name() == series)
            return qobject_cast<QXYSeries *>(one)->count();
    }
    return -1;
}

} // namespace

class TestMachinistDay : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void aMachinistsDay()
    {
        Station s;
        s.window.resize(1280, 720);
        QVERIFY(s.window.openFile(kExample));
        QVERIFY(QTest::qWaitForWindowExposed(&s.window));
        Library *library = s.window.history()->library();
        QVERIFY(library);

        // Four probes of T2 this morning, 74 s apart, on the 6 mm cutter.
        const QDateTime morning = QDateTime::currentDateTimeUtc().addSecs(-3600);
        QList<HistoryEvent> probes;
        for (int i = 0; i < 4; ++i) {
            HistoryEvent e;
            e.id = HistoryEvent::newId();
            e.machine = u"Carvera"_s;
            e.tool = 2;
            e.at = morning.addSecs(74 * i);
            e.kind = EventKind::Probe;
            e.tlo = 9.652 - 0.001 * i;
            e.referenceMz = -115.34;
            probes << e;
        }
        QVERIFY(library->append(probes));

        // The History panel: the chart spans the four probes, not hours around them.
        s.window.historyDock()->show();
        s.window.historyDock()->raise();
        select(s, 2);
        QTRY_VERIFY(historyChart(s));
        QTRY_COMPARE(pointsOf(historyChart(s), u"Probes"_s), 4);
        auto *time = qobject_cast<QDateTimeAxis *>(historyChart(s)->axes(Qt::Horizontal).value(0));
        QVERIFY(time);
        const qint64 span = time->min().secsTo(time->max());
        QVERIFY2(span >= 222 && span < 600, qPrintable(QString::number(span)));
        QCOMPARE(time->format(), u"HH:mm:ss"_s);
        auto *tlo = qobject_cast<QValueAxis *>(historyChart(s)->axes(Qt::Vertical).value(0));
        QVERIFY(tlo && tlo->min() <= 9.649 && tlo->max() >= 9.652 && tlo->max() - tlo->min() < 1.0);
        // The chart grows with the window: the panels below the table keep their share of the height.
        const int chartBefore = s.window.historyDock()->chartView()->height();
        s.window.resize(1280, 1000);
        QTRY_VERIFY2(s.window.historyDock()->chartView()->height() > chartBefore + 60,
            qPrintable(QString::number(s.window.historyDock()->chartView()->height())));
        s.window.resize(1280, 720);
        QTRY_VERIFY(s.window.historyDock()->chartView()->height() < chartBefore + 20);
        screenshot(s.window, u"machinist-history-1280x720.png"_s);

        // A new cutter in T2: asked first, naming what ends; No keeps everything.
        auto *newCutter = s.find<QAction>(u"actionNewCutter"_s);
        QCOMPARE(newCutter->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N));
        s.window.findChild<QTableView *>(u"toolTable"_s)->setFocus();
        select(s, 2);
        QString question;
        answerNextBox(QMessageBox::Cancel, &question);
        s.key(Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY2(question.contains(
                     u"T2 gets a new cutter: its TLO 9.652 mm (measured), its length 71.488 mm belong "
                     u"to the old one"_s),
            qPrintable(question));
        QCOMPARE(s.table().find(2)->measuredTlo, std::optional(9.652));
        answerNextBox(QMessageBox::NoButton, nullptr, u"newCutterButton"_s);
        s.trigger(u"actionNewCutter"_s); // from the Edit menu this time
        QTRY_VERIFY(!s.table().find(2)->measuredTlo);
        QCOMPARE(s.table().find(2)->lengthGeometry, 0.0); // the old cutter's length, which G43 would apply
        QCOMPARE(s.cell(2, ToolTableModel::MeasuredTloColumn), u"not measured"_s);
        QVERIFY(s.window.statusBar()->currentMessage().contains(
            u"T2 has a new cutter: measure it before it cuts"_s));
        // The history keeps the old cutter's TLO, ended; the chart draws its probes apart, off the trend.
        const QList<HistoryEvent> history = library->history({ u"Carvera"_s, 2, {}, 0 }).value();
        QCOMPARE(history.last().kind, EventKind::NewCutter);
        QCOMPARE(history.last().oldTlo, std::optional(9.652));
        QTRY_COMPARE(pointsOf(historyChart(s), u"Old cutter"_s), 4);
        QCOMPARE(pointsOf(historyChart(s), u"Probes"_s), 0);
        auto *historyTable = s.window.historyDock()->findChild<QTableView *>(u"historyTable"_s);
        QCOMPARE(historyTable->model()->index(0, 1).data().toString(), u"new cutter (old one ended)"_s);
        // Undo puts the table's values back; the history still says a new cutter went in, and the job check
        // says the TLO is the old cutter's.
        s.trigger(u"actionUndo"_s);
        QCOMPARE(s.table().find(2)->measuredTlo, std::optional(9.652));
        {
            QTemporaryDir jobs;
            JobCheckDialog *undone
                = s.window.openJobCheck(write(jobs, u"t2.nc"_s, "M6 T2\nG1 X10 F600\nM30\n"));
            QVERIFY(QTest::qWaitFor([undone] { return !undone->isRunning() && undone->report(); }, 60000));
            const auto found = undone->report()->findings;
            QVERIFY(std::any_of(found.cbegin(), found.cend(), [](const Finding &f) {
                return f.tool == 2 && f.message.contains(u"that TLO is the old cutter's"_s);
            }));
            undone->close();
        }
        s.trigger(u"actionRedo"_s);
        QVERIFY(!s.table().find(2)->measuredTlo);

        // Tool life: a limit typed into T1's Tool life cell, from the keyboard.
        auto *view = s.window.findChild<QTableView *>(u"toolTable"_s);
        select(s, 1);
        view->setCurrentIndex(
            view->model()->index(view->currentIndex().row(), ToolTableModel::ToolLifeColumn));
        view->setFocus();
        QTest::keyClick(view, Qt::Key_F2);
        QWidget *editor = view->indexWidget(view->currentIndex());
        QVERIFY(editor);
        QTest::keyClicks(editor, u"1 min, 5 uses"_s);
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_COMPARE(s.table().find(1)->lifeLimitMinutes, std::optional(1.0));
        QCOMPARE(s.table().find(1)->lifeLimitUses, std::optional(5));
        QCOMPARE(s.cell(1, ToolTableModel::ToolLifeColumn), u"0 s of 1 min · 0 of 5 uses"_s);
        // A program ran: 600 mm at 600 mm/min is T1's whole minute, near (at) its limit, shown in orange.
        QTemporaryDir dir;
        const QString program
            = write(dir, u"pocket.nc"_s, "G21 G90\nM6 T1\nG0 X0 Y0 Z0\nG1 X600 F600\nM30\n");
        QVERIFY(s.window.recordProgramRun(program));
        QTRY_COMPARE(s.cell(1, ToolTableModel::ToolLifeColumn), u"1 min of 1 min · 1 of 5 uses"_s);
        // Read whole: the column is as wide as its text.
        QVERIFY(view->columnWidth(ToolTableModel::ToolLifeColumn)
            >= view->fontMetrics().horizontalAdvance(u"1 min of 1 min · 1 of 5 uses"_s));
        auto *model = s.window.document()->model();
        QCOMPARE(model->index(model->rowOfTool(1), ToolTableModel::ToolLifeColumn)
                     .data(Qt::ForegroundRole)
                     .value<QColor>(),
            QColor(0xb0, 0x50, 0x00));
        // The job check: the program again would take T1 past its limit.
        JobCheckDialog *check = s.window.openJobCheck(program);
        QVERIFY(QTest::qWaitFor([check] { return !check->isRunning() && check->report(); }, 60000));
        const auto findings = check->report()->findings;
        QVERIFY(std::any_of(findings.cbegin(), findings.cend(), [](const Finding &f) {
            return f.kind == FindingKind::LifeExceeded && f.tool == 1
                && f.message.contains(u"would pass its life limit of 1 min"_s);
        }));
        auto *findingsView = check->findChild<QTableView *>(u"jobFindingsView"_s);
        bool shown = false;
        for (int row = 0; row < findingsView->model()->rowCount(); ++row)
            shown = shown
                || findingsView->model()
                       ->index(row, JobFindingsModel::MessageColumn)
                       .data()
                       .toString()
                       .contains(u"life limit"_s);
        QVERIFY(shown);
        // The finding is read whole: its column ends within the view, and the row wraps it.
        check->show();
        QTRY_VERIFY(findingsView->columnViewportPosition(JobFindingsModel::MessageColumn)
                + findingsView->columnWidth(JobFindingsModel::MessageColumn)
            <= findingsView->viewport()->width());
        screenshot(*check, u"machinist-life-exceeded.png"_s);
        check->close();

        // A Fusion library whose T9 gives no unit: asked, then previewed, then imported.
        const QByteArray t9 = R"({"guid": "9", "type": "flat end mill", "description": "1/4 in flat",
            "geometry": {"DC": 0.25, "OAL": 2.5}, "post-process": {"number": 9}})";
        const QString fusion = write(dir, u"shop.json"_s, "{\"version\": 14, \"data\": [" + t9 + "]}");
        QString unitQuestion;
        answerNextBox(QMessageBox::NoButton, &unitQuestion, u"camUnitsInches"_s);
        QTimer::singleShot(400, [] {
            auto *dialog = qobject_cast<QDialog *>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            auto *list = dialog->findChild<QTreeWidget *>(u"importToolList"_s);
            QVERIFY(list);
            QVERIFY(list->topLevelItem(0)->text(3).contains(u"read in inches, as you said"_s));
            dialog->findChild<QAbstractButton *>(u"importButton"_s)->click();
        });
        QVERIFY(s.window.importFile(fusion));
        QVERIFY2(unitQuestion.contains(
                     u"Tools in shop.json without a unit (Fusion writes \"unit\" on every tool): T9."_s),
            qPrintable(unitQuestion));
        QCOMPARE(s.table().find(9)->radiusGeometry, 3.175);

        // Connected and probing, the TLO strip keeps its height whatever its note says: the table never
        // moves.
        auto *strip = s.window.findChild<TloPanel *>();
        const int stripHeight = strip->height();
        const int tableTop = view->mapTo(&s.window, QPoint(0, 0)).y();
        s.connect();
        QVERIFY(!s.text(u"tloNoteLabel"_s).isEmpty());
        QCOMPARE(strip->height(), stripHeight);
        s.probe();
        QVERIFY(s.text(u"tloNoteLabel"_s).startsWith(u"measured "_s));
        QCOMPARE(strip->height(), stripHeight);
        QCOMPARE(view->mapTo(&s.window, QPoint(0, 0)).y(), tableTop);

        // The window at the sizes a shop has.
        select(s, 2);
        screenshot(s.window, u"machinist-1280x720.png"_s);
        s.window.resize(1024, 700);
        screenshot(s.window, u"machinist-1024x700.png"_s);
    }

    // The same window in German, at both sizes: every text whole.
    void inGerman()
    {
        QCOMPARE(
            installTranslations(qApp, u"de"_s, QStringLiteral(TOFFEE_BUILD_DIR "/translations")), u"de_DE"_s);
        Station s;
        s.window.resize(1280, 720);
        QVERIFY(s.window.openFile(kExample));
        QVERIFY(QTest::qWaitForWindowExposed(&s.window));
        select(s, 1);
        QCOMPARE(s.find<QAction>(u"actionNewCutter"_s)->text(), u"Neuer &Fräser…"_s);
        screenshot(s.window, u"machinist-de-1280x720.png"_s);
        s.window.resize(1024, 700);
        screenshot(s.window, u"machinist-de-1024x700.png"_s);
    }

    // Halted, in German and in Chinese at 1024×700: the banner's long words wrap or are cut inside the
    // window, which keeps its width, and Unlock stays on screen.
    void haltedFitsAt1024x700_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("German") << u"de"_s;
        QTest::newRow("Chinese") << u"zh_CN"_s;
    }
    void haltedFitsAt1024x700()
    {
        QFETCH(QString, language);
        QVERIFY(
            !installTranslations(qApp, language, QStringLiteral(TOFFEE_BUILD_DIR "/translations")).isEmpty());
        Station s;
        s.window.resize(1024, 700);
        QVERIFY(s.window.openFile(kExample));
        QVERIFY(QTest::qWaitForWindowExposed(&s.window));
        s.window.connection()->connectTo(ConnectionTarget {});
        QTRY_VERIFY(s.window.connection()->state() == MachineConnection::State::Connected);
        s.window.connection()->emulator()->halt(4); // the tool setter's halt: the longest meaning
        QTRY_VERIFY(s.window.connection()->isHalted());
        auto *unlock = s.find<QPushButton>(u"unlockButton"_s);
        QTRY_VERIFY(unlock->isVisible());
        QTest::qWait(300); // the layout settles
        QCOMPARE(s.window.width(), 1024);
        const QPoint right = unlock->mapTo(&s.window, QPoint(unlock->width(), unlock->height()));
        QVERIFY2(right.x() <= s.window.width() && right.y() <= s.window.height(),
            qPrintable(u"Unlock ends at %1,%2"_s.arg(right.x()).arg(right.y())));
        QVERIFY2(unlock->text().contains(u'&'), qPrintable(unlock->text())); // Alt and its letter press it
        auto *banner = s.find<QLabel>(u"haltLabel"_s);
        QVERIFY(banner->isVisible());
        QVERIFY(banner->mapTo(&s.window, QPoint(banner->width(), 0)).x() <= s.window.width());
        // Every word of it shown: as tall as its words need at the width it has.
        QVERIFY2(banner->height() >= banner->heightForWidth(banner->width()),
            qPrintable(u"%1 < %2"_s.arg(banner->height()).arg(banner->heightForWidth(banner->width()))));
        screenshot(s.window, u"machinist-%1-halted-1024x700.png"_s.arg(language));
    }
};

QTEST_MAIN(TestMachinistDay)
#include "tst_machinistday.moc"
