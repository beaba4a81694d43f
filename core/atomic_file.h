// Writing a file so that a reader never sees half of it: the text goes to a temporary file
// beside the target (`<path>.partial`), is flushed to disk, and is renamed over the target
// only once complete. A process killed while writing (SIGKILL, a power cut after the rename
// is durable) leaves either the old file or the new one, never a mix; a failed write (disk
// full, a read-only folder) leaves the old file and throws an error naming the file and the
// reason.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace holebench {

/// Writes what `write` puts into the stream to `path`, atomically (see above). Throws
/// std::runtime_error "cannot write PATH: REASON" on failure; the temporary file is removed.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

/// The same for a text known in full.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace holebench
