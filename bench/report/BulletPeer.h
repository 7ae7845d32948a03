#pragma once
/// \file
/// The peer: the same colon as a Bullet btSoftBody (position-based links,
/// Bullet 2.x soft bodies, single precision as Debian ships it).
///
/// Same terms: one node per physics node at the same position with the same
/// mass (Fixed nodes mass 0, i.e. immovable), one link per wall spring of the
/// SpringSet, gravity through the world info. Everything our model adds
/// beyond the wall springs is applied to the Bullet nodes as external forces
/// computed each step by our own force terms at Bullet's node positions and
/// velocities: the standard load, insufflation (InsufflationPressure), the
/// mesentery tethers (Mesentery) and the retroperitoneal anchors
/// (AnchorSprings); after each step our OrganConstraint projects the nodes
/// out of the organs, as in our integrators.
///
/// Bullet's links have no stiffness in N/m: a link is a distance constraint
/// relaxed by the unitless factor kLST in [0, 1] piterations times per step,
/// so its effective stiffness depends on kLST, the iterations, the masses
/// and the step. matchBulletStiffness() bisects kLST so that the static
/// deflection under the standard load equals our model's (StaticSolver),
/// raising piterations while kLST = 1 is still too soft.

#include "bench/report/BenchScene.h"

#include <memory>
#include <string>

namespace colonosim::bench {

struct BulletSettings {
    double linearStiffness = 1.0;  ///< kLST, [0, 1]
    int positionIterations = 1;    ///< piterations
    double damping = 0.0;          ///< kDP, [0, 1]
    bool withOrgans = true;
};

class BulletColon {
public:
    BulletColon(const BenchScene& scene, const BulletSettings& settings);
    ~BulletColon();
    BulletColon(const BulletColon&) = delete;
    BulletColon& operator=(const BulletColon&) = delete;

    /// One step of h seconds; the load is evaluated at time t.
    void step(double t, double h, bool withLoad);
    [[nodiscard]] const physics::Positions& positions() const { return m_x; }

private:
    struct World;
    void readState();

    const BenchScene& m_scene;
    BulletSettings m_settings;
    std::unique_ptr<World> m_world;
    physics::ColonBody m_terms;  ///< our force terms, evaluated at Bullet's state
    physics::Positions m_x;
    physics::Velocities m_v;
    physics::Forces m_f;
};

/// Static deflection under the standard load: mean displacement of the
/// loaded nodes along the load direction between the loaded and unloaded
/// equilibria (gravity and insufflation in both, no organs), m.
[[nodiscard]] double ourStaticDeflection(const BenchScene& scene);
[[nodiscard]] double bulletStaticDeflection(const BenchScene& scene, const BulletSettings& settings);

struct BulletMatch {
    BulletSettings settings;
    double targetDeflection = 0.0;  ///< ours, m
    double peerDeflection = 0.0;    ///< Bullet's at the matched kLST, m
    int evaluations = 0;
    std::string note;  ///< how it was matched, for summary.json
};

/// `halvings` bisection steps on kLST.
[[nodiscard]] BulletMatch matchBulletStiffness(const BenchScene& scene, int halvings, std::ostream& log);

}  // namespace colonosim::bench
