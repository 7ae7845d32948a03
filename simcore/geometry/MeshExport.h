#pragma once
/// \file
/// Writes a TriangleMesh as Wavefront OBJ, STL (ASCII or binary, little
/// endian, float32) or PLY (ASCII or binary_little_endian). Used to export
/// anatomies for inspection and to generate import fixtures at test time.
/// Throws std::runtime_error naming the file when it cannot be written.

#include "simcore/geometry/TriangleMesh.h"

#include <filesystem>

namespace colonosim::geometry {

enum class MeshEncoding { Ascii, Binary };

void writeObj(const std::filesystem::path& path, const TriangleMesh& mesh);
void writeStl(const std::filesystem::path& path, const TriangleMesh& mesh, MeshEncoding encoding);
void writePly(const std::filesystem::path& path, const TriangleMesh& mesh, MeshEncoding encoding);

}  // namespace colonosim::geometry
