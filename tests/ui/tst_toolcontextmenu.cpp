// SPDX-License-Identifier: GPL-3.0-or-later
// The tool table answers the operator: its context menu (the Menu key opens it too) and its keys make a tool
// active (asked first), set its TLO by hand, restore it and probe it, each enabled only when it can run and
// saying why not. An operator's story on the built-in emulator: what the menu offers at each step, what the
// machine then holds, and what the table records.
#include <cmath>

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QContextMenuEvent>
#include <QDoubleSpinBox>
#include <QMenu>
#include <QPushButton>
#include <QStandardPaths>
#include <QTableView>
#include <QTest>

#include "serial/emulator/carveraemulator.h"
#include "tests/support/messageboxes.h"
#include "tests/support/station.h"
#include "ui/table/tooltablepanel.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

const QString kExample = QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json");

// The menu's entries as the operator reads them: text, and whether it can be chosen.
QStringList entries(QMenu *menu)
{
    QStringList out;
    for (const QAction *a : menu->actions()) {
        if (!a->isSeparator())
            out << (a->isEnabled() ? QString() : u"(off) "_s) + QString(a->text()).remove(u'&');
    }
    return out;
}

// What the platform sends for the Menu key (or Shift+F10) and for the right button, at `at` in the rows.
void openMenu(QTableView *view, QContextMenuEvent::Reason reason, QPoint at)
{
    QContextMenuEvent event(reason, at, view->viewport()->mapToGlobal(at));
    QApplication::sendEvent(view->viewport(), &event);
}

QAction *entry(QMenu *menu, const QString &startsWith)
{
    for (QAction *a : menu->actions()) {
        if (QString(a->text()).remove(u'&').startsWith(startsWith))
            return a;
    }
    return nullptr;
}

} // namespace

class TestToolContextMenu : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void anOperatorWorksFromTheTable()
    {
        Station s;
        QVERIFY(s.window.openFile(kExample));
        auto *view = s.window.findChild<QTableView *>(u"toolTable"_s);
        view->setFocus();
        // Not connected: nothing that needs the machine can be chosen, and each says why.
        s.window.findChild<ToolTablePanel *>()->selectTool(2);
        auto *makeActive = s.find<QAction>(u"actionMakeActive"_s);
        QVERIFY(!makeActive->isEnabled());
        QVERIFY(makeActive->toolTip().contains(u"Connect"_s));

        s.connect();
        QCOMPARE(s.machine()->tool(), 1);
        // The right button on T3's row makes it the selection and opens the menu for it.
        s.window.findChild<ToolTablePanel *>()->selectTool(2);
        const QModelIndex t3 = view->model()->index(2, 0);
        openMenu(view, QContextMenuEvent::Mouse, view->visualRect(t3).center());
        QTRY_VERIFY(qobject_cast<QMenu *>(QApplication::activePopupWidget()));
        QVERIFY(entry(qobject_cast<QMenu *>(QApplication::activePopupWidget()), u"Make T3 Active"_s));
        QApplication::activePopupWidget()->close();
        s.window.findChild<ToolTablePanel *>()->selectTool(2);
        // The Menu key opens the table's menu for the selected tool.
        openMenu(view, QContextMenuEvent::Keyboard, view->visualRect(view->currentIndex()).center());
        QTRY_VERIFY(qobject_cast<QMenu *>(QApplication::activePopupWidget()));
        auto *menu = qobject_cast<QMenu *>(QApplication::activePopupWidget());
        QCOMPARE(menu->objectName(), u"toolContextMenu"_s);
        QCOMPARE(entries(menu),
            (QStringList { u"Change to T2 (M6)…"_s, u"Make T2 Active (No Probe)…"_s, u"(off) Set T2's TLO…"_s,
                u"Restore T2's Known TLO…"_s, u"Probe T1 (in the Spindle)"_s, u"New Cutter…"_s,
                u"Remove Tool"_s }));
        QVERIFY(entry(menu, u"Set T2"_s)->toolTip().contains(u"make T2 active first"_s));
        if (const QString folder = qEnvironmentVariable("TOFFEE_SCREENSHOTS"); !folder.isEmpty())
            QVERIFY(s.window.grab().save(folder + u"/table-context-window.png"_s)
                && menu->grab().save(folder + u"/table-context-menu.png"_s));
        menu->close();

        // Make T2 active (Ctrl+M): asked first, naming what is sent and what stays; Cancel sends nothing.
        QString question;
        answerNextBox(QMessageBox::Cancel, &question);
        s.key(Qt::Key_M, Qt::ControlModifier);
        QVERIFY2(question.contains(u"Is T2 in the spindle now?"_s) && question.contains(u"Sends: M493.2 T2"_s)
                && question.contains(u"keeps the TLO in force now"_s),
            qPrintable(question));
        QVERIFY(!s.sent.contains("M493.2 T2"));
        s.window.activateWindow(); // back from the box
        QVERIFY(QTest::qWaitForWindowActive(&s.window));
        answerNextBox(QMessageBox::NoButton, nullptr, u"makeActiveYesButton"_s);
        s.key(Qt::Key_M, Qt::ControlModifier);
        QTRY_VERIFY2(s.idle() && s.sent.contains("M493.2 T2"),
            qPrintable(QString::fromUtf8(s.sent.join(" | ")) + u" modal: "_s
                + (QApplication::activeModalWidget() ? QApplication::activeModalWidget()->objectName()
                                                     : QString())));
        QTRY_COMPARE(s.machine()->tool(), 2);
        QTRY_VERIFY(!makeActive->isEnabled()); // T2 is the active tool now

        // Its TLO by hand (Ctrl+Shift+O): the Machine dock's editor, set to "Set TLO to", its value focused.
        auto *setTlo = s.find<QAction>(u"actionSetTlo"_s);
        QTRY_VERIFY(setTlo->isEnabled());
        s.window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&s.window));
        s.key(Qt::Key_O, Qt::ControlModifier | Qt::ShiftModifier);
        auto *value = s.find<QDoubleSpinBox>(u"offsetValueSpin"_s);
        QTRY_COMPARE(QApplication::focusWidget(), static_cast<QWidget *>(value));
        QCOMPARE(s.find<QComboBox>(u"offsetModeCombo"_s)->currentText(), u"Set TLO to"_s);
        QTest::keyClicks(value, u"12.5"_s);
        answerNextBox(QMessageBox::Yes);
        QTest::mouseClick(s.find<QPushButton>(u"sendOffsetButton"_s), Qt::LeftButton);
        QTRY_VERIFY(s.idle() && s.sent.contains("M493.3 Z12.5"));
        QTRY_COMPARE(s.table().find(2)->measuredTlo, std::optional(12.5));
        QCOMPARE(s.table().find(2)->tloSource, TloSource::Manual);

        // Probed from the menu: the entry names the tool in the spindle; the table now holds its measurement.
        openMenu(view, QContextMenuEvent::Keyboard, view->visualRect(view->currentIndex()).center());
        QTRY_VERIFY(qobject_cast<QMenu *>(QApplication::activePopupWidget()));
        menu = qobject_cast<QMenu *>(QApplication::activePopupWidget());
        QAction *probe = entry(menu, u"Probe T2"_s);
        QVERIFY2(probe && probe->isEnabled(), qPrintable(entries(menu).join(u" | "_s)));
        menu->close();
        answerNextBox(QMessageBox::Yes);
        probe->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(s.idle() && s.table().find(2)->tloSource == TloSource::Probe, 10000);
        QVERIFY(std::fabs(*s.table().find(2)->measuredTlo - s.machine()->tlo()) < 0.0006); // at 0.001 mm
        QVERIFY(std::fabs(*s.table().find(2)->measuredTlo - 12.5) > 0.01);

        // Change to T3 (Ctrl+Shift+M): asked first, naming what is sent; the machine's change from its rack,
        // then T3 measured and recorded.
        s.window.findChild<ToolTablePanel *>()->selectTool(3);
        auto *changeTo = s.find<QAction>(u"actionChangeTo"_s);
        QTRY_VERIFY(changeTo->isEnabled());
        QCOMPARE(QString(changeTo->text()).remove(u'&'), u"Change to T3 (M6)…"_s);
        s.window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&s.window));
        answerNextBox(QMessageBox::Cancel, &question);
        s.key(Qt::Key_M, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_VERIFY2(question.contains(u"Change to T3 now?"_s) && question.contains(u"Sends: M6 T3"_s)
                && question.contains(u"from its rack"_s),
            qPrintable(question));
        QVERIFY(!s.sent.contains("M6 T3"));
        const auto t3Before = s.table().find(3)->measuredAt;
        s.window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&s.window));
        answerNextBox(QMessageBox::NoButton, nullptr, u"changeToYesButton"_s);
        s.key(Qt::Key_M, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_VERIFY_WITH_TIMEOUT(s.idle() && s.sent.contains("M6 T3"), 15000);
        QTRY_COMPARE(s.machine()->tool(), 3);
        QTRY_VERIFY(s.table().find(3)->measuredAt != t3Before);
        QVERIFY(std::fabs(*s.table().find(3)->measuredTlo - s.machine()->tlo()) < 0.0006);
        QVERIFY(!changeTo->isEnabled()); // T3 is the active tool now
    }
};

QTEST_MAIN(TestToolContextMenu)
#include "tst_toolcontextmenu.moc"
