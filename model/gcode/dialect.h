// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QList>
#include <QString>

#include "model/result.h"
#include "model/tooltable.h"

namespace Toffee {

// The controllers Toffee speaks. One tool table; what differs is the G-code that writes offsets into the
// controller and how a program's positions are compensated (see docs/DIALECTS.md).
enum class Dialect { Carvera, Fanuc, Fagor8055M, AllenBradley9, Aerotech, LinuxCnc, GrblHal };

struct DialectInfo
{
    Dialect dialect;
    QString key; // as on the command line: carvera, fanuc, fagor, ab9, aerotech, linuxcnc, grblhal
    QString name;
    // How a table is written, or empty when the controller has no way to program its offset table.
    QString howOffsetsAreWritten;
    // Whether a whole table survives export -> simulate (the controller keeps a table of offsets).
    bool holdsATable = false;
};

[[nodiscard]] const QList<DialectInfo> &dialects();
[[nodiscard]] const DialectInfo &dialectInfo(Dialect dialect);
[[nodiscard]] std::optional<Dialect> dialectFromKey(QStringView key);
// Whether the controller's length compensation is G43 / G44 / G49 with a register (FANUC, FAGOR,
// Allen-Bradley, LinuxCNC): a tool change needs its G43 after it.
[[nodiscard]] bool usesG43(Dialect dialect);
// LinuxCNC's tool table words: G10 L1 writes a tool's entry, G43 H applies it, G43.1 Z a dynamic offset, and
// G59.1 to G59.3 exist (LinuxCNC, and grblHAL, which took them from it).
[[nodiscard]] bool usesToolTableWords(Dialect dialect);
// Whether the controller applies the TLO Toffee measured on its setter (the Carvera, grblHAL), not the
// table's geometric length (the others).
[[nodiscard]] bool measuresTlos(Dialect dialect);

// The program that loads `table` into the controller. Offset numbers are tool numbers (H = D = T). Values are
// written at the controller's resolution (0.001 mm, 0.0001 in); `tool` picks the one tool for controllers
// that hold a single set of offsets (Aerotech; the Carvera takes a TLO per tool as it is selected).
[[nodiscard]] Result<QString> exportProgram(
    const ToolTable &table, Dialect dialect, std::optional<int> tool = {});

} // namespace Toffee
