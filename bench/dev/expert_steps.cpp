#include <vector>
#include <string>
#include <memory>
#include <map>
#include <span>
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
  double T0 = atof(argv[1]), T1 = atof(argv[2]);
  geometry::AnatomyParameters ap;
  auto anatomy = geometry::buildProceduralColon(ap);
  procedure::ProcedureSettings settings; if (getenv("MU")) settings.contact.frictionCoefficient = atof(getenv("MU")); if (getenv("STEP")) settings.contactStepLimit = atof(getenv("STEP"));
  procedure::ProcedureLoop loop(anatomy, settings);
  procedure::ScriptedOperator op(procedure::expertStyle());
  Eigen::Vector3d last = Eigen::Vector3d::Zero();
  for (int s = 1; s <= (int)(T1*1000); ++s) {
    auto in = op.next(loop); loop.step(in);
    auto nodes = loop.scope().nodePositions(); int n = nodes.size();
    double jump = (nodes[n-1]-last).norm(); last = nodes[n-1];
    if (s < T0*1000) continue;
    const auto& cs = loop.lumen().contacts();
    const auto& L = loop.coupling().loads();
    printf("s=%d n=%d jump=%.2fmm dial=(%.2f,%.2f) ins=%.4f |", s, n, jump*1e3, in.dialUpDown, in.dialLeftRight, in.insertion);
    for (int i = 0; i < n; ++i) if (cs[i].depth > -2e-3 || L.col(i).norm() > 0) printf(" [%d d=%.1f L=%.2f]", i, cs[i].depth*1e3, L.col(i).norm());
    {const auto& c=cs[n-1]; printf(" ring=%d u=%.2f end=%d nrm=(%.2f %.2f %.2f) dist=%.1f R=%.1f tip=(%.1f %.1f %.1f)", c.station.ring, c.station.u, (int)c.endCap, c.normal.x(), c.normal.y(), c.normal.z(), c.lever*1e3, c.wallRadius*1e3, nodes[n-1].x()*1e3, nodes[n-1].y()*1e3, nodes[n-1].z()*1e3);} printf(" th_tip=(%.2f %.2f %.2f)\n", loop.scope().rod().theta[n-2].x(), loop.scope().rod().theta[n-2].y(), loop.scope().rod().theta[n-2].z());
  }
}
