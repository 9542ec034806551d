#pragma once
// Output files appear whole or not at all (DESIGN.md, Errors): the content is written to a
// temporary file beside the target, flushed, and renamed over it. On any failure the temporary file
// is removed and the target is left as it was.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

namespace antkit::io {

// Throws antkit::kernel::InputError (where = the path) when the file cannot be written.
void write_file_atomic(const std::filesystem::path& path,
                       const std::function<void(std::ostream&)>& write);
void write_file_atomic(const std::filesystem::path& path, std::string_view content);

// The same for a writer that opens the file itself by its name (Cairo's SVG and PNG surfaces):
// `write` is given the temporary file's name beside `path` and writes it whole; it is then renamed
// over `path`. When `write` throws or the rename fails the temporary file is removed and `path`
// left as it was; a failed rename throws InputError(path, "cannot rename into place: ...").
void write_file_atomic_at(const std::filesystem::path& path,
                          const std::function<void(const std::filesystem::path& temporary)>& write);

} // namespace antkit::io
