# SPDX-License-Identifier: GPL-3.0-or-later
# The house's rules a newcomer relies on. Run as
#   cmake -DROOT=<source root> -DRULE=docs|size -P tests/house.cmake
# docs: the product's documents (README.md, CHANGELOG.md, docs/*.md) speak of the product, never of the
#       work tracker ("issue 29", "issue #29").
# size: no source file (model, serial, ui, app, tests) is longer than 450 lines; none is excused.

cmake_minimum_required(VERSION 3.25)

if(NOT ROOT OR NOT RULE)
    message(FATAL_ERROR "usage: cmake -DROOT=<source root> -DRULE=docs|size -P house.cmake")
endif()
set(problems "")
set(checked 0)
if(RULE STREQUAL "docs")
    file(GLOB documents RELATIVE ${ROOT} ${ROOT}/README.md ${ROOT}/CHANGELOG.md ${ROOT}/docs/*.md)
    foreach(document IN LISTS documents)
        math(EXPR checked "${checked} + 1")
        file(STRINGS ${ROOT}/${document} lines REGEX "[Ii]ssues? #?[0-9]")
        foreach(line IN LISTS lines)
            string(APPEND problems "\n  ${document}: ${line}")
        endforeach()
    endforeach()
    set(what "a document names an issue number: say what the product does instead")
elseif(RULE STREQUAL "size")
    file(GLOB_RECURSE sources RELATIVE ${ROOT}
        ${ROOT}/model/*.h ${ROOT}/model/*.cpp ${ROOT}/serial/*.h ${ROOT}/serial/*.cpp
        ${ROOT}/ui/*.h ${ROOT}/ui/*.cpp ${ROOT}/app/*.h ${ROOT}/app/*.cpp ${ROOT}/tests/*.h ${ROOT}/tests/*.cpp)
    list(FILTER sources EXCLUDE REGEX "^tests/data/")
    foreach(source IN LISTS sources)
        math(EXPR checked "${checked} + 1")
        file(READ ${ROOT}/${source} text)
        string(REGEX MATCHALL "\n" ends "${text}")
        list(LENGTH ends count)
        if(count GREATER 450)
            string(APPEND problems "\n  ${source}: ${count} lines")
        endif()
    endforeach()
    set(what "a source file is longer than 450 lines: split it by responsibility")
else()
    message(FATAL_ERROR "unknown rule ${RULE}")
endif()
if(checked EQUAL 0)
    message(FATAL_ERROR "nothing to check under ${ROOT}")
endif()
if(problems)
    message(FATAL_ERROR "${what}:${problems}")
endif()
message(STATUS "${checked} files checked")
