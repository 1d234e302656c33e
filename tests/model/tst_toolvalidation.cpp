// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <limits>

#include <QTest>

#include "model/toolvalidation.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

class TestToolValidation : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void validatesEachField_data()
    {
        QTest::addColumn<Tool>("tool");
        QTest::addColumn<int>("units");
        QTest::addColumn<QString>("error"); // a fragment of the message; empty: valid

        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        const int mm = int(Units::Millimetre);
        const int in = int(Units::Inch);
        auto tool = [](auto change) {
            Tool t;
            t.number = 5;
            t.pocket = 5;
            change(t);
            return t;
        };
        QTest::newRow("plain tool") << tool([](Tool &) {}) << mm << QString();
        QTest::newRow("geometry at the limit")
            << tool([](Tool &t) { t.lengthGeometry = 999.999; }) << mm << QString();
        QTest::newRow("geometry over the limit") << tool([](Tool &t) { t.lengthGeometry = 1000.0; }) << mm
                                                 << u"length geometry 1000 mm is out of range"_s;
        QTest::newRow("negative geometry at the limit")
            << tool([](Tool &t) { t.lengthGeometry = -999.999; }) << mm << QString();
        QTest::newRow("wear at the limit")
            << tool([](Tool &t) { t.lengthWear = -99.999; }) << mm << QString();
        QTest::newRow("wear over the limit")
            << tool([](Tool &t) { t.lengthWear = 100.0; }) << mm << u"length wear 100 mm is out of range"_s;
        QTest::newRow("radius wear over the limit")
            << tool([](Tool &t) { t.radiusWear = -120.5; }) << mm << u"radius wear -120.5 mm"_s;
        QTest::newRow("radius geometry NaN")
            << tool([=](Tool &t) { t.radiusGeometry = nan; }) << mm << u"radius geometry is not a number"_s;
        QTest::newRow("length infinite")
            << tool([=](Tool &t) { t.lengthGeometry = inf; }) << mm << u"length geometry is not a number"_s;
        QTest::newRow("inch geometry over the inch limit")
            << tool([](Tool &t) { t.lengthGeometry = 100.0; }) << in << u"out of range"_s;
        QTest::newRow("inch wear at the inch limit")
            << tool([](Tool &t) { t.lengthWear = 9.9999; }) << in << QString();
        QTest::newRow("inch wear over the inch limit")
            << tool([](Tool &t) { t.lengthWear = 10.0; }) << in << u"-9.9999 to 9.9999 in"_s;
        QTest::newRow("measured TLO out of range")
            << tool([](Tool &t) { t.measuredTlo = -1200.0; }) << mm << u"measured TLO"_s;
        QTest::newRow("measured TLO without a time is fine")
            << tool([](Tool &t) { t.measuredTlo = -33.388; }) << mm << QString();
        QTest::newRow("negative tool number")
            << tool([](Tool &t) { t.number = -1; }) << mm << u"tool number -1"_s;
        QTest::newRow("tool number too big")
            << tool([](Tool &t) { t.number = 1000000; }) << mm << u"tool number 1000000 is out of range"_s;
        QTest::newRow("T0 (wireless probe)") << tool([](Tool &t) { t.number = 0; }) << mm << QString();
        QTest::newRow("T999999 (3-axis probe)")
            << tool([](Tool &t) { t.number = 999999; }) << mm << QString();
        QTest::newRow("pocket 0 (spindle)") << tool([](Tool &t) { t.pocket = 0; }) << mm << QString();
        QTest::newRow("pocket 99999 (LinuxCNC sample)")
            << tool([](Tool &t) { t.pocket = 99999; }) << mm << QString();
        QTest::newRow("pocket too big")
            << tool([](Tool &t) { t.pocket = 100000; }) << mm << u"pocket 100000"_s;
        QTest::newRow("description with a line break")
            << tool([](Tool &t) { t.description = u"a\nb"_s; }) << mm << u"one line"_s;
        QTest::newRow("description too long")
            << tool([](Tool &t) { t.description = QString(300, u'x'); }) << mm << u"300 characters"_s;
        QTest::newRow("notes may span lines")
            << tool([](Tool &t) { t.notes = u"a\nb"_s; }) << mm << QString();
        QTest::newRow("LinuxCNC extras")
            << tool([](Tool &t) { t.linuxCncExtra = u"X0.5 Q2 I-12"_s; }) << mm << QString();
        QTest::newRow("LinuxCNC extra Q out of range")
            << tool([](Tool &t) { t.linuxCncExtra = u"Q12"_s; }) << mm << u"\"Q12\""_s;
        QTest::newRow("LinuxCNC extra unknown letter")
            << tool([](Tool &t) { t.linuxCncExtra = u"K1"_s; }) << mm << u"\"K1\""_s;
    }
    void validatesEachField()
    {
        QFETCH(Tool, tool);
        QFETCH(int, units);
        QFETCH(QString, error);
        const auto result = validateTool(tool, Units(units));
        if (error.isEmpty()) {
            QVERIFY2(result.ok(), qPrintable(result.error().message));
        } else {
            QVERIFY(!result.ok());
            QVERIFY2(result.error().message.contains(error), qPrintable(result.error().message));
        }
    }
};

QTEST_GUILESS_MAIN(TestToolValidation)
#include "tst_toolvalidation.moc"
