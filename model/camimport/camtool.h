// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QList>
#include <QString>

#include "model/units.h"

namespace Toffee {

// One cutter as a CAM tool library describes it, in the library's own units. Only what Toffee takes from a
// CAM library is kept: the CAM's lengths are the cutter's, never the machine's tool length offset.
struct CamTool
{
    int number = 0; // the T number the post-processor writes
    QString description; // one line; empty when the library gives none (the import then names a new tool)
    QString type; // "flat end mill", "drill", …
    Units units = Units::Millimetre;
    // False when the library gives no unit (a Fusion tool without "unit"): its numbers are read in units the
    // operator says (ImportPreview::build's `assumed`), never guessed.
    bool unitGiven = true;
    std::optional<double> diameter; // absent: the library says nothing about the radius
    std::optional<double> fluteLength;
    std::optional<double> stickOut; // below the holder (Fusion LB, Makera sticklength)
    std::optional<double> overallLength;
    // The post's H (Fusion "length-offset", HSM nc/@length-offset): never imported, since Toffee's rule is
    // H = T; the preview says so when it differs.
    std::optional<int> lengthOffset;
    // Where the tool is in its file, for messages: "tool 3 in data" or "line 12"; and its line when known.
    QString place;
    int line = 0;

    friend bool operator==(const CamTool &, const CamTool &) = default;
};

// The CAM files Toffee imports tools from.
enum class CamFormat { FusionJson, FusionArchive, HsmLibrary, MakeraProgram };

// What one CAM file holds: its tools, in the order the file lists them, with unique numbers.
struct CamLibrary
{
    QString path;
    CamFormat format = CamFormat::FusionJson;
    QList<CamTool> tools;
};

} // namespace Toffee

// Moved, not copied, when a list of them grows: a library's reader appends one at a time.
Q_DECLARE_TYPEINFO(Toffee::CamTool, Q_RELOCATABLE_TYPE);
