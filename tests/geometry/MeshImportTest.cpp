#include "simcore/geometry/MeshImport.h"

#include "MeshChecks.h"
#include "simcore/geometry/MeshExport.h"
#include "simcore/geometry/TubeCentreline.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>

namespace colonosim::geometry {
namespace {

constexpr double kBendRadius = 0.12;  // m
constexpr double kTubeRadius = 0.02;  // m
constexpr double kArc = 1.2 * std::numbers::pi / 2.0;
constexpr int kRings = 120;
constexpr int kPerRing = 32;

Eigen::Vector3d trueCentre(double phi)
{
    return {kBendRadius * (1.0 - std::cos(phi)), 0.0, kBendRadius * std::sin(phi)};
}

/// A curved tube open at both ends, normals outward.
TriangleMesh curvedTube()
{
    TriangleMesh mesh;
    mesh.vertices.resize(3, kRings * kPerRing);
    for (int i = 0; i < kRings; ++i) {
        const double phi = kArc * i / (kRings - 1);
        const Eigen::Vector3d t(std::sin(phi), 0.0, std::cos(phi));
        const Eigen::Vector3d n(std::cos(phi), 0.0, -std::sin(phi));
        const Eigen::Vector3d b = t.cross(n);
        for (int j = 0; j < kPerRing; ++j) {
            const double theta = 2.0 * std::numbers::pi * j / kPerRing;
            mesh.vertices.col(i * kPerRing + j) =
                trueCentre(phi) + kTubeRadius * (std::cos(theta) * n + std::sin(theta) * b);
        }
    }
    for (int i = 0; i + 1 < kRings; ++i) {
        for (int j = 0; j < kPerRing; ++j) {
            const int a = i * kPerRing + j, b = i * kPerRing + (j + 1) % kPerRing;
            mesh.triangles.push_back({a, b, a + kPerRing});
            mesh.triangles.push_back({b, b + kPerRing, a + kPerRing});
        }
    }
    return mesh;
}

std::filesystem::path tempDir()
{
    static const std::filesystem::path dir = [] {
        std::random_device random;
        auto path = std::filesystem::temp_directory_path() / ("colonosim_import_" + std::to_string(random()));
        std::filesystem::create_directories(path);
        return path;
    }();
    return dir;
}

enum class Format { Obj, StlAscii, StlBinary, PlyAscii, PlyBinary };

std::filesystem::path write(const TriangleMesh& mesh, const std::string& stem, Format format)
{
    switch (format) {
    case Format::Obj: {
        auto p = tempDir() / (stem + ".obj");
        writeObj(p, mesh);
        return p;
    }
    case Format::StlAscii: {
        auto p = tempDir() / (stem + "_a.stl");
        writeStl(p, mesh, MeshEncoding::Ascii);
        return p;
    }
    case Format::StlBinary: {
        auto p = tempDir() / (stem + "_b.stl");
        writeStl(p, mesh, MeshEncoding::Binary);
        return p;
    }
    case Format::PlyAscii: {
        auto p = tempDir() / (stem + "_a.ply");
        writePly(p, mesh, MeshEncoding::Ascii);
        return p;
    }
    case Format::PlyBinary: {
        auto p = tempDir() / (stem + "_b.ply");
        writePly(p, mesh, MeshEncoding::Binary);
        return p;
    }
    }
    return {};
}

struct FormatCase {
    const char* name;
    Format format;
};

class ImportFormat : public ::testing::TestWithParam<FormatCase> {};

TEST_P(ImportFormat, RoundTripsCountsOrientationAndCentreline)
{
    const TriangleMesh tube = curvedTube();
    const auto path = write(tube, "tube", GetParam().format);
    const auto start = std::chrono::steady_clock::now();
    const ImportedMesh imported = importMesh(path);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::cout << GetParam().name << ": import " << ms << " ms; " << imported.report.summary() << "\n";
    EXPECT_EQ(imported.mesh.numVertices(), tube.numVertices());
    EXPECT_EQ(imported.mesh.numTriangles(), tube.numTriangles());
    EXPECT_FALSE(imported.report.globallyFlipped);
    EXPECT_EQ(imported.report.numFacesReoriented, 0);
    EXPECT_EQ(imported.report.numOpenEnds, 2);
    const testing::EdgeCounts counts = testing::countEdges(imported.mesh);
    EXPECT_EQ(counts.numInconsistentEdges, 0);
    EXPECT_EQ(counts.numBoundaryEdges, 2 * kPerRing);

    const Centreline c = computeCentreline(imported.mesh);
    double worst = 0.0;
    for (const Eigen::Vector3d& p : c.points) {
        // Distance to the true arc: |distance to the bend centre - R| in the plane y = 0.
        const Eigen::Vector3d fromCentre = p - Eigen::Vector3d(kBendRadius, 0.0, 0.0);
        const double phi = std::atan2(fromCentre.z(), -fromCentre.x());
        const double clamped = std::clamp(phi, 0.0, kArc);
        worst = std::max(worst, (p - trueCentre(clamped)).norm());
    }
    const double trueLength = kBendRadius * kArc;
    std::cout << "  centreline: max deviation " << worst << " m, length " << c.length() << " vs "
              << trueLength << " m\n";
    EXPECT_LT(worst, 0.1 * kTubeRadius);
    EXPECT_NEAR(c.length(), trueLength, 0.03 * trueLength);
    const double midRadius = c.radius[c.radius.size() / 2];
    EXPECT_NEAR(midRadius, kTubeRadius, 0.05 * kTubeRadius) << "mean vertex distance from the axis";
}

INSTANTIATE_TEST_SUITE_P(Formats, ImportFormat,
                         ::testing::Values(FormatCase{"obj", Format::Obj},
                                           FormatCase{"stlAscii", Format::StlAscii},
                                           FormatCase{"stlBinary", Format::StlBinary},
                                           FormatCase{"plyAscii", Format::PlyAscii},
                                           FormatCase{"plyBinary", Format::PlyBinary}),
                         [](const auto& info) { return std::string(info.param.name); });

// ---- broken fixtures -------------------------------------------------------

void removeFan(TriangleMesh& mesh, int vertex)
{
    std::erase_if(mesh.triangles,
                  [vertex](const auto& t) { return t[0] == vertex || t[1] == vertex || t[2] == vertex; });
}

struct BrokenCase {
    const char* name;
    Format format;
    std::function<void(TriangleMesh&)> breakMesh;
    const char* expectedError;  ///< substring of the MeshImportError, or nullptr when repaired
    std::function<void(const MeshRepairReport&)> checkReport;
};

class BrokenMesh : public ::testing::TestWithParam<BrokenCase> {};

TEST_P(BrokenMesh, IsRepairedOrRefusedWithAMessage)
{
    const BrokenCase& c = GetParam();
    TriangleMesh mesh = curvedTube();
    c.breakMesh(mesh);
    const auto path = write(mesh, std::string("broken_") + c.name, c.format);
    if (c.expectedError != nullptr) {
        try {
            (void)importMesh(path);
            FAIL() << "accepted";
        } catch (const MeshImportError& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find(path.filename().string()), std::string::npos) << message;
            EXPECT_NE(message.find(c.expectedError), std::string::npos) << message;
        }
        return;
    }
    const ImportedMesh imported = importMesh(path);
    c.checkReport(imported.report);
    const testing::EdgeCounts counts = testing::countEdges(imported.mesh);
    EXPECT_EQ(counts.numInconsistentEdges, 0);
    EXPECT_EQ(counts.numNonManifoldEdges, 0);
    EXPECT_EQ(counts.numBoundaryEdges, 2 * kPerRing) << "only the two tube ends stay open";
    // Outward normals: the first triangle's normal points away from the axis.
    const auto& t = imported.mesh.triangles.front();
    const Eigen::Vector3d a = imported.mesh.vertices.col(t[0]);
    const Eigen::Vector3d n =
        (imported.mesh.vertices.col(t[1]) - a).cross(imported.mesh.vertices.col(t[2]) - a);
    const Centreline axis = computeCentreline(imported.mesh);
    double dist = 0.0;
    Eigen::Index nearest = 0;
    Eigen::Matrix3Xd pts(3, axis.numPoints());
    for (int i = 0; i < axis.numPoints(); ++i)
        pts.col(i) = axis.points[static_cast<std::size_t>(i)];
    dist = (pts.colwise() - a).colwise().squaredNorm().minCoeff(&nearest);
    EXPECT_GT(dist, 0.0);
    EXPECT_GT(n.dot(a - pts.col(nearest)), 0.0) << "normals point out of the lumen";
}

const int kMid = (kRings / 2) * kPerRing + 5;

INSTANTIATE_TEST_SUITE_P(
    Fixtures, BrokenMesh,
    ::testing::Values(
        BrokenCase{"smallHole", Format::Obj, [](TriangleMesh& m) { removeFan(m, kMid); }, nullptr,
                   [](const MeshRepairReport& r) { EXPECT_EQ(r.numHolesFilled, 1); }},
        BrokenCase{"largeHole", Format::PlyBinary,
                   [](TriangleMesh& m) {
                       for (int k = 0; k < 12; ++k)
                           for (int j = 0; j < 8; ++j)
                               removeFan(m, (30 + k) * kPerRing + j);
                   },
                   "too large to fill", nullptr},
        BrokenCase{"nonManifoldEdge", Format::PlyAscii,
                   [](TriangleMesh& m) {
                       const int extra = m.numVertices();
                       m.vertices.conservativeResize(3, extra + 1);
                       m.vertices.col(extra) = Eigen::Vector3d(0.5, 0.5, 0.5);
                       const auto t = m.triangles[100];
                       m.triangles.push_back({t[0], t[1], extra});
                   },
                   "non-manifold edge (vertices", nullptr},
        BrokenCase{"degenerateFaces", Format::PlyAscii,
                   [](TriangleMesh& m) {
                       const int twin = m.numVertices();
                       m.vertices.conservativeResize(3, twin + 1);
                       m.vertices.col(twin) = m.vertices.col(kMid);  // merged into kMid -> repeated index
                       m.triangles.push_back({kMid, kMid + 1, twin});
                       m.triangles.push_back({kMid, kMid, kMid + 1});
                   },
                   nullptr,
                   [](const MeshRepairReport& r) {
                       EXPECT_EQ(r.numDegenerateFacesRemoved, 2);
                       EXPECT_EQ(r.numMergedVertices, 1);
                   }},
        BrokenCase{"globallyInverted", Format::StlBinary,
                   [](TriangleMesh& m) {
                       for (auto& t : m.triangles)
                           std::swap(t[1], t[2]);
                   },
                   nullptr, [](const MeshRepairReport& r) { EXPECT_TRUE(r.globallyFlipped); }},
        BrokenCase{"someFacesInverted", Format::Obj,
                   [](TriangleMesh& m) {
                       for (std::size_t f = 1000; f < 1400; f += 3)
                           std::swap(m.triangles[f][1], m.triangles[f][2]);
                   },
                   nullptr, [](const MeshRepairReport& r) { EXPECT_GT(r.numFacesReoriented, 0); }},
        BrokenCase{"twoComponents", Format::PlyBinary,
                   [](TriangleMesh& m) {
                       const int n = m.numVertices();
                       const auto numTriangles = m.triangles.size();
                       m.vertices.conservativeResize(3, 2 * n);
                       m.vertices.rightCols(n) =
                           m.vertices.leftCols(n).colwise() + Eigen::Vector3d(1.0, 0.0, 0.0);
                       for (std::size_t f = 0; f < numTriangles; ++f) {
                           const auto t = m.triangles[f];
                           m.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
                       }
                   },
                   "2 connected components (allowed: 1)", nullptr},
        BrokenCase{"nanCoordinateObj", Format::Obj,
                   [](TriangleMesh& m) { m.vertices(1, 7) = std::numeric_limits<double>::quiet_NaN(); },
                   "non-finite coordinate", nullptr},
        BrokenCase{"infCoordinateStl", Format::StlBinary,
                   [](TriangleMesh& m) { m.vertices(2, 9) = std::numeric_limits<double>::infinity(); },
                   "non-finite coordinate", nullptr}),
    [](const auto& info) { return std::string(info.param.name); });

struct RawFileCase {
    const char* name;
    const char* fileName;
    std::string bytes;
    const char* expectedError;
};

class RawFile : public ::testing::TestWithParam<RawFileCase> {};

TEST_P(RawFile, IsRefusedWithoutCrashing)
{
    const auto path = tempDir() / GetParam().fileName;
    {
        std::ofstream out(path, std::ios::binary);
        out << GetParam().bytes;
    }
    try {
        (void)importMesh(path);
        FAIL() << "accepted";
    } catch (const MeshImportError& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.rfind(GetParam().fileName, 0), 0u) << "starts with the file name: " << message;
        EXPECT_NE(message.find(GetParam().expectedError), std::string::npos) << message;
    }
}

std::string junk(std::size_t n)
{
    std::mt19937 random(42);
    std::string bytes(n, '\0');
    for (char& c : bytes)
        c = static_cast<char>(random() & 0xff);
    return bytes;
}

INSTANTIATE_TEST_SUITE_P(Files, RawFile,
                         ::testing::Values(RawFileCase{"emptyObj", "empty.obj", "", "empty file"},
                                           RawFileCase{"junkStl", "junk.stl", junk(4000), ": "},
                                           RawFileCase{"junkPly", "junk.ply", junk(4000), ": "},
                                           RawFileCase{"junkObj", "junk.obj", junk(4000), ": "},
                                           RawFileCase{"unknownExtension", "tube.xyz", "v 0 0 0\n",
                                                       "unknown extension '.xyz'"},
                                           RawFileCase{"missing", "missing.obj", "", "empty file"}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace colonosim::geometry
