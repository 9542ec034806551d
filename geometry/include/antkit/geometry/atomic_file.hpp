#pragma once
// Output files appear whole or not at all (DESIGN.md, Errors): the content is written to a
// temporary file beside the target, flushed, and renamed over it. On any failure the temporary file
// is removed and the target is left as it was.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

namespace antkit::geometry {

// Throws antkit::kernel::InputError (where = the path) when the file cannot be written.
void write_file_atomic(const std::filesystem::path& path,
                       const std::function<void(std::ostream&)>& write);
void write_file_atomic(const std::filesystem::path& path, std::string_view content);

} // namespace antkit::geometry
