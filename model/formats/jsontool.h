// SPDX-License-Identifier: GPL-3.0-or-later
// The native JSON format's keys, and the reading of one tool object (jsontool.cpp) apart from the table
// around it (jsontableformat.cpp). Not part of the model's interface.
#pragma once

#include <QString>

namespace Toffee {

class JsonScanner;
struct Tool;

namespace JsonKey {
inline constexpr QLatin1StringView Format("format");
inline constexpr QLatin1StringView Version("version");
inline constexpr QLatin1StringView Units("units");
inline constexpr QLatin1StringView Tools("tools");
inline constexpr QLatin1StringView Number("number");
inline constexpr QLatin1StringView Pocket("pocket");
inline constexpr QLatin1StringView Description("description");
inline constexpr QLatin1StringView LengthGeometry("length_geometry");
inline constexpr QLatin1StringView LengthWear("length_wear");
inline constexpr QLatin1StringView RadiusGeometry("radius_geometry");
inline constexpr QLatin1StringView RadiusWear("radius_wear");
inline constexpr QLatin1StringView MeasuredTlo("measured_tlo");
inline constexpr QLatin1StringView MeasuredAt("measured_at");
inline constexpr QLatin1StringView Notes("notes");
inline constexpr QLatin1StringView TloSource("tlo_source");
inline constexpr QLatin1StringView BreakTestFailed("break_test_failed");
inline constexpr QLatin1StringView ReferenceMz("reference_mz");
inline constexpr QLatin1StringView LinuxCnc("linuxcnc");
inline constexpr QLatin1StringView CutterType("cutter_type");
inline constexpr QLatin1StringView OverallLength("overall_length");
inline constexpr QLatin1StringView LifeLimitMinutes("life_limit_minutes");
inline constexpr QLatin1StringView LifeLimitUses("life_limit_uses");
inline constexpr QLatin1StringView Flutes("flutes");
inline constexpr QLatin1StringView ProbeX("probe_x");
inline constexpr QLatin1StringView ProbeY("probe_y");
inline constexpr QLatin1StringView ProbeTouches("probe_touches");
inline constexpr QLatin1StringView ProbeTurn("probe_turn");
inline constexpr QLatin1StringView ProbeLatchFeed("probe_latch_feed");
inline constexpr QLatin1StringView SpreadLimit("spread_limit");
} // namespace JsonKey

// One tool object, `json` at its '{'. False when it is not a tool Toffee reads, the reason in `json.error()`.
[[nodiscard]] bool readJsonTool(JsonScanner &json, Tool &tool);

} // namespace Toffee
