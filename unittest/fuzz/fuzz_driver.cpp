// Bounded mutation driver for the fuzz harnesses when libFuzzer is not used
// (ctest fuzz.*; the coverage-guided campaign is unittest/scripts/fuzz.sh). Replays the
// seed corpus, then mutates its entries (bit flips, bytes, insertions,
// deletions, duplications, splices, numbers replaced by extreme ones,
// 32-bit counts) for a fixed time or number of runs, from a fixed seed, so
// that a run is repeatable. A finding aborts the process; the input that
// caused it is the harness's scratch file (/tmp/polydem_fuzz_*); an input
// that runs longer than 10 s is reported as a hang and aborts too.
//   fuzz_X [-seconds S] [-runs N] [-seed K] corpus_dir_or_file...
#include <algorithm>
#include <cctype>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
extern "C" int LLVMFuzzerInitialize(int *argc, char ***argv) __attribute__((weak));

namespace {

using Bytes = std::vector<uint8_t>;

void load(const std::string &path, std::vector<Bytes> &corpus)
{
  struct stat st;
  if (stat(path.c_str(), &st) != 0) return;
  if (S_ISDIR(st.st_mode)) {
    DIR *d = opendir(path.c_str());
    if (!d) return;
    std::vector<std::string> names;
    while (dirent *e = readdir(d))
      if (e->d_name[0] != '.') names.push_back(path + "/" + e->d_name);
    closedir(d);
    std::sort(names.begin(), names.end());
    for (auto &n : names) load(n, corpus);
    return;
  }
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string s = ss.str();
  corpus.emplace_back(s.begin(), s.end());
}

const char *const NUMBERS[] = {
    "0",           "-0",   "1",    "-1",    "1e308", "-1e308", "1e-308", "4e-320",     "nan",
    "inf",         "-inf", "1e70", "1e200", "1e-11", "1e",     "0x10",   "2147483648", "4294967295",
    "-2147483649", "3",    "128",  "129",   "1e15",  "",       "+",      "."};

void mutate(Bytes &b, const std::vector<Bytes> &corpus, std::mt19937_64 &rng)
{
  auto pick = [&](size_t n) {
    return n ? (size_t) (rng() % n) : 0;
  };
  const int nmut = 1 + (int) (rng() % 4);
  for (int k = 0; k < nmut; k++) {
    switch (rng() % 8) {
      case 0:    // bit flip
        if (!b.empty()) b[pick(b.size())] ^= (uint8_t) (1u << (rng() % 8));
        break;
      case 1:    // random byte
        if (!b.empty()) b[pick(b.size())] = (uint8_t) rng();
        break;
      case 2: {    // insert random bytes
        const size_t at = pick(b.size() + 1), n = 1 + rng() % 8;
        Bytes ins(n);
        for (auto &c : ins) c = (uint8_t) (rng() % 2 ? rng() : " \n-.0123456789e"[rng() % 15]);
        b.insert(b.begin() + at, ins.begin(), ins.end());
        break;
      }
      case 3: {    // delete a range (also truncation)
        if (b.empty()) break;
        const size_t at = pick(b.size()), n = 1 + pick(rng() % 4 ? 16 : b.size() - at);
        b.erase(b.begin() + at, b.begin() + std::min(b.size(), at + n));
        break;
      }
      case 4: {    // duplicate a range
        if (b.empty() || b.size() > (1u << 18)) break;
        const size_t at = pick(b.size()), n = 1 + pick(std::min<size_t>(256, b.size() - at));
        const Bytes r(b.begin() + at, b.begin() + at + n);
        b.insert(b.begin() + pick(b.size() + 1), r.begin(), r.end());
        break;
      }
      case 5: {    // splice with another corpus entry
        const Bytes &o = corpus[pick(corpus.size())];
        if (o.empty()) break;
        const size_t at = pick(b.size() + 1), from = pick(o.size());
        b.resize(at);
        b.insert(b.end(), o.begin() + from, o.end());
        break;
      }
      case 6: {    // a number token replaced by an extreme one
        std::vector<size_t> starts;
        for (size_t i = 0; i < b.size(); i++)
          if ((isdigit(b[i]) || b[i] == '-') && (i == 0 || isspace(b[i - 1]))) starts.push_back(i);
        if (starts.empty()) break;
        const size_t s = starts[pick(starts.size())];
        size_t e = s;
        while (e < b.size() && !isspace(b[e])) e++;
        const char *n = NUMBERS[pick(sizeof(NUMBERS) / sizeof(NUMBERS[0]))];
        b.erase(b.begin() + s, b.begin() + e);
        b.insert(b.begin() + s, n, n + std::strlen(n));
        break;
      }
      default: {    // a 32-bit count (binary STL header at byte 80, or anywhere)
        if (b.size() < 4) break;
        const uint32_t vals[] = {0u,
                                 1u,
                                 2u,
                                 0xffffffffu,
                                 0x7fffffffu,
                                 0x80000000u,
                                 (uint32_t) ((b.size() - 84) / 50),
                                 (uint32_t) rng()};
        const uint32_t v = vals[rng() % 8];
        const size_t at = b.size() >= 84 && rng() % 2 ? 80 : pick(b.size() - 3);
        std::memcpy(&b[at], &v, 4);
        break;
      }
    }
  }
  if (b.size() > (1u << 20)) b.resize(1u << 20);
}

void hang(int)
{
  const char msg[] = "fuzz driver: an input ran longer than 10 s (hang); it is in the "
                     "harness's scratch file /tmp/polydem_fuzz_*\n";
  if (write(2, msg, sizeof(msg) - 1) < 0) _exit(3);
  std::abort();
}

int run_one(const Bytes &b)
{
  alarm(10);
  const int r = LLVMFuzzerTestOneInput(b.data(), b.size());
  alarm(0);
  return r;
}

}    // namespace

int main(int argc, char **argv)
{
  if (LLVMFuzzerInitialize) LLVMFuzzerInitialize(&argc, &argv);
  double seconds = 10.0;
  long runs = -1;
  unsigned long seed = 17;
  std::vector<Bytes> corpus;
  for (int i = 1; i < argc; i++) {
    const std::string a = argv[i];
    if (a == "-seconds" && i + 1 < argc)
      seconds = std::atof(argv[++i]);
    else if (a == "-runs" && i + 1 < argc)
      runs = std::atol(argv[++i]);
    else if (a == "-seed" && i + 1 < argc)
      seed = std::strtoul(argv[++i], nullptr, 10);
    else
      load(a, corpus);
  }
  if (corpus.empty()) {
    std::fprintf(stderr, "fuzz driver: no seed corpus given\n");
    return 2;
  }
  std::signal(SIGALRM, hang);
  for (const auto &c : corpus) run_one(c);
  std::mt19937_64 rng(seed);
  const auto t0 = std::chrono::steady_clock::now();
  long n = 0;
  Bytes b;
  for (;; n++) {
    if (runs >= 0 && n >= runs) break;
    if ((n & 63) == 0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > seconds)
      break;
    b = corpus[rng() % corpus.size()];
    mutate(b, corpus, rng);
    run_one(b);
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("fuzz driver: %zu seed inputs and %ld mutants in %.1f s (%.0f / s), seed %lu, no "
              "finding\n",
              corpus.size(), n, s, n / (s > 0 ? s : 1), seed);
  return 0;
}
