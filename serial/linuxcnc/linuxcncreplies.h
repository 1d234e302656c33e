// SPDX-License-Identifier: GPL-3.0-or-later
// What linuxcncrsh, LinuxCNC's remote console, answers (docs/LINUXCNC.md), read by pure functions: a line's
// kind, a `get`'s value, the machine's state, a `(DEBUG,…)` line Toffee printed through MDI, the INI's tool
// table.
#pragma once

#include <array>
#include <map>
#include <optional>

#include <QByteArray>
#include <QString>

#include "serial/machine/machinereplies.h"

namespace Toffee::LinuxCnc {

// linuxcncrsh's port when none is given (its --port default).
inline constexpr quint16 kDefaultPort = 5007;
// The client name and version Toffee's hello gives (the version at most 7 characters: a longer one is
// refused).
inline constexpr char kHello[] = "hello EMC toffee 1.0";
// LinuxCNC's own default enable password (linuxcncrsh --enablepw).
inline constexpr char kDefaultEnablePassword[] = "EMCTOO";
// The longest line linuxcncrsh reads safely (its buffer is 256 bytes and unchecked).
inline constexpr qsizetype kMaxLineBytes = 240;

// "SET X ACK" and "HELLO ACK …": Ok; "SET X NAK", "GET X NAK", "HELLO NAK": Error; anything else (a get's
// answer, an echo): Other.
[[nodiscard]] ReplyKind classify(QByteArrayView line);
// Whether the line is linuxcncrsh's answer to a hello: "HELLO ACK <server> 1.1" or "HELLO NAK".
[[nodiscard]] bool isHelloAck(QByteArrayView line);
[[nodiscard]] bool isHelloNak(QByteArrayView line);
// The value of a get's answer: "TOOL 2" for keyword "TOOL" gives "2"; nothing for another line.
[[nodiscard]] std::optional<QByteArray> valueOf(QByteArrayView line, QByteArrayView keyword);

// What a series of gets said about the machine.
struct State
{
    bool estop = true;
    bool machineOn = false;
    QByteArray mode; // MANUAL, AUTO, MDI
    QByteArray program; // IDLE, RUNNING, PAUSED
    int homedJoints = 0; // of the first three
    bool enabled = false; // this connection holds linuxcncrsh's enable
    int tool = 0; // 0: an empty spindle
    std::array<double, 3> machinePosition { 0, 0, 0 };
    QByteArray programCodes; // "G80 G17 G40 G21 G90 …"
    bool millimetres = true; // G21 in the program codes (G20: inches)

    [[nodiscard]] bool homed() const { return homedJoints >= 3; }
    [[nodiscard]] bool idle() const { return program == "IDLE"; }
    // "Estop", "Off", "Idle", "Run", for the status line.
    [[nodiscard]] QString word() const;
};

// "JOINT_HOMED YES YES NO NO NO NO": how many of the first three joints say YES.
[[nodiscard]] int homedJoints(QByteArrayView value);
// "ABS_ACT_POS x y z a b c" (the value): X, Y, Z.
[[nodiscard]] std::optional<std::array<double, 3>> position(QByteArrayView value);
// Whether "PROGRAM_CODES …" has G20 in force.
[[nodiscard]] bool inInches(QByteArrayView codes);

// "TOFFEE-PRB p=-75.000000 a=… ok=1.000000" (a (DEBUG,…) line Toffee printed) as its fields, when it starts
// with `marker`; every field a number.
[[nodiscard]] std::optional<std::map<QByteArray, double>> displayFields(
    QByteArrayView display, QByteArrayView marker);

// The tool table an INI names ([EMCIO] TOOL_TABLE), relative to the INI's folder when not absolute; empty
// when it names none.
[[nodiscard]] QString toolTableOfIni(const QByteArray &iniText, const QString &iniPath);

} // namespace Toffee::LinuxCnc
