#include "simcore/geometry/ColonLayout.h"

#include "simcore/geometry/CentrelineSampling.h"
#include "simcore/geometry/FilletedPolyline.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace colonosim::geometry {

namespace {

/// Interior control point of a span: where along the chord between its
/// anchors, and which way it is displaced per unit amplitude.
struct Bend {
    double t;
    Eigen::Vector3d direction;
};

/// The spans between consecutive anchors, and the segments each one holds.
enum Span {
    kRectumSpan,
    kSigmoidSpan,
    kDescendingSpan,
    kTransverseSpan,
    kAscendingSpan,
    kCecumSpan,
    kNumSpans
};
constexpr int kNumAnchors = kNumSpans + 1;
constexpr std::array<std::array<int, 2>, kNumSpans> kSpanSegments{
    {{0, 0}, {1, 1}, {2, 3}, {3, 5}, {5, 6}, {7, 7}}};

const std::array<Eigen::Vector3d, kNumAnchors>& defaultAnchors()
{
    static const std::array<Eigen::Vector3d, kNumAnchors> anchors{{
        {0.0, 0.0, 0.0},       // anal verge
        {0.01, 0.05, 0.12},    // rectosigmoid junction
        {0.12, 0.05, 0.21},    // sigmoid-descending junction, left iliac fossa
        {0.15, 0.05, 0.43},    // splenic flexure corner, under the left diaphragm
        {-0.15, 0.05, 0.41},   // hepatic flexure corner, under the liver
        {-0.11, 0.05, 0.25},   // ileocecal valve
        {-0.10, 0.03, 0.175},  // cecal base (recomputed: continues the ascending colon)
    }};
    return anchors;
}

const std::array<std::vector<Bend>, kNumSpans>& shapes()
{
    static const std::array<std::vector<Bend>, kNumSpans> s{{
        {{0.5, {0.0, 1.0, 0.0}}},  // rectum: sacral curve
        {{0.2, {-0.3, -0.7, 0.3}}, {0.5, {0.0, -1.0, 0.8}}, {0.75, {0.4, -0.8, -0.1}}},  // sigmoid loop
        {{0.5, {1.0, 0.0, 0.0}}},  // descending: lateral
        {{0.15, {0.0, -0.75, -0.2}},
         {0.33, {0.0, -0.65, -0.8}},
         {0.5, {0.0, -0.6, -0.85}},  // transverse: U-shaped
         {0.67, {0.0, -0.65, -0.8}},
         {0.85, {0.0, -0.75, -0.2}}},  // sag, wide bottom
        {{0.65, {-1.0, 0.0, 0.0}}},    // ascending: lateral
        {},                            // cecum: straight pouch
    }};
    return s;
}

struct ControlPolygon {
    std::vector<Eigen::Vector3d> points;
    std::vector<double> lumenRadius;  ///< largest declared radius of the span(s) each point bends
    std::array<int, kNumAnchors> anchorIndex{};
};

ControlPolygon buildControlPolygon(const AnatomyParameters& params,
                                   const std::array<Eigen::Vector3d, kNumAnchors>& anchors,
                                   const std::array<double, kNumSpans>& amplitude)
{
    const auto spanRadius = [&](int span) {
        if (span < 0 || span >= kNumSpans)
            return 0.0;
        double r = 0.0;
        for (int seg = kSpanSegments[static_cast<std::size_t>(span)][0];
             seg <= kSpanSegments[static_cast<std::size_t>(span)][1]; ++seg) {
            r = std::max(r, 0.5 * params.diameter(static_cast<Segment>(seg)));
        }
        return r;
    };
    ControlPolygon poly;
    for (int span = 0; span <= kNumSpans; ++span) {
        const auto i = static_cast<std::size_t>(span);
        poly.anchorIndex[i] = static_cast<int>(poly.points.size());
        poly.points.push_back(anchors[i]);
        poly.lumenRadius.push_back(std::max(spanRadius(span - 1), spanRadius(span)));
        if (span == kNumSpans)
            break;
        for (const Bend& bend : shapes()[i]) {
            Eigen::Vector3d direction = bend.direction;
            if (span == kSigmoidSpan) {
                direction.x() *= params.sigmoidSweep;
            }
            poly.points.push_back((1.0 - bend.t) * anchors[i] + bend.t * anchors[i + 1] +
                                  amplitude[i] * direction);
            poly.lumenRadius.push_back(spanRadius(span));
        }
    }
    return poly;
}

FilletedPolyline rounded(const ControlPolygon& poly)
{
    return filletPolyline(poly.points, poly.lumenRadius);
}

double spanArcLength(const ControlPolygon& poly, int span)
{
    const FilletedPolyline f = rounded(poly);
    const auto s = static_cast<std::size_t>(span);
    return f.vertexArcLength[static_cast<std::size_t>(poly.anchorIndex[s + 1])] -
           f.vertexArcLength[static_cast<std::size_t>(poly.anchorIndex[s])];
}

double smoothstep(double x)
{
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

/// Safety net: narrows the lumen where the bend radius is below it, so rings of wall
/// nodes never pass through each other on the inner side of a flexure.
void limitRadiusByBend(Centreline& c)
{
    const int n = c.numPoints();
    constexpr int kHalfStencil = 1;
    constexpr int kHalfWindow = 25;
    std::vector<double> cap(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const auto a = static_cast<std::size_t>(std::max(0, i - kHalfStencil));
        const auto b = static_cast<std::size_t>(std::min(n - 1, i + kHalfStencil));
        const double ds = c.arcLength[b] - c.arcLength[a];
        const double curvature = ds > 0.0 ? (c.tangents[b] - c.tangents[a]).norm() / ds : 0.0;
        cap[static_cast<std::size_t>(i)] = std::min(c.radius[static_cast<std::size_t>(i)],
                                                    curvature > 0.0 ? kMaxBendRatio / curvature : 1e9);
    }
    // Erode then average over the same window: the result is smooth and never
    // above the cap at any sample.
    std::vector<double> eroded(cap.size());
    for (int i = 0; i < n; ++i) {
        double m = cap[static_cast<std::size_t>(i)];
        for (int j = std::max(0, i - kHalfWindow); j <= std::min(n - 1, i + kHalfWindow); ++j) {
            m = std::min(m, cap[static_cast<std::size_t>(j)]);
        }
        eroded[static_cast<std::size_t>(i)] = m;
    }
    for (int i = 0; i < n; ++i) {
        double sum = 0.0;
        int count = 0;
        for (int j = std::max(0, i - kHalfWindow); j <= std::min(n - 1, i + kHalfWindow); ++j) {
            sum += eroded[static_cast<std::size_t>(j)];
            ++count;
        }
        c.radius[static_cast<std::size_t>(i)] = sum / count;
    }
}

}  // namespace

ColonLayout layoutColon(const AnatomyParameters& params, double sampleSpacing)
{
    params.validate();
    ColonLayout layout;
    const auto length = [&](int seg) { return params.length(static_cast<Segment>(seg)); };
    // A flexure is the middle of the bend around its corner: half of it
    // belongs to each span that meets there.
    const std::array<double, kNumSpans> target{length(0),
                                               length(1),
                                               length(2) + 0.5 * length(3),
                                               0.5 * length(3) + length(4) + 0.5 * length(5),
                                               0.5 * length(5) + length(6),
                                               length(7)};
    std::array<double, kNumSpans> amplitude{};
    std::array<Eigen::Vector3d, kNumAnchors> anchors{};

    double scale = 1.0;
    ControlPolygon poly;
    for (int attempt = 0; attempt < 20; ++attempt) {
        for (std::size_t i = 0; i < kNumAnchors; ++i) {
            anchors[i] = scale * defaultAnchors()[i];
        }
        amplitude.fill(0.0);
        double cecumChord = target[kCecumSpan];
        for (int sweep = 0; sweep < 8; ++sweep) {
            // The cecum continues the ascending colon straight down: its base
            // lies on the line from the last ascending control point through
            // the ileocecal valve, at the distance that gives its length.
            const ControlPolygon current = buildControlPolygon(params, anchors, amplitude);
            const auto valve = static_cast<std::size_t>(current.anchorIndex[kCecumSpan]);
            const Eigen::Vector3d down = (current.points[valve] - current.points[valve - 1]).normalized();
            anchors[kNumSpans] = anchors[kCecumSpan] + cecumChord * down;
            cecumChord *= target[kCecumSpan] /
                          spanArcLength(buildControlPolygon(params, anchors, amplitude), kCecumSpan);
            for (int span = 0; span < kCecumSpan; ++span) {
                const auto s = static_cast<std::size_t>(span);
                const auto lengthAt = [&](double a) {
                    amplitude[s] = a;
                    return spanArcLength(buildControlPolygon(params, anchors, amplitude), span);
                };
                double lo = 0.0;
                double hi = 0.02;
                if (lengthAt(lo) >= target[s]) {
                    amplitude[s] = 0.0;
                    continue;
                }
                while (lengthAt(hi) < target[s] && hi < 2.0) {
                    hi *= 2.0;
                }
                for (int it = 0; it < 50; ++it) {
                    const double mid = 0.5 * (lo + hi);
                    (lengthAt(mid) < target[s] ? lo : hi) = mid;
                }
                amplitude[s] = 0.5 * (lo + hi);
            }
        }
        poly = buildControlPolygon(params, anchors, amplitude);
        double worstRatio = 1.0;
        for (int span = 0; span < kNumSpans; ++span) {
            worstRatio =
                std::min(worstRatio, target[static_cast<std::size_t>(span)] / spanArcLength(poly, span));
        }
        if (worstRatio > 0.999) {
            break;
        }
        scale *= worstRatio * 0.98;  // shrink the body until every span fits
    }
    layout.bodyScale = scale;

    // The rounded polygon, sampled evenly by arc length. Each anchor's
    // boundary is the curve point closest to it; a flexure is centred there.
    const FilletedPolyline curve = rounded(poly);
    const double total = curve.length();
    const auto anchorAt = [&](int a) {
        return curve.vertexArcLength[static_cast<std::size_t>(poly.anchorIndex[static_cast<std::size_t>(a)])];
    };
    layout.segmentStart = {0.0,
                           anchorAt(1),
                           anchorAt(2),
                           anchorAt(3) - 0.5 * length(3),
                           anchorAt(3) + 0.5 * length(3),
                           anchorAt(4) - 0.5 * length(5),
                           anchorAt(4) + 0.5 * length(5),
                           anchorAt(5),
                           total};
    for (std::size_t s = 0; s <= kNumSegments; ++s) {
        layout.stations[s] = curve.pointAt(layout.segmentStart[s]);
    }
    const int numSamples = std::max(2, static_cast<int>(std::ceil(total / sampleSpacing)) + 1);
    Centreline& c = layout.centreline;
    c.points.resize(static_cast<std::size_t>(numSamples));
    for (int i = 0; i < numSamples; ++i) {
        c.points[static_cast<std::size_t>(i)] = curve.pointAt(total * i / (numSamples - 1));
    }
    computeArcLengthAndFrames(c, -Eigen::Vector3d::UnitY());  // first normal points anteriorly
    // Rescale the chord arc length to the exact length so segment starts line up.
    const double resampledTotal = c.length();
    for (double& s : c.arcLength) {
        s *= total / resampledTotal;
    }
    c.arcLength.back() = total;  // exactly segmentStart[kNumSegments], not an ulp beyond

    c.radius.resize(c.points.size());
    c.segment.resize(c.points.size());
    for (std::size_t i = 0; i < c.points.size(); ++i) {
        const double s = c.arcLength[i];
        int seg = 0;
        while (seg + 1 < kNumSegments && s >= layout.segmentStart[static_cast<std::size_t>(seg + 1)]) {
            ++seg;
        }
        c.segment[i] = static_cast<Segment>(seg);
        double radius = 0.5 * params.diameter(Segment::Rectum);
        for (int b = 1; b < kNumSegments; ++b) {
            const double halfWidth = std::min({0.03, 0.5 * params.length(static_cast<Segment>(b - 1)),
                                               0.5 * params.length(static_cast<Segment>(b))});
            const double jump = 0.5 * (params.diameter(static_cast<Segment>(b)) -
                                       params.diameter(static_cast<Segment>(b - 1)));
            radius += jump * smoothstep((s - layout.segmentStart[static_cast<std::size_t>(b)] + halfWidth) /
                                        (2.0 * halfWidth));
        }
        c.radius[i] = radius;
    }
    limitRadiusByBend(c);
    return layout;
}

LumenSelfOverlap lumenSelfOverlap(const Centreline& centreline)
{
    LumenSelfOverlap overlap;
    const std::vector<Eigen::Vector3d>& c = centreline.points;
    const std::vector<double>& s = centreline.arcLength;
    const std::vector<double>& r = centreline.radius;
    for (size_t i = 0; i < c.size(); ++i) {
        for (size_t j = i + 1; j < c.size(); ++j) {
            const double reach = r[i] + r[j];
            if (s[j] - s[i] <= 2.0 * reach) {
                continue;
            }
            const double depth = reach - (c[i] - c[j]).norm();
            if (depth > 0.0) {
                ++overlap.pairs;
                if (depth > overlap.deepest) {
                    overlap = {overlap.pairs, depth, s[i], s[j]};
                }
            }
        }
    }
    return overlap;
}

}  // namespace colonosim::geometry
