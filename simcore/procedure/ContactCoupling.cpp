#include "simcore/procedure/ContactCoupling.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>

namespace colonosim::procedure {

namespace {
Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
    Eigen::Matrix3d s;
    s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return s;
}

/// Re-indexes per-node state after `added` nodes entered the rod at its base
/// (negative: left it), keeping the tip end: new[i] = old[i - added]. In
/// place, so a warm vector does not allocate.
template <class T>
void shiftToTip(std::vector<T>& v, int numNodes, int added, const T& empty)
{
    const int old = static_cast<int>(v.size());
    v.resize(static_cast<size_t>(std::max(old, numNodes)), empty);
    const auto at = [&](int i) -> T { return i >= 0 && i < old ? v[static_cast<size_t>(i)] : empty; };
    if (added > 0) {
        for (int i = numNodes - 1; i >= 0; --i) {
            v[static_cast<size_t>(i)] = at(i - added);  // reads below i: not yet overwritten
        }
    } else {
        for (int i = 0; i < numNodes; ++i) {
            v[static_cast<size_t>(i)] = at(i - added);  // reads at or above i
        }
    }
    v.resize(static_cast<size_t>(numNodes));
}

constexpr double kActiveGap = 5e-3;          ///< m: nodes this close to the wall join the update
const double kCarryCosine = std::sqrt(0.5);  ///< a load follows a normal that turned less than 45 degrees
constexpr double kLeastAcross = 0.2;  ///< a side normal needs this much of the wall's normal across the shaft
}  // namespace

void ContactCoupling::measureAxes(const scope::DiscreteRod& rod)
{
    // The scope's axis at each active point: its element's inside one, the
    // chord of its neighbours at a node, the first element at the base; none
    // at the tip, which meets the wall head on.
    const std::vector<Eigen::Vector3d>& x = rod.position;
    const int last = rod.numNodes() - 1;
    m_axis.resize(m_active.size());
    for (size_t a = 0; a < m_active.size(); ++a) {
        const int point = m_active[a];
        const auto node = static_cast<size_t>(m_points.node(point));
        Eigen::Vector3d axis = Eigen::Vector3d::Zero();
        if (point % m_points.stride != 0) {
            axis = x[node + 1] - x[node];
        } else if (static_cast<int>(node) < last) {
            axis = x[node + 1] - x[node == 0 ? node : node - 1];
        }
        const double length = axis.norm();
        m_axis[a] = length > 0.0 ? Eigen::Vector3d(axis / length) : Eigen::Vector3d::Zero();
    }
}

Eigen::Vector3d ContactCoupling::loadDirection(size_t a, const Eigen::Vector3d& n) const
{
    if (!m_sideNormals) {
        return n;
    }
    const Eigen::Vector3d& axis = m_axis[a];
    const Eigen::Vector3d across = n - n.dot(axis) * axis;
    const double left = across.norm();
    return left < kLeastAcross ? n : Eigen::Vector3d(across / left);
}

void ContactCoupling::align(int numPoints, int addedAtBase)
{
    shiftToTip(m_load, numPoints, addedAtBase, Eigen::Vector3d::Zero().eval());
    shiftToTip(m_stepDepth, numPoints, addedAtBase, std::numeric_limits<double>::quiet_NaN());
    if (m_stickingFriction) {
        shiftToTip(m_friction, numPoints, addedAtBase, Eigen::Vector3d::Zero().eval());
        shiftToTip(m_stepFriction, numPoints, addedAtBase, Eigen::Vector3d::Zero().eval());
    }
}

void ContactCoupling::buildCompliance(const scope::DiscreteRod& rod)
{
    const int n = rod.numNodes();
    const auto size = static_cast<size_t>(n) + 1;
    m_prefixA.resize(size);
    m_prefixB.resize(size);
    m_prefixC.resize(size);
    m_prefixA[0].setZero();
    m_prefixB[0].setZero();
    m_prefixC[0].setZero();
    for (int k = 0; k < n; ++k) {
        const auto i = static_cast<size_t>(k);
        const Eigen::Matrix3d& frame = rod.frame[i];
        const Eigen::Matrix3d w =
            frame * rod.jointResistance(k).cwiseInverse().asDiagonal() * frame.transpose();
        const Eigen::Matrix3d x = skew(rod.position[i]);
        m_prefixA[i + 1] = m_prefixA[i] + w;
        m_prefixB[i + 1] = m_prefixB[i] + w * x;
        m_prefixC[i + 1] = m_prefixC[i] + x.transpose() * w * x;
    }
    if (m_spinFriction) {
        // How far a moment turns the joints before a point, bounded by each
        // joint's most compliant axis: the spin slip's compliance below.
        m_prefixTwist.resize(size);
        m_prefixTwist[0] = 0.0;
        for (int k = 0; k < n; ++k) {
            const auto i = static_cast<size_t>(k);
            m_prefixTwist[i + 1] = m_prefixTwist[i] + rod.jointResistance(k).cwiseInverse().maxCoeff();
        }
    }
    // C_ab = X_a^T A X_b - X_a^T B - B^T X_b + C from the prefix sums up to
    // joint min(a, b) - 1 (X = [x]x, X^T = -X).
    // A point inside an element moves as a node there (ContactPoints.h): the
    // same sums up to the joints that move both.
    // update() lists the active points from base to tip, so the joints that
    // move a point never decrease along m_active: for b >= a the sums are
    // those up to a's joints, and X_a^T A and X_a^T B are taken once per a.
    const auto m = m_active.size();
    m_block.resize(m * m);
    for (size_t a = 0; a < m; ++a) {
        const Eigen::Matrix3d xa = skew(m_at[a]);
        const auto upto = static_cast<size_t>(m_points.joints(m_active[a]));
        const Eigen::Matrix3d xaA = xa.transpose() * m_prefixA[upto];
        const Eigen::Matrix3d xaB = xa.transpose() * m_prefixB[upto];
        const Eigen::Matrix3d& pb = m_prefixB[upto];
        for (size_t b = a; b < m; ++b) {
            const Eigen::Matrix3d xb = skew(m_at[b]);
            const Eigen::Matrix3d c = xaA * xb - xaB - pb.transpose() * xb + m_prefixC[upto];
            m_block[a * m + b] = c;
            m_block[b * m + a] = c.transpose();
        }
    }
    if (!m_limits.prefixSums) {
        return;
    }
    for (auto* v : {&m_skew, &m_toR1, &m_toR2}) {
        v->resize(m);
    }
    for (size_t a = 0; a < m; ++a) {
        const auto node = static_cast<size_t>(m_points.joints(m_active[a]));
        m_skew[a] = skew(m_at[a]);
        m_toR1[a] = m_prefixA[node] * m_skew[a] - m_prefixB[node];
        m_toR2[a] = m_prefixC[node] - m_prefixB[node].transpose() * m_skew[a];
    }
}

void ContactCoupling::addWallCompliance(const std::vector<contact::LumenNodeContact>& contacts,
                                        const Eigen::VectorXd& wallCompliance)
{
    // Shared wall compliance of (a, b): sum over common wall nodes k of
    // w_ak w_bk dt^2 / (2 m_k). Contacts are ordered along the scope, hence
    // along the lumen: only those within a ring of each other can share nodes.
    const auto m = m_active.size();
    m_wall.assign(m * m, 0.0);
    m_wallSpan.assign(m, {m, 0});
    for (size_t a = 0; a < m; ++a) {
        const contact::LumenNodeContact& ca = contacts[static_cast<size_t>(m_active[a])];
        for (size_t b = a; b < m; ++b) {
            const contact::LumenNodeContact& cb = contacts[static_cast<size_t>(m_active[b])];
            if (std::abs(cb.station.ring - ca.station.ring) > 1) {
                continue;
            }
            double shared = 0.0;
            for (size_t k = 0; k < 4; ++k) {
                for (size_t l = 0; l < 4; ++l) {
                    if (ca.wallNodes[k] == cb.wallNodes[l]) {
                        shared += ca.weights[k] * cb.weights[l] * wallCompliance[ca.wallNodes[k]];
                    }
                }
            }
            m_wall[a * m + b] = shared;
            m_wall[b * m + a] = shared;
            if (shared != 0.0) {
                for (const auto& [row, column] : {std::pair{a, b}, std::pair{b, a}}) {
                    m_wallSpan[row].first = std::min(m_wallSpan[row].first, column);
                    m_wallSpan[row].second = std::max(m_wallSpan[row].second, column + 1);
                }
            }
        }
    }
}

void ContactCoupling::solve(const std::vector<contact::LumenNodeContact>& contacts, double tolerance)
{
    // The start state (loads carried onto the present normals) is update()'s.
    const auto m = m_active.size();
    const bool prefix = m_limits.prefixSums;
    m_sweeps = 0;
    m_residual = 0.0;
    // No more differences than the loads have dimensions (the least squares
    // would be underdetermined).
    const int depth =
        std::min(std::clamp(m_limits.acceleration, 0, kMaxAcceleration), static_cast<int>(m) - 1);
    if (depth > 0) {
        for (auto* v : {&m_andersonF, &m_andersonG}) {
            v->resize(m * static_cast<size_t>(depth));
        }
        for (auto* v : {&m_andersonX, &m_andersonFPrev, &m_andersonGPrev}) {
            v->resize(m);
        }
    }
    int stored = 0;
    int next = 0;
    double lastChange = 0.0;
    for (int sweep = 0; sweep < m_limits.maxSweeps && m > 0; ++sweep) {
        ++m_sweeps;
        double largest = 0.0;
        if (depth > 0) {
            std::copy(m_lambda.begin(), m_lambda.begin() + static_cast<std::ptrdiff_t>(m),
                      m_andersonX.begin());
        }
        // The prefix sweeps' sums (SweepLimits): every node on the tip side.
        Eigen::Vector3d s0 = Eigen::Vector3d::Zero();
        Eigen::Vector3d s1 = Eigen::Vector3d::Zero();
        Eigen::Vector3d r1 = Eigen::Vector3d::Zero();
        Eigen::Vector3d r2 = Eigen::Vector3d::Zero();
        if (prefix) {
            for (size_t b = 0; b < m; ++b) {
                const Eigen::Vector3d change = m_force[b] - m_startForce[b];
                s0 += change;
                s1 += m_skew[b] * change;
            }
        }
        for (size_t a = 0; a < m; ++a) {
            // Predicted motion of node a relative to its wall under the
            // load changes so far (the current shapes carry the old loads).
            Eigen::Vector3d moved = Eigen::Vector3d::Zero();
            if (prefix) {
                const auto node = static_cast<size_t>(m_points.joints(m_active[a]));
                const Eigen::Matrix3d& sumB = m_prefixB[node];
                moved = m_skew[a].transpose() * (m_prefixA[node] * s1 - sumB * s0 + r1) +
                        m_prefixC[node] * s0 - sumB.transpose() * s1 + r2;
                for (size_t b = m_wallSpan[a].first; b < m_wallSpan[a].second; ++b) {
                    moved += m_wall[a * m + b] * (m_force[b] - m_startForce[b]);
                }
            } else {
                for (size_t b = 0; b < m; ++b) {
                    const Eigen::Vector3d change = m_force[b] - m_startForce[b];
                    moved += m_block[a * m + b] * change + m_wall[a * m + b] * change;
                }
            }
            const contact::LumenNodeContact& c = contacts[static_cast<size_t>(m_active[a])];
            Eigen::Vector3d n;
            const double depth = c.depthAt(m_at[a] + moved, n);
            // The normal turns as the node moves round the wall, by dx / lever,
            // and the load turns with it: a gain of lambda G_t / lever (G_t
            // the node's compliance along the turn), which a compliant tip or
            // a shaft near its buckling load takes far above 1, so that the
            // re-measured normal overshoots from sweep to sweep. The turn is
            // taken implicitly (one Newton step on the linear model): the
            // normal moves towards the re-measured one by 1 / (1 + gain).
            const Eigen::Vector3d turn = n - m_normal[a];
            const double turned = turn.norm();
            if (turned > 0.0 && c.lever > 0.0) {
                const double along = (m_block[a * m + a] * turn).norm() / turned + m_wall[a * m + a];
                const double gain = m_lambda[a] * along / c.lever;
                n = (m_normal[a] + turn / (1.0 + gain)).normalized();
            }
            // The load's direction; the depth is measured along n.
            const Eigen::Vector3d d = loadDirection(a, n);
            const Eigen::Vector3d moves =
                m_block[a * m + a] * d;  // the rod's response to a unit load along d
            const double g = m_sideNormals ? std::max(0.0, n.dot(moves) + m_wall[a * m + a] * n.dot(d))
                                           : n.dot(moves) + m_wall[a * m + a];
            double lambda =
                std::max(0.0, m_lambda[a] + (m_stiffness * depth - m_lambda[a]) / (1.0 + m_stiffness * g));
            // Trust region on the contact-driven motion of this step.
            // The whole motion, not only its normal part: a load along a bent
            // tip's axis swings the tip sideways.
            const double reach = moves.norm() + m_wall[a * m + a];
            const double limit = m_maxStep / std::max(reach, 1e-12);
            const double raise =
                (m_maxStep + m_growth[static_cast<size_t>(m_active[a])]) / std::max(reach, 1e-12);
            lambda = std::clamp(lambda, std::max(0.0, m_startLambda[a] - limit), m_startLambda[a] + raise);
            largest = std::max(largest, std::abs(lambda - m_lambda[a]));
            if (prefix) {
                // Node a leaves the tip side's sums with its old change and
                // joins the base side's with its new one.
                const Eigen::Vector3d before = m_force[a] - m_startForce[a];
                const Eigen::Vector3d after = lambda * d - m_startForce[a];
                s0 -= before;
                s1 -= m_skew[a] * before;
                r1 += m_toR1[a] * after;
                r2 += m_toR2[a] * after;
            }
            m_lambda[a] = lambda;
            m_normal[a] = n;
            m_direction[a] = d;
            m_force[a] = lambda * d;
        }
        m_residual = largest;
        if (largest < tolerance) {
            break;
        }
        if (depth > 0) {
            accelerate(depth, sweep, stored, next, lastChange);
        }
    }
}

void ContactCoupling::accelerate(int depth, int sweep, int& stored, int& next, double& lastChange)
{
    // Type-II Anderson: with f_k = g_k - x_k the sweep's change from x_k to
    // its result g_k, gamma = argmin |f_k - dF gamma| over the last depth
    // differences dF of successive f, and x_{k+1} = g_k - dG gamma.
    const auto m = static_cast<Eigen::Index>(m_active.size());
    using Vector = Eigen::Map<Eigen::VectorXd>;
    using Matrix = Eigen::Map<Eigen::MatrixXd>;
    const Vector x(m_andersonX.data(), m);
    const Vector g(m_lambda.data(), m);
    Vector fPrev(m_andersonFPrev.data(), m);
    Vector gPrev(m_andersonGPrev.data(), m);
    Matrix dF(m_andersonF.data(), m, depth);
    Matrix dG(m_andersonG.data(), m, depth);
    // A sweep whose change grew restarts the history (the safeguard of
    // restarted Anderson): the combination is taken again from plain sweeps.
    const double change = (g - x).cwiseAbs().maxCoeff();
    if (sweep > 0 && change > lastChange) {
        stored = 0;
        next = 0;
    } else if (sweep > 0) {
        dF.col(next) = (g - x) - fPrev;
        dG.col(next) = g - gPrev;
        next = (next + 1) % depth;
        stored = std::min(stored + 1, depth);
    }
    lastChange = change;
    fPrev = g - x;
    gPrev = g;
    if (stored == 0) {
        return;
    }
    using Small =
        Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxAcceleration, kMaxAcceleration>;
    using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxAcceleration, 1>;
    Small gram = dF.leftCols(stored).transpose() * dF.leftCols(stored);
    const SmallVector rhs = dF.leftCols(stored).transpose() * fPrev;
    gram.diagonal().array() += 1e-12 * gram.diagonal().maxCoeff() + 1e-300;
    const SmallVector gamma = gram.ldlt().solve(rhs);
    for (Eigen::Index a = 0; a < m; ++a) {
        const auto i = static_cast<size_t>(a);
        m_lambda[i] = std::max(0.0, g(a) - dG.row(a).head(stored).dot(gamma));
        m_force[i] = m_lambda[i] * m_direction[i];
    }
}

void ContactCoupling::update(const std::vector<contact::LumenNodeContact>& contacts,
                             const scope::DiscreteRod& rod, int addedAtBase,
                             const Eigen::VectorXd& wallCompliance, bool newStep)
{
    const int points = m_points.count(rod.numNodes());
    const int n = std::min(points, static_cast<int>(contacts.size()));
    align(points, addedAtBase * m_points.stride);
    if (newStep) {
        // How far each point came into its wall over the last step: its depth
        // now against its depth at the last step's start (none for a point
        // just inserted).
        m_growth.assign(static_cast<size_t>(points), 0.0);
        for (int point = 0; point < n; ++point) {
            const auto i = static_cast<size_t>(point);
            const double before = m_stepDepth[i];
            m_growth[i] = std::isnan(before) ? 0.0 : std::max(0.0, contacts[i].depth - before);
            m_stepDepth[i] = contacts[i].depth;
        }
        if (m_stickingFriction) {
            m_stepFriction = m_friction;
        }
    } else {
        m_growth.resize(static_cast<size_t>(points), 0.0);
    }
    // The update covers the points near or in the wall and those still
    // carrying a load (which the signed depth may release).
    m_active.clear();
    for (int point = 0; point < n; ++point) {
        const auto i = static_cast<size_t>(point);
        if (contacts[i].depth > -kActiveGap || m_load[i].squaredNorm() > 0.0) {
            m_active.push_back(point);
        }
    }
    m_at.resize(m_active.size());
    for (size_t a = 0; a < m_active.size(); ++a) {
        m_at[a] = m_points.at(rod.position, m_active[a]);
    }
    if (m_sideNormals) {
        measureAxes(rod);
    }
    buildCompliance(rod);
    addWallCompliance(contacts, wallCompliance);
    const auto m = m_active.size();
    m_force.resize(m);
    m_startForce.resize(m);
    m_normal.resize(m);
    m_direction.resize(m);
    m_lambda.resize(m);
    m_startLambda.resize(m);
    m_contacts = &contacts;
    for (size_t a = 0; a < m; ++a) {
        const auto point = static_cast<size_t>(m_active[a]);
        const contact::LumenNodeContact& c = contacts[point];
        // The load keeps its magnitude and takes the wall's present normal
        // (a point sliding round a curved wall turns its normal, not its
        // load) when the normal has turned by less than 45 degrees; beyond
        // that it is the part along the new normal (the load's direction
        // for that normal, with side normals).
        const Eigen::Vector3d d = loadDirection(a, c.normal);
        m_normal[a] = c.normal;
        m_direction[a] = d;
        m_startForce[a] = m_load[point];
        const double carried = m_load[point].norm();
        const double along = m_load[point].dot(d);
        m_startLambda[a] = along > kCarryCosine * carried ? carried : std::max(0.0, along);
        m_lambda[a] = m_startLambda[a];
        m_force[a] = m_lambda[a] * d;
    }
    m_sweeps = 0;
}

void ContactCoupling::relax()
{
    // Each solve moves the loads the fraction omega of the way from where
    // they start (the last solve's) to what the linear model asks for.
    for (size_t a = 0; a < m_active.size(); ++a) {
        m_force[a] = m_startForce[a] + m_relaxation * (m_force[a] - m_startForce[a]);
        m_lambda[a] = m_force[a].norm();
    }
}

void ContactCoupling::measureSlipCompliance()
{
    // R_a = sum_b || P_a X_ab P_b ||_F, X_ab = C_ab + W_ab I and P the
    // projection onto a contact's tangent plane: how far the friction of all
    // the contacts moves node a along its wall, per newton. The Frobenius
    // norm bounds the spectral one, so with the stick below
    // 2 mu lambda_b R_b / dt the friction map over one step,
    // dx_a = -sum_b P_a X_ab P_b dx_b / (2 R_b), has columns of norm at most
    // 1/2 (X is symmetric) and by Gershgorin a spectral radius of at most
    // 1/2. ||P_a X P_b||^2 = ||X||^2 - |X n_b|^2 - |X^T n_a|^2 + (n_a.X n_b)^2.
    const auto m = m_active.size();
    m_slipCompliance.assign(m, 0.0);
    for (size_t a = 0; a < m; ++a) {
        const Eigen::Vector3d& na = m_normal[a];
        for (size_t b = a; b < m; ++b) {
            const Eigen::Vector3d& nb = m_normal[b];
            const Eigen::Matrix3d x = m_block[a * m + b] + m_wall[a * m + b] * Eigen::Matrix3d::Identity();
            const Eigen::Vector3d xb = x * nb;
            const double across = na.dot(xb);
            const double squared =
                x.squaredNorm() - xb.squaredNorm() - (x.transpose() * na).squaredNorm() + across * across;
            const double norm = std::sqrt(std::max(0.0, squared));
            m_slipCompliance[a] += norm;
            if (b != a) {
                m_slipCompliance[b] += norm;
            }
        }
    }
    if (!m_spinFriction) {
        return;
    }
    // The friction acts at the surface, r from the axis: its moment turns the
    // shaft, and a turn of w slides the surface by r w. The moment of a load
    // at b turns the joints before both a and b, by at most T (the prefix of
    // their most compliant axes) per newton metre, so it slides a's surface
    // by at most r^2 T per newton. Through the surface points' levers the
    // slip compliance is bounded by (sqrt(R_a) + sqrt(r^2 sum_b T_ab))^2.
    const std::vector<contact::LumenNodeContact>& contacts = *m_contacts;
    for (size_t a = 0; a < m; ++a) {
        const double ra = contacts[static_cast<size_t>(m_active[a])].scopeRadius;
        double turn = 0.0;
        for (size_t b = 0; b < m; ++b) {
            const double rb = contacts[static_cast<size_t>(m_active[b])].scopeRadius;
            const auto upto =
                static_cast<size_t>(std::min(m_points.joints(m_active[a]), m_points.joints(m_active[b])));
            turn += ra * rb * m_prefixTwist[upto];
        }
        const double root = std::sqrt(m_slipCompliance[a]) + std::sqrt(turn);
        m_slipCompliance[a] = root * root;
    }
}

void ContactCoupling::solveAndApply(scope::DiscreteRod& rod, const contact::LumenContact& law, bool lastSolve)
{
    const std::vector<contact::LumenNodeContact>& contacts = *m_contacts;
    solve(contacts, lastSolve ? m_limits.tolerance : m_limits.passTolerance);
    relax();
    measureSlipCompliance();
    for (Eigen::Vector3d& load : m_load) {
        load.setZero();
    }
    m_loads.setZero(3, static_cast<Eigen::Index>(m_load.size()));
    if (m_stickingFriction) {
        for (Eigen::Vector3d& f : m_friction) {
            f.setZero();
        }
    }
    const double mu = law.parameters().frictionCoefficient;
    for (size_t a = 0; a < m_active.size(); ++a) {
        const auto point = static_cast<size_t>(m_active[a]);
        // Friction opposes the slip measured this step, with the normal load
        // just settled on. It is explicit, so its stick is regularised below
        // the speed at which the friction of all the contacts together would
        // carry the nodes back past their sticking points in one step
        // (2 mu lambda R / dt, see measureSlipCompliance()): it cannot
        // reverse the slip it resists. With a node's own compliance alone in
        // place of R, the many contacts of a shaft bent round the sigmoid
        // swung it from side to side by up to 20 mm a step.
        const Eigen::Vector3d friction =
            m_stickingFriction ? stickingFriction(a, contacts[point], mu)
                               : law.friction(contacts[point], m_lambda[a],
                                              2.0 * mu * m_lambda[a] * m_slipCompliance[a] / m_loopStep);
        const Eigen::Vector3d load = m_force[a] + friction;
        m_load[point] = m_force[a];
        m_loads.col(static_cast<Eigen::Index>(point)) = load;
        // The rod's node forces hold its base loads (gravity) since update().
        const auto base = static_cast<size_t>(m_points.node(m_active[a]));
        const double t = m_points.share(m_active[a]);
        if (t == 0.0) {
            rod.force[base] += load;
        } else {
            rod.force[base] += (1.0 - t) * load;
            rod.force[base + 1] += t * load;
        }
        if (m_spinFriction) {
            // The friction acts where the surface touches the wall, r from
            // the axis against the normal: a moment about the axis besides.
            const Eigen::Vector3d moment = (-contacts[point].scopeRadius * m_normal[a]).cross(friction);
            if (t == 0.0) {
                rod.torque[base] += moment;
            } else {
                rod.torque[base] += (1.0 - t) * moment;
                rod.torque[base + 1] += t * moment;
            }
        }
    }
}

Eigen::Vector3d ContactCoupling::stickingFriction(size_t a, const contact::LumenNodeContact& contact,
                                                  double mu)
{
    // The step's friction at its start, turned into the tangent plane of the
    // normal just settled on, and the load that stops the step's slip added
    // (see solveAndApply() in the header); at most mu lambda.
    const auto point = static_cast<size_t>(m_active[a]);
    const Eigen::Vector3d& n = m_normal[a];
    const Eigen::Vector3d& held = m_stepFriction[point];
    const Eigen::Vector3d slip = contact.slip - contact.slip.dot(n) * n;
    Eigen::Vector3d f = held - held.dot(n) * n;
    if (m_slipCompliance[a] > 0.0) {
        f -= (m_loopStep / (2.0 * m_slipCompliance[a])) * slip;
    }
    const double limit = mu * m_lambda[a];
    const double size = f.norm();
    if (size > limit) {
        f *= limit / size;  // size > limit >= 0
    }
    m_friction[point] = f;
    return f;
}

Eigen::MatrixXd ContactCoupling::delassus() const
{
    const auto m = m_active.size();
    Eigen::MatrixXd g(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
    for (size_t a = 0; a < m; ++a) {
        for (size_t b = 0; b < m; ++b) {
            g(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) =
                m_normal[a].dot(m_block[a * m + b] * m_direction[b]) +
                m_wall[a * m + b] * m_normal[a].dot(m_direction[b]);
        }
    }
    return g;
}

}  // namespace colonosim::procedure
