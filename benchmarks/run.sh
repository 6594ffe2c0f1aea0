#!/bin/sh
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# Build and run the core benchmark (Release, 2 OpenMP threads by default).
#     benchmarks/run.sh [--quick] [eval] [update] [greedy] [stored]
# Output: a markdown report on stdout, also written to build/benchmarks/report.md
set -e
cd "$(dirname "$0")/.."
build=build/benchmarks
mkdir -p "$build"
cmake -S benchmarks -B "$build" -DCMAKE_BUILD_TYPE=Release > "$build/cmake.log"
cmake --build "$build" -j 2 > "$build/make.log"
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-2}"
"$build/coreBenchmark" "$@" | tee "$build/report.md"
