// SPDX-License-Identifier: GPL-3.0-or-later
#include <csignal>
#include <cstdio>

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QStandardPaths>
#include <QTimer>

#include "appearance.h"
#include "appsettings.h"
#include "connectionpanel.h"
#include "machineconnection.h"
#include "machinedock.h"
#include "mainwindow.h"
#include "recoveryprompt.h"
#include "selftest.h"
#include "translations.h"

using namespace Qt::StringLiterals;

int main(int argc, char *argv[])
{
    QElapsedTimer sinceLaunch;
    sinceLaunch.start();
    // Over a file-size limit (ulimit -f) a write then fails with "File too large", which a save reports like
    // a full disk with the old file whole, instead of the process being killed in the middle of it.
    std::signal(SIGXFSZ, SIG_IGN);
    QApplication app(argc, argv);
    QApplication::setOrganizationName(u"Toffee"_s);
    QApplication::setApplicationName(u"Toffee"_s);
    QApplication::setApplicationDisplayName(u"Toffee"_s);
    QApplication::setApplicationVersion(QStringLiteral(TOFFEE_VERSION));
    QApplication::setDesktopFileName(u"org.toffee.Toffee"_s);

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate("main", "Toffee, the tool offset manager."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption emulator(
        u"emulator"_s, QApplication::translate("main", "Connect to the built-in emulator."));
    const QCommandLineOption port(
        u"port"_s, QApplication::translate("main", "Connect to the machine on PORT."), u"PORT"_s);
    const QCommandLineOption baud(
        u"baud"_s, QApplication::translate("main", "Baud rate (default 115200)."), u"N"_s, u"115200"_s);
    const QCommandLineOption selfTest(u"self-test"_s,
        QApplication::translate("main",
            "Open the window, connect to the emulator, load the example table, probe, "
            "render once, and exit (0 when all went well)."));
    const QCommandLineOption dark(u"dark"_s, QApplication::translate("main", "Use the dark palette."));
    const QCommandLineOption lang(u"lang"_s,
        QApplication::translate("main", "Language: de, zh_CN or en (default: the system's)."), u"LANGUAGE"_s);
    parser.addOptions({ emulator, port, baud, selfTest, dark, lang });
    parser.addPositionalArgument(
        u"table"_s, QApplication::translate("main", "A tool table to open."), u"[table]"_s);
    parser.process(app);
    if (parser.value(lang) != u"en")
        Toffee::installTranslations(&app, parser.value(lang));

    if (parser.isSet(selfTest))
        QStandardPaths::setTestModeEnabled(true); // a smoke test leaves the user's settings alone
    Toffee::applyPalette(parser.isSet(dark) || Toffee::AppSettings().darkPalette());
    Toffee::MainWindow window;
    if (parser.isSet(selfTest)) {
        Toffee::SelfTest test(&window, [](int code, const QString &message) {
            std::fprintf(code == 0 ? stdout : stderr, "toffee: %s\n", qPrintable(message));
            // A step that failed may have left a message box up: a smoke test never waits for a person.
            for (int i = 0; i < 16 && QApplication::activeModalWidget(); ++i)
                QApplication::activeModalWidget()->close();
            QApplication::exit(code);
        });
        // Started inside the event loop, so that exit() ends it even when a step fails before it would run.
        QTimer::singleShot(0, &window, [&test, &sinceLaunch] { test.start(sinceLaunch); });
        return QApplication::exec();
    }
    window.show();
    // Edits a crash would have lost come first; the table asked for opens when none are recovered.
    if (!Toffee::offerRecovery(&window) && !parser.positionalArguments().isEmpty())
        window.openFile(parser.positionalArguments().constFirst());
    if (parser.isSet(emulator) || parser.isSet(port)) {
        const Toffee::ConnectionTarget target { parser.isSet(emulator), parser.value(port),
            parser.value(baud).toInt() };
        window.machineDock()->connectionPanel()->setTarget(target);
        window.connection()->connectTo(target);
    }
    return QApplication::exec();
}
