#include "simcore/scope/DiscreteRod.h"

#include "simcore/scope/Rotation.h"

#include <algorithm>

namespace colonosim::scope {

namespace {

/// A frame C held in registers along the chain of eqs 6-7, split as Eigen
/// evaluates a Matrix3d product with two-lane packets: rows 0-1 of each
/// column as one Vector2d, row 2 as a scalar. Read back from `frame`, each
/// link of the chain would first wait for the store of the one before; and a
/// Matrix3d local is copied through memory in 16-byte pieces that straddle
/// those halves, which the processor cannot forward from the stores (both
/// measured slower than the old loop).
struct SplitFrame {
    Eigen::Vector2d top[3];
    double bottom[3];

    static SplitFrame of(const Eigen::Matrix3d& c)
    {
        SplitFrame s;
        for (int j = 0; j < 3; ++j) {
            s.top[j] = c.col(j).head<2>();
            s.bottom[j] = c(2, j);
        }
        return s;
    }

    void store(Eigen::Matrix3d& c) const
    {
        for (int j = 0; j < 3; ++j) {
            c.col(j).head<2>() = top[j];
            c(2, j) = bottom[j];
        }
    }
};

/// c * r with the operations of Eigen's own Matrix3d product, in its order
/// (bit for bit; tests/scope/ChainSolverBitTest.cpp holds it to Eigen's
/// product): rows 0-1 of a column are one packet accumulated left to right,
/// (p0 + p1) + p2; row 2 is a scalar reduction, p0 + (p1 + p2). Forced
/// inline: out of line, GCC passes the SplitFrame through memory.
[[gnu::always_inline]] inline SplitFrame times(const SplitFrame& c, const Eigen::Matrix3d& r)
{
    SplitFrame out;
    for (int j = 0; j < 3; ++j) {
        out.top[j] = (c.top[0] * r(0, j) + c.top[1] * r(1, j)) + c.top[2] * r(2, j);
        out.bottom[j] = c.bottom[0] * r(0, j) + (c.bottom[1] * r(1, j) + c.bottom[2] * r(2, j));
    }
    return out;
}

// rebuild() in three passes over the joints. The first holds the sin/cos
// calls of the rare joint beyond the series' range: within the others, each
// call would spill the registers of their arithmetic, and of the frame chain.

/// Rodrigues' (a, b) of every joint.
void updateRodrigues(DiscreteRod& rod)
{
    const size_t n = rod.theta.size();
    const Eigen::Vector3d* theta = rod.theta.data();
    Eigen::Array2d* rodrigues = rod.rodrigues.data();
    for (size_t i = 0; i < n; ++i) {
        rodrigues[i] = rodriguesCoefficients(theta[i].squaredNorm());
    }
}

/// D_k R(Theta_k) of every joint, from its (a, b): the dial's rest rotation
/// and the joint's own, outside the frame chain that would wait on both.
void updateRotations(DiscreteRod& rod)
{
    const size_t n = rod.theta.size();
    const Eigen::Vector3d* theta = rod.theta.data();
    const Eigen::Array2d* rodrigues = rod.rodrigues.data();
    const unsigned char* hasDial = rod.hasDial.data();
    const Eigen::Matrix3d* dial = rod.dial.data();
    Eigen::Matrix3d* rotation = rod.rotation.data();
    for (size_t i = 0; i < n; ++i) {
        const Eigen::Matrix3d r = rotationFromCoefficients(theta[i], rodrigues[i]);
        if (hasDial[i]) {
            rotation[i].noalias() = dial[i] * r;
        } else {
            rotation[i] = r;
        }
    }
}

/// Eqs 6-7 from the rotations, from the base to the tip. The arrays are
/// taken as raw pointers (Eigen's stores may alias a std::vector's own data
/// pointer, which would be reloaded after each), and x_{k+1} is advanced
/// from the frame held in registers, not read back from its store.
void chainFrames(DiscreteRod& rod)
{
    const size_t n = rod.theta.size();
    const double length = rod.elementLength;
    const Eigen::Matrix3d* rotation = rod.rotation.data();
    Eigen::Matrix3d* frame = rod.frame.data();
    Eigen::Vector3d* position = rod.position.data();
    const Eigen::Vector3d start = rod.basePosition + rod.stubLength * rod.baseFrame.col(2);
    Eigen::Vector2d xTop = start.head<2>();
    double xBottom = start.z();
    SplitFrame before = SplitFrame::of(rod.baseFrame);
    for (size_t i = 0; i < n; ++i) {
        position[i].head<2>() = xTop;
        position[i].z() = xBottom;
        // C_k = C_{k-1} (D_k R_k): the dial is applied first.
        const SplitFrame current = times(before, rotation[i]);
        current.store(frame[i]);
        xTop += length * current.top[2];  // eq 7: x_{k+1} = x_k + l C_k e_3
        xBottom += length * current.bottom[2];
        before = current;
    }
}

}  // namespace

void DiscreteRod::reset(int numNodes, double length, double flexuralRigidity, double torsionalRigidity,
                        int capacity)
{
    const auto cap = static_cast<size_t>(std::max(capacity, numNodes));
    for (auto* v :
         {&theta, &force, &torque, &position, &damping, &thetaStart, &relaxationGain, &dampingPull}) {
        v->reserve(cap);
        v->assign(static_cast<size_t>(numNodes), Eigen::Vector3d::Zero());
    }
    for (auto* m : {&dial, &frame, &rotation}) {
        m->reserve(cap);
        m->assign(static_cast<size_t>(numNodes), Eigen::Matrix3d::Identity());
    }
    rodrigues.reserve(cap);
    rodrigues.assign(static_cast<size_t>(numNodes), Eigen::Array2d::Zero());
    hasDial.reserve(cap);
    hasDial.assign(static_cast<size_t>(numNodes), 0);
    elementLength = numNodes > 1 ? length / (numNodes - 1) : length;
    stiffness = Eigen::Vector3d(flexuralRigidity, flexuralRigidity, torsionalRigidity) / elementLength;
    rebuild();
}

Eigen::Vector3d DiscreteRod::jointStiffness(int joint) const
{
    if (joint == numNodes() - 1) {
        return 2.0 * stiffness;  // the tip half-joint (also when it is the only one)
    }
    if (joint == 0) {
        // The clamp joint stands for the stub and half of element 0.
        return stiffness * (elementLength / (stubLength + 0.5 * elementLength));
    }
    return stiffness;
}

const Eigen::Matrix3d& DiscreteRod::frameBefore(int joint) const
{
    return joint == 0 ? baseFrame : frame[static_cast<size_t>(joint - 1)];
}

void DiscreteRod::resizeAtBase(int numNodes)
{
    const int old = this->numNodes();
    const auto n = static_cast<size_t>(numNodes);
    if (numNodes > old) {
        const auto added = static_cast<size_t>(numNodes - old);
        theta.resize(n);
        std::copy_backward(theta.begin(), theta.begin() + old, theta.end());
        std::fill(theta.begin(), theta.begin() + static_cast<std::ptrdiff_t>(added), Eigen::Vector3d::Zero());
    } else if (numNodes < old) {
        // The joints that leave at the base pass their rotation on to the new
        // first joint, so every element that stays keeps its direction (the
        // stays are translated by at most l |Theta_0|, not turned about the
        // clamp by the dropped angles).
        const auto dropped = static_cast<size_t>(old - numNodes);
        Eigen::Matrix3d carried = Eigen::Matrix3d::Identity();
        for (size_t k = 0; k <= dropped; ++k) {
            carried =
                carried * (hasDial[k] ? dial[k] : Eigen::Matrix3d::Identity()) * rotationFromVector(theta[k]);
        }
        theta[dropped] = vectorFromRotation(carried);
        std::copy(theta.begin() + (old - numNodes), theta.end(), theta.begin());
        theta.resize(n);
    }
    dial.assign(n, Eigen::Matrix3d::Identity());
    hasDial.assign(n, 0);
    force.assign(n, Eigen::Vector3d::Zero());
    torque.assign(n, Eigen::Vector3d::Zero());
    damping.assign(n, Eigen::Vector3d::Zero());
    thetaStart = theta;
    relaxationGain.resize(n);
    dampingPull.resize(n);
    position.resize(n);
    frame.resize(n);
    rodrigues.resize(n);
    rotation.resize(n);
    rebuild();
}

void DiscreteRod::rebuild()
{
    updateRodrigues(*this);
    updateRotations(*this);
    chainFrames(*this);
}

void DiscreteRod::clearLoads()
{
    std::fill(force.begin(), force.end(), Eigen::Vector3d::Zero());
    std::fill(torque.begin(), torque.end(), Eigen::Vector3d::Zero());
}

}  // namespace colonosim::scope
