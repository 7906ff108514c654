// What this host's memory gives one core: k independent chains of dependent loads, each load a
// random 64-byte line of a buffer far larger than the caches (in BigVector's huge pages, as the
// engine's arrays at N = 1e6). One chain measures the latency of a line from memory; k chains
// in one loop measure how many lines the core keeps in flight, and where that stops growing.
// An event-driven run at N = 1e6 reads 56-98 lines from memory per collision
// (tests/bench/README.md, "What N = 1e6 waits for"); this says how fast it could read them.
//   carom_memory_chains [--mib M] [--loads L]
// Each row: chains k, nanoseconds per load of one chain, lines per microsecond over all chains.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <vector>

#include "core/huge_pages.hpp"
#include "core/rng.hpp"

using namespace carom;

namespace {

struct alignas(64) Line {
  std::uint32_t next;  ///< The line this chain reads after this one.
};

/// One random cycle through all lines (Sattolo's shuffle): a chain never repeats a line before
/// it has read them all, so the caches hold none of what it reads next.
BigVector<Line> random_cycle(std::size_t lines, std::uint64_t seed) {
  std::vector<std::uint32_t> order(lines);
  std::iota(order.begin(), order.end(), 0u);
  Rng rng(seed);
  for (std::size_t i = lines - 1; i > 0; --i) std::swap(order[i], order[rng.below(i)]);
  BigVector<Line> buffer(lines);
  for (std::size_t i = 0; i < lines; ++i) buffer[order[i]].next = order[(i + 1) % lines];
  return buffer;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"carom_memory_chains: a core's latency and lines in flight from memory"};
  std::size_t mib = 512, loads = 4000000;
  app.add_option("--mib", mib, "buffer size, MiB (512: far above the caches; 4-16: near the L3)")
      ->check(CLI::Range(1, 16384));
  app.add_option("--loads", loads, "loads per row, over all chains")
      ->check(CLI::Range(1000, 1000000000));
  CLI11_PARSE(app, argc, argv);

  const std::size_t lines = (mib << 20) / sizeof(Line);
  const BigVector<Line> buffer = random_cycle(lines, 1);
  std::printf("buffer=%zu MiB lines=%zu\n", mib, lines);
  std::uint64_t checksum = 0;  // keeps the loads
  // Microseconds for `loads` loads shared among `chains` chains.
  auto time_chains = [&](std::size_t chains) {
    std::vector<std::uint32_t> at(chains);
    for (std::size_t c = 0; c < chains; ++c)
      at[c] = static_cast<std::uint32_t>(c * (lines / chains));
    const std::size_t steps = loads / chains;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t s = 0; s < steps; ++s)
      for (std::size_t c = 0; c < chains; ++c) at[c] = buffer[at[c]].next;
    const double us =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    for (const std::uint32_t a : at) checksum += a;
    return us;
  };
  time_chains(16);  // untimed: without it the first row ran slow
  for (const std::size_t k : {1, 2, 4, 8, 12, 16, 24, 32, 48}) {
    const std::size_t steps = loads / k;
    const double us = time_chains(k);
    std::printf("chains=%2zu ns_per_load=%6.1f lines_per_us=%6.1f\n", k, 1e3 * us / steps,
                static_cast<double>(steps * k) / us);
  }
  std::printf("checksum=%llu\n", static_cast<unsigned long long>(checksum % 1000));
}
