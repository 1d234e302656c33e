// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace Toffee {

class MainWindow;

// At start: offers, newest first, the unsaved edits that a Toffee which died left behind. Recover puts them
// on top of their file as one undoable, unsaved step; Discard deletes the copy and offers the next; Later
// keeps them all for the next start. Returns whether edits were recovered into the window.
bool offerRecovery(MainWindow *window);

} // namespace Toffee
