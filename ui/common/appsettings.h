// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QByteArray>
#include <QSettings>
#include <QStringList>

#include "model/toolsetter.h"

namespace Toffee {

// Every remembered setting, typed, with its key in one place. Tests enable QStandardPaths' test mode so
// that they never touch the user's settings.
class AppSettings
{
public:
    [[nodiscard]] QByteArray windowGeometry() const;
    void setWindowGeometry(const QByteArray &geometry);
    [[nodiscard]] QByteArray windowState() const;
    void setWindowState(const QByteArray &state);
    [[nodiscard]] QString lastDirectory() const;
    void setLastDirectory(const QString &directory);
    [[nodiscard]] QStringList recentFiles() const;
    // Puts `path` first, keeps at most kMaxRecentFiles.
    void addRecentFile(const QString &path);

    // "emulator", or a serial port's path.
    [[nodiscard]] QString connectionPort() const;
    void setConnectionPort(const QString &port);
    // How the machine was last reached: "serial", "wifi" or "emulator" (empty before any: connectionPort()
    // says it then), and the last machine on the network as HOST:PORT.
    [[nodiscard]] QString connectionKind() const;
    void setConnectionKind(const QString &kind);
    // "carvera" or "grblhal": the controller chosen for a serial port or an address typed in.
    [[nodiscard]] QString connectionController() const;
    void setConnectionController(const QString &controller);
    // A machine's tool setter, on this computer (the library keeps it too, when there is one).
    [[nodiscard]] std::optional<ToolSetter> toolSetter(const QString &machine) const;
    void setToolSetter(const QString &machine, const ToolSetter &setter);
    // How a LinuxCNC machine is reached beyond its address, on this computer: the INI it runs (whose tool table
    // Toffee reads) and linuxcncrsh's enable password (empty: LinuxCNC's default). Never shown or logged.
    struct LinuxCncAccess
    {
        QString ini;
        QString enablePassword;
    };
    [[nodiscard]] LinuxCncAccess linuxCncAccess(const QString &machine) const;
    void setLinuxCncAccess(const QString &machine, const LinuxCncAccess &access);
    [[nodiscard]] QString connectionHost() const;
    void setConnectionHost(const QString &address);
    // The name the last machine on the network announced itself by (empty: typed, never heard), so that it
    // is found again at a new address.
    [[nodiscard]] QString connectionHostName() const;
    void setConnectionHostName(const QString &name);
    [[nodiscard]] int connectionBaud() const;
    void setConnectionBaud(int baud);
    [[nodiscard]] double breakTestTolerance() const;
    void setBreakTestTolerance(double millimetres);

    [[nodiscard]] QString exportDialect() const;
    void setExportDialect(const QString &key);
    // The history library ("sqlite:PATH"; empty: the standard one) and this machine's name in it.
    [[nodiscard]] QString libraryLocation() const;
    void setLibraryLocation(const QString &location);
    [[nodiscard]] QString machineName() const;
    void setMachineName(const QString &name);
    // The name the operator gave the machine; empty when none (then machineName() is the default).
    [[nodiscard]] QString chosenMachineName() const;
    // Who this station writes as in a shared library ("Mill 2 PC"); empty: the computer's name.
    [[nodiscard]] QString stationName() const;
    void setStationName(const QString &name);
    // A measurement older than this is stale (the table marks it).
    [[nodiscard]] int staleAfterDays() const;
    void setStaleAfterDays(int days);
    // File ▸ Check Job…: the controller a program is checked for, the Z floor (nothing: none), and what
    // Prepare… does for the Carvera.
    [[nodiscard]] QString jobDialect() const;
    void setJobDialect(const QString &key);
    [[nodiscard]] std::optional<double> jobZFloor() const;
    // The floor until one is chosen: on, 20 mm below work Z0 (deeper than the stock of most jobs on a desktop
    // machine); turned off, it stays off.
    static constexpr double kDefaultJobZFloor = -20.0;
    void setJobZFloor(std::optional<double> z);
    // The Carvera's rack, as written in the dialog ("1-6", "none").
    [[nodiscard]] QString jobRack() const;
    void setJobRack(const QString &rack);
    [[nodiscard]] bool prepareUsesStoredTlo() const;
    void setPrepareUsesStoredTlo(bool use);
    [[nodiscard]] bool prepareBreakTests() const;
    void setPrepareBreakTests(bool test);
    // The Rack panel: Check Rack's tolerance, and whether a manual change takes a fresh stored TLO instead of
    // a probe (its rack is jobRack(), so that the panel and the job check agree).
    [[nodiscard]] double rackTolerance() const;
    void setRackTolerance(double millimetres);
    [[nodiscard]] bool rackUsesStoredTlo() const;
    void setRackUsesStoredTlo(bool use);
    [[nodiscard]] bool darkPalette() const;
    void setDarkPalette(bool dark);
    // The window's language: "de", "zh_CN", "en", or empty for the system's; --lang overrides it for one run.
    [[nodiscard]] QString language() const;
    void setLanguage(const QString &language);

    static constexpr int kMaxRecentFiles = 8;

private:
    QSettings m_settings;
};

} // namespace Toffee
