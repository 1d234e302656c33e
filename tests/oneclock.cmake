# SPDX-License-Identifier: GPL-3.0-or-later
# Fails when the product reads the wall clock anywhere but its one seam, model/clock.cpp (Clock::now, which
# tests set). Run as
#   cmake -DROOT=<source root> -P tests/oneclock.cmake
# Time limits use QDeadlineTimer / QElapsedTimer (monotonic), which this allows.

cmake_minimum_required(VERSION 3.25)

if(NOT ROOT)
    message(FATAL_ERROR "usage: cmake -DROOT=<source root> -P oneclock.cmake")
endif()

file(GLOB_RECURSE sources RELATIVE ${ROOT}
    ${ROOT}/model/*.h ${ROOT}/model/*.cpp ${ROOT}/serial/*.h ${ROOT}/serial/*.cpp
    ${ROOT}/ui/*.h ${ROOT}/ui/*.cpp ${ROOT}/app/*.h ${ROOT}/app/*.cpp)
set(problems "")
set(checked 0)
foreach(source IN LISTS sources)
    if(source STREQUAL "model/clock.cpp")
        continue()
    endif()
    math(EXPR checked "${checked} + 1")
    file(STRINGS ${ROOT}/${source} reads
        REGEX "QDateTime::current|QDate::currentDate|QTime::currentTime|system_clock|[^a-zA-Z_.>:]time\\((nullptr|NULL|0)\\)|std::time\\(|gettimeofday|clock_gettime\\(CLOCK_REALTIME")
    foreach(line IN LISTS reads)
        string(STRIP "${line}" line)
        string(APPEND problems "  ${source}: ${line}\n")
    endforeach()
endforeach()
if(checked EQUAL 0)
    message(FATAL_ERROR "no source files under ${ROOT}")
endif()
if(problems)
    message(FATAL_ERROR "the wall clock is read outside model/clock.cpp (use Clock::now()):\n${problems}")
endif()
message(STATUS "${checked} files read the wall clock only through Clock::now()")
