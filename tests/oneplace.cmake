# SPDX-License-Identifier: GPL-3.0-or-later
# Fails when a rule that has one place in the product is written anywhere else: the wall clock read
# (model/clock.cpp), a length converted between millimetres and inches (model/units.h). Run as
#   cmake -DROOT=<source root> -DRULE=clock|units -P tests/oneplace.cmake
# Time limits use QDeadlineTimer / QElapsedTimer (monotonic), which the clock rule allows.

cmake_minimum_required(VERSION 3.25)

if(NOT ROOT OR NOT RULE)
    message(FATAL_ERROR "usage: cmake -DROOT=<source root> -DRULE=clock|units -P oneplace.cmake")
endif()
if(RULE STREQUAL "clock")
    set(place "model/clock.cpp")
    set(pattern "QDateTime::current|QDate::currentDate|QTime::currentTime|system_clock|[^a-zA-Z_.>:]time\\((nullptr|NULL|0)\\)|std::time\\(|gettimeofday|clock_gettime\\(CLOCK_REALTIME")
    set(what "the wall clock is read outside model/clock.cpp (use Clock::now())")
elseif(RULE STREQUAL "units")
    set(place "model/units.h")
    set(pattern "25\\.4|0\\.0393700")
    set(what "a length is converted outside model/units.h (use convertLength, toMillimetres, fromMillimetres)")
else()
    message(FATAL_ERROR "unknown rule ${RULE}")
endif()

file(GLOB_RECURSE sources RELATIVE ${ROOT}
    ${ROOT}/model/*.h ${ROOT}/model/*.cpp ${ROOT}/serial/*.h ${ROOT}/serial/*.cpp
    ${ROOT}/ui/*.h ${ROOT}/ui/*.cpp ${ROOT}/app/*.h ${ROOT}/app/*.cpp)
set(problems "")
set(checked 0)
foreach(source IN LISTS sources)
    if(source STREQUAL place)
        continue()
    endif()
    math(EXPR checked "${checked} + 1")
    file(STRINGS ${ROOT}/${source} lines REGEX "${pattern}")
    foreach(line IN LISTS lines)
        string(STRIP "${line}" line)
        string(APPEND problems "  ${source}: ${line}\n")
    endforeach()
endforeach()
if(checked EQUAL 0)
    message(FATAL_ERROR "no source files under ${ROOT}")
endif()
if(problems)
    message(FATAL_ERROR "${what}:\n${problems}")
endif()
message(STATUS "${checked} files leave this rule to ${place}")
