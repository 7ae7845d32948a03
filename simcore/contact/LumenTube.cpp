#include "simcore/contact/LumenTube.h"

#include "simcore/params/Parameter.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace colonosim::contact {

namespace {
double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
    return a.x() * b.y() - a.y() * b.x();
}
}  // namespace

LumenTube::LumenTube(const geometry::ColonAnatomy& anatomy)
{
    const auto& info = anatomy.physicsNodes;
    const int n = static_cast<int>(info.size());
    const auto refuse = [](const std::string& why) {
        throw params::ParameterError("physics mesh: " + why +
                                     " (lumen contact needs the procedural tube of rings)");
    };
    if (n < 7 || anatomy.physicsMesh.numVertices() != n) {
        refuse("numVertices = " + std::to_string(n) + " is not a tube of at least two rings and an apex");
    }
    int perRing = 0;
    while (perRing < n && info[static_cast<size_t>(perRing)].arcLength == info[0].arcLength) {
        ++perRing;
    }
    if (perRing < 3 || (n - 1) % perRing != 0) {
        refuse("nodes per ring = " + std::to_string(perRing) +
               " does not divide numVertices - 1 = " + std::to_string(n - 1));
    }
    m_perRing = perRing;
    m_numRings = (n - 1) / perRing;
    m_apex = n - 1;
    if (m_numRings < 2) {
        refuse("rings = " + std::to_string(m_numRings) + ", at least 2 needed");
    }
    for (int i = 0; i < m_numRings; ++i) {
        for (int j = 0; j < perRing; ++j) {
            const auto& node = info[static_cast<size_t>(i * perRing + j)];
            const double expected = 2.0 * std::numbers::pi * j / perRing;
            if (node.arcLength != info[static_cast<size_t>(i * perRing)].arcLength ||
                std::abs(node.angle - expected) > 1e-9) {
                refuse("node " + std::to_string(i * perRing + j) + " is not node " + std::to_string(j) +
                       " of ring " + std::to_string(i));
            }
        }
    }
    const auto rings = static_cast<size_t>(m_numRings);
    m_ringArc.resize(rings);
    for (size_t i = 0; i < rings; ++i) {
        m_ringArc[i] = info[i * static_cast<size_t>(perRing)].arcLength;
    }
    m_centre.assign(rings, Eigen::Vector3d::Zero());
    m_axis.assign(rings, Eigen::Vector3d::UnitZ());
    m_basisU.assign(rings, Eigen::Vector3d::UnitX());
    m_basisV.assign(rings, Eigen::Vector3d::UnitY());
    m_planar.assign(rings * static_cast<size_t>(perRing), Eigen::Vector2d::Zero());
    update(anatomy.physicsMesh.vertices);
}

double LumenTube::arcLength(const LumenStation& at) const
{
    if (at.beforeStart) {
        return m_ringArc.front();
    }
    const auto ring = static_cast<size_t>(std::clamp(at.ring, 0, m_numRings - 1));
    if (at.beyondEnd || ring + 1 >= m_ringArc.size()) {
        return m_ringArc.back();
    }
    const double u = std::clamp(at.u, 0.0, 1.0);
    return (1.0 - u) * m_ringArc[ring] + u * m_ringArc[ring + 1];
}

void LumenTube::update(const Eigen::Matrix3Xd& wall)
{
    const int p = m_perRing;
    for (int i = 0; i < m_numRings; ++i) {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (int j = 0; j < p; ++j) {
            sum += wall.col(i * p + j);
        }
        m_centre[static_cast<size_t>(i)] = sum / p;
    }
    for (int i = 0; i < m_numRings; ++i) {
        const int prev = std::max(i - 1, 0);
        const int next = std::min(i + 1, m_numRings - 1);
        Eigen::Vector3d a = m_centre[static_cast<size_t>(next)] - m_centre[static_cast<size_t>(prev)];
        const double length = a.norm();
        const auto k = static_cast<size_t>(i);
        m_axis[k] = length > 0.0 ? Eigen::Vector3d(a / length) : m_axis[k];
        Eigen::Vector3d radial = wall.col(i * p) - m_centre[k];
        radial -= radial.dot(m_axis[k]) * m_axis[k];
        const double r = radial.norm();
        if (r > 0.0) {
            m_basisU[k] = radial / r;
        }
        m_basisV[k] = m_axis[k].cross(m_basisU[k]);
        for (int j = 0; j < p; ++j) {
            const Eigen::Vector3d d = wall.col(i * p + j) - m_centre[k];
            m_planar[k * static_cast<size_t>(p) + static_cast<size_t>(j)] = {d.dot(m_basisU[k]),
                                                                             d.dot(m_basisV[k])};
        }
    }
    m_endHeight = height(m_numRings - 1, wall.col(m_apex));
}

double LumenTube::sectionFraction(const Eigen::Vector3d& p, int ring) const
{
    const Eigen::Vector3d& c0 = centre(ring);
    const Eigen::Vector3d d = centre(ring + 1) - c0;
    const double length2 = d.squaredNorm();
    return length2 > 0.0 ? (p - c0).dot(d) / length2 : -1.0;
}

LumenStation LumenTube::locate(const Eigen::Vector3d& p, int start, int window) const
{
    // Walk along the centre polyline from section `start` while its nearest
    // point comes closer, at most `window` sections: the station follows the
    // point continuously. The nearest point and not the bracketing ring
    // planes, which cross on the inner side of a bend; a walk and not the
    // nearest section within the window, because where the colon is folded
    // (a flattened ring at a hairpin) a section a few rings on can lie
    // nearer across the wall than the point's own: the point would be
    // taken through the fold in one step, and pushed on the wrong way. A
    // point outside the wall stays in its own part of the colon and is
    // pushed back the way it came, so the lumen cannot be tunnelled into a
    // neighbouring loop at any speed.
    const int reach = std::max(0, window);
    const int lastSection = m_numRings - 2;
    const int from = std::clamp(start, 0, lastSection);
    const auto nearest = [&](int i, double& u) {
        u = std::clamp(sectionFraction(p, i), 0.0, 1.0);
        const Eigen::Vector3d& c0 = centre(i);
        return (p - (c0 + u * (centre(i + 1) - c0))).squaredNorm();
    };
    LumenStation best;
    best.ring = from;
    double bestDistance = nearest(from, best.u);
    for (const int direction : {1, -1}) {
        for (int i = from + direction; std::abs(i - from) <= reach && i >= 0 && i <= lastSection;
             i += direction) {
            double u = 0.0;
            const double distance = nearest(i, u);
            if (!(distance < bestDistance)) {
                break;
            }
            bestDistance = distance;
            best.ring = i;
            best.u = u;
        }
        if (best.ring != from) {
            break;  // it walked forward: the nearest point is not behind
        }
    }
    best.beforeStart = best.ring == 0 && height(0, p) < 0.0;
    best.beyondEnd = best.ring == lastSection && height(lastSection + 1, p) >= 0.0;
    return best;
}

bool LumenTube::holds(const Eigen::Vector3d& p, int ring, LumenStation& at) const
{
    if (ring < 0 || ring > m_numRings - 2) {
        return false;
    }
    const double u = sectionFraction(p, ring);
    if (u < 0.0 || u > 1.0) {
        return false;
    }
    at = LumenStation{};
    at.ring = ring;
    at.u = u;
    const LumenWallSample w = wallAt(p, at);
    return w.distance < w.wallRadius;
}

bool LumenTube::findHolding(const Eigen::Vector3d& p, int from, int towards, int window, LumenStation& at,
                            const Eigen::Vector3d* neighbour, double slack) const
{
    const int gap = std::abs(from - towards);
    for (int offset = 1; offset <= window; ++offset) {
        for (const int ring : {from - offset, from + offset}) {
            const bool towardsNeighbour = std::abs(ring - towards) < gap;
            if ((!towardsNeighbour && neighbour == nullptr) || !holds(p, ring, at)) {
                continue;
            }
            if (towardsNeighbour || passesThrough(*neighbour, p, towards, ring, slack)) {
                return true;
            }
        }
    }
    return false;
}

bool LumenTube::passesThrough(const Eigen::Vector3d& q, const Eigen::Vector3d& p, int from, int to,
                              double slack) const
{
    const int first = std::min(from, to) + 1;
    const int last = std::max(from, to);
    for (int ring = std::max(first, 0); ring <= std::min(last, m_numRings - 1); ++ring) {
        const double hq = height(ring, q);
        const double hp = height(ring, p);
        if ((hq > 0.0 && hp > 0.0) || (hq < 0.0 && hp < 0.0)) {
            return false;  // the segment does not reach the ring's plane
        }
        const double s = hq != hp ? hq / (hq - hp) : 0.0;
        Eigen::Vector3d across = q + s * (p - q) - centre(ring);
        across -= across.dot(axis(ring)) * axis(ring);
        const double distance = across.norm();
        if (distance == 0.0) {
            continue;  // through the centre
        }
        double radius = 0.0;
        int edge = 0;
        double fraction = 0.0;
        rayToRing(ring, across / distance, radius, edge, fraction);
        if (distance > radius + slack) {
            return false;  // it crosses the plane outside the wall
        }
    }
    return true;
}

void LumenTube::rayToRing(int ring, const Eigen::Vector3d& e, double& radius, int& edge,
                          double& fraction) const
{
    const auto k = static_cast<size_t>(ring);
    Eigen::Vector2d d(e.dot(m_basisU[k]), e.dot(m_basisV[k]));
    const double norm = d.norm();
    d = norm > 0.0 ? Eigen::Vector2d(d / norm) : Eigen::Vector2d(1.0, 0.0);
    const int p = m_perRing;
    const Eigen::Vector2d* q = &m_planar[k * static_cast<size_t>(p)];
    // Start at the edge the angle points to (nodes sit at 2 pi j / P) and
    // widen the search; the first edge the ray crosses is the wall.
    const double angle = std::atan2(d.y(), d.x());
    const int guess = static_cast<int>(std::floor(angle / (2.0 * std::numbers::pi) * p + p)) % p;
    double best = -1.0;
    for (int offset = 0; offset < p; ++offset) {
        const int j = (guess + (offset % 2 == 0 ? offset / 2 : p - (offset + 1) / 2)) % p;
        const Eigen::Vector2d& q0 = q[j];
        const Eigen::Vector2d e01 = q[(j + 1) % p] - q0;
        const double denom = cross2(d, e01);
        if (std::abs(denom) < 1e-15) {
            continue;
        }
        const double w = cross2(q0, d) / denom;
        const double s = cross2(q0, e01) / denom;
        if (w >= -1e-12 && w <= 1.0 + 1e-12 && s > 0.0 && (best < 0.0 || s < best)) {
            best = s;
            edge = j;
            fraction = std::clamp(w, 0.0, 1.0);
        }
        if (offset >= 2 && best >= 0.0) {
            break;  // the edges around the guess have been seen and one is hit: the wall
        }
    }
    if (best < 0.0) {
        // A ring folded through its own centre: take the nearest node's radius.
        int nearest = 0;
        for (int j = 1; j < p; ++j) {
            if (q[j].dot(d) > q[nearest].dot(d)) {
                nearest = j;
            }
        }
        best = std::max(q[nearest].dot(d), 0.0);
        edge = nearest;
        fraction = 0.0;
    }
    radius = best;
}

LumenWallSample LumenTube::wallAt(const Eigen::Vector3d& p, const LumenStation& station) const
{
    const int i = station.ring;
    const double u = station.u;
    LumenWallSample w;
    w.centre = (1.0 - u) * centre(i) + u * centre(i + 1);
    Eigen::Vector3d a = (1.0 - u) * axis(i) + u * axis(i + 1);
    const double an = a.norm();
    w.axis = an > 0.0 ? Eigen::Vector3d(a / an) : axis(i);
    Eigen::Vector3d rho = p - w.centre;
    rho -= rho.dot(w.axis) * w.axis;
    w.distance = rho.norm();
    if (w.distance > 0.0) {
        w.radial = rho / w.distance;
    } else {
        w.radial = m_basisU[static_cast<size_t>(i)];
    }
    double r0 = 0.0, r1 = 0.0, f0 = 0.0, f1 = 0.0;
    int e0 = 0, e1 = 0;
    rayToRing(i, w.radial, r0, e0, f0);
    rayToRing(i + 1, w.radial, r1, e1, f1);
    w.wallRadius = (1.0 - u) * r0 + u * r1;
    w.nodes = {node(i, e0), node(i, e0 + 1), node(i + 1, e1), node(i + 1, e1 + 1)};
    w.weights = {(1.0 - u) * (1.0 - f0), (1.0 - u) * f0, u * (1.0 - f1), u * f1};
    return w;
}

Eigen::Vector3d LumenTube::centreAlong(const LumenStation& from, double distance) const
{
    int i = from.ring;
    double u = from.u;
    Eigen::Vector3d at = (1.0 - u) * centre(i) + u * centre(i + 1);
    double left = std::abs(distance);
    if (distance >= 0.0) {
        while (left > 0.0) {
            const Eigen::Vector3d next = centre(i + 1);
            const double d = (next - at).norm();
            if (d >= left || i + 1 >= m_numRings - 1) {
                return d > 0.0 ? Eigen::Vector3d(at + std::min(left, d) / d * (next - at)) : at;
            }
            left -= d;
            at = next;
            ++i;
        }
    } else {
        while (left > 0.0) {
            const Eigen::Vector3d prev = centre(i);
            const double d = (prev - at).norm();
            if (d >= left || i == 0) {
                return d > 0.0 ? Eigen::Vector3d(at + std::min(left, d) / d * (prev - at)) : at;
            }
            left -= d;
            at = prev;
            --i;
        }
    }
    return at;
}

}  // namespace colonosim::contact
