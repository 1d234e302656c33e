// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>

#include "serial/emulator/emulatorwire.h"

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
    // What waits for a client that does not read; beyond it, output is lost, as from a UART's overrun.
    static constexpr qsizetype kMaxPendingBytes = 64 * 1024;

    PtyServer(CarveraEmulator *emulator, const QString &linkPath = {}, QObject *parent = nullptr);
    ~PtyServer() override;

    // Frames, as Makera's current firmware speaks on USB, instead of plain text; before start().
    void setFramed(bool framed);
    // Opens the terminal; false, with errorString(), when the system has none to give.
    bool start();
    [[nodiscard]] QString devicePath() const { return m_devicePath; }
    [[nodiscard]] QString errorString() const { return m_error; }
    // Output waiting for the client to read, and the lines lost because it did not.
    [[nodiscard]] qsizetype pendingBytes() const { return m_out.size(); }
    [[nodiscard]] qint64 droppedLines() const { return m_droppedLines; }

Q_SIGNALS:
    // A new terminal, after start() or after a hang-up.
    void deviceChanged(const QString &path);

private:
    void readMaster();
    void send(const QByteArray &line);
    void flush();
    void stop();

    CarveraEmulator *m_emulator;
    EmulatorWire m_wire;
    QString m_linkPath;
    QString m_devicePath;
    QString m_error;
    int m_master = -1;
    int m_slave = -1; // held open so the master never reads EIO between clients
    QSocketNotifier *m_notifier = nullptr;
    QSocketNotifier *m_writable = nullptr; // on while output waits
    QByteArray m_out;
    qint64 m_droppedLines = 0;
};

} // namespace Toffee
