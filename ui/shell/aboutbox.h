// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

class QWidget;

namespace Toffee {

// Help ▸ About Toffee: what it is, and its version (CMake's project version, as --version and the package
// say).
void showAbout(QWidget *parent);

} // namespace Toffee
