// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>

#include <QObject>
#include <QTimer>

#include "model/result.h"
#include "serial/machine/machinereplies.h"

namespace Toffee {

class MachineLink;

// Which controller the machine runs. Auto: found by asking (ControllerDetector), never assumed.
enum class ControllerKind { Auto, Carvera, GrblHal, LinuxCnc };

// "carvera", "grblhal", "linuxcnc" (toffee-cli --controller, the settings, the JSON); "auto" for Auto.
[[nodiscard]] QString controllerKindName(ControllerKind kind);
// "Carvera", "grblHAL", "LinuxCNC", for people.
[[nodiscard]] QString controllerKindTitle(ControllerKind kind);
// Every controller Toffee manages, Auto first: what --controller, the settings and the window offer.
[[nodiscard]] QList<ControllerKind> controllerKinds();
// Whether the controller keeps its own reference tool (the Carvera's firmware); the others are given the one
// Toffee kept for the machine (grblHAL, LinuxCNC: the first tool measured on it).
[[nodiscard]] bool keepsOwnReference(ControllerKind kind);
// The G-code dialect a machine with this controller's programs are checked in ("carvera", "grblhal",
// "linuxcnc").
[[nodiscard]] QString dialectKeyOf(ControllerKind kind);

// What the questions found: the controller and what it said of itself.
struct DetectedController
{
    ControllerKind kind = ControllerKind::Auto;
    FirmwareInfo firmware; // from `version` (a Carvera) or $I (grblHAL)
    QString name; // the name the controller gives itself: grblHAL's build name ($I=NAME), else empty
};

// Finds which controller answers on a link before anything controller-specific is sent. The link's transport
// has asked its first question already (StreamTransport: `version ?` in a frame, harmless to all). A link
// that speaks Makera's frames is a Carvera's. Otherwise, in plain text: `version`, which a Carvera answers
// "version = …" and grblHAL refuses ("error:2"); then, refused, `$I`, which grblHAL answers with
// [FIRMWARE:grblHAL]. Both are questions that change nothing on either (seen on the firmwares in
// ../shared/peers; docs/ARCHITECTURE.md). A network link whose first question got no answer at all is asked
// LinuxCNC's `hello EMC toffee 1.0`, which linuxcncrsh answers HELLO ACK (a Carvera and grblHAL refuse it, seen
// on their peers). Anything else is refused by what it said, and nothing more is sent.
class ControllerDetector final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ControllerDetector)

public:
    using Done = std::function<void(const Result<DetectedController> &)>;

    explicit ControllerDetector(MachineLink *link, QObject *parent = nullptr);
    // Opens the link when it is not open, asks, and calls `done` once.
    void detect(Done done);

private:
    void ask();
    void askBuild(const QString &versionAnswer);
    void askHello();
    void finish(const Result<DetectedController> &result);

    MachineLink *m_link;
    Done m_done;
    QTimer m_openGuard;
    QList<QMetaObject::Connection> m_opening;
};

} // namespace Toffee
