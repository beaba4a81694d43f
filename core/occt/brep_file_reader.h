// Reading a B-Rep file (STEP, IGES, BREP) into an OpenCASCADE shape, with OpenCASCADE's
// console messages silenced and every failure turned into a one-line InvalidInputError.
#pragma once

// Before any OpenCASCADE header: OpenCASCADE's `Handle` macro breaks OpenMesh's headers.
#include "core/occt/brep_mesh.h"

#include <TopoDS_Shape.hxx>

#include <filesystem>

namespace holebench::occt {

/// Removes the console printers of OpenCASCADE's default messenger (it writes to stdout,
/// where holebench's own output goes). Idempotent and thread-safe.
void silence_opencascade_messages();

/// The shape in `path`, chosen by its extension (.step/.stp, .iges/.igs, .brep/.brp; any
/// case): for STEP and IGES all transferable roots as one shape. Throws InvalidInputError
/// naming the file: missing, unknown extension, not readable as its format (naming
/// OpenCASCADE's read status), or a file with no face.
TopoDS_Shape read_brep_shape(const std::filesystem::path& path);

}  // namespace holebench::occt
