// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QString>

#include "serial/controllerdetection.h"

namespace Toffee {

struct ConnectionTarget;

// Which machine this is: its controller and the name it gives itself (grblHAL's build name, `$I=NAME`, kept in
// its EEPROM), else how it is reached (the serial port, the network address); or the built-in emulator, its
// own machine. A machine's reference, tool setter and history belong to the name the library binds to this
// identity (Library::bindMachine) and to no other machine. The Carvera says nothing that tells one machine
// from another (its `version` is the firmware's), so it is known by its link.
struct MachineIdentity
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::MachineIdentity)

public:
    ControllerKind controller = ControllerKind::Auto;
    bool emulator = false;
    QString link; // "/dev/ttyACM0", "192.168.1.57:2222"; empty for the emulator
    QString name; // what the controller calls itself (grblHAL's build name); empty when it says nothing

    // "emulator", "carvera:/dev/ttyACM0", "grblhal:192.168.1.60:23", "grblhal:name=LongMill": as the library
    // keeps it.
    [[nodiscard]] QString key() const;
    // "the built-in emulator", "the Carvera at /dev/ttyACM0", "grblHAL at 192.168.1.60:23", "grblHAL
    // “LongMill”", for people.
    [[nodiscard]] QString title() const;
    // The machine's name when nobody gave it one: "Emulator", "Carvera", "grblHAL".
    [[nodiscard]] QString defaultName() const;
    [[nodiscard]] bool isKnown() const { return emulator || controller != ControllerKind::Auto; }
    // A name bound to `bound` follows this machine without asking: both Carveras, neither named, only the link
    // differs (a USB port that came back as another device, an address that changed). The Carvera keeps its
    // reference itself, so nothing Toffee keeps is applied to the wrong machine; grblHAL's reference is
    // Toffee's, and another kind is another machine: those are asked about.
    [[nodiscard]] bool followsFrom(const MachineIdentity &bound) const
    {
        return !emulator && !bound.emulator && controller == ControllerKind::Carvera
            && bound.controller == ControllerKind::Carvera && name.isEmpty() && bound.name.isEmpty();
    }
    // The identity a key() names (a library's binding), for its title.
    [[nodiscard]] static MachineIdentity fromKey(const QString &key);
};

[[nodiscard]] MachineIdentity identityOf(
    const ConnectionTarget &target, ControllerKind controller, const QString &name = {});

} // namespace Toffee
