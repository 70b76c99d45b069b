#include "process_memory.hpp"

#include <malloc.h>

#include <fstream>
#include <string>

namespace geompm::bench {

namespace {

// A "Key:   1234 kB" line of /proc/self/status, in bytes.
std::size_t status_field(const std::string& key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(key + ":", 0) == 0) return std::stoull(line.substr(key.size() + 1)) * 1024;
  return 0;
}

}  // namespace

std::size_t heap_in_use() {
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd;
}

std::size_t resident_bytes() { return status_field("VmRSS"); }

std::size_t peak_resident_bytes() { return status_field("VmHWM"); }

bool reset_peak_resident() {
  // "5" resets the peak RSS of the process (Documentation/filesystems/proc.rst).
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  return static_cast<bool>(clear);
}

void release_free_heap() { malloc_trim(0); }

}  // namespace geompm::bench
