// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/linetransport.h"

namespace Toffee {

LineTransport::~LineTransport() = default;

} // namespace Toffee
