// SPDX-License-Identifier: GPL-3.0-or-later
// An operator's station for whole-window stories: the real window, offscreen, on the built-in emulator, and
// the few gestures a story is made of (connect, a menu action, a key, Save As).
#pragma once

#include <QAction>
#include <QApplication>
#include <QFileDialog>
#include <QLabel>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include "model/document/tooldocument.h"
#include "model/document/tooltablemodel.h"
#include "serial/emulator/carveraemulator.h"
#include "serial/machineconnection.h"
#include "tests/support/messageboxes.h"
#include "ui/machine/machinedock.h"
#include "ui/shell/mainwindow.h"

namespace Toffee::Test {

using namespace Qt::StringLiterals;

// The six-tool Carvera table every first run opens.
inline const QString kExampleTable = QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json");

// A window test of its own: its settings and folders apart from the user's and from other tests
// (QStandardPaths' test mode, under `application`). Call from initTestCase; startFresh from init, for a first
// start's window.
inline void isolateWindowTest(const QString &application)
{
    QStandardPaths::setTestModeEnabled(true);
    QApplication::setOrganizationName(QStringLiteral("ToffeeTest"));
    QApplication::setApplicationName(application);
}

// Each story starts from the defaults (a first start), whatever the last one remembered.
inline void startFresh()
{
    QSettings().clear();
}

struct Station
{
    QList<QByteArray> sent;
    QTemporaryDir libraryFolder; // each story its own history library
    MainWindow window;

    Station()
    {
        window.setLibrary({ libraryPath() });
        window.show();
    }
    QString libraryPath() const { return libraryFolder.filePath(QStringLiteral("library.sqlite")); }

    template<typename T> T *find(const QString &name) const
    {
        T *found = window.findChild<T *>(name);
        if (!found)
            qFatal("no widget named %s", qPrintable(name));
        return found;
    }
    QString text(const QString &label) const { return find<QLabel>(label)->text(); }
    CarveraEmulator *machine() const { return window.connection()->emulator(); }
    const ToolTable &table() const { return window.document()->table(); }
    bool idle() const { return !window.connection()->isBusy(); }
    // What the table shows in a cell of tool `number`.
    QString cell(int number, int column) const
    {
        auto *model = window.document()->model();
        return model->index(model->rowOfTool(number), column).data().toString();
    }

    void connect()
    {
        window.connection()->connectTo(ConnectionTarget {});
        QVERIFY(QTest::qWaitFor(
            [this] { return window.connection()->state() == MachineConnection::State::Connected; }));
        QObject::connect(window.connection(), &MachineConnection::consoleLine, &window,
            [this](const QByteArray &line, bool outgoing) {
                if (outgoing)
                    sent.append(line);
            });
        QTRY_VERIFY(text(u"machineStateLabel"_s) == u"Idle"_s);
    }
    void trigger(const QString &action) { find<QAction>(action)->trigger(); }
    // Presses a key on whatever has focus, as a person at the keyboard does.
    void key(int key, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
    {
        QWidget *target = QApplication::activeModalWidget() ? QApplication::activeModalWidget()
            : QApplication::focusWidget()                   ? QApplication::focusWidget()
                                                            : &window;
        QTest::keyClick(target, Qt::Key(key), modifiers);
    }
    // Probes through the Machine menu (F5), answering its question.
    QString probe()
    {
        QString question;
        answerNextBox(QMessageBox::Yes, &question);
        trigger(u"actionProbe"_s);
        if (!QTest::qWaitFor([this] { return idle(); }, 10000))
            qWarning("the probe did not finish");
        return question;
    }
    // Saves through File ▸ Save As, typing the name into the file dialog; answers a lossy-format question.
    void saveAs(const QString &path, QString *lossQuestion = nullptr)
    {
        QTimer::singleShot(0, [path] {
            auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            dialog->selectFile(path);
            static_cast<QDialog *>(dialog)->accept();
        });
        if (lossQuestion)
            QTimer::singleShot(50, [lossQuestion] { answerNextBox(QMessageBox::Yes, lossQuestion); });
        trigger(u"actionSaveAs"_s);
    }
};

} // namespace Toffee::Test
