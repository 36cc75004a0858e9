#pragma once
// Timing helpers of the glyph benches (header-only, bench code only): per-thread CPU time and
// order statistics of the measured milliseconds.

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "vicc_glyphs/render/process_heap.hpp"

namespace vicc_glyphs::bench {

/// CPU time of this thread in milliseconds: "one core", and not counting other processes that
/// share the core on a shared machine.
inline double threadCpuMilliseconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return now.tv_sec * 1e3 + now.tv_nsec * 1e-6;
}

/// Runs `run` (which returns its times: a type with total()) `repeats` times, at least once, and
/// returns the times of the fastest run. On a shared machine a single run's CPU time swings by a
/// third (other processes' use of the caches and of the core's sibling); the benches' results
/// are the same in every run, so the fastest run is the code's own cost.
template <class Run>
auto fastestRun(int repeats, Run&& run) {
  auto fastest = run();
  for (int r = 1; r < repeats; ++r) {
    const auto times = run();
    if (times.total() < fastest.total()) fastest = times;
  }
  return fastest;
}

/// Sets malloc as the glyph server node sets it for its process (keepFreedMemoryForReuse),
/// unless `default_heap` (the benches' --default-heap); says which for the output.
inline std::string heapAsInTheServer(bool default_heap) {
  if (default_heap) return "glibc defaults (--default-heap)";
  return keepFreedMemoryForReuse() ? "freed memory kept for reuse, as in glyph_server"
                                   : "glibc defaults (the C library refused the setting)";
}

/// The middle value (the upper one of an even count); 0 for none.
inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

/// The 95th percentile (nearest rank); 0 for none.
inline double percentile95(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, static_cast<std::size_t>(0.95 * values.size()))];
}

inline double maximum(const std::vector<double>& values) {
  return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

/// The machine's load average (1, 5, 15 min): CPU times are per thread, but a loaded machine
/// still slows them (shared caches, hyper-threads).
inline std::string loadAverage() {
  std::FILE* file = std::fopen("/proc/loadavg", "r");
  char text[64] = "unknown";
  if (file) {
    if (!std::fgets(text, sizeof text, file)) std::snprintf(text, sizeof text, "unknown");
    std::fclose(file);
  }
  std::string load = text;
  const std::size_t cut = load.find(' ', load.find(' ', load.find(' ') + 1) + 1);
  return cut == std::string::npos ? load : load.substr(0, cut);
}

}  // namespace vicc_glyphs::bench
