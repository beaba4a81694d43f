// Parts built in code with OpenCASCADE for the B-Rep reading tests, so CI needs no download:
// each has planar and curved faces of known types and is written to STEP, IGES or BREP by the
// tests themselves.
#pragma once

// First: it includes OpenMesh before OpenCASCADE, whose `Handle` macro breaks OpenMesh.
#include "core/occt/brep_file_reader.h"

#include <TopoDS_Shape.hxx>

#include <filesystem>
#include <string>
#include <vector>

namespace holebench::occt::test {

struct TestPart {
  std::string name;
  TopoDS_Shape shape;
};

/// A 40 x 30 x 20 block with a 12 x 10 x 8 pocket in its top face and a through hole of
/// radius 4 along z (11 planar faces, 1 cylindrical).
TopoDS_Shape block_with_pocket_and_hole();

/// An L-shaped prism (legs 40 and 30, thickness 8, depth 20) with a fillet of radius 4 on
/// its reflex edge.
TopoDS_Shape l_bracket_with_fillet();

/// Three coaxial cylinders of radii 10, 7 and 4 and lengths 20, 15 and 10, fused.
TopoDS_Shape stepped_shaft();

/// A 60 x 40 x 5 plate with a cylindrical boss (radius 6, height 10) and a conical boss
/// (radii 6 and 3, height 8) on top.
TopoDS_Shape plate_with_bosses();

/// The four parts above, by name.
std::vector<TestPart> test_parts();

/// A fifth part for the face-removal family: a 60 x 40 x 20 block with a triangular pad (height
/// 5) on its top and a triangular pocket (depth 6) in it, and three 3 x 3 x 3 cubes fused flush
/// into it that split its faces into coplanar faces (as CAD models built by fusing often are):
/// a square inside the top face, one on the top-front edge (a square in the top and one in the
/// front) and one at the top-front-right corner (a square in each of the three faces).
TopoDS_Shape block_with_pad_pocket_and_split_faces();

/// Writes `shape` as STEP (AP214, the writer's default) to `path`; throws on failure.
void write_step(const TopoDS_Shape& shape, const std::filesystem::path& path);

/// Writes `shape` as IGES with B-Rep entities (a solid, not loose faces); throws on failure.
void write_iges(const TopoDS_Shape& shape, const std::filesystem::path& path);

/// Writes each face of `shape` as its own IGES trimmed surface (entity 144), with edges shared
/// with no other face: the faces are not sewn into a shell, as in the IGES files of many CAD
/// part libraries. Throws on failure.
void write_iges_unsewn(const TopoDS_Shape& shape, const std::filesystem::path& path);

/// A fresh folder below the system's temporary folder, named after `name`.
std::filesystem::path fresh_temp_dir(const std::string& name);

}  // namespace holebench::occt::test
