#include "simcore/geometry/ColonLayout.h"

#include "simcore/geometry/CentrelineSampling.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace colonosim::geometry {

namespace {

constexpr int kSamplesPerPiece = 64;

/// Interior control point of a segment: where along the chord, and which way
/// it is displaced per unit amplitude.
struct Bend {
    double t;
    Eigen::Vector3d direction;
};

struct SegmentShape {
    std::vector<Bend> bends;
};

const std::array<Eigen::Vector3d, kNumSegments + 1>& defaultStations()
{
    static const std::array<Eigen::Vector3d, kNumSegments + 1> stations{{
        {0.0, 0.0, 0.0},        // anal verge
        {0.01, 0.05, 0.12},     // rectosigmoid junction
        {0.12, 0.05, 0.17},     // sigmoid-descending junction, left iliac fossa
        {0.13, 0.07, 0.40},     // top of the descending colon, left flank
        {0.09, 0.03, 0.44},     // splenic flexure -> transverse, under the left diaphragm
        {-0.09, 0.03, 0.42},    // transverse -> hepatic flexure, under the liver
        {-0.12, 0.06, 0.37},    // hepatic flexure -> ascending
        {-0.11, 0.05, 0.22},    // ileocecal valve
        {-0.10, 0.03, 0.175},   // cecal base, right iliac fossa
    }};
    return stations;
}

const std::array<SegmentShape, kNumSegments>& shapes()
{
    static const std::array<SegmentShape, kNumSegments> s{{
        {{{0.5, {0.0, 1.0, 0.0}}}},                                                          // rectum: sacral curve
        {{{0.2, {-0.3, -0.7, 0.3}}, {0.5, {0.0, -1.0, 0.8}}, {0.8, {0.4, -0.6, 0.3}}}},     // sigmoid loop
        {{{0.5, {1.0, 0.0, 0.0}}}},                                                          // descending: lateral
        {{{0.5, {0.7, 0.0, 0.7}}}},                                                          // splenic flexure
        {{{0.25, {0.0, -0.3, -0.45}}, {0.5, {0.0, -0.7, -1.0}}, {0.75, {0.0, -0.3, -0.45}}}},   // transverse sag
        {{{0.5, {-0.7, 0.0, 0.7}}}},                                                         // hepatic flexure
        {{{0.5, {-1.0, 0.0, 0.0}}}},                                                         // ascending: lateral
        {},                                                                                  // cecum: straight pouch
    }};
    return s;
}

/// Centripetal Catmull-Rom point on the piece p1 -> p2 (Barry-Goldman pyramid).
Eigen::Vector3d catmullRom(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                           const Eigen::Vector3d& p3, double u)
{
    const auto knot = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
        return std::max(std::sqrt((b - a).norm()), 1e-9);
    };
    const double t0 = 0.0;
    const double t1 = t0 + knot(p0, p1);
    const double t2 = t1 + knot(p1, p2);
    const double t3 = t2 + knot(p2, p3);
    const double t = t1 + u * (t2 - t1);
    const Eigen::Vector3d a1 = (t1 - t) / (t1 - t0) * p0 + (t - t0) / (t1 - t0) * p1;
    const Eigen::Vector3d a2 = (t2 - t) / (t2 - t1) * p1 + (t - t1) / (t2 - t1) * p2;
    const Eigen::Vector3d a3 = (t3 - t) / (t3 - t2) * p2 + (t - t2) / (t3 - t2) * p3;
    const Eigen::Vector3d b1 = (t2 - t) / (t2 - t0) * a1 + (t - t0) / (t2 - t0) * a2;
    const Eigen::Vector3d b2 = (t3 - t) / (t3 - t1) * a2 + (t - t1) / (t3 - t1) * a3;
    return (t2 - t) / (t2 - t1) * b1 + (t - t1) / (t2 - t1) * b2;
}

struct ControlPolygon {
    std::vector<Eigen::Vector3d> points;
    std::array<int, kNumSegments + 1> stationIndex{};
};

ControlPolygon buildControlPolygon(const std::array<Eigen::Vector3d, kNumSegments + 1>& stations,
                                   const std::array<double, kNumSegments>& amplitude)
{
    ControlPolygon poly;
    for (int seg = 0; seg < kNumSegments; ++seg) {
        const auto i = static_cast<std::size_t>(seg);
        poly.stationIndex[i] = static_cast<int>(poly.points.size());
        poly.points.push_back(stations[i]);
        for (const Bend& bend : shapes()[i].bends) {
            const Eigen::Vector3d base = (1.0 - bend.t) * stations[i] + bend.t * stations[i + 1];
            poly.points.push_back(base + amplitude[i] * bend.direction);
        }
    }
    poly.stationIndex[kNumSegments] = static_cast<int>(poly.points.size());
    poly.points.push_back(stations[kNumSegments]);
    return poly;
}

/// Dense samples of the spline piece k (control point k -> k + 1), excluding its end.
void appendPiece(const std::vector<Eigen::Vector3d>& pts, int k, std::vector<Eigen::Vector3d>& out)
{
    const int n = static_cast<int>(pts.size());
    const auto at = [&](int i) -> Eigen::Vector3d {
        if (i < 0) return 2.0 * pts[0] - pts[1];
        if (i >= n) return 2.0 * pts[static_cast<std::size_t>(n - 1)] - pts[static_cast<std::size_t>(n - 2)];
        return pts[static_cast<std::size_t>(i)];
    };
    for (int j = 0; j < kSamplesPerPiece; ++j) {
        out.push_back(catmullRom(at(k - 1), at(k), at(k + 1), at(k + 2), static_cast<double>(j) / kSamplesPerPiece));
    }
}

double polylineLength(const std::vector<Eigen::Vector3d>& p)
{
    double length = 0.0;
    for (std::size_t i = 1; i < p.size(); ++i) {
        length += (p[i] - p[i - 1]).norm();
    }
    return length;
}

double segmentArcLength(const ControlPolygon& poly, int seg)
{
    std::vector<Eigen::Vector3d> samples;
    const auto s = static_cast<std::size_t>(seg);
    for (int k = poly.stationIndex[s]; k < poly.stationIndex[s + 1]; ++k) {
        appendPiece(poly.points, k, samples);
    }
    samples.push_back(poly.points[static_cast<std::size_t>(poly.stationIndex[s + 1])]);
    return polylineLength(samples);
}

double smoothstep(double x)
{
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

/// Narrows the lumen where the bend radius is below it, so rings of wall
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
    std::array<double, kNumSegments> amplitude{};
    std::array<double, kNumSegments> declared{};
    for (int i = 0; i < kNumSegments; ++i) {
        declared[static_cast<std::size_t>(i)] = params.length(static_cast<Segment>(i));
    }

    double scale = 1.0;
    ControlPolygon poly;
    for (int attempt = 0; attempt < 20; ++attempt) {
        for (std::size_t i = 0; i <= kNumSegments; ++i) {
            layout.stations[i] = scale * defaultStations()[i];
        }
        amplitude.fill(0.0);
        double cecumChord = declared[kNumSegments - 1];
        for (int sweep = 0; sweep < 8; ++sweep) {
            // The cecum continues the ascending colon straight down: its base
            // lies on the line from the last ascending control point through
            // the ileocecal valve, at the distance that gives its length.
            const ControlPolygon current = buildControlPolygon(layout.stations, amplitude);
            const auto valve = static_cast<std::size_t>(current.stationIndex[kNumSegments - 1]);
            const Eigen::Vector3d down = (current.points[valve] - current.points[valve - 1]).normalized();
            layout.stations[kNumSegments] = layout.stations[kNumSegments - 1] + cecumChord * down;
            cecumChord *= declared[kNumSegments - 1] / segmentArcLength(buildControlPolygon(layout.stations, amplitude), kNumSegments - 1);
            for (int seg = 0; seg + 1 < kNumSegments; ++seg) {
                const auto s = static_cast<std::size_t>(seg);
                const auto lengthAt = [&](double a) {
                    amplitude[s] = a;
                    return segmentArcLength(buildControlPolygon(layout.stations, amplitude), seg);
                };
                double lo = 0.0;
                double hi = 0.02;
                if (lengthAt(lo) >= declared[s]) {
                    amplitude[s] = 0.0;
                    continue;
                }
                while (lengthAt(hi) < declared[s] && hi < 2.0) {
                    hi *= 2.0;
                }
                for (int it = 0; it < 50; ++it) {
                    const double mid = 0.5 * (lo + hi);
                    (lengthAt(mid) < declared[s] ? lo : hi) = mid;
                }
                amplitude[s] = 0.5 * (lo + hi);
            }
        }
        poly = buildControlPolygon(layout.stations, amplitude);
        double worstRatio = 1.0;
        for (int seg = 0; seg < kNumSegments; ++seg) {
            worstRatio = std::min(worstRatio, declared[static_cast<std::size_t>(seg)] / segmentArcLength(poly, seg));
        }
        if (worstRatio > 0.999) {
            break;
        }
        scale *= worstRatio * 0.98;  // shrink the body until every segment fits
    }
    layout.bodyScale = scale;

    // Dense spline, then even arc-length resampling.
    std::vector<Eigen::Vector3d> dense;
    std::vector<double> stationDense(kNumSegments + 1, 0.0);
    for (int k = 0; k + 1 < static_cast<int>(poly.points.size()); ++k) {
        for (std::size_t s = 0; s <= kNumSegments; ++s) {
            if (poly.stationIndex[s] == k) {
                stationDense[s] = polylineLength(dense) + (dense.empty() ? 0.0 : (poly.points[static_cast<std::size_t>(k)] - dense.back()).norm());
            }
        }
        appendPiece(poly.points, k, dense);
    }
    dense.push_back(poly.points.back());
    const double total = polylineLength(dense);
    stationDense[kNumSegments] = total;
    for (std::size_t s = 0; s <= kNumSegments; ++s) {
        layout.segmentStart[s] = stationDense[s];
    }

    const int numSamples = std::max(2, static_cast<int>(std::ceil(total / sampleSpacing)) + 1);
    Centreline& c = layout.centreline;
    c.points = resampleByArcLength(dense, numSamples);
    computeArcLengthAndFrames(c, -Eigen::Vector3d::UnitY());  // first normal points anteriorly
    // Rescale the arc length to the dense length so segment starts line up.
    const double resampledTotal = c.length();
    for (double& s : c.arcLength) {
        s *= total / resampledTotal;
    }

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
            const double jump = 0.5 * (params.diameter(static_cast<Segment>(b)) - params.diameter(static_cast<Segment>(b - 1)));
            radius += jump * smoothstep((s - layout.segmentStart[static_cast<std::size_t>(b)] + halfWidth) / (2.0 * halfWidth));
        }
        c.radius[i] = radius;
    }
    limitRadiusByBend(c);
    return layout;
}

}  // namespace colonosim::geometry
