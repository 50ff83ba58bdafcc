// Shared by the fuzz harnesses: the scratch file the readers read (they take
// a path), and the invariant check that makes a broken invariant a finding.
#ifndef POLYDEM_FUZZ_COMMON_H
#define POLYDEM_FUZZ_COMMON_H

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace polydem_fuzz {

// one scratch file per process; it holds the last input (a finding's reproducer)
inline const std::string &scratch()
{
  static std::string path;
  if (path.empty()) {
    char tmpl[] = "/tmp/polydem_fuzz_XXXXXX";
    const int fd = mkstemp(tmpl);
    if (fd >= 0) close(fd);
    path = tmpl;
  }
  return path;
}

inline void write_input(const uint8_t *data, size_t size)
{
  FILE *f = std::fopen(scratch().c_str(), "wb");
  if (!f) {
    std::perror("polydem fuzz: cannot write the scratch file");
    std::abort();
  }
  if (size) std::fwrite(data, 1, size, f);
  std::fclose(f);
}

inline void check(bool ok, const char *what)
{
  if (ok) return;
  std::fprintf(stderr, "polydem fuzz: invariant broken: %s (input: %s)\n", what, scratch().c_str());
  std::abort();
}

}    // namespace polydem_fuzz

#endif
