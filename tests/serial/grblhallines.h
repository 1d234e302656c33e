// SPDX-License-Identifier: GPL-3.0-or-later
// What tst_grblhalreplies.cpp and tst_grblhalstatus.cpp share: the build info the peer printed, and a line no
// controller sends.
#pragma once

#include "serial/grblhal/grblhalreplies.h"
#include <QTest>

namespace Toffee::Test {

using namespace Qt::StringLiterals;

// A million characters: a line no controller sends, which must cost little and conclude nothing.
inline QByteArray huge(const QByteArray &head, const QByteArray &tail)
{
    return head + QByteArray(1000000, '1') + tail;
}

// What $I printed on the peer (../shared/peers/grblhal), line ends and all.
inline const QByteArrayList kPeerBuildInfo { "[VER:1.1f.20260817:]\r\n", "[OPT:VNML+,100,1024,3,16]\r\n",
    "[AXS:3:XYZ]\r\n", "[NEWOPT:ENUMS,RT+,TC,SED]\r\n", "[FIRMWARE:grblHAL]\r\n", "[SIGNALS:D]\r\n",
    "[NVS STORAGE:*EEPROM]\r\n", "[DRIVER:Simulator]\r\n", "[DRIVER VERSION:260324]\r\n" };

} // namespace Toffee::Test
