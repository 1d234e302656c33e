// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <vector>

#include <QtGlobal>

#include "model/limits.h"

namespace Toffee {

// A set of tool numbers (-1, the Carvera's empty spindle, to 999999) as one bit each: at most 125 KB whatever
// a program loads, and only as large as the highest tool in it.
class ToolBits
{
public:
    // Adds `tool`; true when it was not there yet. A number outside the range is never added.
    bool insert(int tool)
    {
        if (tool < Limits::kEmptySpindle || tool > Limits::kMaxToolNumber)
            return false;
        const auto bit = size_t(tool - Limits::kEmptySpindle);
        if (bit / 64 >= m_words.size())
            m_words.resize(bit / 64 + 1); // geometric: a program of rising numbers does not copy each time
        const quint64 mask = quint64(1) << (bit % 64);
        if (m_words[bit / 64] & mask)
            return false;
        m_words[bit / 64] |= mask;
        return true;
    }
    [[nodiscard]] bool contains(int tool) const
    {
        if (tool < Limits::kEmptySpindle || tool > Limits::kMaxToolNumber)
            return false;
        const auto bit = size_t(tool - Limits::kEmptySpindle);
        return bit / 64 < m_words.size() && (m_words[bit / 64] >> (bit % 64)) & 1;
    }

private:
    std::vector<quint64> m_words;
};

} // namespace Toffee
