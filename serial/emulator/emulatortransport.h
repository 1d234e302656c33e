// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "serial/transport/linetransport.h"

namespace Toffee {

class CarveraEmulator;

// The in-process emulator behind the transport seam. Both directions are queued, as a real port is
// asynchronous: nothing above can tell it from a serial port.
class EmulatorTransport final : public LineTransport
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(EmulatorTransport)

public:
    // Uses `emulator` (not owned) or, when null, a default one of its own.
    explicit EmulatorTransport(CarveraEmulator *emulator = nullptr, QObject *parent = nullptr);
    ~EmulatorTransport() override;

    void open() override;
    void close() override;
    [[nodiscard]] bool isOpen() const override { return m_open; }
    void writeLine(const QByteArray &line) override;
    void writeRealtime(char c) override;
    [[nodiscard]] QString description() const override;

    [[nodiscard]] CarveraEmulator *emulator() const { return m_emulator; }

private:
    void lose(const QString &message);

    CarveraEmulator *m_emulator;
    bool m_ownsEmulator;
    bool m_open = false;
};

} // namespace Toffee
