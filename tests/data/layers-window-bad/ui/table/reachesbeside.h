// A room of the window that reaches into a room beside it (the table into the machine's): tests/layers.cmake must
// refuse it.
#include "ui/machine/machinedock.h"
