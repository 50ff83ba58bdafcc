#include "polydem_shape_template.h"
#include <gtest/gtest.h>
#include <cstdio>
using namespace polydem;
TEST(Shape, Cube) {
  std::vector<PolyShapeTemplate::Point> p;
  for (int i=0;i<8;++i) p.push_back({double(i&1), double((i>>1)&1), double((i>>2)&1)});
  auto s = PolyShapeTemplate::from_points(p);
  printf("V=%g nv=%d nf=%d ne=%d I=%g %g %g r=%g\n", s.volume(), s.nverts(), s.nfaces(), s.nedges(), s.moments()[0], s.moments()[1], s.moments()[2], s.radius());
}
