// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>

class QSocketNotifier;

namespace Toffee {

class CarveraEmulator;

// Serves an emulator on a pseudo-terminal, so a real QSerialPort (and any terminal program) can talk to it.
// The byte stream is split as the firmware splits it: '?' and Ctrl-X act at once, '!' and '~' at a line's
// start, and '\r' ends a line like '\n'. A "close link" fault hangs the terminal up and opens a new one.
class PtyServer final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(PtyServer)

public:
    PtyServer(CarveraEmulator *emulator, const QString &linkPath = {}, QObject *parent = nullptr);
    ~PtyServer() override;

    // Opens the terminal; false, with errorString(), when the system has none to give.
    bool start();
    [[nodiscard]] QString devicePath() const { return m_devicePath; }
    [[nodiscard]] QString errorString() const { return m_error; }

Q_SIGNALS:
    // A new terminal, after start() or after a hang-up.
    void deviceChanged(const QString &path);

private:
    void readMaster();
    void feed(char c);
    void send(const QByteArray &line);
    void stop();

    CarveraEmulator *m_emulator;
    QString m_linkPath;
    QString m_devicePath;
    QString m_error;
    int m_master = -1;
    int m_slave = -1; // held open so the master never reads EIO between clients
    QSocketNotifier *m_notifier = nullptr;
    QByteArray m_line;
};

} // namespace Toffee
