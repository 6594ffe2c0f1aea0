# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# Test-only reference implementations as a CMake static library
# "dcprbfReference" (not part of libdcpRBF.so): RbfInterpolant and
# SaddleSolver (dense from-scratch solves) and NaiveGreedyModel/selectNaive
# (GreedySelector's loop re-solving per iteration). Used by the unit tests
# (tests/core) and the benchmarks to check and time the core against them.
# include() it after project(); it includes the core (dcprbfCore.cmake).
include_guard(GLOBAL)
include(${CMAKE_CURRENT_LIST_DIR}/../../../src/core/dcprbfCore.cmake)

file(GLOB DCPRBF_REFERENCE_SOURCES ${CMAKE_CURRENT_LIST_DIR}/*.cpp)
add_library(dcprbfReference STATIC ${DCPRBF_REFERENCE_SOURCES})
target_include_directories(dcprbfReference PUBLIC ${CMAKE_CURRENT_LIST_DIR})
dcprbf_warnings(dcprbfReference)
set_target_properties(dcprbfReference PROPERTIES CXX_STANDARD 14)
target_link_libraries(dcprbfReference PUBLIC dcprbfCore)
