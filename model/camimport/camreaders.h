// SPDX-License-Identifier: GPL-3.0-or-later
// The readers of each CAM format, on a file's bytes. Each returns every tool or the first problem, never part
// of a file; an Error carries the line where the file has lines, and the message says the column or the
// tool, but not the file's name (loadCamLibrary adds it).
#pragma once

#include <QByteArrayView>
#include <QList>

#include "model/camimport/camtool.h"
#include "model/result.h"

namespace Toffee {

// The largest CAM library Toffee reads, and the largest tools.json it unpacks from a .tools archive: Fusion's
// own libraries are a few megabytes, and a parsed JSON document takes up to ten times its size in memory.
inline constexpr qint64 kMaxCamLibraryBytes = 32LL * 1024 * 1024;
// How much of a G-code program's beginning may be its tool header: the program after it is never read.
inline constexpr qint64 kMaxProgramHeaderBytes = 4LL * 1024 * 1024;

// Autodesk Fusion / HSM's JSON tool library: {"version": …, "data": [tool, …]}.
[[nodiscard]] Result<QList<CamTool>> readFusionJson(QByteArrayView data);
// A .tools file: a zip archive holding that JSON as tools.json.
[[nodiscard]] Result<QList<CamTool>> readFusionArchive(QByteArrayView zip);
// HSMWorks / Fusion .hsmlib: XML in any encoding it declares (usually UTF-16 with a byte-order mark).
[[nodiscard]] Result<QList<CamTool>> readHsmLibrary(QByteArrayView xml);
// Makera CAM's ";@MKR|TOOL|number=…" lines at the start of a G-code program. `complete`: whether `program` is
// the whole file, or only its first bytes (then a header running past them is refused).
[[nodiscard]] Result<QList<CamTool>> readMakeraHeader(QByteArrayView program, bool complete = true);

// What every reader checks last: at least one tool, numbers in Toffee's range and not repeated, no negative
// diameter or length. The first problem names the tool by its place, and its line.
[[nodiscard]] Result<QList<CamTool>> checkCamTools(QList<CamTool> tools);

} // namespace Toffee
