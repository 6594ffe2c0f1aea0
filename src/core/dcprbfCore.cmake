# The OpenFOAM-free core as a CMake static library "dcprbfCore", for the unit
# tests (tests/core) and the benchmarks (benchmarks). include() it after
# project(); OpenFOAM builds the same sources with wmake (src/Make/files).
include_guard(GLOBAL)

#- The warning flags of every target of the core, tests and benchmarks
function(dcprbf_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra)
endfunction()

find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(OpenMP REQUIRED)

file(GLOB DCPRBF_CORE_SOURCES ${CMAKE_CURRENT_LIST_DIR}/*.cpp)
add_library(dcprbfCore STATIC ${DCPRBF_CORE_SOURCES})
target_include_directories(dcprbfCore PUBLIC ${CMAKE_CURRENT_LIST_DIR})
dcprbf_warnings(dcprbfCore)
# the core is also built by wmake for OpenFOAM v1912, whose default is C++14
set_target_properties(dcprbfCore PROPERTIES CXX_STANDARD 14)
target_link_libraries(dcprbfCore PUBLIC Eigen3::Eigen OpenMP::OpenMP_CXX)
