// Writing an output file so that, whatever happens (a full disk, an I/O error, another
// process writing the same name, a crash), the target holds either its old contents or
// the complete new file, never a torn or empty one, and no temporary is left behind:
// the bytes go to a temporary file in the same folder (a name unique to this process),
// every write, the fsync and the close are checked, the temporary is renamed over the
// target, and the folder is synced so that the rename itself is durable.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace facet {

// The temporary file beside `path` that a safe write of it uses: hidden, unique to this
// process and call, at most NAME_MAX bytes long (a long name is shortened), and ending
// with the target's extension (OpenImageIO picks the format from it).
std::string temporary_path_for(const std::string& path);

// Writes `path` through `write`, which must create the file it is given (a temporary
// beside `path`) and throw facet::Error on failure. Then syncs it, calls `verify` on it
// when given (e.g. reading an image back), and renames it into place. On any failure the
// temporary is removed, the old `path` is kept, and facet::Error names `path`, `what`
// and the system's reason (never the temporary's name).
void write_file_safely(const std::string& path, const std::string& what,
                       const std::function<void(const std::string& tmp)>& write,
                       const std::function<void(const std::string& tmp)>& verify = {});

// write_file_safely for bytes in memory (text reports, films, cache entries).
void write_bytes_safely(const std::string& path, const std::string& what, std::string_view bytes);

// Checks, before any work, that `path` can be written as an output: not a folder, not a
// device or other special file, a name within NAME_MAX, and a folder (created when
// missing) in which a temporary can be created and removed. Throws facet::Error starting
// with `option` and the path.
void check_output_path(const std::string& path, const std::string& option);

}  // namespace facet
