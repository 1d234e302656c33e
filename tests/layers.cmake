# SPDX-License-Identifier: GPL-3.0-or-later
# Fails when a source file includes from a layer above its own. Run as
#   cmake -DROOT=<source root> -P tests/layers.cmake
# The layers, lowest first: model ← formats, gcode, library, camimport, job ← document; wire ← transport;
# model, gcode, wire, transport ← emulator; transport ← machine ← carvera, grblhal, linuxcnc (the controllers, none
# reaching another; LinuxCNC's reads its tool.tbl with formats); emulator, carvera, grblhal, linuxcnc ← serial ← carverarack (the Carvera's rack, run over a
# connection); then the window's rooms: common ← connection, table, history, job, library, rack (the rack alone
# with carverarack) and machine (with connection) ← shell; app. The window reaches the controllers only through the
# neutral layers (serial, machine): no room of it includes carvera, grblhal or linuxcnc.
# Includes are written from the source root ("serial/carvera/machinesession.h"), so the first folders name the layer.

cmake_minimum_required(VERSION 3.25)

if(NOT ROOT)
    message(FATAL_ERROR "usage: cmake -DROOT=<source root> -P layers.cmake")
endif()

# The layer of a path relative to ROOT, most specific first.
function(layer_of path out)
    foreach(pair "model/document:document" "model/formats:formats" "model/gcode:gcode" "model/library:library"
            "model/camimport:camimport" "model/job:job" "model:model"
            "serial/wire:wire" "serial/transport:transport" "serial/emulator:emulator"
            "serial/machine:machine" "serial/carvera/rack:carverarack" "serial/carvera:carvera" "serial/grblhal:grblhal" "serial/linuxcnc:linuxcnc"
            "serial:serial"
            "ui/common:ui_common" "ui/connection:ui_connection" "ui/table:ui_table" "ui/machine:ui_machine"
            "ui/history:ui_history" "ui/job:ui_job" "ui/rack:ui_rack" "ui/library:ui_library" "ui/shell:ui_shell"
            "app:app")
        string(REPLACE ":" ";" pair "${pair}")
        list(GET pair 0 prefix)
        list(GET pair 1 name)
        if(path MATCHES "^${prefix}/")
            set(${out} ${name} PARENT_SCOPE)
            return()
        endif()
    endforeach()
    set(${out} "" PARENT_SCOPE)
endfunction()

# What each layer may include.
set(allowed_model model)
set(allowed_formats model formats)
set(allowed_gcode model gcode)
set(allowed_document model formats library document)
set(allowed_library model formats gcode library)
set(allowed_camimport model formats camimport)
set(allowed_job model formats gcode library job)
set(allowed_wire wire)
set(allowed_transport model wire transport)
set(allowed_emulator model gcode wire transport emulator)
set(allowed_machine model gcode wire transport machine)
set(allowed_carvera model gcode wire transport machine carvera)
set(allowed_grblhal model gcode wire transport machine grblhal)
set(allowed_linuxcnc model formats gcode wire transport machine linuxcnc)
set(allowed_serial model formats gcode wire transport emulator machine carvera grblhal linuxcnc serial)
set(allowed_carverarack model gcode wire transport machine carvera serial carverarack)
# What every room of the window may reach below it: the model and the neutral machine layers.
set(below_ui model formats gcode document library camimport job wire transport machine serial)
set(allowed_ui_common ${below_ui} ui_common)
foreach(room connection table history job library)
    set(allowed_ui_${room} ${below_ui} ui_common ui_${room})
endforeach()
set(allowed_ui_rack ${below_ui} carverarack ui_common ui_rack)
set(allowed_ui_machine ${below_ui} ui_common ui_connection ui_machine)
set(allowed_ui_shell ${below_ui} ui_common ui_connection ui_table ui_machine ui_history ui_job ui_rack ui_library
    ui_shell)
set(allowed_app model formats gcode document library camimport job wire transport emulator machine carvera
    grblhal linuxcnc serial carverarack ui_common ui_connection ui_table ui_machine ui_history ui_job ui_rack ui_library
    ui_shell app)

file(GLOB_RECURSE sources RELATIVE ${ROOT}
    ${ROOT}/model/*.h ${ROOT}/model/*.cpp ${ROOT}/serial/*.h ${ROOT}/serial/*.cpp
    ${ROOT}/ui/*.h ${ROOT}/ui/*.cpp ${ROOT}/app/*.h ${ROOT}/app/*.cpp)
set(problems "")
set(checked 0)
foreach(source IN LISTS sources)
    layer_of(${source} own)
    file(STRINGS ${ROOT}/${source} includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"")
    foreach(line IN LISTS includes)
        string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([^\"]+)\".*" "\\1" included "${line}")
        math(EXPR checked "${checked} + 1")
        if(NOT included MATCHES "/")
            if(NOT included MATCHES "\\.moc$")
                list(APPEND problems "${source}: \"${included}\" names no folder; write it from the source root")
            endif()
            continue()
        endif()
        layer_of(${included} theirs)
        if(NOT theirs)
            list(APPEND problems "${source}: \"${included}\" is in no layer")
        elseif(NOT theirs IN_LIST allowed_${own})
            list(APPEND problems "${source} (${own}) includes \"${included}\" (${theirs}), a layer it may not reach (above its own, or beside it)")
        endif()
    endforeach()
endforeach()

list(LENGTH sources files)
if(problems)
    list(JOIN problems "\n  " text)
    message(FATAL_ERROR "layers: ${files} files, ${checked} includes:\n  ${text}")
endif()
message(STATUS "layers: ${files} files, ${checked} includes, none reaches up or aside")
