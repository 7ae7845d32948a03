#include "simcore/geometry/ProceduralColon.h"

#include "simcore/geometry/CentrelineSampling.h"
#include "simcore/geometry/ColonLayout.h"
#include "simcore/geometry/ProceduralOrgans.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace colonosim::geometry {

namespace {

/// Where a tube vertex sits: arc length, angle, and whether it is on the cap.
struct TubeVertex {
    double s = 0.0;
    double theta = 0.0;
    bool onCap = false;
};

struct Tube {
    TriangleMesh mesh;
    std::vector<TubeVertex> where;
};

/// Rings at the arc lengths `ringS`, then `numCapRings - 1` dome rings and an
/// apex. `radiusAt(s, theta)` gives the wall radius of the tube part.
template <class RadiusFn>
Tube buildTube(const Centreline& c, const std::vector<double>& ringS, int perRing, int numCapRings,
               RadiusFn radiusAt)
{
    Tube tube;
    const int numRings = static_cast<int>(ringS.size());
    const int numVertices = (numRings + numCapRings - 1) * perRing + 1;
    tube.mesh.vertices.resize(3, numVertices);
    tube.where.resize(static_cast<std::size_t>(numVertices));
    int v = 0;
    const auto angle = [perRing](int j) { return 2.0 * std::numbers::pi * j / perRing; };
    for (double s : ringS) {
        const CentrelineSample cs = sampleCentreline(c, s);
        for (int j = 0; j < perRing; ++j) {
            const double theta = angle(j);
            const double r = radiusAt(s, theta);
            tube.mesh.vertices.col(v) =
                cs.point + r * (std::cos(theta) * cs.normal + std::sin(theta) * cs.binormal);
            tube.where[static_cast<std::size_t>(v++)] = {s, theta, false};
        }
    }
    const CentrelineSample end = sampleCentreline(c, c.length());
    const double capDepth = 0.5 * end.radius;
    for (int k = 1; k < numCapRings; ++k) {
        const double phi = 0.5 * std::numbers::pi * k / numCapRings;
        for (int j = 0; j < perRing; ++j) {
            const double theta = angle(j);
            const Eigen::Vector3d radial = std::cos(theta) * end.normal + std::sin(theta) * end.binormal;
            tube.mesh.vertices.col(v) =
                end.point + end.radius * std::cos(phi) * radial + capDepth * std::sin(phi) * end.tangent;
            tube.where[static_cast<std::size_t>(v++)] = {c.length(), theta, true};
        }
    }
    tube.mesh.vertices.col(v) = end.point + capDepth * end.tangent;
    tube.where[static_cast<std::size_t>(v)] = {c.length(), 0.0, true};
    const int apex = v;

    const int numBands = numRings + numCapRings - 1;
    for (int i = 0; i + 1 < numBands; ++i) {
        for (int j = 0; j < perRing; ++j) {
            const int j1 = (j + 1) % perRing;
            const int a = i * perRing + j;
            const int b = i * perRing + j1;
            const int cc = (i + 1) * perRing + j;
            const int d = (i + 1) * perRing + j1;
            tube.mesh.triangles.push_back({a, b, cc});
            tube.mesh.triangles.push_back({b, d, cc});
        }
    }
    const int last = (numBands - 1) * perRing;
    for (int j = 0; j < perRing; ++j) {
        tube.mesh.triangles.push_back({last + j, last + (j + 1) % perRing, apex});
    }
    return tube;
}

std::vector<double> evenRings(double length, int numRings)
{
    std::vector<double> s(static_cast<std::size_t>(numRings));
    for (int i = 0; i < numRings; ++i) {
        s[static_cast<std::size_t>(i)] = length * i / (numRings - 1);
    }
    return s;
}

double smoothstep(double x)
{
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

double mesenteryHeight(const AnatomyParameters& p, Segment segment)
{
    switch (segment) {
    case Segment::Sigmoid: return p.sigmoidMesenteryHeight;
    case Segment::Transverse: return p.transverseMesenteryHeight;
    default: return p.mobileColonMesenteryHeight;
    }
}

Attachment attachmentOf(const AnatomyParameters& p, const ColonLayout& layout, double s, Segment segment)
{
    if (s < kAnalCanalLength) {
        return Attachment::Fixed;
    }
    const double total = layout.segmentStart[kNumSegments];
    switch (segment) {
    case Segment::Sigmoid:
    case Segment::Transverse: return Attachment::Mesenteric;
    case Segment::Descending:
        return p.isDescendingMobile() ? Attachment::Mesenteric : Attachment::Retroperitoneal;
    case Segment::Ascending:
    case Segment::Cecum: {
        const double mobileLength = p.ascendingMobileFraction * (p.ascendingLength + p.cecumLength);
        return total - s < mobileLength ? Attachment::Mesenteric : Attachment::Retroperitoneal;
    }
    default: return Attachment::Retroperitoneal;
    }
}

/// The sigmoid's mesocolon on one root line (AnatomyParameters::sigmoidRootLength):
/// `length` long, centred on the chord between the centres of the sigmoid's
/// first and last mobile rings, a lumen radius behind it; each mobile sigmoid
/// node is tethered to its nearest point on that line.
void hangSigmoidFromOneRoot(ColonAnatomy& anatomy, double length)
{
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
    const auto mobileSigmoid = [](const PhysicsNodeInfo& info) {
        return info.segment == Segment::Sigmoid && info.attachment == Attachment::Mesenteric;
    };
    for (const PhysicsNodeInfo& info : anatomy.physicsNodes) {
        if (mobileSigmoid(info)) {
            lo = std::min(lo, info.arcLength);
            hi = std::max(hi, info.arcLength);
        }
    }
    if (!(hi > lo)) {
        return;
    }
    const CentrelineSample first = sampleCentreline(anatomy.centreline, lo);
    const CentrelineSample last = sampleCentreline(anatomy.centreline, hi);
    const Eigen::Vector3d chord = last.point - first.point;
    const Eigen::Vector3d along = chord.normalized();
    const Eigen::Vector3d middle =
        0.5 * (first.point + last.point) + 0.5 * (first.radius + last.radius) * Eigen::Vector3d::UnitY();
    const Eigen::Vector3d from = middle - 0.5 * length * along;
    for (std::size_t i = 0; i < anatomy.physicsNodes.size(); ++i) {
        PhysicsNodeInfo& info = anatomy.physicsNodes[i];
        if (mobileSigmoid(info)) {
            const Eigen::Vector3d x = anatomy.physicsMesh.vertices.col(static_cast<Eigen::Index>(i));
            info.mesenteryRoot = from + std::clamp((x - from).dot(along), 0.0, length) * along;
        }
    }
}

int nearestVertex(const TriangleMesh& mesh, const Eigen::Vector3d& p)
{
    Eigen::Index best = 0;
    (mesh.vertices.colwise() - p).colwise().squaredNorm().minCoeff(&best);
    return static_cast<int>(best);
}

}  // namespace

ColonAnatomy buildProceduralColon(const AnatomyParameters& params)
{
    params.validate();
    const ColonLayout layout = layoutColon(params);
    ColonAnatomy anatomy;
    anatomy.centreline = layout.centreline;
    const Centreline& c = anatomy.centreline;
    const double total = c.length();

    // Physics mesh: 2 cap bands (one dome ring + apex).
    const int physPerRing = static_cast<int>(std::lround(params.physicsNodesPerRing));
    constexpr int kPhysicsCapRings = 2;
    const int capNodes = (kPhysicsCapRings - 1) * physPerRing + 1;
    const int physRings =
        std::max(3, static_cast<int>(std::lround((params.physicsTargetNodeCount - capNodes) / physPerRing)));
    const Tube physics = buildTube(c, evenRings(total, physRings), physPerRing, kPhysicsCapRings,
                                   [&](double s, double) { return sampleCentreline(c, s).radius; });
    anatomy.physicsMesh = physics.mesh;
    anatomy.physicsNodes.resize(physics.where.size());
    for (std::size_t i = 0; i < physics.where.size(); ++i) {
        const TubeVertex& tv = physics.where[i];
        const CentrelineSample cs = sampleCentreline(c, tv.s);
        PhysicsNodeInfo& info = anatomy.physicsNodes[i];
        info.segment = cs.segment;
        info.arcLength = tv.s;
        info.angle = tv.theta;
        info.attachment = attachmentOf(params, layout, tv.s, cs.segment);
        const Eigen::Vector3d rest = physics.mesh.vertices.col(static_cast<Eigen::Index>(i));
        info.mesenteryRoot =
            info.attachment == Attachment::Mesenteric
                ? Eigen::Vector3d(cs.point + (mesenteryHeight(params, cs.segment) + cs.radius) *
                                                 Eigen::Vector3d::UnitY())
                : rest;
    }
    if (params.sigmoidRootLength > 0.0) {
        hangSigmoidFromOneRoot(anatomy, params.sigmoidRootLength);
    }

    // Visual mesh with haustral folds and taeniae.
    const int visPerRing = static_cast<int>(std::lround(params.visualNodesPerRing));
    const int visRings = static_cast<int>(std::lround(params.visualRingCount));
    const double rectumEnd = layout.segmentStart[1];
    const double taeniaWidth = 0.12;  // rad, about 2.5 mm of a 4.5 cm lumen
    const auto visualRadius = [&](double s, double theta) {
        const double r = sampleCentreline(c, s).radius;
        const double haustra = smoothstep((s - rectumEnd + 0.02) / 0.04);
        const double fold = std::pow(
            0.5 * (1.0 + std::cos(2.0 * std::numbers::pi * (s - rectumEnd) / params.haustralFoldSpacing)), 6);
        double taenia = 0.0;
        for (int k = 0; k < 3; ++k) {
            double d = std::remainder(theta - 2.0 * std::numbers::pi * k / 3.0, 2.0 * std::numbers::pi);
            taenia += std::exp(-(d * d) / (taeniaWidth * taeniaWidth));
        }
        return r - haustra * (params.haustralFoldDepth * fold * (1.0 - taenia) + params.taeniaDepth * taenia);
    };
    constexpr int kVisualCapRings = 8;
    anatomy.visualMesh =
        buildTube(c, evenRings(total, visRings), visPerRing, kVisualCapRings, visualRadius).mesh;

    // Landmarks.
    const CentrelineSample icv =
        sampleCentreline(c, layout.segmentStart[static_cast<std::size_t>(Segment::Cecum)]);
    Eigen::Vector3d medial =
        Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitX().dot(icv.tangent) * icv.tangent;
    medial.normalize();
    Landmark valve{"ileocecal_valve", Segment::Cecum, icv.point + icv.radius * medial, -medial, -1};
    const CentrelineSample end = sampleCentreline(c, total);
    Landmark orifice{"appendiceal_orifice", Segment::Cecum, end.point + 0.5 * end.radius * end.tangent,
                     -end.tangent, -1};
    for (Landmark* l : {&valve, &orifice}) {
        l->nearestPhysicsNode = nearestVertex(anatomy.physicsMesh, l->position);
        anatomy.landmarks.push_back(*l);
    }

    anatomy.organs = placeProceduralOrgans(layout, anatomy.physicsMesh);
    return anatomy;
}

}  // namespace colonosim::geometry
