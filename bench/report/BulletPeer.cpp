#include "bench/report/BulletPeer.h"

#include "simcore/physics/StaticSolver.h"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>

#include <cmath>
#include <ostream>
#include <sstream>
#include <vector>

namespace colonosim::bench {

struct BulletColon::World {
    btSoftBodyRigidBodyCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btSoftRigidDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
    std::unique_ptr<btSoftBody> body;
};

BulletColon::BulletColon(const BenchScene& scene, const BulletSettings& settings)
    : m_scene(scene), m_settings(settings), m_world(std::make_unique<World>()), m_terms(scene.makeBody())
{
    const physics::TissueBody& body = m_terms.body;
    const int n = body.numNodes();
    std::vector<btVector3> x(static_cast<size_t>(n));
    std::vector<btScalar> m(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d p = body.positions().col(i);
        x[static_cast<size_t>(i)] = btVector3(btScalar(p.x()), btScalar(p.y()), btScalar(p.z()));
        m[static_cast<size_t>(i)] = body.isFixed(i) ? btScalar(0) : btScalar(body.masses()[i]);
    }
    const Eigen::Vector3d g =
        scene.environment.gravity * physics::downDirection(scene.environment.patientPosition);
    const btVector3 gravity(btScalar(g.x()), btScalar(g.y()), btScalar(g.z()));
    btSoftBodyWorldInfo& info = m_world->world.getWorldInfo();
    info.m_gravity = gravity;
    info.m_sparsesdf.Initialize();
    m_world->world.setGravity(gravity);

    m_world->body = std::make_unique<btSoftBody>(&info, n, x.data(), m.data());
    btSoftBody& soft = *m_world->body;
    for (int s = 0; s < m_terms.springs->numSprings(); ++s) {
        soft.appendLink(m_terms.springs->nodeA(s), m_terms.springs->nodeB(s));
    }
    soft.m_materials[0]->m_kLST = btScalar(settings.linearStiffness);
    soft.m_cfg.piterations = settings.positionIterations;
    soft.m_cfg.kDP = btScalar(settings.damping);
    m_world->world.addSoftBody(&soft);
    m_x = body.positions();
    m_v.setZero(3, n);
    m_f.setZero(3, n);
}

BulletColon::~BulletColon()
{
    m_world->world.removeSoftBody(m_world->body.get());
}

void BulletColon::readState()
{
    const btSoftBody& soft = *m_world->body;
    for (int i = 0; i < soft.m_nodes.size(); ++i) {
        const btVector3& p = soft.m_nodes[i].m_x;
        const btVector3& v = soft.m_nodes[i].m_v;
        m_x.col(i) = Eigen::Vector3d(p.x(), p.y(), p.z());
        m_v.col(i) = Eigen::Vector3d(v.x(), v.y(), v.z());
    }
}

void BulletColon::step(double t, double h, bool withLoad)
{
    btSoftBody& soft = *m_world->body;
    m_f.setZero();
    if (withLoad) {
        const Eigen::Vector3d f = m_scene.load.nodeForce(t);
        for (const int node : m_scene.load.nodes) {
            m_f.col(node) += f;
        }
    }
    if (m_terms.insufflation != nullptr) {
        m_terms.insufflation->addForce(m_x, m_f);
    }
    m_terms.mesentery->addForceAndDamping(m_x, m_v, m_f);
    m_terms.retroperitoneal->addForceAndDamping(m_x, m_v, m_f);
    m_terms.adhesions->addForceAndDamping(m_x, m_v, m_f);
    for (int i = 0; i < soft.m_nodes.size(); ++i) {
        const Eigen::Vector3d f = m_f.col(i);
        soft.addForce(btVector3(btScalar(f.x()), btScalar(f.y()), btScalar(f.z())), i);
    }
    m_world->world.stepSimulation(btScalar(h), 0);
    readState();
    if (m_settings.withOrgans && m_terms.body.projectConstraints(m_x, m_v) > 0) {
        for (int i = 0; i < soft.m_nodes.size(); ++i) {
            soft.m_nodes[i].m_x = btVector3(btScalar(m_x(0, i)), btScalar(m_x(1, i)), btScalar(m_x(2, i)));
            soft.m_nodes[i].m_v = btVector3(btScalar(m_v(0, i)), btScalar(m_v(1, i)), btScalar(m_v(2, i)));
        }
    }
}

namespace {
double meanAlong(const StandardLoad& load, const physics::Positions& loaded,
                 const physics::Positions& unloaded)
{
    double sum = 0.0;
    for (const int node : load.nodes) {
        sum += (loaded.col(node) - unloaded.col(node)).dot(load.direction);
    }
    return sum / static_cast<double>(load.nodes.size());
}

physics::Positions staticState(const BenchScene& scene, bool withLoad)
{
    physics::ColonBody colon = scene.makeBody();
    if (withLoad) {
        scene.load.apply(colon.body, scene.load.rampTime);
    }
    (void)physics::solveStaticEquilibrium(colon.body, 1e-7, 100);
    return colon.body.positions();
}

constexpr double kSettleTime = 0.4;     ///< s of damped Bullet stepping to reach equilibrium
constexpr double kSettleDamping = 0.2;  ///< kDP while settling (no effect on the equilibrium)
}  // namespace

double ourStaticDeflection(const BenchScene& scene)
{
    return meanAlong(scene.load, staticState(scene, true), staticState(scene, false));
}

double bulletStaticDeflection(const BenchScene& scene, const BulletSettings& settings)
{
    BulletSettings settle = settings;
    settle.damping = kSettleDamping;
    settle.withOrgans = false;
    BulletColon loaded(scene, settle);
    BulletColon unloaded(scene, settle);
    constexpr double h = 1e-3;
    const auto steps = static_cast<int>(std::lround(kSettleTime / h));
    for (int s = 0; s < steps; ++s) {
        loaded.step(scene.load.rampTime, h, true);
        unloaded.step(0.0, h, false);
    }
    return meanAlong(scene.load, loaded.positions(), unloaded.positions());
}

BulletMatch matchBulletStiffness(const BenchScene& scene, int halvings, std::ostream& log)
{
    BulletMatch match;
    match.targetDeflection = ourStaticDeflection(scene);
    log << "peer: our static deflection under the standard load " << match.targetDeflection * 1e3 << " mm\n";
    BulletSettings settings;
    // Raise the iterations until kLST = 1 is at least as stiff as our model.
    for (settings.positionIterations = 1; settings.positionIterations <= 64;
         settings.positionIterations *= 2) {
        settings.linearStiffness = 1.0;
        const double stiffest = bulletStaticDeflection(scene, settings);
        ++match.evaluations;
        log << "peer: piterations " << settings.positionIterations << ", kLST 1: deflection "
            << stiffest * 1e3 << " mm\n";
        if (stiffest <= match.targetDeflection) {
            break;
        }
    }
    double lo = 0.0;  // too soft (deflection too large)
    double hi = 1.0;  // too stiff
    double deflection = NAN;
    for (int it = 0; it < halvings; ++it) {
        settings.linearStiffness = 0.5 * (lo + hi);
        deflection = bulletStaticDeflection(scene, settings);
        ++match.evaluations;
        (deflection > match.targetDeflection ? lo : hi) = settings.linearStiffness;
    }
    settings.linearStiffness = 0.5 * (lo + hi);
    match.peerDeflection = bulletStaticDeflection(scene, settings);
    ++match.evaluations;
    match.settings = settings;
    std::ostringstream note;
    note << "bisection on m_kLST (" << halvings << " halvings, piterations " << settings.positionIterations
         << ", raised from 1 while kLST = 1 was too soft) so that the static deflection of the loaded nodes "
            "under the standard 2 N load (mean along the load, loaded minus unloaded, gravity and "
            "insufflation "
            "in both, no organs) equals our model's static solution: ours "
         << match.targetDeflection * 1e3 << " mm, Bullet " << match.peerDeflection * 1e3 << " mm at kLST "
         << settings.linearStiffness << "; kDP 0 in the dynamic run (0.2 while settling)";
    match.note = note.str();
    log << "peer: " << match.note << "\n";
    return match;
}

}  // namespace colonosim::bench
