// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <optional>

#include <QByteArray>
#include <QStringList>

#include "model/result.h"
#include "model/tooltable.h"

namespace Toffee {

enum class TableFormat { Json, LinuxCnc, Csv };

[[nodiscard]] std::optional<TableFormat> formatForPath(const QString &path); // by suffix: .json .tbl .csv
[[nodiscard]] std::optional<TableFormat> formatFromName(QStringView name); // json, tbl, csv
[[nodiscard]] QString formatName(TableFormat format);
[[nodiscard]] QString formatSuffix(TableFormat format);

// A reader either returns the whole table or an Error naming the line; it never returns part of a file.
// LinuxCNC tables carry no units: `tblUnits` says what their numbers are.
[[nodiscard]] Result<ToolTable> readTable(
    const QByteArray &data, TableFormat format, Units tblUnits = Units::Millimetre);
[[nodiscard]] QByteArray writeTable(const ToolTable &table, TableFormat format);

// What `format` cannot hold of `table`, one sentence each, for a warning before a lossy save.
[[nodiscard]] QStringList formatLosses(const ToolTable &table, TableFormat format);

// The largest table file Toffee reads, and so the largest it writes.
inline constexpr qint64 kMaxTableFileBytes = 256LL * 1024 * 1024;

[[nodiscard]] Result<ToolTable> loadTableFile(
    const QString &path, std::optional<TableFormat> format = {}, Units tblUnits = Units::Millimetre);
// Only regular files are read (see readRegularFile). Saving writes the file whole or not at all (see
// writeFileAtomically): a crash or a full disk leaves the old file whole, and a table whose file would be
// too large to read back is refused.
[[nodiscard]] Result<void> saveTableFile(const QString &path, const ToolTable &table, TableFormat format);

// Writers hand the file over in pieces of about a megabyte, in order; a sink returning false stops them.
using ByteSink = std::function<bool(QByteArrayView piece)>;
bool writeTable(const ToolTable &table, TableFormat format, const ByteSink &sink);

// The individual formats, for tests and benchmarks.
[[nodiscard]] Result<ToolTable> readJsonTable(const QByteArray &data);
[[nodiscard]] QByteArray writeJsonTable(const ToolTable &table);
bool writeJsonTable(const ToolTable &table, const ByteSink &sink);
[[nodiscard]] Result<ToolTable> readLinuxCncTable(const QByteArray &data, Units units);
[[nodiscard]] QByteArray writeLinuxCncTable(const ToolTable &table);
bool writeLinuxCncTable(const ToolTable &table, const ByteSink &sink);
[[nodiscard]] Result<ToolTable> readCsvTable(const QByteArray &data);
[[nodiscard]] QByteArray writeCsvTable(const ToolTable &table);
bool writeCsvTable(const ToolTable &table, const ByteSink &sink);

} // namespace Toffee
