// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <functional>
#include <map>
#include <optional>

#include <QByteArrayView>
#include <QCoreApplication>
#include <QList>

#include "model/gcode/dialect.h"
#include "model/result.h"
#include "model/units.h"

namespace Toffee {

// One offset register (FANUC H/D, AB, FAGOR L+K; LinuxCNC keeps only the geometry, a total).
struct OffsetEntry
{
    double lengthGeometry = 0.0;
    double lengthWear = 0.0;
    double radiusGeometry = 0.0;
    double radiusWear = 0.0;
    [[nodiscard]] double length() const { return lengthGeometry + lengthWear; }
    friend bool operator==(const OffsetEntry &, const OffsetEntry &) = default;
};
using OffsetTable = std::map<int, OffsetEntry>;
using Position = std::array<double, 3>;

class ToolTable;
// The offsets a controller of `dialect` holds for `table`: each tool's length and radius, geometry and wear;
// for the Carvera, which keeps one TLO and measures it at every change, each tool's measured TLO.
[[nodiscard]] OffsetTable offsetTableFor(const ToolTable &table, Dialect dialect);

// What one tool did in a program: its feed moves' time at their F (no override assumed) and length, in the
// program's units (mm on every machine Toffee drives).
struct ToolUsage
{
    double cuttingSeconds = 0.0;
    double feedPathMm = 0.0;
};

// What the block just run did, for a caller that follows a program block by block (the job check and its
// preparation). Work Z is the programmed Z: without the work offset and the length offset.
struct BlockEffect
{
    enum class Motion : quint8 { None, Rapid, Feed };
    Motion motion = Motion::None;
    bool machineCoordinates = false; // G53: neither the work offset nor the length offset applies
    bool toolChange = false; // M6 or M61 loaded a tool
    // The Carvera measured its tool on the setter (M6 without H, M491, M491.1): its TLO is the tool's own.
    bool probe = false;
    bool setsTlo = false; // the Carvera's TLO set by the program itself (M493.3 Z, M6 … H)
    bool unitsWord = false; // G20 or G21
    bool lengthAxisWord = false; // the block commands the length axis (Z under G17), which takes the offset
    double lowestZ = 0.0; // the lowest work Z the move reaches: its end, or lower on an arc
    // The block's feed moves (a cycle's included), as toolUsage() counts them for the active tool.
    double feedPathMm = 0.0;
    double cuttingSeconds = 0.0;
};

// The length compensation in force: whether any, and which register (H, FAGOR's D or T, LinuxCNC's tool) it
// took its value from; -1 for a value given directly (LinuxCNC's G43.1, the Carvera's TLO).
struct LengthCompensation
{
    bool active = false;
    int reg = -1;
    double value = 0.0; // what the length axis carries (0 when none is active)
    double latched = 0.0; // the value the last call selected, which G43 would apply
};

struct SimulatedMove
{
    int line = 0;
    Position end {};
    QList<Position> points; // start to end, both included, when sampling
};

// Runs G-code as a controller of the given dialect would, with the offsets of docs/DIALECTS.md applied, and
// reports where each motion block leaves the machine. Shared by `toffee-cli simulate`, the conformance suite
// and the emulator's idea of a machine. The rules, each from docs/DIALECTS.md:
// - a length offset takes effect when the length axis next moves (G17: Z, G18: Y, G19: X);
// - FANUC G43 Hn adds, G44 Hn subtracts, G49 or H0 cancel, a new H replaces; AB the same, but H0 keeps the
// mode;
// - FAGOR G43 switches compensation on with the value's own sign, G44 (and G74) off; D, else the tool's
// offset;
// - LinuxCNC G43 [Hn], G43.1 Z, G43.2 Hn (adds), G49; M6/M61 do not change the offset; G10 L1 writes the
// table;
// - G10 L10-L13 write geometry and wear, G90 replacing and G91 adding, refused (AB) in cutter compensation;
//   an offset in use changes only when its H or D is called again;
// - Aerotech: G44 X Y Z / CutterCompensationSetAxes, CutterCompensationSetOffsets, G143 / G144 / G149 applied
//   and removed gradually over the next coordinated move, Home() dropping them at once;
// - Carvera: no G43; the TLO set by M493.3 Z (or M6 T H) always applies.
class GCodeInterpreter
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::GCodeInterpreter)

public:
    GCodeInterpreter(Dialect dialect, OffsetTable offsets = {}, int samples = 0);

    // Runs a whole program; stops at the first error (which names its line) or at M2/M30.
    [[nodiscard]] Result<void> run(QByteArrayView program);
    // One block. Line numbers are 1-based.
    [[nodiscard]] Result<void> runLine(QByteArrayView line, int lineNumber);

    void setRecordMoves(bool record) { m_recordMoves = record; }
    // Each move handed over as it is made instead of kept (moves()): a program's moves in memory that does
    // not grow with the program.
    using MoveSink = std::function<void(const SimulatedMove &move)>;
    void setMoveSink(MoveSink sink) { m_moveSink = std::move(sink); }
    [[nodiscard]] const QList<SimulatedMove> &moves() const { return m_moves; }
    [[nodiscard]] const OffsetTable &offsets() const { return m_offsets; }
    [[nodiscard]] const Position &position() const { return m_machine; }
    [[nodiscard]] qint64 blocks() const { return m_blocks; }
    [[nodiscard]] const Position &workOffset() const { return m_g54; }

    // For a machine that also moves by itself (the emulator's probing cycle) and sets its TLO by M-codes:
    // where the machine is now, its G54, and the length offset it carries (the Carvera's TLO always applies).
    void setMachinePosition(const Position &position);
    void setWorkOffset(const Position &offset) { m_g54 = offset; }
    void setLengthOffset(double offset);
    [[nodiscard]] bool ended() const { return m_ended; }

    // Tool life: what each tool did, by the tool loaded (M6, M61) or, before any change, selected (T); -1 for
    // moves before any tool. Rapids (G0) count only in the rapid distance.
    [[nodiscard]] const std::map<int, ToolUsage> &toolUsage() const { return m_usage; }
    // Off: toolUsage() stays empty, so a program of a million tools does not hold one entry each; a caller
    // that needs it per tool adds up each block's (BlockEffect::feedPathMm, cuttingSeconds).
    void setKeepToolUsage(bool keep) { m_keepUsage = keep; }
    [[nodiscard]] double rapidDistance() const { return m_rapid; }
    [[nodiscard]] int activeTool() const { return m_cuttingTool >= 0 ? m_cuttingTool : m_selectedTool; }
    // The tool M6 (or M61) loaded last; -1 before any change.
    [[nodiscard]] int loadedTool() const { return m_cuttingTool; }

    // The last block's effect, and the state a job check follows.
    [[nodiscard]] const BlockEffect &lastBlock() const { return m_effect; }
    [[nodiscard]] LengthCompensation lengthCompensation() const;
    // How many blocks have called a length offset (G43, G44, G49, H, …) so far: whether one came since a tool
    // change.
    [[nodiscard]] qint64 lengthCalls() const { return m_lengthCalls; }
    // The program's units once it says (G20, G21); nothing before.
    [[nodiscard]] std::optional<Units> programUnits() const { return m_units; }
    // Where the program is, in work coordinates.
    [[nodiscard]] const Position &workPosition() const { return m_program; }
    [[nodiscard]] double feedRate() const { return m_feed; }
    // The axis a length offset rides on: 2 (Z) under G17, 1 (Y) under G18, 0 (X) under G19.
    [[nodiscard]] int lengthAxis() const { return m_lengthAxis; }
    // The spindle turns (M3, M4) or stands (M5, and at the start).
    [[nodiscard]] bool spindleOn() const { return m_spindleOn; }

private:
    struct Words;
    [[nodiscard]] Result<void> execute(const Words &w, int line);
    [[nodiscard]] Result<void> modalGCodes(const Words &w, int line, bool &motion);
    [[nodiscard]] Result<void> aerotechWords(const Words &w, int line);
    [[nodiscard]] Result<void> motionOf(const Words &w, int line, bool motion);
    // G54-G59: the machine stays; its work position is now the other offset's.
    void selectWorkOffset(int index);
    // Canned cycles (G73, G81-G89): the cycle's modal state, and one hole.
    [[nodiscard]] static bool isCycle(double g);
    void startCycle(int code);
    [[nodiscard]] Result<void> cycle(const Words &w, int line);
    // A straight move of the cycle to `target` (work coordinates), at rapid or at feed.
    void cycleMove(const Position &target, bool feed, int line);
    [[nodiscard]] Result<void> callFunction(QByteArrayView call, int line);
    [[nodiscard]] Result<void> g10(const Words &w, int line);
    [[nodiscard]] Result<void> g10WorkOffset(const Words &w, double l, int line);
    [[nodiscard]] Result<void> g10ToolTable(const Words &w, double l, int line);
    [[nodiscard]] Result<void> g10Register(const Words &w, double l, int line);
    [[nodiscard]] Result<void> lengthWords(const Words &w, int line);
    [[nodiscard]] Result<void> linuxCncLength(const Words &w, int line);
    [[nodiscard]] Result<void> aerotechAxes(const QList<int> &axes, int line);
    void move(const Words &w, int line);
    [[nodiscard]] Result<void> modalWords(const Words &w, int line);
    [[nodiscard]] Result<void> carveraLength(const Words &w, int line);
    // The move just made from `programStart`: its path (a line, or the arc of G2/G3 in the active plane) and
    // the lowest work Z it reaches (an arc in G18 or G19 may dip below both ends).
    struct MoveGeometry
    {
        double length = 0.0;
        double lowestZ = 0.0;
    };
    [[nodiscard]] Result<MoveGeometry> measureMove(
        const Words &w, const Position &programStart, int line) const;
    // A move's length to the block's effect and the tally: the rapid distance, or the tool's feed path and
    // time.
    void account(double length);
    void tally(double length, bool feed);
    [[nodiscard]] double feedSeconds(double length) const;
    void home(const QList<int> &axes, int line);
    // G28: through the point the axis words give to the machine's home on those axes, at rapid.
    void returnHome(const Words &w, int line);
    void recordStraight(int line, const Position &start);
    void keep(SimulatedMove &&move);
    void recordCompensated(int line, const Position &programStart, double fromFraction, double toFraction);
    [[nodiscard]] double lengthContribution() const;
    [[nodiscard]] Error error(int line, const QString &message) const;
    [[nodiscard]] static bool isPassive(double g);
    [[nodiscard]] double offsetValue(int number) const;
    // A word naming a tool or a register (T, D, H, P, Q): a whole number from low to high, or an error.
    [[nodiscard]] Result<int> wholeWord(const Words &w, char letter, int low, int high, int line) const;

    Dialect m_dialect;
    OffsetTable m_offsets;
    int m_samples;
    bool m_recordMoves = true;
    QList<SimulatedMove> m_moves;
    MoveSink m_moveSink;
    qint64 m_blocks = 0;
    bool m_ended = false;

    Position m_program {}; // programmed (work) position
    int m_motionMode = 0; // G0, G1, G2 or G3: modal
    BlockEffect m_effect;
    std::optional<Units> m_units;
    bool m_spindleOn = false;
    double m_spindleSpeed = 0.0; // S
    int m_feedMode = 94; // G93 inverse time, G94 units a minute, G95 units a revolution
    bool m_arcCentresAbsolute = false; // G90.1; G91.1 (the default) has them from the arc's start
    qint64 m_lengthCalls = 0;
    int m_lengthRegister = -1; // the register the length value came from
    double m_feed = 0.0; // F, units per minute
    int m_selectedTool = -1; // tool life: the last T word
    int m_cuttingTool = -1; // tool life: the tool M6 (or M61) loaded
    std::map<int, ToolUsage> m_usage;
    bool m_keepUsage = true;
    double m_rapid = 0.0;
    Position m_machine {}; // where the machine is
    Position m_g54 {}; // the work offset in use (G54 to G59)
    std::array<Position, 9> m_workOffsets {}; // G54 to G59, G59.1 to G59.3; the one in use kept in m_g54
    int m_workOffset = 0;
    int m_cycle = 0; // the canned cycle in force (73, 81 … 89), or 0
    bool m_cycleCalled = false; // this block names the cycle: it drills even without X or Y
    bool m_cycleToR = false; // G99: back to R after each hole; G98: to the level the cycle began at
    double m_cycleInitialZ = 0.0;
    std::optional<double> m_cycleR;
    std::optional<double> m_cycleZ;
    bool m_absolute = true;
    int m_lengthAxis = 2;
    bool m_radiusComp = false;

    enum class LengthMode { Off, Plus, Minus };
    LengthMode m_lengthMode = LengthMode::Off;
    int m_hNumber = 0;
    double m_lengthValue = 0.0; // latched when H/D/T calls it
    double m_appliedLength = 0.0; // what the machine's length axis carries now
    int m_preparedTool = 0;
    int m_loadedTool = 0;

    // Aerotech cutter offset compensation
    QList<int> m_compAxes { 0, 1 };
    QList<double> m_compOffsets { 0.0, 0.0 };
    int m_compSign = 0; // +1 G143, -1 G144, 0 off
    double m_compFraction = 0.0; // how much of the offsets the position carries now
    int m_pending = 0; // +1/-1 a lead-on, 2 a lead-off, on the next coordinated move
};

} // namespace Toffee
