#include "simcore/geometry/MeshExport.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace colonosim::geometry {

namespace {

std::ofstream openFor(const std::filesystem::path& path, std::ios::openmode mode)
{
    std::ofstream out(path, mode);
    if (!out) {
        throw std::runtime_error(path.string() + ": cannot open for writing");
    }
    out.precision(17);
    return out;
}

template <class T>
void put(std::ofstream& out, T value)
{
    out.write(reinterpret_cast<const char*>(&value), sizeof(T));  // little-endian hosts only (x86-64, arm64)
}

Eigen::Vector3d faceNormal(const TriangleMesh& mesh, const std::array<int, 3>& t)
{
    const Eigen::Vector3d a = mesh.vertices.col(t[0]);
    const Eigen::Vector3d n = (mesh.vertices.col(t[1]) - a).cross(mesh.vertices.col(t[2]) - a);
    const double len = n.norm();
    return len > 0.0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
}

}  // namespace

void writeObj(const std::filesystem::path& path, const TriangleMesh& mesh)
{
    std::ofstream out = openFor(path, std::ios::out);
    for (Eigen::Index i = 0; i < mesh.vertices.cols(); ++i) {
        out << "v " << mesh.vertices(0, i) << ' ' << mesh.vertices(1, i) << ' ' << mesh.vertices(2, i)
            << '\n';
    }
    for (const auto& t : mesh.triangles) {
        out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    }
}

void writeStl(const std::filesystem::path& path, const TriangleMesh& mesh, MeshEncoding encoding)
{
    if (encoding == MeshEncoding::Ascii) {
        std::ofstream out = openFor(path, std::ios::out);
        out << "solid colonosim\n";
        for (const auto& t : mesh.triangles) {
            const Eigen::Vector3d n = faceNormal(mesh, t);
            out << "facet normal " << n.x() << ' ' << n.y() << ' ' << n.z() << "\nouter loop\n";
            for (int k : t) {
                out << "vertex " << mesh.vertices(0, k) << ' ' << mesh.vertices(1, k) << ' '
                    << mesh.vertices(2, k) << '\n';
            }
            out << "endloop\nendfacet\n";
        }
        out << "endsolid colonosim\n";
        return;
    }
    std::ofstream out = openFor(path, std::ios::out | std::ios::binary);
    const std::string header(80, ' ');
    out.write(header.data(), 80);
    put(out, static_cast<std::uint32_t>(mesh.triangles.size()));
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d n = faceNormal(mesh, t);
        for (int c = 0; c < 3; ++c)
            put(out, static_cast<float>(n[c]));
        for (int k : t) {
            for (int c = 0; c < 3; ++c)
                put(out, static_cast<float>(mesh.vertices(c, k)));
        }
        put(out, std::uint16_t{0});
    }
}

void writePly(const std::filesystem::path& path, const TriangleMesh& mesh, MeshEncoding encoding)
{
    const bool binary = encoding == MeshEncoding::Binary;
    std::ofstream out = openFor(path, binary ? std::ios::out | std::ios::binary : std::ios::out);
    out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
        << "element vertex " << mesh.vertices.cols()
        << "\nproperty double x\nproperty double y\nproperty double z\n"
        << "element face " << mesh.triangles.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (Eigen::Index i = 0; i < mesh.vertices.cols(); ++i) {
        if (binary) {
            for (int c = 0; c < 3; ++c)
                put(out, mesh.vertices(c, i));
        } else {
            out << mesh.vertices(0, i) << ' ' << mesh.vertices(1, i) << ' ' << mesh.vertices(2, i) << '\n';
        }
    }
    for (const auto& t : mesh.triangles) {
        if (binary) {
            put(out, std::uint8_t{3});
            for (int k : t)
                put(out, static_cast<std::int32_t>(k));
        } else {
            out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
        }
    }
}

}  // namespace colonosim::geometry
