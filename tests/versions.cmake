# SPDX-License-Identifier: GPL-3.0-or-later
# The version has one home, CMake's project version: each program's --version and the AppStream metainfo's
# newest release must say it. cmake -DVERSION=… -DBIN=… -DMETAINFO=… -P versions.cmake
foreach(program toffee toffee-cli toffee-emulator)
    execute_process(COMMAND ${BIN}/${program} --version
        OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE code)
    if(NOT code EQUAL 0 OR NOT out MATCHES "^(Toffee|toffee-cli|toffee-emulator) ${VERSION}\n")
        message(FATAL_ERROR "${program} --version says \"${out}${err}\" (exit ${code}), not ${VERSION}")
    endif()
endforeach()
file(READ ${METAINFO} metainfo)
string(REGEX MATCH "<release version=\"([^\"]*)\"" release "${metainfo}")
if(NOT CMAKE_MATCH_1 STREQUAL VERSION)
    message(FATAL_ERROR "${METAINFO}'s newest release is \"${CMAKE_MATCH_1}\", not ${VERSION}")
endif()
message(STATUS "every program and the metainfo say ${VERSION}")
