// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/common/appsettings.h"

#include <algorithm>
#include <cmath>

#include <QDir>

#include "model/library/historyevent.h"
#include "model/limits.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {
namespace Key {
const auto Geometry = u"window/geometry"_s;
const auto State = u"window/state"_s;
const auto LastDirectory = u"files/lastDirectory"_s;
const auto RecentFiles = u"files/recent"_s;
const auto ConnectionPort = u"machine/port"_s;
const auto ConnectionBaud = u"machine/baud"_s;
const auto ConnectionKind = u"machine/link"_s;
const auto ConnectionHost = u"machine/host"_s;
const auto ConnectionHostName = u"machine/hostName"_s;
// "auto", "carvera" or "grblhal". A new key: the old one ("machine/controller") held "carvera" for everyone
// who never chose, which would now insist on a Carvera; automatic finds either.
const auto ConnectionController = u"machine/controllerChoice"_s;
const auto ToolSetters = u"machine/toolSetters"_s; // a group: one key per machine name
const auto LinuxCncInis = u"machine/linuxcncIni"_s; // groups: one key per machine name
const auto LinuxCncPasswords = u"machine/linuxcncEnable"_s;
const auto Tolerance = u"machine/breakTestTolerance"_s;
const auto DarkPalette = u"view/darkPalette"_s;
const auto Language = u"view/language"_s;
const auto Library = u"history/library"_s;
const auto MachineName = u"history/machine"_s;
const auto StaleDays = u"history/staleAfterDays"_s;
const auto ExportDialect = u"files/exportDialect"_s;
const auto JobDialect = u"jobs/dialect"_s;
const auto JobZFloor = u"jobs/zFloor"_s;
const auto StationName = u"history/station"_s;
const auto PrepareStoredTlo = u"jobs/prepareUsesStoredTlo"_s;
const auto JobRack = u"jobs/rack"_s;
const auto PrepareBreakTests = u"jobs/prepareBreakTests"_s;
const auto RackTolerance = u"rack/tolerance"_s;
const auto RackStoredTlo = u"rack/useStoredTlo"_s;
} // namespace Key
} // namespace

QByteArray AppSettings::windowGeometry() const
{
    return m_settings.value(Key::Geometry).toByteArray();
}

void AppSettings::setWindowGeometry(const QByteArray &geometry)
{
    m_settings.setValue(Key::Geometry, geometry);
}

QByteArray AppSettings::windowState() const
{
    return m_settings.value(Key::State).toByteArray();
}

void AppSettings::setWindowState(const QByteArray &state)
{
    m_settings.setValue(Key::State, state);
}

QString AppSettings::lastDirectory() const
{
    return m_settings.value(Key::LastDirectory, QDir::homePath()).toString();
}

void AppSettings::setLastDirectory(const QString &directory)
{
    m_settings.setValue(Key::LastDirectory, directory);
}

QStringList AppSettings::recentFiles() const
{
    return m_settings.value(Key::RecentFiles).toStringList();
}

void AppSettings::addRecentFile(const QString &path)
{
    QStringList files = recentFiles();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > kMaxRecentFiles)
        files.removeLast();
    m_settings.setValue(Key::RecentFiles, files);
}

QString AppSettings::connectionPort() const
{
    return m_settings.value(Key::ConnectionPort, u"emulator"_s).toString();
}

void AppSettings::setConnectionPort(const QString &port)
{
    m_settings.setValue(Key::ConnectionPort, port);
}

QString AppSettings::connectionKind() const
{
    return m_settings.value(Key::ConnectionKind).toString();
}

void AppSettings::setConnectionKind(const QString &kind)
{
    m_settings.setValue(Key::ConnectionKind, kind);
}

QString AppSettings::connectionController() const
{
    return m_settings.value(Key::ConnectionController).toString();
}

void AppSettings::setConnectionController(const QString &controller)
{
    m_settings.setValue(Key::ConnectionController, controller);
}

std::optional<ToolSetter> AppSettings::toolSetter(const QString &machine) const
{
    const QString text
        = m_settings.value(Key::ToolSetters + u'/' + QString::fromLatin1(machine.toUtf8().toHex()))
              .toString();
    if (text.isEmpty())
        return std::nullopt;
    auto setter = ToolSetter::parse(text);
    return setter ? std::optional(setter.value()) : std::nullopt;
}

AppSettings::LinuxCncAccess AppSettings::linuxCncAccess(const QString &machine) const
{
    const QString key = u'/' + QString::fromLatin1(machine.toUtf8().toHex());
    return { m_settings.value(Key::LinuxCncInis + key).toString(),
        m_settings.value(Key::LinuxCncPasswords + key).toString() };
}

void AppSettings::setLinuxCncAccess(const QString &machine, const LinuxCncAccess &access)
{
    const QString key = u'/' + QString::fromLatin1(machine.toUtf8().toHex());
    m_settings.setValue(Key::LinuxCncInis + key, access.ini);
    m_settings.setValue(Key::LinuxCncPasswords + key, access.enablePassword);
}

void AppSettings::setToolSetter(const QString &machine, const ToolSetter &setter)
{
    m_settings.setValue(
        Key::ToolSetters + u'/' + QString::fromLatin1(machine.toUtf8().toHex()), setter.text());
}

QString AppSettings::connectionHost() const
{
    return m_settings.value(Key::ConnectionHost).toString();
}

void AppSettings::setConnectionHost(const QString &address)
{
    m_settings.setValue(Key::ConnectionHost, address);
}

QString AppSettings::connectionHostName() const
{
    return m_settings.value(Key::ConnectionHostName).toString();
}

void AppSettings::setConnectionHostName(const QString &name)
{
    m_settings.setValue(Key::ConnectionHostName, name);
}

int AppSettings::connectionBaud() const
{
    return m_settings.value(Key::ConnectionBaud, 115200).toInt();
}

void AppSettings::setConnectionBaud(int baud)
{
    m_settings.setValue(Key::ConnectionBaud, baud);
}

QString AppSettings::libraryLocation() const
{
    return m_settings.value(Key::Library).toString();
}

void AppSettings::setLibraryLocation(const QString &location)
{
    m_settings.setValue(Key::Library, location);
}

QString AppSettings::machineName() const
{
    const QString name = m_settings.value(Key::MachineName).toString().trimmed();
    return name.isEmpty() ? kDefaultMachineName : name;
}

QString AppSettings::chosenMachineName() const
{
    return m_settings.value(Key::MachineName).toString().trimmed();
}

void AppSettings::setMachineName(const QString &name)
{
    m_settings.setValue(Key::MachineName, name);
}

QString AppSettings::stationName() const
{
    return m_settings.value(Key::StationName).toString().simplified();
}

void AppSettings::setStationName(const QString &name)
{
    if (name.simplified().isEmpty())
        m_settings.remove(Key::StationName);
    else
        m_settings.setValue(Key::StationName, name.simplified());
}

int AppSettings::staleAfterDays() const
{
    return std::max(1, m_settings.value(Key::StaleDays, 7).toInt());
}

void AppSettings::setStaleAfterDays(int days)
{
    m_settings.setValue(Key::StaleDays, days);
}

double AppSettings::breakTestTolerance() const
{
    return m_settings.value(Key::Tolerance, 0.1).toDouble();
}

void AppSettings::setBreakTestTolerance(double millimetres)
{
    m_settings.setValue(Key::Tolerance, millimetres);
}

QString AppSettings::exportDialect() const
{
    return m_settings.value(Key::ExportDialect, u"fanuc"_s).toString();
}

void AppSettings::setExportDialect(const QString &key)
{
    m_settings.setValue(Key::ExportDialect, key);
}

bool AppSettings::darkPalette() const
{
    return m_settings.value(Key::DarkPalette, false).toBool();
}

void AppSettings::setDarkPalette(bool dark)
{
    m_settings.setValue(Key::DarkPalette, dark);
}

QString AppSettings::language() const
{
    const QString language = m_settings.value(Key::Language).toString();
    return QStringList { u"de"_s, u"zh_CN"_s, u"en"_s }.contains(language) ? language : QString();
}

void AppSettings::setLanguage(const QString &language)
{
    if (language.isEmpty())
        m_settings.remove(Key::Language);
    else
        m_settings.setValue(Key::Language, language);
}

QString AppSettings::jobDialect() const
{
    return m_settings.value(Key::JobDialect, u"carvera"_s).toString();
}

void AppSettings::setJobDialect(const QString &key)
{
    m_settings.setValue(Key::JobDialect, key);
}

std::optional<double> AppSettings::jobZFloor() const
{
    // On until the operator turns it off: a feed below the stock is the crash the check exists for.
    if (!m_settings.contains(Key::JobZFloor))
        return kDefaultJobZFloor;
    if (m_settings.value(Key::JobZFloor).toString() == u"off"_s)
        return std::nullopt;
    bool ok = false;
    const double z = m_settings.value(Key::JobZFloor).toDouble(&ok);
    return ok && std::isfinite(z) ? std::optional(z) : kDefaultJobZFloor;
}

void AppSettings::setJobZFloor(std::optional<double> z)
{
    if (z)
        m_settings.setValue(Key::JobZFloor, *z);
    else
        m_settings.setValue(Key::JobZFloor, u"off"_s);
}

QString AppSettings::jobRack() const
{
    return m_settings.value(Key::JobRack, u"1-6"_s).toString();
}

void AppSettings::setJobRack(const QString &rack)
{
    m_settings.setValue(Key::JobRack, rack);
}

bool AppSettings::prepareUsesStoredTlo() const
{
    return m_settings.value(Key::PrepareStoredTlo, true).toBool();
}

void AppSettings::setPrepareUsesStoredTlo(bool use)
{
    m_settings.setValue(Key::PrepareStoredTlo, use);
}

double AppSettings::rackTolerance() const
{
    return m_settings.value(Key::RackTolerance, Limits::kDefaultBreakTolerance).toDouble();
}

void AppSettings::setRackTolerance(double millimetres)
{
    m_settings.setValue(Key::RackTolerance, millimetres);
}

bool AppSettings::rackUsesStoredTlo() const
{
    return m_settings.value(Key::RackStoredTlo, false).toBool();
}

void AppSettings::setRackUsesStoredTlo(bool use)
{
    m_settings.setValue(Key::RackStoredTlo, use);
}

bool AppSettings::prepareBreakTests() const
{
    return m_settings.value(Key::PrepareBreakTests, true).toBool();
}

void AppSettings::setPrepareBreakTests(bool test)
{
    m_settings.setValue(Key::PrepareBreakTests, test);
}

} // namespace Toffee
