// SPDX-License-Identifier: GPL-3.0-or-later
#include <csignal>
#include <cstdio>

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QStandardPaths>
#include <QTextStream>
#include <QTimer>

#include "serial/machineconnection.h"
#include "ui/common/appearance.h"
#include "ui/common/appsettings.h"
#include "ui/common/translations.h"
#include "ui/connection/connectionpanel.h"
#include "ui/machine/machinedock.h"
#include "ui/shell/mainwindow.h"
#include "ui/shell/recoveryprompt.h"
#include "ui/shell/selftest.h"

using namespace Qt::StringLiterals;

namespace {

// The command line, described once for the window and for --help, which is answered without a display.
struct Options
{
    QCommandLineOption emulator { u"emulator"_s,
        QApplication::translate("main",
            "Connect to the built-in emulator, which takes a real machine's time for a tool change and a "
            "probe.") };
    QCommandLineOption emulatorFirmware { u"emulator-firmware"_s,
        QApplication::translate(
            "main", "The firmware the built-in emulator plays: community (default) or stock."),
        u"FIRMWARE"_s, u"community"_s };
    QCommandLineOption port { u"port"_s, QApplication::translate("main", "Connect to the machine on PORT."),
        u"PORT"_s };
    QCommandLineOption baud { u"baud"_s, QApplication::translate("main", "Baud rate (default 115200)."),
        u"N"_s, u"115200"_s };
    QCommandLineOption host { u"host"_s,
        QApplication::translate(
            "main", "Connect to the machine over Wi-Fi at HOST[:PORT] (port 2222 by default)."),
        u"HOST"_s };
    QCommandLineOption selfTest { u"self-test"_s,
        QApplication::translate("main",
            "Open the window, connect to the emulator, load the example table, probe, "
            "render once, and exit (0 when all went well).") };
    QCommandLineOption dark { u"dark"_s, QApplication::translate("main", "Use the dark palette.") };
    QCommandLineOption lang { u"lang"_s,
        QApplication::translate("main", "Language: de, zh_CN or en (default: the system's)."),
        u"LANGUAGE"_s };

    const QCommandLineOption library { u"library"_s,
        QApplication::translate("main",
            "The history library: an SQLite file (or sqlite:PATH), or a shared one on PostgreSQL "
            "(postgresql://user@host:port/dbname; the password in ~/.pgpass)."),
        u"LIBRARY"_s };

    const QCommandLineOption checkJob { u"check-job"_s,
        QApplication::translate(
            "main", "Check the G-code PROGRAM against the table once the window is open."),
        u"PROGRAM"_s };

    void describe(QCommandLineParser &parser) const
    {
        parser.setApplicationDescription(QApplication::translate("main", "Toffee, the tool offset manager."));
        parser.addHelpOption();
        parser.addVersionOption();
        parser.addOptions(
            { emulator, emulatorFirmware, port, baud, host, selfTest, dark, lang, library, checkJob });
        parser.addPositionalArgument(
            u"table"_s, QApplication::translate("main", "A tool table to open."), u"[table]"_s);
    }
};

void nameTheApplication()
{
    QCoreApplication::setOrganizationName(u"Toffee"_s);
    QCoreApplication::setApplicationName(u"Toffee"_s);
    QCoreApplication::setApplicationVersion(QStringLiteral(TOFFEE_VERSION));
}

// --help and --version are answered before the window system is touched: they need no display.
bool asksForHelpOrVersion(int argc, char *argv[])
{
    for (int i = 1; i < argc; ++i) {
        const QByteArrayView a(argv[i]);
        if (a == "--")
            return false;
        if (a == "-h" || a == "--help" || a == "--help-all" || a == "-v" || a == "--version")
            return true;
    }
    return false;
}

} // namespace

int main(int argc, char *argv[])
{
    QElapsedTimer sinceLaunch;
    sinceLaunch.start();
    // Over a file-size limit (ulimit -f) a write then fails with "File too large", which a save reports like
    // a full disk with the old file whole, instead of the process being killed in the middle of it.
    std::signal(SIGXFSZ, SIG_IGN);
    if (asksForHelpOrVersion(argc, argv)) {
        QCoreApplication core(argc, argv);
        nameTheApplication();
        QCommandLineParser parser;
        Options().describe(parser);
        parser.process(core); // prints and exits
        return 0;
    }
    QApplication app(argc, argv);
    nameTheApplication();
    QApplication::setApplicationDisplayName(u"Toffee"_s);
    QApplication::setDesktopFileName(u"org.toffee.Toffee"_s);

    QCommandLineParser parser;
    const Options options;
    options.describe(parser);
    parser.process(app);
    const QString firmware = parser.value(options.emulatorFirmware);
    if (firmware != u"community" && firmware != u"stock") {
        std::fprintf(stderr, "toffee: --emulator-firmware takes community or stock, not \"%s\".\n",
            qPrintable(firmware));
        return 2;
    }
    // --lang for this run, else the language chosen in the window (View ▸ Language), else the system's.
    const QString language
        = parser.isSet(options.lang) ? parser.value(options.lang) : Toffee::AppSettings().language();
    if (language != u"en")
        Toffee::installTranslations(&app, language);

    if (parser.isSet(options.selfTest))
        QStandardPaths::setTestModeEnabled(true); // a smoke test leaves the user's settings alone
    Toffee::applyPalette(parser.isSet(options.dark) || Toffee::AppSettings().darkPalette());
    // An operator's start shows the frame first and builds what fills it after (see below); the self-test and
    // the tests build it whole, at once.
    Toffee::MainWindow window(parser.isSet(options.selfTest) ? Toffee::MainWindow::Build::Now
                                                             : Toffee::MainWindow::Build::AfterShow);
    if (parser.isSet(options.selfTest)) {
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
    window.showThenBuild();
    if (parser.isSet(options.library)) {
        // A library named wrongly is said in the window (started from a desktop menu, nobody reads stderr),
        // which goes on with the station's own library.
        const auto location = Toffee::LibraryLocation::parse(parser.value(options.library));
        if (location)
            window.setLibrary(location.value());
        else
            window.refuseLibrary(location.error().message);
    }
    // Edits a crash would have lost come first; the table asked for opens when none are recovered.
    if (!Toffee::offerRecovery(&window) && !parser.positionalArguments().isEmpty())
        window.openFile(parser.positionalArguments().constFirst());
    if (parser.isSet(options.emulator) || parser.isSet(options.port) || parser.isSet(options.host)) {
        Toffee::ConnectionTarget target;
        target.emulator = parser.isSet(options.emulator);
        target.port = parser.value(options.port);
        target.baud = parser.value(options.baud).toInt();
        if (parser.isSet(options.host) && !target.emulator) {
            const auto address = Toffee::TcpTransport::parseAddress(parser.value(options.host));
            if (!address) {
                QTextStream(stderr) << "toffee: " << address.error().message << '\n';
                return 2;
            }
            target.host = address.value().host;
            target.tcpPort = address.value().port;
        }
        target.emulatorStock = firmware == u"stock";
        target.emulatorPaced = true;
        window.machineDock()->connectionPanel()->setTarget(target);
        window.connection()->connectTo(target);
    }
    if (parser.isSet(options.checkJob))
        window.openJobCheck(parser.value(options.checkJob));
    return QApplication::exec();
}
