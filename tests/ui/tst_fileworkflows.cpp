// SPDX-License-Identifier: GPL-3.0-or-later
// Whole stories through the real window (offscreen) against the built-in emulator about what the files hold:
// one tool exported for each dialect, and a table saved as LinuxCNC's tool.tbl, with what the window says it
// keeps and what the file then holds.
#include <cmath>

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include "model/document/tooldocument.h"
#include "model/document/tooltablemodel.h"
#include "model/gcode/dialect.h"
#include "model/library/historyrecorder.h"
#include "serial/emulator/carveraemulator.h"
#include "serial/machineconnection.h"
#include "tests/support/messageboxes.h"
#include "tests/support/station.h"
#include "ui/common/appsettings.h"
#include "ui/machine/consoledock.h"
#include "ui/machine/machinedock.h"
#include "ui/machine/tlopanel.h"
#include "ui/shell/mainwindow.h"
#include "ui/table/exportdialog.h"
#include "ui/table/tooltablepanel.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Toffee::Test::answerNextBox;
using Toffee::Test::Station;

class TestFileWorkflows : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { Test::isolateWindowTest(u"tst_fileworkflows"_s); }
    void init() { Test::startFresh(); }

    void exportsOneToolForEachDialect()
    {
        Station s;
        QVERIFY(s.window.openFile(Test::kExampleTable));
        QStringList checked;
        QTimer::singleShot(0, [&] {
            auto *dialog = qobject_cast<ExportDialog *>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            auto *tool = dialog->findChild<QComboBox *>(u"exportToolCombo"_s);
            auto *preview = dialog->findChild<QPlainTextEdit *>(u"exportPreview"_s);
            for (const DialectInfo &d : dialects()) {
                dialog->selectDialect(d.key);
                tool->setCurrentIndex(tool->findData(2));
                const QString program = preview->toPlainText();
                checked << d.key;
                if (!dialog->findChild<QPushButton *>(u"exportSaveButton"_s)->isEnabled()) {
                    // A dialect Toffee cannot write says why instead (FAGOR).
                    QVERIFY(!dialog->findChild<QLabel *>(u"exportProblem"_s)->text().isEmpty());
                    continue;
                }
                // T2 and no other tool of the six: never a whole offset table for one tool.
                QVERIFY2(program.contains(u"1 tool,"_s), qPrintable(program));
                for (int other : { 1, 3, 4, 5, 6 }) {
                    const QString n = QString::number(other);
                    for (const QString &word : QStringList {
                             u"P"_s + n + u' ', u"T"_s + n + u' ', u"T"_s + n + u'\n', u"H"_s + n + u' ' })
                        QVERIFY2(!program.contains(word),
                            qPrintable(d.key + u": "_s + word + u" in\n"_s + program));
                }
                QVERIFY2(program.contains(u"2"_s), qPrintable(d.key));
            }
            dialog->reject();
        });
        s.trigger(u"actionExportProgram"_s);
        QCOMPARE(checked.size(), dialects().size());
        QVERIFY(checked.contains(u"fanuc"_s) && checked.contains(u"aerotech"_s));
    }

    void saveAsTblShowsWhatTheFileHolds()
    {
        QTemporaryDir dir;
        Station s;
        QVERIFY(s.window.openFile(Test::kExampleTable));
        QVERIFY(s.table().find(2)->measuredTlo);
        const ToolTable full = s.table();
        const QString path = dir.filePath(u"mill.tbl"_s);
        QString question;
        s.saveAs(path, &question);
        QVERIFY(question.contains(u"no place for measured TLOs"_s));
        QVERIFY(question.contains(u"shows what the file holds"_s));
        // The window, the file and the title agree: no TLOs, nothing unsaved.
        QVERIFY(!s.window.document()->isModified());
        QVERIFY(!s.window.isWindowModified());
        QCOMPARE(s.window.document()->filePath(), path);
        const auto onDisk = loadTableFile(path);
        QVERIFY(onDisk.ok());
        QCOMPARE(s.table(), onDisk.value());
        QCOMPARE(s.cell(2, ToolTableModel::MeasuredTloColumn), u"not measured"_s);
        // Undo brings the rest back, as an unsaved change to the .tbl.
        s.trigger(u"actionUndo"_s);
        QCOMPARE(s.table(), full);
        QVERIFY(s.window.isWindowModified());
        QCOMPARE(s.cell(2, ToolTableModel::MeasuredTloColumn), u"9.652"_s);
        // Cancelling the question saves nothing and changes nothing.
        QTimer::singleShot(0, [] { answerNextBox(QMessageBox::Cancel); });
        s.trigger(u"actionSave"_s);
        QCOMPARE(s.table(), full);
        QVERIFY(s.window.isWindowModified());
    }
};

QTEST_MAIN(TestFileWorkflows)
#include "tst_fileworkflows.moc"
