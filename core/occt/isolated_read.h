// Reading a B-Rep file in a child process: OpenCASCADE dereferences null handles on some
// damaged STEP, IGES and BREP files (found by the fuzz targets fuzz_brep_*: for example in
// StepShape_FaceBound::Bound, IGESSolid_Face::NbLoops, Geom2d_OffsetCurve::SetBasisCurve)
// instead of reporting an error. A segmentation fault in the library would end holebench
// (the case catalog reads `--mesh` files in the main process). The child reads and
// tessellates the file and sends the welded triangles back through a pipe; a child that
// dies becomes an InvalidInputError naming the file and the signal; one that runs past the
// time limit (OpenCASCADE loops on other damaged files) is killed, with an error too.
#pragma once

// Before any OpenCASCADE header: OpenCASCADE's `Handle` macro breaks OpenMesh's headers.
#include "core/occt/shape_tessellation.h"

#include <filesystem>

namespace holebench::occt {

/// read_brep_shape, sew_free_edges (where options.sewing_tolerance_rel_diag > 0; its note
/// first in TessellatedSoup::notes) and tessellate_shape_soup of `path`, in a child process
/// (fork). Throws
/// InvalidInputError naming the file: the child's own InvalidInputError, or "OpenCASCADE
/// crashed reading it (SIGNAL)" for a child that died, "did not finish reading it" for one
/// that ran past options.time_limit_seconds (it is killed). The result is the same, bit for
/// bit, as reading in this process.
TessellatedSoup read_and_tessellate_isolated(const std::filesystem::path& path,
                                             const TessellationOptions& options);

}  // namespace holebench::occt
