// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The interpreter's own parts, shared by its source files (gcodeinterpreter.cpp, gcodeoffsets.cpp,
// gcodeaerotech.cpp); not for use outside model/gcode.

#include <array>
#include <cmath>

#include "model/gcode/gcodeinterpreter.h"
#include "model/gcode/gcodewords.h"
#include "model/limits.h"
#include "model/numberformat.h"
#include "model/translate.h"

namespace Toffee {

inline constexpr int kMaxOffsetNumber = Limits::kMaxOffsetNumber;
inline constexpr double kMaxGeometry = Limits::kMaxGeometryMm;
inline constexpr double kMaxWear = Limits::kMaxWearMm;
// Controllers take at most eight digits before the point (FANUC's +-99999999). The bound also keeps every
// position a program can reach finite: without it, two G91 moves of 1e308 end at infinity.
inline constexpr double kMaxWordValue = Limits::kMaxWordValue;

inline bool same(double a, double b)
{
    return std::fabs(a - b) < 1e-6;
}

inline int axisIndex(char letter)
{
    return letter == 'X' ? 0 : letter == 'Y' ? 1 : letter == 'Z' ? 2 : -1;
}

struct GCodeInterpreter::Words
{
    std::array<double, 26> value {};
    std::array<bool, 26> has {};
    std::array<bool, 26> bare {}; // a letter with no number: Aerotech's "G44 X Y Z"
    std::array<double, 8> g {};
    int gCount = 0;
    std::array<double, 4> m {};
    int mCount = 0;

    [[nodiscard]] bool hasG(double code) const
    {
        for (int i = 0; i < gCount; ++i) {
            if (same(g[size_t(i)], code))
                return true;
        }
        return false;
    }
    [[nodiscard]] bool hasM(double code) const
    {
        for (int i = 0; i < mCount; ++i) {
            if (same(m[size_t(i)], code))
                return true;
        }
        return false;
    }
    [[nodiscard]] bool word(char letter) const { return has[size_t(letter - 'A')]; }
    [[nodiscard]] double get(char letter) const { return value[size_t(letter - 'A')]; }
    [[nodiscard]] bool isBare(char letter) const { return bare[size_t(letter - 'A')]; }
    [[nodiscard]] bool anyAxis() const { return word('X') || word('Y') || word('Z'); }

    // Takes one word of the block; false, with what is wrong in `problem`, when it cannot.
    [[nodiscard]] bool add(const GCodeWord &word, QString &problem)
    {
        const size_t slot = size_t(word.letter - 'A');
        if (word.bare) {
            if (axisIndex(word.letter) < 0) {
                problem
                    = GCodeInterpreter::tr("the word %1 needs a value.").arg(QChar::fromLatin1(word.letter));
                return false;
            }
            has[slot] = bare[slot] = true;
        } else if (word.letter == 'G') {
            if (gCount == int(g.size())) {
                problem = GCodeInterpreter::tr("too many G codes in one block.");
                return false;
            }
            g[size_t(gCount++)] = word.value;
        } else if (word.letter == 'M') {
            if (mCount == int(m.size())) {
                problem = GCodeInterpreter::tr("too many M codes in one block.");
                return false;
            }
            m[size_t(mCount++)] = word.value;
        } else {
            if (has[slot]) {
                problem = GCodeInterpreter::tr("the word %1 appears twice in one block.")
                              .arg(QChar::fromLatin1(word.letter));
                return false;
            }
            has[slot] = true;
            value[slot] = word.value;
        }
        return true;
    }
};

} // namespace Toffee
