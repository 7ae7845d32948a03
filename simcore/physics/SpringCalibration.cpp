#include "simcore/physics/SpringCalibration.h"

#include "simcore/params/Parameter.h"
#include "simcore/physics/StaticSolver.h"

#include <cmath>
#include <mutex>
#include <numbers>
#include <string>
#include <vector>

namespace colonosim::physics {

geometry::TriangleMesh makeStraightTube(const TubeResolution& tube)
{
    const int n = tube.nodesPerRing;
    geometry::TriangleMesh mesh;
    mesh.vertices.resize(3, static_cast<Eigen::Index>(n) * tube.rings);
    for (int r = 0; r < tube.rings; ++r) {
        for (int k = 0; k < n; ++k) {
            const double theta = 2.0 * std::numbers::pi * k / n;
            mesh.vertices.col(r * n + k) = Eigen::Vector3d(
                tube.radius * std::cos(theta), tube.radius * std::sin(theta), r * tube.ringSpacing);
        }
    }
    for (int r = 0; r + 1 < tube.rings; ++r) {
        for (int k = 0; k < n; ++k) {
            const int v00 = r * n + k;
            const int v01 = r * n + (k + 1) % n;
            const int v10 = (r + 1) * n + k;
            const int v11 = (r + 1) * n + (k + 1) % n;
            mesh.triangles.push_back({v00, v01, v11});
            mesh.triangles.push_back({v00, v11, v10});
        }
    }
    return mesh;
}

namespace {
struct TubeBody {
    TissueBody body;
    geometry::TriangleMesh mesh;
};

TubeBody makeTubeBody(const TubeResolution& tube, const TissueParameters& tissue,
                      const StiffnessCalibration& factors)
{
    geometry::TriangleMesh mesh = makeStraightTube(tube);
    const std::vector<Eigen::Vector3d> axis(static_cast<size_t>(mesh.numVertices()),
                                            Eigen::Vector3d::UnitZ());
    TubeBody tb{TissueBody(mesh.vertices, wallNodeMasses(mesh, tissue)), mesh};
    auto springs = std::make_unique<SpringSet>("wall");
    addWallSprings(mesh, axis, tissue, factors, *springs);
    tb.body.addForceTerm(std::move(springs));
    for (int k = 0; k < tube.nodesPerRing; ++k) {
        tb.body.setFixed(k, true);
    }
    return tb;
}

double meanOfRing(const Positions& x, const TubeResolution& tube, int ring, bool radial)
{
    double sum = 0.0;
    for (int k = 0; k < tube.nodesPerRing; ++k) {
        const Eigen::Vector3d p = x.col(ring * tube.nodesPerRing + k);
        sum += radial ? p.head<2>().norm() : p.z();
    }
    return sum / tube.nodesPerRing;
}
}  // namespace

MeasuredStiffness measureTubeStiffness(const TubeResolution& tube, const TissueParameters& tissue,
                                       const StiffnessCalibration& factors)
{
    const double et = tissue.wallYoungModulus * tissue.wallThickness;
    const double circumference = 2.0 * std::numbers::pi * tube.radius;
    constexpr double kStrain = 1e-4;  // small: the linear response
    MeasuredStiffness measured;
    const int r1 = tube.rings / 3;
    const int r2 = 2 * tube.rings / 3;

    {
        TubeBody tb = makeTubeBody(tube, tissue, factors);
        const double load = kStrain * circumference * et;
        for (int k = 0; k < tube.nodesPerRing; ++k) {
            tb.body.applyExternalForce((tube.rings - 1) * tube.nodesPerRing + k,
                                       Eigen::Vector3d(0.0, 0.0, load / tube.nodesPerRing));
        }
        const Positions rest = tb.body.positions();
        solveStaticEquilibrium(tb.body, 1e-9 * load);
        const Positions& x = tb.body.positions();
        const double stretched = meanOfRing(x, tube, r2, false) - meanOfRing(x, tube, r1, false);
        const double original = meanOfRing(rest, tube, r2, false) - meanOfRing(rest, tube, r1, false);
        measured.axial = load / (circumference * (stretched / original - 1.0));
    }
    {
        TubeBody tb = makeTubeBody(tube, tissue, factors);
        const double pressure = kStrain * et / tube.radius;
        tb.body.addForceTerm(std::make_unique<InsufflationPressure>(tb.mesh.triangles, pressure));
        const Positions rest = tb.body.positions();
        solveStaticEquilibrium(tb.body, 1e-9 * pressure * tube.radius * tube.ringSpacing);
        const int middle = tube.rings / 2;
        const double r0 = meanOfRing(rest, tube, middle, true);
        const double dr = meanOfRing(tb.body.positions(), tube, middle, true) - r0;
        measured.hoop = pressure * r0 * r0 / dr;
    }
    return measured;
}

double measureTubeBendingRigidity(const TubeResolution& tube, const TissueParameters& tissue,
                                  const StiffnessCalibration& factors)
{
    // A moment that bends the tube by a strain of 1e-4 at its outermost fibre
    // (the linear response), sized from the hoop stiffness E t.
    const double et = tissue.wallYoungModulus * tissue.wallThickness;
    const double moment = 1e-4 * std::numbers::pi * tube.radius * tube.radius * et;
    TubeBody tb = makeTubeBody(tube, tissue, factors);
    const int last = tube.rings - 1;
    double sumX2 = 0.0;
    for (int k = 0; k < tube.nodesPerRing; ++k) {
        const double x = tb.body.positions()(0, last * tube.nodesPerRing + k);
        sumX2 += x * x;
    }
    for (int k = 0; k < tube.nodesPerRing; ++k) {
        const int node = last * tube.nodesPerRing + k;
        const double x = tb.body.positions()(0, node);
        tb.body.applyExternalForce(node, Eigen::Vector3d(0.0, 0.0, -moment * x / sumX2));
    }
    const Positions rest = tb.body.positions();
    solveStaticEquilibrium(tb.body, 1e-9 * moment / tube.radius);
    // Each ring's tilt about y: the least-squares slope of its axial
    // displacement across x.
    const auto tilt = [&](int ring) {
        double num = 0.0;
        double den = 0.0;
        for (int k = 0; k < tube.nodesPerRing; ++k) {
            const int node = ring * tube.nodesPerRing + k;
            const double x = rest(0, node);
            num += x * (tb.body.positions()(2, node) - rest(2, node));
            den += x * x;
        }
        return num / den;
    };
    const int r1 = tube.rings / 3;
    const int r2 = 2 * tube.rings / 3;
    const double curvature = (tilt(r1) - tilt(r2)) / ((r2 - r1) * tube.ringSpacing);
    return moment / curvature;
}

CalibrationReport calibrateWallStiffness(const TubeResolution& tube, const TissueParameters& tissue,
                                         double tolerance)
{
    const double et = tissue.wallYoungModulus * tissue.wallThickness;
    CalibrationReport report;
    for (report.iterations = 1; report.iterations <= 30; ++report.iterations) {
        const MeasuredStiffness m = measureTubeStiffness(tube, tissue, report.factors);
        report.axialStiffnessError = m.axial / (tissue.haustralAxialRatio * et) - 1.0;
        report.hoopStiffnessError = m.hoop / et - 1.0;
        if (std::abs(report.axialStiffnessError) < tolerance &&
            std::abs(report.hoopStiffnessError) < tolerance) {
            break;
        }
        report.factors.axial /= 1.0 + report.axialStiffnessError;
        report.factors.circumferential /= 1.0 + report.hoopStiffnessError;
    }
    return report;
}

namespace {

bool sameTissue(const TissueParameters& a, const TissueParameters& b)
{
    for (const params::Field<TissueParameters>& field : TissueParameters::fields()) {
        if (a.*field.member != b.*field.member) {
            return false;
        }
    }
    return true;
}

/// The haustral calibrations this process has made, by their tissue: each
/// takes two static solves of the test tube (about 4 s), and every procedure
/// on the same tissue asks for the same one. Kept are the factors found for
/// the tissue and for its flat wall, so that any given factors are scaled by
/// them exactly as a fresh calibration would.
struct CalibrationCache {
    struct Entry {
        TissueParameters tissue;
        StiffnessCalibration folded;     ///< calibrateWallStiffness()'s factors for the tissue
        StiffnessCalibration reference;  ///< and for its flat wall (ratio 1)
    };
    static constexpr size_t kCapacity = 8;
    std::mutex mutex;
    std::vector<Entry> entries;  ///< the oldest first
};

CalibrationCache& calibrationCache()
{
    static CalibrationCache cache;
    return cache;
}

/// The factors calibrateWallStiffness() finds for `tissue` and for its flat
/// wall; throws params::ParameterError when either misses its tolerance.
CalibrationCache::Entry calibrateHaustralWall(const TissueParameters& tissue)
{
    constexpr double kTolerance = 1e-3;
    TissueParameters plain = tissue;
    plain.haustralAxialRatio = 1.0;
    const TubeResolution tube;
    const CalibrationReport reference = calibrateWallStiffness(tube, plain, kTolerance);
    const CalibrationReport folded = calibrateWallStiffness(tube, tissue, kTolerance);
    for (const CalibrationReport* report : {&reference, &folded}) {
        if (!(std::abs(report->axialStiffnessError) < kTolerance &&
              std::abs(report->hoopStiffnessError) < kTolerance)) {
            throw params::ParameterError(
                "tissue.haustralAxialRatio = " + std::to_string(tissue.haustralAxialRatio) +
                ": the wall springs' calibration left an axial error of " +
                std::to_string(report->axialStiffnessError) + " and a hoop error of " +
                std::to_string(report->hoopStiffnessError) + " (allowed: below " +
                std::to_string(kTolerance) + ")");
        }
    }
    return {tissue, folded.factors, reference.factors};
}

}  // namespace

StiffnessCalibration wallCalibrationFor(const TissueParameters& tissue, const StiffnessCalibration& isotropic)
{
    if (tissue.haustralAxialRatio == 1.0) {
        return isotropic;
    }
    CalibrationCache& cache = calibrationCache();
    CalibrationCache::Entry found;
    bool kept = false;
    {
        const std::lock_guard<std::mutex> lock(cache.mutex);
        for (const CalibrationCache::Entry& e : cache.entries) {
            if (sameTissue(e.tissue, tissue)) {
                found = e;
                kept = true;
                break;
            }
        }
    }
    if (!kept) {
        // Calibrated outside the lock (a refused calibration throws and is
        // not kept); two threads asking at once both calibrate, alike.
        found = calibrateHaustralWall(tissue);
        const std::lock_guard<std::mutex> lock(cache.mutex);
        if (cache.entries.size() >= CalibrationCache::kCapacity) {
            cache.entries.erase(cache.entries.begin());
        }
        cache.entries.push_back(found);
    }
    return {isotropic.axial * found.folded.axial / found.reference.axial,
            isotropic.circumferential * found.folded.circumferential / found.reference.circumferential};
}

}  // namespace colonosim::physics
