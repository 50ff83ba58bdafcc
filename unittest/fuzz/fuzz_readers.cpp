// Fuzz harnesses of POLYDEM's readers (issue 17, beyond the list): STL files
// (ASCII and binary; then coplanar merging and the bin grid) and shape files
// (parser, CGAL hull, mass properties). One entry point per reader,
// LLVMFuzzerTestOneInput, chosen by POLYDEM_FUZZ_STL or POLYDEM_FUZZ_SHAPE:
// linked with libFuzzer (clang -fsanitize=fuzzer, unittest/scripts/fuzz.sh) it is
// coverage-guided; linked with fuzz_driver.cpp it is the bounded mutation
// run of ctest (fuzz.stl, fuzz.shape). Every input must end in a result or
// a reported error: a crash, hang, sanitizer report or a broken invariant
// (abort) is a finding.
#include "polydem_shape_record.h"
#include "polydem_shape_template.h"
#include "polydem_stl.h"

#include "fuzz_common.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using polydem_fuzz::check;
using polydem_fuzz::scratch;
using polydem_fuzz::write_input;

#if defined(POLYDEM_FUZZ_STL)
void run_one()
{
  polydem::StlMesh m;
  try {
    m = polydem::read_stl(scratch(), polydem::StlTransform());
  } catch (polydem::StlError &) {
    return;    // a reported error
  }
  check(m.ntri() > 0, "an STL read without error has triangles");
  for (double c : m.tri) check(std::isfinite(c), "STL coordinates are finite");
  if (m.ntri() > 20000) return;    // bound the work per input
  std::vector<double> tri = m.tri;
  const auto st = polydem::merge_coplanar(tri, 1e-9);
  check(st.after > 0 && tri.size() % 9 == 0, "merging keeps triangles");
  for (double c : tri) check(std::isfinite(c), "merged coordinates are finite");
  double lo = 1e300, hi = -1e300;
  for (double c : tri) lo = c < lo ? c : lo, hi = c > hi ? c : hi;
  const double h = (hi - lo) / 16 + 1e-300;
  if (std::isfinite(h) && h > 0) {
    const auto g = polydem::build_mesh_grid(tri, h);
    check((long) g.n[0] * g.n[1] * g.n[2] <= (1L << 22), "the bin grid is bounded");
  }
}
#elif defined(POLYDEM_FUZZ_SHAPE)
void run_one()
{
  std::string record, err;
  std::vector<std::string> warnings;
  const auto t = polydem::shape_from_file(scratch(), true, record, warnings, err);
  if (!t) {
    check(!err.empty(), "a refused shape file says why");
    return;
  }
  check(std::isfinite(t->volume()) && t->volume() > 0, "volume finite and positive");
  check(std::isfinite(t->radius()) && t->radius() > 0, "radius finite and positive");
  for (double m : t->moments()) check(std::isfinite(m) && m > 0, "moments finite and positive");
  // the record (restart files) reads back
  std::string err2;
  check(polydem::shape_from_record(record, err2) != nullptr, "the record reads back");
}
#else
#error "define POLYDEM_FUZZ_STL or POLYDEM_FUZZ_SHAPE"
#endif

}    // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  if (size > (1u << 20)) return 0;
  write_input(data, size);
  run_one();
  return 0;
}
