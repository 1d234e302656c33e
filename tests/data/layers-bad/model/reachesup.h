// A model header that reaches up into the serial layer: tests/layers.cmake must refuse it.
#include "serial/carvera/machinesession.h"
