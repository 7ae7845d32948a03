#include <vector>
#include <string>
#include <memory>
#include <map>
#include <span>
#include <sstream>
#include <Eigen/Core>
#include <Eigen/Geometry>
#define private public
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"
#undef private
#include <cstdio>
#include <cstdlib>
using namespace colonosim;
int main(int argc, char** argv) {
  double T = atof(argv[1]);
  geometry::AnatomyParameters ap;
  auto anatomy = geometry::buildProceduralColon(ap);
  procedure::ProcedureSettings settings;
  if (getenv("MU")) settings.contact.frictionCoefficient = atof(getenv("MU"));
  procedure::ProcedureLoop loop(anatomy, settings);
  procedure::ScriptedOperator op(procedure::expertStyle());
  Eigen::Vector3d last = Eigen::Vector3d::Zero(); int lastN = 0; double lastIns = 0; Eigen::Vector2d lastDial(0,0);
  int big = 0, bigN = 0;
  for (int s = 1; s <= (int)(T*1000); ++s) {
    auto in = op.next(loop); loop.step(in);
    auto nodes = loop.scope().nodePositions(); int n = nodes.size();
    double jump = (nodes[n-1]-last).norm(); last = nodes[n-1];
    if (s > 100 && jump > 0.008) { ++big; if (n != lastN) ++bigN;
      if (big <= 15) printf("s=%d jump=%.1fmm n %d->%d ins %.5f->%.5f dial (%.3f,%.3f)->(%.3f,%.3f) tipRing=%d\n", s, jump*1e3, lastN, n, lastIns, in.insertion, lastDial.x(), lastDial.y(), in.dialUpDown, in.dialLeftRight, loop.lumen().contacts().back().station.ring); }
    lastN = n; lastIns = in.insertion; lastDial = Eigen::Vector2d(in.dialUpDown, in.dialLeftRight);
  }
  printf("big jumps %d, of which at a node count change %d\n", big, bigN);
}
