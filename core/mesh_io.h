// Reading and writing meshes: OFF, OBJ, STL (ASCII and binary) and PLY (ASCII and
// binary little/big endian), with an error for every kind of bad input.
#pragma once

#include "core/mesh.h"
#include "core/mesh_builder.h"

#include <filesystem>
#include <string>

namespace holebench {

enum class MeshFormat { Off, Obj, StlAscii, StlBinary, PlyAscii, PlyBinary };

/// The format implied by a file name's extension (.off .obj .stl .ply, any case);
/// STL and PLY map to their binary forms. Throws InvalidInputError for others.
MeshFormat format_from_extension(const std::filesystem::path& path);

struct WriteOptions {
  bool binary = true;         ///< for STL and PLY: binary (default) or ASCII
  bool write_regions = true;  ///< PLY: a per-face int "region" property
};

/// Reads a triangle soup. Polygons with more than three corners are split into a fan.
/// Throws InvalidInputError naming the file and, where it applies, the line (text
/// formats) or byte offset (binary formats): missing or unreadable file, unknown
/// extension, not a mesh of that format, truncated content, unparsable numbers.
TriangleSoup read_soup(const std::filesystem::path& path);

/// read_soup followed by build_mesh (all the topology and geometry checks).
/// STL vertices are merged where their coordinates are identical.
/// A PLY face property "region" (int) is read as the region id.
Mesh read_mesh(const std::filesystem::path& path);

/// Writes `mesh` in the format of the path's extension. Coordinates are written with
/// 17 significant digits in text formats, so text round trips are exact; binary STL
/// stores floats. Throws std::runtime_error when the file cannot be written.
void write_mesh(const Mesh& mesh, const std::filesystem::path& path,
                const WriteOptions& options = {});

}  // namespace holebench
