#pragma once
/// \file
/// The scope's side of scope-wall contact: the contact load on each scope
/// node for the next chain solve, from this step's penalty contacts.
///
/// Why not apply the penalty forces directly. The scope is quasi-static (the
/// chain solver finds its equilibrium under the loads of the step) and the
/// penalty is stiff: k_c = 1e4 N/m against a lateral tip stiffness of
/// 3 EI / L^3 = 160 N/m at 8 cm of insertion and 12 N/m at 20 cm. Applying
/// k_c d as a load, re-solving, re-measuring d and so on is a fixed-point
/// iteration with gain k_c C (C the rod's compliance at the contact), far
/// above 1: the tip bounces from wall to wall. A fixed under-relaxation only
/// moves the limit (0.02 diverges beyond about 10 cm).
///
/// What is done instead: the contact forces of one loop step are solved on
/// a linear model of the scope around its current shape, with the exact
/// local geometry of the wall. A load change df_b at node b moves node a by
/// C_ab df_b, C the compliance of the clamped rod (3 x 3 blocks),
///     C_ab = sum_{k < min(a,b)} [r_ak]x^T C_k K_k^-1 C_k^T [r_bk]x,
/// r_ak = x_a - x_k (a rotation of joint k moves node a by w x r_ak), built
/// in O(n + m^2) from prefix sums over the joints. Each node in or near
/// contact then carries f_a = lambda_a n_a, with the depth and normal
/// re-measured on the local wall (LumenNodeContact::depthAt: a cylinder, or
/// the end plane) at the predicted position x_a + sum_b C_ab (f_b - f_b^old);
/// a projected Gauss-Seidel sweep updates each lambda_a by the Newton step
///     lambda_a += (k_c depth_a - lambda_a) / (1 + k_c G_aa),  lambda_a >= 0,
/// G_aa = n_a^T C_aa n_a (plus the wall's part below), until the largest
/// change is below contact.sweepTolerance (or contact.couplingSweeps sweeps,
/// 0.1 mN and 30 by default). Between sweeps, Anderson acceleration
/// (contact.sweepAcceleration) replaces the loads by the combination of the
/// last few sweeps' results whose changes cancel best: deep in, each node's
/// load drifts about over many sweeps (a slowly decaying oscillation that the
/// plain sweeps follow at 0.85-0.9 a sweep), and the combination cuts across
/// it. The stop is judged on a plain sweep's change either way. The normal is re-measured in every
/// sweep: on a curved wall it turns as the node moves (by dx / lever, with a
/// gain lambda G_aa / lever that easily exceeds 1 on a compliant tip), and a
/// normal frozen for the step makes the tip swing from side to side. The
/// turn is taken implicitly: each sweep moves the normal towards the
/// re-measured one by 1 / (1 + gain), one Newton step on the linear model; a
/// plain re-measurement overshot from sweep to sweep (the expert's first 20 s
/// on the default colon: 1,133 of 20,000 steps at the 30-sweep cap, tip up
/// to 35.6 mm into the wall; implicit: 19 steps, 6.3 mm). A trust
/// region limits the contact-driven motion of each node in one step to
/// maxStep (G_aa |lambda_a - lambda_a^old|); the rest of the way is taken in
/// later steps, so a contact that appears with a large depth is resolved
/// over several steps rather than thrown across the lumen. A node whose depth
/// grew since the last step's start (by g, measured against the moving
/// wall, so a wall pushed away gives none) may be pushed back by that
/// distance as well: its load may grow by (maxStep + g) / reach, and it
/// still lets go by at most maxStep / reach. The chain moves nodes by more than its linear
/// model says (a shaft springing forward as a bend straightens drove the
/// tip into the cecal end at 3-7 m/s with the insertion held), and a load
/// growing by maxStep a step alone let the tip through the wall (generated
/// seed 1, the novice at the cecum: 53 mm past it under 1-3 N).
///
/// Contact points. The contacts are those of the contact points
/// (ContactPoints.h): the nodes and, with contact.elementPoints, points
/// inside each element. A point inside an element moves as a node there
/// would (the elements are rigid between the joints), so its blocks C_ab are
/// the same sums with x_a its position and the joints that move it, and the
/// load it settles on reaches the rod shared by the element's two nodes. With
/// the nodes alone, 21.5 mm apart, an element's chord crossed the wall of a
/// tight bend unseen (README, known limits).
///
/// Side normals (contact.sideNormals). A shaft lies along the wall it
/// touches, so the wall's push on it is across it (friction apart). The
/// lumen's local wall is the cylinder of a section, and where the colon is
/// pleated on the shaft the sections tilt against it: their normals pushed
/// the shaft along its axis, as no smooth wall can. With side normals the
/// load at every point but the tip takes the wall's normal n less its part
/// along the scope's axis t there (the element's direction inside an element,
/// the chord of its neighbours at a node, the first element at the base),
/// d = (n - (n.t) t) / |n - (n.t) t|, and keeps n where less than 0.2 of it
/// is left across (a wall met nearly head on). The depth is still measured
/// along n, so the Newton step's compliance is n^T C d. The tip meets the
/// wall head on and keeps n.
///
/// Relaxation. The linear model leaves out how the loads' lever arms change
/// as the shaft moves (its geometric stiffness: the chain's response to a
/// load on a shaft bent round the sigmoid under 5-10 N is 10-30% larger than
/// C says), and a contact's normal turns with the node round a wall of
/// 10-15 mm radius: under a 9 N load that is a stiffness of about 800 N/m,
/// against compliances of 2-9 mm/N. The solve's error is thus fed back, with
/// a gain of several, through the next re-measure: the shaft swung from side
/// to side by 5-20 mm a step. Each solve therefore applies the fraction
/// omega of its load change (contact.loadRelaxation), as a partitioned
/// coupling does; the remainder follows over the next solves (the passes of
/// the step and the next steps, 1 ms each).
///
#include "simcore/contact/ContactParameters.h"
#include "simcore/contact/LumenContact.h"
#include "simcore/procedure/ContactPoints.h"
#include "simcore/scope/DiscreteRod.h"

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace colonosim::procedure {

/// When a contact solve's Gauss-Seidel sweeps stop (contact.couplingSweeps,
/// contact.sweepTolerance and contact.passSweepTolerance), and how they sum
/// the load changes' effect (contact.prefixSweeps).
struct SweepLimits {
    int maxSweeps = 30;
    double tolerance = 1e-4;  ///< N: the largest change of a normal load in a sweep that stops them
    /// false: node a's predicted motion is sum_b C_ab df_b over the dense
    /// blocks, O(m^2) a sweep. true: the same sum through the rod's prefix
    /// sums, O(m) a sweep. With b >= a the blocks use the prefix sums up to
    /// a, with b < a those up to b, so
    ///     sum_b C_ab df_b = X_a^T (A_a S1 - B_a S0 + R1) + C_a S0 - B_a^T S1 + R2,
    /// S0 = sum_{b>=a} df_b, S1 = sum_{b>=a} X_b df_b (tip side),
    /// R1 = sum_{b<a} (A_b X_b - B_b) df_b, R2 = sum_{b<a} (C_b - B_b^T X_b) df_b
    /// (base side): a sweep from base to tip moves each node from the tip
    /// side's sums to the base side's as it updates it. Same sweeps, other
    /// rounding.
    bool prefixSums = false;
    /// N: the largest change of a normal load in a sweep that stops the
    /// sweeps of a solve that another solve of the step follows
    /// (solveAndApply()'s `lastSolve` false): its loads are re-measured and
    /// solved again, so their last bits are not kept.
    double passTolerance = 1e-4;
    /// Anderson acceleration of the sweeps: after each sweep the normal
    /// loads are replaced by the combination of the last `acceleration`
    /// sweeps' results whose changes cancel best (least squares), projected
    /// to lambda >= 0; 0 sweeps plainly. The stop is always judged on a plain
    /// sweep's change. At most kMaxAcceleration.
    int acceleration = 0;
};

/// The most sweeps Anderson acceleration combines: contact.sweepAcceleration's
/// upper bound, declared once with the parameter.
inline constexpr int kMaxAcceleration =
    static_cast<int>(contact::ContactParameters::accelerationSpec.maxValue);

class ContactCoupling {
public:
    /// `contactStiffness` k_c, N/m; `maxStep` the trust region, m per loop
    /// step; `loopStep` dt, s; `relaxation` omega in (0, 1], the fraction of
    /// the solved load change that each solve applies.
    /// `points`: where along the scope the contacts are (ContactPoints.h;
    /// the nodes alone by default).
    /// `sideNormals`: the loads are pushed across the shaft (see above).
    /// `stickingFriction`: each point's friction is kept from step to step
    /// (see solveAndApply()). `spinFriction`: the friction acts at the
    /// shaft's surface, a moment on the rod besides (see solveAndApply();
    /// the contacts' slip then includes the surface's spin,
    /// LumenContact::addSurfaceSpin()).
    ContactCoupling(double contactStiffness, double maxStep, double loopStep, double relaxation,
                    SweepLimits sweeps = {}, ContactPoints points = {}, bool sideNormals = false,
                    bool stickingFriction = false, bool spinFriction = false)
        : m_stiffness(contactStiffness), m_maxStep(maxStep), m_loopStep(loopStep), m_relaxation(relaxation),
          m_limits(sweeps), m_points(points), m_sideNormals(sideNormals),
          m_stickingFriction(stickingFriction), m_spinFriction(spinFriction)
    {}

    /// Updates the loads from `contacts` (one per contact point of the
    /// inserted rod, ContactPoints.h, measured on the current scope shape,
    /// which carries the loads of the previous update). `addedAtBase` nodes
    /// entered the rod at the base since the last call (negative when nodes
    /// left); `wallCompliance` is dt^2 / (2 m) per wall
    /// node (0 for fixed nodes), m/N. The coupling reads `contacts` again in
    /// solveAndApply(): they must outlive that call.
    /// `newStep`: the first update of a loop step (the depths it is given
    /// start the step); false for the re-measures within one step.
    void update(const std::vector<contact::LumenNodeContact>& contacts, const scope::DiscreteRod& rod,
                int addedAtBase, const Eigen::VectorXd& wallCompliance, bool newStep = true);

    /// The whole linearised contact problem of the step solved once
    /// (Gauss-Seidel on the rod's compliance), and the normal loads moved the
    /// fraction omega of the way from their start to the solution; the rod's
    /// node forces become the base loads (gravity) plus contact: the normal
    /// load and the friction `law` gives for it (Coulomb, against the slip
    /// measured by update()'s contacts). The wall carries the opposite of
    /// loads().
    ///
    /// Friction. A point's slip s over the step (scope minus wall, across
    /// its normal) is measured on the shape that carries the last step's
    /// loads. By default the friction is found afresh from it,
    /// -mu lambda s / max(|s|, v_s), with the stick speed v_s at least
    /// 2 mu lambda R / dt (R the slip compliance, measureSlipCompliance()):
    /// below it that is -s dt / (2 R), whatever mu, and a shaft pushed at
    /// centimetres a second over compliances of millimetres a newton meets a
    /// small fraction of mu lambda. With sticking friction the point's
    /// friction f of the last step is kept, turned into the new tangent
    /// plane, and the load that stops the step's slip added to it:
    ///     f <- f - s dt / (2 R),  then |f| <= mu lambda,
    /// a tangential spring of stiffness 1 / (2 R) anchored where the point
    /// stuck: it holds while the load it needs is within the cone and slides
    /// at mu lambda beyond (Coulomb). The gain is the stick's bound above
    /// (the friction map of one step has a spectral radius of at most 1/2),
    /// so the slip left decays by at least half a step. A point that leaves
    /// its wall (lambda = 0) lets go of its friction.
    ///
    /// Spin friction. The friction f acts where the shaft's surface touches
    /// the wall, r from the axis against the normal n: with spinFriction the
    /// rod takes the moment (-r n) x f at the point besides f at its axis
    /// (shared by an element's two nodes as the force is). Its part about the
    /// axis, r |f| at most mu lambda r, resists the shaft's spin; the slip the
    /// friction opposes is the surface's, the axis's velocity plus -r w x n
    /// (w the spin). The stick's slip compliance R then also bounds how far
    /// the friction's moments slide the surface by turning the joints:
    /// (sqrt(R) + sqrt(r^2 sum_b T_ab))^2, T_ab the sum of the most
    /// compliant axis of each joint before both points.
    /// `lastSolve`: false when the step solves the contact again after this
    /// one (the sweeps stop at SweepLimits::passTolerance, not tolerance).
    void solveAndApply(scope::DiscreteRod& rod, const contact::LumenContact& law, bool lastSolve = true);

    /// Contact load (normal and friction) at each contact point (base to tip;
    /// the nodes themselves by default), N; the wall carries the opposite,
    /// spread over the contact's wall nodes.
    [[nodiscard]] const Eigen::Matrix3Xd& loads() const { return m_loads; }
    /// Normal load carried at each contact point, N (world).
    [[nodiscard]] const std::vector<Eigen::Vector3d>& normalLoads() const { return m_load; }
    /// The contact points in this step's update, and their normal compliance G, m/N.
    [[nodiscard]] const std::vector<int>& activeNodes() const { return m_active; }
    /// G_ab = n_a^T (C_ab + W_ab) d_b: how far a unit load at b moves a along
    /// its wall's normal (d_b = n_b but with side normals).
    [[nodiscard]] Eigen::MatrixXd delassus() const;
    /// Gauss-Seidel sweeps of the last update.
    [[nodiscard]] int sweeps() const { return m_sweeps; }
    /// The largest change of a normal load in the last solve's last sweep, N:
    /// below the tolerance when the sweeps converged, what was left when
    /// they stopped at the cap.
    [[nodiscard]] double residual() const { return m_residual; }
    [[nodiscard]] const ContactPoints& points() const { return m_points; }

private:
    void align(int numPoints, int addedAtBase);
    void relax();
    void measureSlipCompliance();
    void buildCompliance(const scope::DiscreteRod& rod);
    void addWallCompliance(const std::vector<contact::LumenNodeContact>& contacts,
                           const Eigen::VectorXd& wallCompliance);
    /// Sweeps until no normal load changes by more than `tolerance` (N) in a sweep, or the cap.
    void solve(const std::vector<contact::LumenNodeContact>& contacts, double tolerance);
    /// One Anderson step after sweep `sweep` (SweepLimits::acceleration).
    void accelerate(int depth, int sweep, int& stored, int& next, double& lastChange);
    void measureAxes(const scope::DiscreteRod& rod);
    /// The direction of the load at active point a for the wall's normal `n`.
    [[nodiscard]] Eigen::Vector3d loadDirection(size_t a, const Eigen::Vector3d& n) const;
    /// Active point a's sticking friction for this solve (recorded per point), N.
    Eigen::Vector3d stickingFriction(size_t a, const contact::LumenNodeContact& contact, double mu);

    double m_stiffness;
    double m_maxStep;
    double m_loopStep;
    double m_relaxation;
    SweepLimits m_limits;
    ContactPoints m_points;
    bool m_sideNormals;
    bool m_stickingFriction;
    bool m_spinFriction;
    int m_sweeps = 0;
    double m_residual = 0.0;
    std::vector<Eigen::Vector3d> m_load;      ///< normal load per node (lambda n), N
    std::vector<int> m_active;                ///< nodes in the update
    std::vector<double> m_stepDepth;          ///< depth of each node at the last step's start, m (NaN: none)
    std::vector<double> m_growth;             ///< how far each node's depth grew over the last step, m (>= 0)
    std::vector<Eigen::Vector3d> m_friction;  ///< friction load per point, last solve, N (sticking friction)
    std::vector<Eigen::Vector3d> m_stepFriction;  ///< the same at the step's start, N
    // Working storage over the active nodes; it grows to the largest set
    // seen and is then reused, so a warm loop does not allocate.
    std::vector<Eigen::Matrix3d> m_block;  ///< C_ab, row-major over (a, b), m/N
    // Per active node a, for the prefix sweeps (SweepLimits::prefixSums):
    // X_a = [x_a]x and the two matrices that move it to the base side's sums
    // (A_a, B_a, C_a are the prefix sums at its node, m_prefix*).
    std::vector<Eigen::Matrix3d> m_skew, m_toR1, m_toR2;
    std::vector<double> m_wall;  ///< wall compliance shared by (a, b), m/N
    /// Per a: the b in [first, second) that may share wall compliance with it
    /// (empty when first >= second); the rest of its row of m_wall is 0.
    std::vector<std::pair<size_t, size_t>> m_wallSpan;
    std::vector<Eigen::Vector3d> m_force, m_startForce, m_normal;
    std::vector<Eigen::Vector3d> m_direction;  ///< each active point's load direction (unit)
    std::vector<Eigen::Vector3d> m_axis;       ///< the scope's axis there (unit; 0: none), side normals only
    std::vector<double> m_lambda, m_startLambda;
    // Anderson acceleration (SweepLimits::acceleration), column-major m x depth:
    // the differences of successive sweeps' changes and of their results.
    std::vector<double> m_andersonF, m_andersonG;
    std::vector<double> m_andersonX, m_andersonFPrev, m_andersonGPrev;
    std::vector<double> m_slipCompliance;  ///< R_a, m/N (measureSlipCompliance())
    std::vector<Eigen::Vector3d> m_at;     ///< each active point's position, m
    const std::vector<contact::LumenNodeContact>* m_contacts = nullptr;
    Eigen::Matrix3Xd m_loads;
    // Prefix sums over the joints (A = sum W, B = sum W X, C = sum X^T W X).
    std::vector<Eigen::Matrix3d> m_prefixA, m_prefixB, m_prefixC;
    /// Prefix sums of each joint's largest compliance, rad/(N m) (spin friction).
    std::vector<double> m_prefixTwist;
};

}  // namespace colonosim::procedure
