#!/usr/bin/env bash
# scripts/bench_worker_pool.sh [LOOPS]
#
# What: the cost of one parallel loop of 16 pieces of 256 (a relaxation push's
# size at n = 4,096) with almost no work in them, on 2, 8 and 16 threads: the
# worker pool every loop runs on (host/common/worker_pool) against threads
# started and joined for each loop (common/worker_threads, what every loop did
# to 0.19.0). Microseconds a loop, LOOPS loops each (default 2,000).
#
# Why: the relaxation runs about 1,300 loops a run on bunny00 at n = 4,096 and
# the evening one per independent set; what a loop costs besides its work is
# paid that often. Results: docs/PERFORMANCE.md ("At scale", what changed).
set -euo pipefail
loops=${1:-2000}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/loops.cpp" <<'CPP'
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "common/parallel_for.hpp"
#include "common/worker_threads.hpp"

using namespace meshparticles;

// One loop as every loop ran to 0.19.0: threads of its own.
void with_own_threads(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& work) {
  std::atomic<std::size_t> next{0};
  const auto share = [&](unsigned) {
    for (std::size_t k = next++; k < count; k = next++) work(k);
  };
  WorkerThreads workers(threads - 1, share);
  share(0);
}

int main(int, char** argv) {
  const int loops = std::atoi(argv[1]);
  std::vector<double> values(16 * 256, 1.0);
  const auto piece = [&](std::size_t p) {
    for (std::size_t i = p * 256; i < (p + 1) * 256; ++i) values[i] *= 1.0000001;
  };
  for (const unsigned threads : {2u, 8u, 16u}) {
    double us[2];
    for (int pool = 0; pool < 2; ++pool) {
      const auto started = std::chrono::steady_clock::now();
      for (int loop = 0; loop < loops; ++loop) {
        if (pool) {
          for_each_with_slot(16, threads, [&](std::size_t p, unsigned) { piece(p); });
        } else {
          with_own_threads(16, threads, piece);
        }
      }
      us[pool] = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started).count() / loops;
    }
    std::printf("%2u threads: %7.1f us a loop with threads of its own, %6.1f on the pool\n", threads, us[0], us[1]);
  }
}
CPP
g++ -O2 -std=c++20 -pthread -I"$root/host" "$work/loops.cpp" "$root/host/common/worker_pool.cpp" -o "$work/loops"
echo "$(nproc) cores; $loops loops each"
"$work/loops" "$loops"
