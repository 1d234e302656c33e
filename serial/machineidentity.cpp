// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/machineidentity.h"

#include "serial/machineconnection.h"

using namespace Qt::StringLiterals;

namespace Toffee {

QString MachineIdentity::key() const
{
    if (emulator)
        return u"emulator"_s;
    return controllerKindName(controller) + u':' + (name.isEmpty() ? link : u"name="_s + name);
}

QString MachineIdentity::title() const
{
    if (emulator)
        return tr("the built-in emulator");
    if (controller == ControllerKind::GrblHal && !name.isEmpty())
        return tr("grblHAL “%1”").arg(name);
    if (controller == ControllerKind::GrblHal)
        return tr("grblHAL at %1").arg(link);
    if (controller == ControllerKind::Carvera)
        return tr("the Carvera at %1").arg(link);
    if (controller == ControllerKind::LinuxCnc)
        return tr("LinuxCNC at %1").arg(link);
    return tr("the machine at %1").arg(link);
}

QString MachineIdentity::defaultName() const
{
    if (emulator)
        return u"Emulator"_s;
    return controller == ControllerKind::Auto ? u"Carvera"_s : controllerKindTitle(controller);
}

MachineIdentity MachineIdentity::fromKey(const QString &key)
{
    if (key == u"emulator")
        return MachineIdentity { ControllerKind::Carvera, true, {}, {} };
    const qsizetype colon = key.indexOf(u':');
    const auto kind = controllerKindFromName(key.left(colon));
    const QString rest = colon < 0 ? key : key.mid(colon + 1);
    if (rest.startsWith(u"name="))
        return MachineIdentity { kind.value_or(ControllerKind::Auto), false, {}, rest.mid(5) };
    return MachineIdentity { kind.value_or(ControllerKind::Auto), false, rest, {} };
}

MachineIdentity identityOf(const ConnectionTarget &target, ControllerKind controller, const QString &name)
{
    if (target.emulator)
        return MachineIdentity { ControllerKind::Carvera, true, {}, {} };
    return MachineIdentity { controller, false, target.name(), name };
}

} // namespace Toffee
