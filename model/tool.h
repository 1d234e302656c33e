// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QDateTime>
#include <QString>

namespace Toffee {

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

    [[nodiscard]] double totalLength() const { return lengthGeometry + lengthWear; }
    [[nodiscard]] double totalRadius() const { return radiusGeometry + radiusWear; }

    friend bool operator==(const Tool &, const Tool &) = default;
};

} // namespace Toffee

Q_DECLARE_METATYPE(Toffee::Tool)
