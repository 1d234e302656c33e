// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/transport/linetransport.h"

namespace Toffee {

LineTransport::~LineTransport() = default;

} // namespace Toffee
