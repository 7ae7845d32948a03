#include "simcore/procedure/LoopDetector.h"

#include "simcore/geometry/CentrelineSampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace colonosim::procedure {

using geometry::Segment;

std::string_view loopName(LoopKind kind)
{
    switch (kind) {
    case LoopKind::None: return "none";
    case LoopKind::N: return "N";
    case LoopKind::Alpha: return "alpha";
    case LoopKind::ReverseAlpha: return "reverse_alpha";
    case LoopKind::GammaDeepTransverse: return "gamma_deep_transverse";
    case LoopKind::ReverseSplenic: return "reverse_splenic";
    }
    return "none";
}

namespace {
/// The anterior view: the patient's left (+x) on the viewer's right, up (+z) up.
Eigen::Vector2d coronal(const Eigen::Vector3d& p)
{
    return {p.x(), p.z()};
}

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
    return a.x() * b.y() - a.y() * b.x();
}

/// values interpolated at `at`, a node index plus the fraction of its segment.
double valueAt(const std::vector<double>& values, double at)
{
    const auto k = static_cast<size_t>(at);
    const double f = at - std::floor(at);
    return k + 1 < values.size() ? (1.0 - f) * values[k] + f * values[k + 1] : values[k];
}

/// Where segments ab and cd cross in the plane: the fractions along each, or
/// nothing when they do not (touching ends and parallel segments do not cross).
std::optional<Eigen::Vector2d> segmentsCross(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                             const Eigen::Vector2d& c, const Eigen::Vector2d& d)
{
    const double d1 = cross2(b - a, c - a);
    const double d2 = cross2(b - a, d - a);
    const double d3 = cross2(d - c, a - c);
    const double d4 = cross2(d - c, b - c);
    if (!(d1 * d2 < 0.0 && d3 * d4 < 0.0)) {
        return std::nullopt;
    }
    // d3 and d4 are the signed distances of a and b from cd, d1 and d2 those of c and d from ab.
    return Eigen::Vector2d(d3 / (d3 - d4), d1 / (d1 - d2));
}
}  // namespace

std::vector<CoronalCrossing> coronalCrossingList(const Eigen::Matrix3Xd& polyline)
{
    const Eigen::Index n = polyline.cols();
    std::vector<CoronalCrossing> crossings;
    for (Eigen::Index i = 0; i + 1 < n; ++i) {
        for (Eigen::Index j = i + 2; j + 1 < n; ++j) {
            const auto at = segmentsCross(coronal(polyline.col(i)), coronal(polyline.col(i + 1)),
                                          coronal(polyline.col(j)), coronal(polyline.col(j + 1)));
            if (!at) {
                continue;
            }
            const Eigen::Vector3d earlier = polyline.col(i + 1) - polyline.col(i);
            const Eigen::Vector3d later = polyline.col(j + 1) - polyline.col(j);
            const double yEarlier = polyline(1, i) + (*at)(0) * earlier.y();
            const double yLater = polyline(1, j) + (*at)(1) * later.y();
            const bool earlierOver = yEarlier < yLater;  // nearer the front
            const Eigen::Vector2d over = coronal(earlierOver ? earlier : later);
            const Eigen::Vector2d under = coronal(earlierOver ? later : earlier);
            crossings.push_back({static_cast<double>(i) + (*at)(0), static_cast<double>(j) + (*at)(1),
                                 cross2(over, under) > 0.0 ? 1 : -1});
        }
    }
    return crossings;
}

int coronalCrossings(const Eigen::Matrix3Xd& polyline)
{
    return static_cast<int>(coronalCrossingList(polyline).size());
}

double coronalTurning(const Eigen::Matrix3Xd& polyline)
{
    double turning = 0.0;
    for (Eigen::Index i = 1; i + 1 < polyline.cols(); ++i) {
        const Eigen::Vector2d a = coronal(polyline.col(i)) - coronal(polyline.col(i - 1));
        const Eigen::Vector2d b = coronal(polyline.col(i + 1)) - coronal(polyline.col(i));
        if (a.squaredNorm() > 0.0 && b.squaredNorm() > 0.0) {
            turning += std::atan2(cross2(a, b), a.dot(b));
        }
    }
    return turning;
}

namespace {
using L = LoopParameters;
constexpr std::array<params::Field<L>, 6> kLoopFields{{
    {&L::thresholdSpec, &L::threshold},
    {&L::resolveFractionSpec, &L::resolveFraction},
    {&L::typeDwellSpec, &L::typeDwell},
    {&L::analysisIntervalSpec, &L::analysisInterval},
    {&L::paradoxWindowSpec, &L::paradoxWindow},
    {&L::crossingMatchSpec, &L::crossingMatch},
}};
}  // namespace

std::span<const params::Field<LoopParameters>> LoopParameters::fields()
{
    return kLoopFields;
}

void LoopParameters::validate() const
{
    params::validateFields<LoopParameters>("loops", kLoopFields, *this);
}

int LoopParameters::typeDwellAnalyses() const
{
    // The tolerance keeps 0.2 s / 0.01 s at 20 analyses, not 21.
    return std::max(1, static_cast<int>(std::ceil(typeDwell / analysisInterval - 1e-9)));
}

LoopDetector::LoopDetector(const geometry::Centreline& colon, const LoopParameters& parameters)
    : m_colon(colon), m_parameters(parameters)
{
    m_parameters.validate();
    m_typeDwell = m_parameters.typeDwellAnalyses();
}

double LoopDetector::locate(const Eigen::Vector3d& p) const
{
    return locateNear(p, -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
}

double LoopDetector::locateNear(const Eigen::Vector3d& p, double from, double to) const
{
    const auto begin = std::lower_bound(m_colon.arcLength.begin(), m_colon.arcLength.end(), from);
    const auto end = std::upper_bound(begin, m_colon.arcLength.end(), to);
    double best = std::numeric_limits<double>::infinity();
    double bestS = begin == m_colon.arcLength.end() ? m_colon.length() : *begin;
    for (auto it = begin; it != end; ++it) {
        const auto k = static_cast<size_t>(it - m_colon.arcLength.begin());
        const double d2 = (m_colon.points[k] - p).squaredNorm();
        if (d2 < best) {
            best = d2;
            bestS = *it;
        }
    }
    return bestS;
}

Eigen::Matrix3Xd LoopDetector::colonPath(double from, double to) const
{
    constexpr double kSpacing = 0.01;  // m
    const auto count = static_cast<Eigen::Index>(std::max(2.0, std::ceil((to - from) / kSpacing) + 1.0));
    Eigen::Matrix3Xd path(3, count);
    for (Eigen::Index k = 0; k < count; ++k) {
        const double s = from + (to - from) * static_cast<double>(k) / static_cast<double>(count - 1);
        path.col(k) = geometry::sampleCentreline(m_colon, s).point;
    }
    return path;
}

LoopKind LoopDetector::update(const Eigen::Matrix3Xd& shaft, double insertion,
                              std::span<const double> nodeArcs)
{
    const Eigen::Index n = shaft.cols();
    if (n < 2 || m_colon.points.size() < 2) {
        m_current = LoopKind::None;
        return m_current;
    }
    // Each node is located near its predecessor along the colon (topological:
    // a part of the colon that is close in space but far along it, such as the
    // transverse colon over a sigmoid loop, is never a candidate).
    std::vector<double> s(static_cast<size_t>(n));
    std::vector<Segment> segment(static_cast<size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
        const double previous = i == 0 ? 0.0 : s[static_cast<size_t>(i - 1)];
        s[static_cast<size_t>(i)] =
            nodeArcs.size() == static_cast<size_t>(n)
                ? std::clamp(nodeArcs[static_cast<size_t>(i)], 0.0, m_colon.length())
                : locateNear(shaft.col(i), previous - kBackWindow, previous + kForwardWindow);
        segment[static_cast<size_t>(i)] =
            geometry::sampleCentreline(m_colon, s[static_cast<size_t>(i)]).segment;
    }
    // Loops are in the insertion tube: the nodes up to the base of the
    // bending section, the first at least m_bendingSection behind the tip (a
    // tip the dials hook back is not shaft stored in a loop).
    Eigen::Index base = n - 1;
    double beyond = 0.0;
    while (base > 0 && beyond < m_bendingSection) {
        beyond += (shaft.col(base) - shaft.col(base - 1)).norm();
        --base;
    }
    const Eigen::Index tube = base + 1;
    // Excess shaft per segment.
    std::array<double, geometry::kNumSegments> shaftLength{};
    std::array<double, geometry::kNumSegments> lo{};
    std::array<double, geometry::kNumSegments> hi{};
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    for (Eigen::Index i = 0; i < tube; ++i) {
        const auto g = static_cast<size_t>(segment[static_cast<size_t>(i)]);
        lo[g] = std::min(lo[g], s[static_cast<size_t>(i)]);
        hi[g] = std::max(hi[g], s[static_cast<size_t>(i)]);
        if (i + 1 < tube && segment[static_cast<size_t>(i + 1)] == segment[static_cast<size_t>(i)]) {
            shaftLength[g] += (shaft.col(i + 1) - shaft.col(i)).norm();
        }
    }
    LoopSignals signals;
    for (size_t g = 0; g < shaftLength.size(); ++g) {
        if (hi[g] >= lo[g]) {
            const double excess = shaftLength[g] - (hi[g] - lo[g]);
            if (excess > signals.excessShaft) {
                signals.excessShaft = excess;
                signals.segment = static_cast<Segment>(g);
            }
        }
    }
    // Shape of the looped part: the nodes in the worst segment, in order; a
    // loop of the left colon is read over all of its shaft there, since an
    // alpha loop closes on the shaft that leaves the sigmoid.
    const auto leftColon = [](Segment g) {
        return g == Segment::Rectum || g == Segment::Sigmoid || g == Segment::Descending;
    };
    const bool left = leftColon(signals.segment);
    std::vector<int> looped;
    for (Eigen::Index i = 0; i < tube; ++i) {
        const Segment g = segment[static_cast<size_t>(i)];
        if (g == signals.segment || (left && leftColon(g))) {
            looped.push_back(static_cast<int>(i));
        }
    }
    // The looped part, with two nodes either side so that the crossing where
    // the loop closes on the shaft that leads into it is included.
    if (!looped.empty()) {
        const Eigen::Index first = std::max<Eigen::Index>(0, looped.front() - 2);
        const Eigen::Index last = std::min<Eigen::Index>(tube - 1, looped.back() + 2);
        const Eigen::Matrix3Xd part = shaft.middleCols(first, last - first + 1);
        // Relative to the colon's own path over the same stretch: a shaft that
        // merely follows a sigmoid which crosses itself in the anterior view
        // crosses where the colon does; that crossing is shared, not the loop's own.
        const double from = s[static_cast<size_t>(first)];
        const double to = s[static_cast<size_t>(last)];
        const Eigen::Matrix3Xd path = colonPath(from, to);
        const auto pathArc = [&](double at) {
            return from + (to - from) * at / static_cast<double>(std::max<Eigen::Index>(1, path.cols() - 1));
        };
        const std::vector<CoronalCrossing> own = coronalCrossingList(part);
        const std::vector<CoronalCrossing> rest = coronalCrossingList(path);
        const double match = m_parameters.crossingMatch;
        // Length along the part to each of its nodes: a crossing of two strands
        // closer than the threshold along the shaft is no loop (a shaft seen
        // nearly end on projects to a cusp, and a polyline over a cusp may
        // cross itself).
        std::vector<double> along(static_cast<size_t>(part.cols()), 0.0);
        for (Eigen::Index k = 1; k < part.cols(); ++k) {
            along[static_cast<size_t>(k)] =
                along[static_cast<size_t>(k - 1)] + (part.col(k) - part.col(k - 1)).norm();
        }
        for (const CoronalCrossing& c : own) {
            if (valueAt(along, c.second) - valueAt(along, c.first) < m_parameters.threshold) {
                continue;
            }
            // Where the two strands are along the colon (the part starts at node `first`).
            const double a = valueAt(s, static_cast<double>(first) + c.first);
            const double b = valueAt(s, static_cast<double>(first) + c.second);
            const bool colons = std::any_of(rest.begin(), rest.end(), [&](const CoronalCrossing& r) {
                const double ra = pathArc(r.first);
                const double rb = pathArc(r.second);
                return (std::abs(a - ra) <= match && std::abs(b - rb) <= match) ||
                       (std::abs(a - rb) <= match && std::abs(b - ra) <= match);
            });
            if (colons) {
                ++signals.sharedCrossings;
                signals.sharedHandedness += c.handedness;
            } else {
                ++signals.crossings;
                signals.handedness += c.handedness;
            }
        }
        signals.turning = coronalTurning(part) - coronalTurning(path);
    }
    signals.tipArcLength = s.back();
    // The stored shaft, at the base of the bending section: the shaft inside
    // up to that node (the insertion less the shaft beyond it) against where
    // the node is along the colon.
    signals.storedShaft = insertion - beyond - s[static_cast<size_t>(base)];

    // Paradoxical motion over the last paradoxWindow of insertion.
    const double window = m_parameters.paradoxWindow;
    if (insertion < m_windowInsertion) {
        m_windowInsertion = insertion;
        m_windowTip = signals.tipArcLength;
    } else if (insertion - m_windowInsertion >= window) {
        const double tipAdvance = signals.tipArcLength - m_windowTip;
        m_signals.tipAdvanceRatio = (insertion - m_windowInsertion) / std::max(tipAdvance, 1e-3);
        m_windowInsertion = insertion;
        m_windowTip = signals.tipArcLength;
    }
    signals.tipAdvanceRatio = m_signals.tipAdvanceRatio;

    // Hysteresis: a loop forms above the threshold and resolves below resolveFraction of it.
    const double measure = std::max(signals.excessShaft, signals.storedShaft);
    const double threshold = m_parameters.threshold;
    const bool looping = m_current == LoopKind::None ? measure > threshold
                                                     : measure > m_parameters.resolveFraction * threshold;
    signals.reading = looping ? classify(signals) : LoopKind::None;
    m_signals = signals;
    if (!looping || m_current == LoopKind::None) {
        m_current = signals.reading;
        m_pendingReads = 0;
    } else if (signals.reading == m_current) {
        m_pendingReads = 0;
    } else {
        // The type's own hysteresis: another type must be read for typeDwell without a break.
        m_pendingReads = signals.reading == m_pending ? m_pendingReads + 1 : 1;
        m_pending = signals.reading;
        if (m_pendingReads >= m_typeDwell) {
            m_current = signals.reading;
            m_pendingReads = 0;
        }
    }
    return m_current;
}

LoopKind LoopDetector::classify(const LoopSignals& signals)
{
    const bool crossed = signals.crossings > 0;
    switch (signals.segment) {
    case Segment::Rectum:
    case Segment::Sigmoid:
    case Segment::Descending: {
        // The loop's own crossings type it; a loop with none, along a colon
        // that crosses itself at rest, has the shaft crossing there.
        const int handedness = crossed ? signals.handedness : signals.sharedHandedness;
        if (handedness == 0) {
            return LoopKind::N;
        }
        // Right-handed: a clockwise spiral along the shaft, undone by clockwise
        // torque (LoopDetector.h).
        return handedness > 0 ? LoopKind::Alpha : LoopKind::ReverseAlpha;
    }
    case Segment::SplenicFlexure: return crossed ? LoopKind::ReverseSplenic : LoopKind::GammaDeepTransverse;
    default: return LoopKind::GammaDeepTransverse;
    }
}

}  // namespace colonosim::procedure
