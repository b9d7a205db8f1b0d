// first_touch.cpp: bench_first_touch, what the first write to fresh memory costs on this machine, with
// 2 MiB huge pages (MADV_HUGEPAGE, as core/bulk_reserve.h advises a reader's output arrays) and
// with 4 KiB pages (MADV_NOHUGEPAGE, as fast_obj's arrays get). The OBJ reader's arrays of a
// 4M-triangle mesh are 112 MB; their first write is a stage of the 2-thread read
// (bench/io/results.md, objread6), and its time is the spread of that read's medians.
//
// Each round maps MB fresh, 2 MiB-aligned, anonymous bytes, advises them, writes zeros over them
// (memset: the kernel faults in and zeroes each page, the memset follows) and prints the wall and
// process CPU time of the write, then unmaps them; `--sleep S` waits S seconds before each round
// (a one-shot process that starts some time after the last one freed its memory). Also printed:
// /sys/module/page_reporting's page_reporting_order when the kernel has free page reporting (a
// guest of a hypervisor with virtio-balloon's free page reporting: free blocks of that order are
// handed back to the host, which must fault them in again on their next first write).
//
// Usage: bench_first_touch [--mb MB] [--rounds N] [--sleep S] [--pages huge|4k|both]
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>

namespace {

double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// One round: wall and CPU ms of the first write to `bytes` fresh bytes; false when mmap refuses.
bool first_write(std::size_t bytes, bool huge, double& wall, double& cpu) {
  constexpr std::size_t kHuge = std::size_t(2) << 20;
  void* p = ::mmap(nullptr, bytes + kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) return false;
  char* const a = reinterpret_cast<char*>((reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1));
  ::madvise(a, bytes, huge ? MADV_HUGEPAGE : MADV_NOHUGEPAGE);
  const double c0 = cpu_ms();
  const auto t0 = std::chrono::steady_clock::now();
  std::memset(a, 0, bytes);
  wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  cpu = cpu_ms() - c0;
  ::munmap(p, bytes + kHuge);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t mb = 112;
  int rounds = 3;
  double sleep_s = 0;
  std::string pages = "both";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--mb") mb = std::size_t(std::atol(argv[i + 1]));
    else if (a == "--rounds") rounds = std::atoi(argv[i + 1]);
    else if (a == "--sleep") sleep_s = std::atof(argv[i + 1]);
    else if (a == "--pages") pages = argv[i + 1];
    else {
      std::fprintf(stderr, "usage: bench_first_touch [--mb MB] [--rounds N] [--sleep S] [--pages huge|4k|both]\n");
      return 2;
    }
  }
  std::ifstream order("/sys/module/page_reporting/parameters/page_reporting_order");
  std::string o;
  if (order >> o) std::printf("free page reporting: on, order %s (blocks of 4 KiB << %s handed back to the host when free)\n", o.c_str(), o.c_str());
  else std::printf("free page reporting: not found (/sys/module/page_reporting)\n");
  for (int r = 0; r < rounds; ++r) {
    for (const bool huge : {true, false}) {
      if ((huge && pages == "4k") || (!huge && pages == "huge")) continue;
      if (sleep_s > 0) std::this_thread::sleep_for(std::chrono::duration<double>(sleep_s));
      double wall = 0, cpu = 0;
      if (!first_write(mb << 20, huge, wall, cpu)) {
        std::fprintf(stderr, "bench_first_touch: mmap of %zu MB refused\n", mb);
        return 1;
      }
      std::printf("round %d, %s pages, %zu MB: first write %.1f ms wall, %.1f ms CPU\n", r + 1, huge ? "2 MiB" : "4 KiB", mb, wall, cpu);
    }
  }
  return 0;
}
