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
#include <chrono>
using namespace colonosim;
int main(int argc, char** argv) {
  double T = atof(argv[1]); int every = atoi(argv[2]);
  const char* who = argc > 3 ? argv[3] : "expert";
  geometry::AnatomyParameters ap; if (getenv("SIGLEN")) ap.sigmoidLength = atof(getenv("SIGLEN")); if (getenv("SIGDIA")) ap.sigmoidDiameter = atof(getenv("SIGDIA"));
  auto anatomy = geometry::buildProceduralColon(ap);
  procedure::ProcedureSettings settings; if (getenv("MES")) settings.tissue.mesenteryModulus = atof(getenv("MES")); if (getenv("MU")) settings.contact.frictionCoefficient = atof(getenv("MU")); if (getenv("STEP")) settings.contactStepLimit = atof(getenv("STEP"));
  procedure::ProcedureLoop loop(anatomy, settings);
  procedure::ScriptedOperator op(std::string(who) == "novice" ? procedure::noviceStyle() : procedure::expertStyle());
  double maxJump = 0; double maxF = 0; int phaseSw = 0; int lastPhase = 0; Eigen::Vector3d last = Eigen::Vector3d::Zero();
  auto t0 = std::chrono::steady_clock::now();
  for (int s = 1; s <= (int)(T*1000); ++s) {
    auto in = op.next(loop); loop.step(in);
    auto nodes = loop.scope().nodePositions(); int n = nodes.size();
    maxJump = std::max(maxJump, (nodes[n-1]-last).norm()); maxF = std::max(maxF, loop.outputs().handleForce); { int ph = (int)op.m_phase; if (ph != lastPhase) { if (ph==1) printf("  -> reduce at t=%.3f F=%.2f maxF=%.2f loop=%d excess=%.3f tipArc=%.3f\n", s*1e-3, loop.outputs().handleForce, (int)loop.loops().current(), loop.loops().signals().excessShaft, loop.lastFrame().tipArcLength); lastPhase = ph; } } last = nodes[n-1];
    if (s % every) continue;
    const auto& cs = loop.lumen().contacts();
    double deepest = -1; int dn = -1; int inWall = 0;
    for (int i = 0; i < n && i < (int)cs.size(); ++i) { if (cs[i].depth > deepest) { deepest = cs[i].depth; dn = i; } if (cs[i].depth > 0) ++inWall; }
    int tipRing = cs.empty() ? -1 : cs[std::min<int>(n, cs.size())-1].station.ring;
    double wall = std::chrono::duration<double>(std::chrono::steady_clock::now()-t0).count();
    printf("t=%.1f ins=%.3f n=%d tipArc=%.3f tipRing=%d deepest=%.1fmm@%d inWall=%d maxJump=%.1fmm F=%.2f maxF=%.2f loop=%d steps/s=%.0f\n", s*1e-3, in.insertion, n, loop.lastFrame().tipArcLength, tipRing, deepest*1e3, dn, inWall, maxJump*1e3, loop.outputs().handleForce, maxF, (int)loop.loops().current(), s/wall);
    maxJump = 0; maxF = 0;
  }
}
