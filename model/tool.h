// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cmath>
#include <optional>

#include <QDateTime>
#include <QString>

#include "model/probing.h"

namespace Toffee {

// Where a tool's stored TLO came from: the tool setter; an offset the operator set on the machine by hand
// (M493.3 Z, M493.3 H, G10 L1 in the console); or a controller's own table read by Pull Offsets (grblHAL's
// `$#`: set there by someone or something other than Toffee). Only a probe is a measurement: a break test
// compares against the TLO the machine holds, so it matters which.
enum class TloSource : quint8 { Probe, Manual, Pulled };

// "probe", "manual", "pulled": the files' and the CLI's JSON word; the reverse is empty for another word.
[[nodiscard]] QLatin1StringView tloSourceName(TloSource source);
[[nodiscard]] std::optional<TloSource> tloSourceFromName(QByteArrayView name);

// One row of the tool table. Lengths and radii are in the table's units.
struct Tool
{
    int number = 1;
    int pocket = 1;
    QString description;
    double lengthGeometry = 0.0;
    double lengthWear = 0.0;
    double radiusGeometry = 0.0;
    double radiusWear = 0.0;
    // Measured on a tool setter (Carvera M491): TLO = current tool MCS Z - reference tool MCS Z.
    std::optional<double> measuredTlo;
    QDateTime measuredAt; // UTC; invalid when never measured
    QString notes;
    // LinuxCNC fields Toffee does not edit (X, Y, A-C, U-W offsets, I, J, Q), kept verbatim as
    // "X0.5 Q2" so that a LinuxCNC table survives a round trip through Toffee.
    QString linuxCncExtra;
    TloSource tloSource = TloSource::Probe; // Manual or Pulled only with a measuredTlo
    // The last break test found this tool longer or shorter than its TLO: it stays marked (in the file too)
    // until it is probed again.
    bool breakTestFailed = false;
    // The reference tool's MCS Z the TLO was measured (or set) against: a stored TLO is only right on a
    // machine whose reference is still there. Unknown for tables from before Toffee kept it.
    std::optional<double> referenceMz = std::nullopt;
    // The cutter as a CAM library last described it (an import sets them): its type ("flat end mill") and
    // overall length, in the table's units. An import that finds another type, diameter or overall length
    // puts a new cutter in the pocket (ToolTable::newCutter).
    QString cutterType = {};
    std::optional<double> overallLength = std::nullopt;
    // Tool life, as FANUC's tool-life management counts it: at most this many minutes of cutting, or this
    // many programs, on one cutter. Empty: no limit.
    std::optional<double> lifeLimitMinutes = std::nullopt;
    std::optional<int> lifeLimitUses = std::nullopt;
    // Its cutting edges (a CAM library's flute count, or typed): one touch each on the setter by default.
    std::optional<int> flutes = std::nullopt;
    // How it is measured on the tool setter (off-centre, touches, latch feed, spread limit).
    ProbeSettings probing = {};

    // At a micrometre's thousandth: 41.3 − 0.02 is 41.28, not 41.279999999999994.
    [[nodiscard]] double totalLength() const { return std::round((lengthGeometry + lengthWear) * 1e6) / 1e6; }
    [[nodiscard]] double totalRadius() const { return radiusGeometry + radiusWear; }

    // Another cutter in this tool's pocket: the old cutter's TLO (its time, source and reference), its
    // length (a LinuxCNC or FANUC table's offset: the old cutter's, which G43 would apply to the new one),
    // its wear and its break mark no longer hold. Everything else stays.
    void endCutter()
    {
        measuredTlo.reset();
        lengthGeometry = 0.0;
        measuredAt = {};
        tloSource = TloSource::Probe;
        referenceMz.reset();
        breakTestFailed = false;
        lengthWear = 0.0;
        radiusWear = 0.0;
    }

    friend bool operator==(const Tool &, const Tool &) = default;
};

} // namespace Toffee

Q_DECLARE_METATYPE(Toffee::Tool)
