#include "simcore/physics/LumenSelfContact.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace colonosim::physics {

namespace {
/// Rings closer than this along the colon, in units of r_i + r_j, are never
/// paired: a U-bend whose limbs touch spans pi / 2 of it (model choice).
constexpr double kExcludedArc = 2.0;
/// m: the force's onset is smoothed over this much overlap (C1 in delta), so
/// that a Newton solve of the colon's static equilibrium does not cycle on a
/// pair that touches and parts (model choice; 1 mm against the 13-22 mm
/// radii).
constexpr double kOnset = 1e-3;

/// Force magnitude phi(delta), its slope and energy: k delta^2 / (2 s) up to
/// s, k (delta - s / 2) beyond.
double pushOf(double k, double delta)
{
    return delta < kOnset ? 0.5 * k * delta * delta / kOnset : k * (delta - 0.5 * kOnset);
}
double slopeOf(double k, double delta)
{
    return delta < kOnset ? k * delta / kOnset : k;
}
double energyOf(double k, double delta)
{
    return delta < kOnset ? k * delta * delta * delta / (6.0 * kOnset)
                          : k * (0.5 * delta * delta - 0.5 * kOnset * delta + kOnset * kOnset / 6.0);
}
}  // namespace

LumenSelfContact::LumenSelfContact(std::vector<Ring> rings, double stiffness, const Positions& rest)
    : m_rings(std::move(rings)), m_stiffness(stiffness)
{
    if (!(stiffness >= 0.0) || !std::isfinite(stiffness)) {
        throw std::invalid_argument("LumenSelfContact: stiffness = " + std::to_string(stiffness) +
                                    " N/m is not in [0, inf)");
    }
    for (size_t i = 0; i < m_rings.size(); ++i) {
        if (m_rings[i].nodes.size() < 3 || !(m_rings[i].radius > 0.0)) {
            throw std::invalid_argument("LumenSelfContact: ring " + std::to_string(i) + " has " +
                                        std::to_string(m_rings[i].nodes.size()) + " nodes and radius " +
                                        std::to_string(m_rings[i].radius) +
                                        " m (at least 3 nodes and a positive radius needed)");
        }
    }
    m_centre.resize(m_rings.size());
    m_listCentre.resize(m_rings.size());
    onActiveSetChanged({});  // every ring moves until an active region says otherwise
    computeCentres(rest);
    for (size_t i = 0; i < m_rings.size(); ++i) {
        for (size_t j = i + 1; j < m_rings.size(); ++j) {
            const double reach = m_rings[i].radius + m_rings[j].radius;
            if (std::abs(m_rings[i].arcLength - m_rings[j].arcLength) > kExcludedArc * reach) {
                const double atRest = (m_centre[i] - m_centre[j]).norm();
                m_allowed.push_back({static_cast<int>(i), static_cast<int>(j), std::min(reach, atRest)});
            }
        }
    }
}

Eigen::Vector3d LumenSelfContact::ringMean(int ring, const Eigen::Matrix3Xd& values) const
{
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    const std::vector<int>& nodes = m_rings[static_cast<size_t>(ring)].nodes;
    for (const int node : nodes) {
        sum += values.col(node);
    }
    return sum / static_cast<double>(nodes.size());
}

void LumenSelfContact::spread(int ring, const Eigen::Vector3d& total, Eigen::Matrix3Xd& out) const
{
    const std::vector<int>& nodes = m_rings[static_cast<size_t>(ring)].nodes;
    const Eigen::Vector3d share = total / static_cast<double>(nodes.size());
    for (const int node : nodes) {
        out.col(node) += share;
    }
}

LumenSelfContact::Separation LumenSelfContact::separation(const Pair& pair) const
{
    Separation s;
    s.r = m_centre[static_cast<size_t>(pair.i)] - m_centre[static_cast<size_t>(pair.j)];
    s.d = s.r.norm();
    s.delta = pair.reach - s.d;
    return s;
}

void LumenSelfContact::computeCentres(const Positions& x) const
{
    if (x.data() == m_centresOf && x.cols() == m_centresCols) {
        for (const int ring : m_movingRings) {
            m_centre[static_cast<size_t>(ring)] = ringMean(ring, x);
        }
        return;
    }
    for (size_t i = 0; i < m_rings.size(); ++i) {
        m_centre[i] = ringMean(static_cast<int>(i), x);
    }
    m_centresOf = x.data();
    m_centresCols = x.cols();
}

void LumenSelfContact::onActiveSetChanged(const std::vector<std::uint8_t>& awake)
{
    m_movingRings.clear();
    for (size_t i = 0; i < m_rings.size(); ++i) {
        const std::vector<int>& nodes = m_rings[i].nodes;
        const bool moves = std::any_of(nodes.begin(), nodes.end(), [&](int node) {
            return static_cast<size_t>(node) >= awake.size() || awake[static_cast<size_t>(node)] != 0;
        });
        if (moves) {
            m_movingRings.push_back(static_cast<int>(i));
        }
    }
    // The next evaluation takes every centre afresh: nodes that slept until
    // now may have been woken (and may move from here on).
    m_centresOf = nullptr;
}

void LumenSelfContact::updateCentres(const Positions& x) const
{
    computeCentres(x);
    bool stale = !m_listBuilt;
    for (size_t i = 0; i < m_rings.size() && !stale; ++i) {
        stale = (m_centre[i] - m_listCentre[i]).squaredNorm() > 0.25 * kListMargin * kListMargin;
    }
    if (stale) {
        refreshCandidates();
    }
}

void LumenSelfContact::refreshCandidates() const
{
    m_candidates.clear();
    for (const Pair& pair : m_allowed) {
        if (separation(pair).delta > -kListMargin) {
            m_candidates.push_back(pair);
        }
    }
    m_listCentre = m_centre;
    m_listBuilt = true;
}

template <class Visit>
void LumenSelfContact::forEachOverlap(const Positions& x, Visit&& visit) const
{
    if (m_stiffness == 0.0) {
        return;
    }
    updateCentres(x);
    for (const Pair& pair : m_candidates) {
        const Separation s = separation(pair);
        if (s.delta > 0.0 && s.d > 0.0) {
            visit(pair, s.r, s.d, s.delta);
        }
    }
}

void LumenSelfContact::addForce(const Positions& x, Forces& f) const
{
    forEachOverlap(x, [&](const Pair& pair, const Eigen::Vector3d& r, double d, double delta) {
        const Eigen::Vector3d push = pushOf(m_stiffness, delta) / d * r;
        spread(pair.i, push, f);
        spread(pair.j, -push, f);
    });
}

void LumenSelfContact::addProduct(const Positions& x, const Eigen::Matrix3Xd& dx, Eigen::Matrix3Xd& df,
                                  bool definite) const
{
    forEachOverlap(x, [&](const Pair& pair, const Eigen::Vector3d& r, double d, double delta) {
        const Eigen::Vector3d u = r / d;
        const Eigen::Vector3d moved = ringMean(pair.i, dx) - ringMean(pair.j, dx);
        const double along = u.dot(moved);
        Eigen::Vector3d change = -slopeOf(m_stiffness, delta) * along * u;
        if (!definite) {
            change += pushOf(m_stiffness, delta) / d * (moved - along * u);
        }
        spread(pair.i, change, df);
        spread(pair.j, -change, df);
    });
}

void LumenSelfContact::addStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                                           Eigen::Matrix3Xd& df) const
{
    addProduct(x, dx, df, false);
}

void LumenSelfContact::addDefiniteStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                                                   Eigen::Matrix3Xd& df) const
{
    addProduct(x, dx, df, true);
}

void LumenSelfContact::addStiffnessBound(const Positions& x, Eigen::VectorXd& kRow, Eigen::VectorXd&) const
{
    if (m_stiffness == 0.0) {
        return;
    }
    // Node a of ring i: its blocks are J / P_i^2 with the P_i nodes of ring i
    // and J / (P_i P_j) with the P_j nodes of ring j, ||J|| = k max(1, delta / d):
    // a row sum of 2 ||J|| / P_i. Every candidate pair counts, overlapping or
    // not yet, so the bound holds while a pair closes during the step.
    updateCentres(x);
    for (const Pair& pair : m_candidates) {
        const Separation s = separation(pair);
        const double norm =
            std::max(m_stiffness, s.d > 0.0 ? pushOf(m_stiffness, s.delta) / s.d : m_stiffness);
        for (const int ring : {pair.i, pair.j}) {
            const std::vector<int>& nodes = m_rings[static_cast<size_t>(ring)].nodes;
            const double row = 2.0 * norm / static_cast<double>(nodes.size());
            for (const int node : nodes) {
                kRow[node] += row;
            }
        }
    }
}

double LumenSelfContact::potentialEnergy(const Positions& x) const
{
    double energy = 0.0;
    forEachOverlap(x, [&](const Pair&, const Eigen::Vector3d&, double, double delta) {
        energy += energyOf(m_stiffness, delta);
    });
    return energy;
}

int LumenSelfContact::overlappingPairs(const Positions& x, double* deepest) const
{
    int count = 0;
    double worst = 0.0;
    computeCentres(x);
    for (const Pair& pair : m_allowed) {
        const double delta = separation(pair).delta;
        if (delta > 0.0) {
            ++count;
            worst = std::max(worst, delta);
        }
    }
    if (deepest != nullptr) {
        *deepest = worst;
    }
    return count;
}

std::vector<LumenSelfContact::Ring> lumenRings(const Eigen::Matrix3Xd& restPositions,
                                               const std::vector<double>& arcLength)
{
    std::vector<LumenSelfContact::Ring> rings;
    const int n = static_cast<int>(arcLength.size());
    int perRing = 0;  // the first ring's size; a longer run of one arc length holds several rings
    int start = 0;
    while (start < n) {
        int end = start + 1;
        while (end < n && arcLength[static_cast<size_t>(end)] == arcLength[static_cast<size_t>(start)]) {
            ++end;
        }
        if (perRing == 0 && end - start >= 3) {
            perRing = end - start;
        }
        for (int first = start; perRing > 0 && end - first >= 3; first += perRing) {
            const int last = std::min(end, first + perRing);
            LumenSelfContact::Ring ring;
            ring.arcLength = arcLength[static_cast<size_t>(first)];
            Eigen::Vector3d centre = Eigen::Vector3d::Zero();
            for (int node = first; node < last; ++node) {
                ring.nodes.push_back(node);
                centre += restPositions.col(node);
            }
            centre /= static_cast<double>(last - first);
            double radius = 0.0;
            for (const int node : ring.nodes) {
                radius += (restPositions.col(node) - centre).norm();
            }
            ring.radius = radius / static_cast<double>(last - first);
            rings.push_back(std::move(ring));
        }
        start = end;
    }
    return rings;
}

}  // namespace colonosim::physics
