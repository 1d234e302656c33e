// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QByteArrayView>
#include <QString>

#include "model/camimport/camtool.h"
#include "model/result.h"

namespace Toffee {

// Which CAM format `path` is, by its name (.json, .tools, .hsmlib, or a G-code program: .nc, .gcode, .cnc,
// .ngc, .tap, .txt), or nothing. A .json file may be a Toffee table instead: see isToffeeTable.
[[nodiscard]] std::optional<CamFormat> camFormatForPath(const QString &path);
// A CAM format's name for people: "Fusion tool library (JSON)".
[[nodiscard]] QString camFormatName(CamFormat format);
// Whether JSON text is a Toffee tool table ("format": "toffee-tool-table") rather than a CAM library.
[[nodiscard]] bool isToffeeTable(QByteArrayView json);
// Whether the window and toffee-cli import `path` as a CAM library: by its name, and for .json by its
// content.
[[nodiscard]] bool isCamLibraryFile(const QString &path);

// Reads a CAM file whole (a program: only its header), through the same safe file reading as tables, within
// kMaxCamLibraryBytes. A refusal names the file, the place and the reason; nothing is ever half read.
[[nodiscard]] Result<CamLibrary> loadCamLibrary(const QString &path);

} // namespace Toffee
