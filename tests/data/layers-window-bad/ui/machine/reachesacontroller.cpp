// A room of the window that reaches past the neutral layers into one controller's: tests/layers.cmake must refuse
// it.
#include "serial/carvera/carverareplies.h"
