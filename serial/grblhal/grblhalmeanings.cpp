// SPDX-License-Identifier: GPL-3.0-or-later
// grblHAL's alarms and errors in an operator's words, with what to do. The numbers and what the controller
// means by them are grblHAL's (alarms.h, errors.h); the words are Toffee's.
#include "serial/grblhal/grblhalreplies.h"

#include <QCoreApplication>

namespace Toffee::GrblHal {

namespace {
// lupdate files a free function's tr() under its namespace: these are translated in that context.
QString tr(const char *text)
{
    return QCoreApplication::translate("Toffee::GrblHal", text);
}
} // namespace

QString alarmMeaning(int alarm)
{
    switch (alarm) {
    case 1:
        return tr("A limit switch was hit while moving: the machine stopped at once and may have lost its "
                  "position. Clear the switch, unlock ($X) and home the machine ($H) before going on.");
    case 2:
        return tr(
            "A move would have gone beyond the machine's travel: nothing moved and the position is kept. "
            "Unlock ($X) and check the target (for a probe: the setter's position and the lowest Z to "
            "search to).");
    case 3:
        return tr(
            "The controller was reset or stopped while moving: the position may be lost. Unlock ($X) and "
            "home the machine ($H) before going on.");
    case 4:
        return tr("Probe already touching: the probe input was triggered before the probe moved, so nothing "
                  "was measured. Unlock ($X), then check that the tool is not resting on the setter and that "
                  "the setter is clean and wired right.");
    case 5:
        return tr(
            "Probe found nothing: the tool never touched the setter within the travel allowed, so nothing "
            "was measured. Unlock ($X), then check the setter and the tool: the right tool in the "
            "spindle, the setter under it, the lowest Z deep enough.");
    case 6:
        return tr("Homing was interrupted by a reset. Unlock ($X) or home the machine again ($H).");
    case 7:
        return tr("Homing stopped because the safety door was opened. Close the door and home again ($H).");
    case 8:
        return tr("Homing failed: the machine could not move off a limit switch. Check the switch and its "
                  "wiring (or the pull-off distance), then home again ($H).");
    case 9:
    case 15:
        return tr(
            "Homing failed: a limit switch was not found within the search distance. Check the switches "
            "and their wiring, then home again ($H).");
    case 10:
        return tr("The emergency stop is engaged. Make the machine safe, release the stop, then reset the "
                  "controller and unlock ($X).");
    case 11:
        return tr("The machine must be homed before it moves: home it ($H).");
    case 12:
        return tr("A limit switch is pressed. Unlock ($X), move the machine off the switch, then go on.");
    case 13:
        return tr("The probe's protection tripped: the probe was touched while the machine moved. Check the "
                  "probe, then unlock ($X).");
    case 14:
        return tr("The spindle did not reach its speed in time. Check the spindle and its drive, then unlock "
                  "($X).");
    case 16:
        return tr(
            "The controller's power-on self test failed. Switch the controller off and on; if it happens "
            "again, check its wiring.");
    case 17:
        return tr("A motor driver reported a fault. Check the drivers and the motors, then reset the "
                  "controller.");
    case 18:
        return tr(
            "Homing failed: the homing settings do not fit the machine. Check them ($$), then home again "
            "($H).");
    case 19:
        return tr("A Modbus device (often the spindle's drive) did not answer or answered wrong. Check its "
                  "cable and settings, then reset the controller.");
    case 20:
        return tr("The controller lost contact with an input/output expander. Check it and its cable, then "
                  "reset the controller.");
    case 21:
        return tr("The controller's settings memory failed: its settings and tool table may be lost. Check "
                  "them ($$ and $#) before going on.");
    case 22:
        return tr("The controller's buffer overflowed. Reset the controller and send the work again.");
    default:
        return tr("The controller halted (ALARM:%1). Make the machine safe, then unlock ($X) or reset the "
                  "controller; the controller's documentation says what this alarm means.")
            .arg(alarm);
    }
}

QString errorMeaning(int error)
{
    switch (error) {
    case 1:
    case 2:
        return tr("The controller could not read a word of the line (a letter and a number each). Check the "
                  "line.");
    case 3:
        return tr("The controller does not know this $ command.");
    case 8:
        return tr("The controller takes this $ command only while idle: wait for the machine to stop, then "
                  "try again.");
    case 9:
        return tr("G-code locked out during alarm or jog state: the controller is halted. Find out why it "
                  "halted, unlock ($X), then try again.");
    case 11:
        return tr("The line is too long for the controller; it was not carried out.");
    case 13:
        return tr("The safety door is open. Close it and go on.");
    case 15:
        return tr("The jog would go beyond the machine's travel; the machine did not move.");
    case 18:
        return tr("The controller was reset; the line was not carried out.");
    case 20:
        return tr("The controller does not support a command in the line (or the command is not valid "
                  "there).");
    case 21:
    case 24:
    case 25:
    case 36:
    case 48:
        return tr("The line holds words that cannot go together. Check the line.");
    case 22:
        return tr("No feed rate is set for the move: give one with F.");
    case 23:
    case 28:
        return tr("A command in the line lacks a value or needs a whole number. Check the line.");
    case 26:
    case 33:
        return tr("The move has no valid target. Check its axis words.");
    case 37:
        return tr("G43.1 was given for an axis that is not the controller's tool length axis (Z).");
    case 38:
        return tr(
            "No such tool in the controller: the number is beyond its tool table, or the tool is not in "
            "it. Check the table's size ($I) and the tool's number.");
    case 39:
        return tr("A value in the line is out of the range the controller takes.");
    case 40:
        return tr("A tool change is waiting to be finished: finish it (cycle start) before sending more.");
    case 45:
        return tr("A limit switch is pressed: only homing is allowed. Move off the switch or home ($H).");
    case 46:
        return tr("The machine must be homed first: home it ($H).");
    case 47:
        return tr("The controller does not know which tool is in the spindle: tell it with M61 Q<n>.");
    case 49:
        return tr("The controller's power-on self test failed: switch it off and on.");
    case 50:
        return tr("The emergency stop is engaged. Release it and reset the controller.");
    case 51:
        return tr("A motor driver reported a fault. Check the drivers and the motors, then reset the "
                  "controller.");
    case 79:
        return tr("Not allowed while a critical event is active (an emergency stop, a hard limit or a motor "
                  "fault). Clear it and reset the controller.");
    case 87:
        return tr("There is already a tool in the spindle: remove it first.");
    case 88:
        return tr("There is no tool in the spindle: put one in (or tell the controller with M61 Q<n>).");
    default:
        return tr("The controller refused the line (error:%1).").arg(error);
    }
}

} // namespace Toffee::GrblHal
