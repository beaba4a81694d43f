// The four mesh formats' readers, one file each (core/mesh_io/read_*.cpp). `src` names the
// file in errors; `text`/`data` is its whole content. Each throws InvalidInputError naming
// the file and the line or byte. Internal to core's mesh I/O: callers use core/mesh_io.h.
#pragma once

#include "core/mesh_io.h"

#include <string>
#include <string_view>

namespace holebench::mesh_io {

TriangleSoup read_off(const std::string& src, std::string_view text);
TriangleSoup read_obj(const std::string& src, std::string_view text);
TriangleSoup read_stl(const std::string& src, std::string_view data);
TriangleSoup read_ply(const std::string& src, std::string_view data);

}  // namespace holebench::mesh_io
