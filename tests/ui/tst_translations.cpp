// SPDX-License-Identifier: GPL-3.0-or-later
// The translations are complete, and what the window shows really comes out translated.
#include <QApplication>
#include <QDir>
#include <QDirIterator>
#include <QDoubleSpinBox>
#include <QFile>
#include <QHeaderView>
#include <QLabel>
#include <QMenuBar>
#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTranslator>
#include <QXmlStreamReader>

#include "model/document/tooldocument.h"
#include "model/gcode/gcodeinterpreter.h"
#include "model/job/jobchecker.h"
#include "model/job/jobpreparer.h"
#include "ui/common/appearance.h"
#include "ui/common/translations.h"
#include "ui/shell/mainwindow.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

struct Message
{
    QString source;
    QString translation;
    QString type;
};

QList<Message> readTs(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QXmlStreamReader xml(&file);
    QList<Message> messages;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement() && xml.name() == u"message")
            messages.append(Message {});
        else if (xml.isStartElement() && xml.name() == u"source")
            messages.last().source = xml.readElementText();
        else if (xml.isStartElement() && xml.name() == u"translation") {
            messages.last().type = xml.attributes().value(u"type"_s).toString();
            messages.last().translation = xml.readElementText();
        }
    }
    return messages;
}

QStringList placeholders(const QString &text)
{
    QStringList found;
    auto it = QRegularExpression(u"%\\d"_s).globalMatch(text);
    while (it.hasNext())
        found << it.next().captured();
    found.sort();
    found.removeDuplicates();
    return found;
}

} // namespace

class TestTranslations : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void everyStringIsTranslated_data()
    {
        QTest::addColumn<QString>("file");
        QTest::newRow("German") << u"toffee_de.ts"_s;
        QTest::newRow("Simplified Chinese") << u"toffee_zh_CN.ts"_s;
    }
    void everyStringIsTranslated()
    {
        QFETCH(QString, file);
        const QList<Message> messages = readTs(QStringLiteral(TOFFEE_SOURCE_DIR "/translations/") + file);
        QVERIFY(messages.size() > 300);
        for (const Message &m : messages) {
            QVERIFY2(m.type.isEmpty(), qPrintable(m.type + u": "_s + m.source));
            QVERIFY2(!m.translation.isEmpty(), qPrintable(m.source));
            QVERIFY2(placeholders(m.source) == placeholders(m.translation), qPrintable(m.source));
            QVERIFY2(m.source.contains(u'&') == m.translation.contains(u'&'), qPrintable(m.source));
        }
    }

    void theFilesCoverEveryStringInTheSources()
    {
        // lupdate over the sources into a copy: nothing new may turn up (run `cmake --build build -t
        // update_translations` and translate, when this fails).
        QTemporaryDir dir;
        const QString copy = dir.filePath(u"toffee_de.ts"_s);
        QVERIFY(QFile::copy(QStringLiteral(TOFFEE_SOURCE_DIR "/translations/toffee_de.ts"), copy));
        QFile::setPermissions(copy, QFileDevice::ReadOwner | QFileDevice::WriteOwner);
        QProcess lupdate;
        lupdate.setWorkingDirectory(QStringLiteral(TOFFEE_SOURCE_DIR));
        lupdate.start(QStringLiteral(TOFFEE_LUPDATE),
            { u"-no-obsolete"_s, u"-locations"_s, u"none"_s, u"-I"_s, u"."_s, u"model"_s, u"serial"_s,
                u"ui"_s, u"app/gui"_s, u"-ts"_s, copy });
        QVERIFY(lupdate.waitForFinished(60000));
        QCOMPARE(lupdate.exitCode(), 0);
        for (const Message &m : readTs(copy))
            QVERIFY2(m.type.isEmpty(), qPrintable(u"not in translations/*.ts yet: "_s + m.source));
    }

    // lupdate files a class member's tr() under the class, but at run time an unqualified tr() in a class
    // without Q_OBJECT or Q_DECLARE_TR_FUNCTIONS is the free one (context "Toffee"): its messages would never
    // come out translated. Every context in the files must be one the code really translates in.
    void everyContextIsOneTheCodeTranslatesIn()
    {
        QString sources;
        for (const QString &folder : { u"app"_s, u"ui"_s, u"model"_s, u"serial"_s }) {
            QDirIterator it(QStringLiteral(TOFFEE_SOURCE_DIR "/") + folder, { u"*.h"_s, u"*.cpp"_s },
                QDir::Files, QDirIterator::Subdirectories);
            while (it.hasNext()) {
                QFile file(it.next());
                QVERIFY(file.open(QIODevice::ReadOnly));
                sources += QString::fromUtf8(file.readAll());
            }
        }
        QFile ts(QStringLiteral(TOFFEE_SOURCE_DIR "/translations/toffee_de.ts"));
        QVERIFY(ts.open(QIODevice::ReadOnly));
        QXmlStreamReader xml(&ts);
        QStringList wrong;
        int contexts = 0;
        while (xml.readNextStartElement() || !xml.atEnd()) {
            if (!xml.isStartElement() || xml.name() != u"name")
                continue;
            const QString context = xml.readElementText();
            ++contexts;
            if (context.isEmpty()) { // lupdate could not tell whose tr() it was (an alias, D::tr): none at
                                     // run time
                wrong << u"(a context without a name)"_s;
                continue;
            }
            if (context == u"Toffee" || context == u"main")
                continue; // the free tr() of model/translate.h, and the programs' main()
            const QString name = context.section(u"::"_s, -1);
            const bool declared = QRegularExpression(
                u"(class|struct) "_s + name + u"\\b[^;{]*\\{\\s*(Q_OBJECT|Q_GADGET|Q_DECLARE_TR_FUNCTIONS)"_s)
                                      .match(sources)
                                      .hasMatch();
            const bool named = sources.contains(u'"' + context + u'"'); // QCoreApplication::translate("…", …)
            if (!declared && !named)
                wrong << context;
        }
        QVERIFY(contexts > 10);
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join(u", "_s)));
    }

    void theWindowSpeaksGerman()
    {
        QTranslator german;
        QVERIFY(german.load(QStringLiteral(TOFFEE_BUILD_DIR "/translations/toffee_de.qm")));
        QCoreApplication::installTranslator(&german);
        {
            MainWindow window;
            QStringList menus;
            for (QAction *a : window.menuBar()->actions())
                menus << a->text();
            QVERIFY2(
                menus.contains(u"&Datei"_s) && menus.contains(u"&Maschine"_s), qPrintable(menus.join(u' ')));
            auto *view = window.findChild<QTableView *>(u"toolTable"_s);
            QCOMPARE(view->model()->headerData(0, Qt::Horizontal).toString(), u"Werkzeug"_s);
            // A message from the model library, a free function's tr(): the contexts must line up.
            QVERIFY(window.document()->addTool(Tool { 1, 1, {}, 10, 0, 0, 0, {}, {}, {}, {} }).ok());
            QSignalSpy rejected(window.document()->model(), &ToolTableModel::editRejected);
            QTimer::singleShot(0, [] {
                if (auto *box = QApplication::activeModalWidget())
                    box->close();
            });
            QVERIFY(!window.document()->model()->setData(
                window.document()->model()->index(0, ToolTableModel::LengthWearColumn), u"250"_s));
            QCOMPARE(rejected.size(), 1);
            const QString message = rejected.front().front().toString();
            QVERIFY2(message.contains(u"Längenverschleiß"_s) && message.contains(u"außerhalb des Bereichs"_s),
                qPrintable(message));
            // The interpreter's and the tokenizer's messages (they were filed under their classes by lupdate
            // but looked up in "Toffee" at run time, and came out in English).
            GCodeInterpreter fanuc(Dialect::Fanuc);
            const auto twice = fanuc.runLine("G0 X1 X2", 1);
            QVERIFY(!twice);
            QCOMPARE(twice.error().message, u"Das Wort X kommt in einem Satz zweimal vor."_s);
            const auto notANumber = fanuc.runLine("G0 X1..2", 2);
            QVERIFY(!notANumber);
            QCOMPARE(notANumber.error().message, u"„1..2“ ist keine Zahl."_s);
            // The job check speaks German; the comments a preparation writes into a program stay English and
            // ASCII, for the controller.
            JobCheckSetup setup;
            JobChecker checker(setup);
            checker.feed("G20", 1);
            QVERIFY(checker.finish(u"de.nc"_s, false).findings.front().message.contains(u"Zoll"_s));
            const ToolTable table = ToolTable::fromTools(
                { Tool { 2, 2, {}, 40, 0, 3, 0, -33.388, QDateTime::currentDateTimeUtc(), {}, {} } },
                Units::Millimetre)
                                        .value();
            PrepareOptions options;
            options.breakTest = true;
            options.useStoredTlo = true;
            options.rack = {};
            JobPreparer preparer(table, options);
            QByteArray program;
            const auto sink = [&program](QByteArrayView line) {
                program += line.toByteArray() + '\n';
                return true;
            };
            for (const QByteArray &line :
                { QByteArray("M6 T2"), QByteArray("M3 S1000"), QByteArray("G1 Z-1 F100") })
                QVERIFY(preparer.feed(line, 1, sink).ok());
            QVERIFY(preparer.finish(sink).ok());
            QVERIFY2(program.contains("(Toffee: break test of T2"), program.constData());
            for (char c : program)
                QVERIFY2(c > 0 && c < 0x7f, program.constData());
        }
        QCoreApplication::removeTranslator(&german);
    }

    // Last: it leaves German installed, as the window's start does.
    void theGermanWindowHasQtsOwnButtonsAndOneDecimalSeparator()
    {
        QCOMPARE(
            installTranslations(qApp, u"de"_s, QStringLiteral(TOFFEE_BUILD_DIR "/translations")), u"de_DE"_s);
        // Qt's own dialogs' buttons (Debian's qt6-translations-l10n), not English beside German.
        QCOMPARE(QCoreApplication::translate("QPlatformTheme", "&Yes"), u"&Ja"_s);
        QCOMPARE(QCoreApplication::translate("QPlatformTheme", "Cancel"), u"Abbrechen"_s);
        {
            MainWindow window;
            Tool tool { 1, 1, {}, 71.488, 0, 3, 0, -33.388, QDateTime::currentDateTimeUtc(), {}, {} };
            QVERIFY(window.document()->addTool(tool).ok());
            auto *model = window.document()->model();
            // The table, the panels' numbers and the spin boxes all write 0,000.
            QCOMPARE(model->index(0, ToolTableModel::LengthGeometryColumn).data().toString(), u"71,488"_s);
            QCOMPARE(model->index(0, ToolTableModel::MeasuredTloColumn).data().toString(), u"-33,388"_s);
            QCOMPARE(millimetres(-33.388), u"-33,388 mm"_s);
            QCOMPARE(millimetres(1234.5), u"1234,500 mm"_s); // never grouped
            auto *spin = window.findChild<QDoubleSpinBox *>(u"toleranceSpin"_s);
            QVERIFY(spin->text().contains(u','));
            // The longer German words still fit the smallest screen Toffee is laid out for.
            QVERIFY2(window.minimumSizeHint().width() <= 1280,
                qPrintable(QString::number(window.minimumSizeHint().width())));
            // What goes to the machine keeps G-code's point whatever the language.
            auto *preview = window.findChild<QLabel *>(u"offsetCommandPreview"_s);
            QVERIFY2(!preview->text().contains(u','), qPrintable(preview->text()));
        }
        QLocale::setDefault(QLocale::c());
    }
};

QTEST_MAIN(TestTranslations)
#include "tst_translations.moc"
