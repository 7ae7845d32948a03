#include "simcore/geometry/ProceduralColon.h"
#include "simcore/geometry/CentrelineSampling.h"
#include "simcore/physics/ColonBody.h"
#include "simcore/physics/StaticSolver.h"
#include "simcore/physics/TissueSimulation.h"
#include "simcore/procedure/ProcedureLoop.h"
#include <cstdio>
#include <cstdlib>
using namespace colonosim;
int main(int argc, char** argv) {
  geometry::AnatomyParameters ap;
  auto anatomy = geometry::buildProceduralColon(ap);
  procedure::ProcedureSettings settings;
  if (getenv("MES")) settings.tissue.mesenteryModulus = atof(getenv("MES"));
  auto colon = physics::buildColonBody(anatomy, settings.tissue, settings.environment, settings.calibration);
  auto r0 = physics::solveStaticEquilibrium(colon.body, 1e-5, 3000);
  setvbuf(stdout,nullptr,_IONBF,0); printf("rest conv=%d it=%d\n", r0.converged, r0.iterations);
  physics::Positions x0 = colon.body.positions();
  const double F = argc > 1 ? atof(argv[1]) : 2.0;
  for (double s : {0.20, 0.30, 0.38, 0.45, 0.52}) {
    colon.body.positions() = x0;
    auto at = geometry::sampleCentreline(anatomy.centreline, s);
    auto ahead = geometry::sampleCentreline(anatomy.centreline, s + 0.01);
    auto behind = geometry::sampleCentreline(anatomy.centreline, s - 0.01);
    Eigen::Vector3d kappa = (ahead.tangent - behind.tangent) / 0.02;
    Eigen::Vector3d dir = kappa.norm() > 1e-9 ? Eigen::Vector3d(-kappa.normalized()) : Eigen::Vector3d::UnitX();
    std::vector<int> nodes;
    for (int i = 0; i < (int)anatomy.physicsNodes.size(); ++i)
      if (std::abs(anatomy.physicsNodes[i].arcLength - s) < 0.02) nodes.push_back(i);
    colon.body.clearExternalForces();
    for (int i : nodes) colon.body.applyExternalForce(i, F / nodes.size() * dir);
    colon.body.velocities().setZero();
    physics::TissueSimulation sim(colon.body, settings.stepping);
    const int steps = getenv("STEPS") ? atoi(getenv("STEPS")) : 2000;
    for (int k = 0; k < steps; ++k) { sim.advance(); colon.body.clearExternalForces(); for (int i : nodes) colon.body.applyExternalForce(i, F / nodes.size() * dir); }
    struct { bool converged; int iterations; } r{true, steps};
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    for (int i : nodes) d += colon.body.positions().col(i) - x0.col(i);
    d /= nodes.size();
    printf("s=%.2f seg=%d R=%.3f m nodes=%zu conv=%d it=%d disp along load=%.1f mm total=%.1f mm\n", s, (int)at.segment,
           kappa.norm() > 1e-9 ? 1.0 / kappa.norm() : 0.0, nodes.size(), r.converged, r.iterations, d.dot(dir) * 1e3, d.norm() * 1e3);
  }
}
