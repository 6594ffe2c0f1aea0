# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# The OpenFOAM-free core as a CMake static library "dcprbfCore", for the unit
# tests (tests/core) and the benchmarks (benchmarks). include() it after
# project(); OpenFOAM builds the same sources with wmake (src/Make/files).
include_guard(GLOBAL)

# Warnings: dcprbf_warnings(<target>) compiles a target of the core, the test
# reference library, the tests or the benchmarks with
#     -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Woverloaded-virtual
# and with -Werror when warnings are errors, i.e. when
#   - the option DCPRBF_WERROR is ON (cmake -DDCPRBF_WERROR=ON; default OFF), or
#   - the environment variable CI is set and non-empty when cmake configures
#     (CI runs `bash .ci/run` with CI=true).
option(DCPRBF_WERROR "Treat compiler warnings as errors (also on when the environment variable CI is set)" OFF)
if(DCPRBF_WERROR OR (DEFINED ENV{CI} AND NOT "$ENV{CI}" STREQUAL ""))
    set(DCPRBF_WARNINGS_AS_ERRORS ON)
else()
    set(DCPRBF_WARNINGS_AS_ERRORS OFF)
endif()
message(STATUS "dcpRBF: warnings as errors: ${DCPRBF_WARNINGS_AS_ERRORS}")

function(dcprbf_warnings target)
    target_compile_options(${target} PRIVATE
        -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Woverloaded-virtual)
    if(DCPRBF_WARNINGS_AS_ERRORS)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
endfunction()

find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(OpenMP REQUIRED)

# Sources in folders by role (see src/core/README.md); headers are included
# by name alone, as wmake's lnInclude flattens them for OpenFOAM
file(GLOB_RECURSE DCPRBF_CORE_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/*.cpp)
file(GLOB_RECURSE DCPRBF_CORE_HEADERS CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/*.hpp)
set(DCPRBF_CORE_INCLUDE_DIRS)
foreach(header IN LISTS DCPRBF_CORE_HEADERS)
    get_filename_component(dir ${header} DIRECTORY)
    list(APPEND DCPRBF_CORE_INCLUDE_DIRS ${dir})
endforeach()
list(REMOVE_DUPLICATES DCPRBF_CORE_INCLUDE_DIRS)
add_library(dcprbfCore STATIC ${DCPRBF_CORE_SOURCES})
target_include_directories(dcprbfCore PUBLIC ${DCPRBF_CORE_INCLUDE_DIRS})
dcprbf_warnings(dcprbfCore)
# the core is also built by wmake for OpenFOAM v1912, whose default is C++14
set_target_properties(dcprbfCore PROPERTIES CXX_STANDARD 14)
target_link_libraries(dcprbfCore PUBLIC Eigen3::Eigen OpenMP::OpenMP_CXX)
# Eigen's own threading (products) blocks by the number of threads: results
# would depend on it at round-off, and a greedy selection near a tie would
# pick other points on 1 and on 2 threads. The core threads its loops itself
# (OpenMP, per point: the same result whatever the thread count).
target_compile_definitions(dcprbfCore PUBLIC EIGEN_DONT_PARALLELIZE)
# No errno from sqrt: the SIMD quality kernels' sqrt vectorizes (GCC 12 keeps
# errno for std::sqrt under TetKernel.hpp's optimize pragma); the values are
# the same (src/Make/options: the same for wmake)
target_compile_options(dcprbfCore PRIVATE -fno-math-errno)
