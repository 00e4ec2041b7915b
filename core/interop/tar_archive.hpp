#pragma once
// Export files as one POSIX ustar archive (what `tar xf` unpacks): regular files, mode 0644,
// owner 0, mtime 0, so the same files always give the same bytes.
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/interop/export_hunav.hpp"

namespace socsim::interop {

// kValidation for a path that ustar cannot hold (over 100 bytes of name after a 155-byte directory
// prefix), an absolute path or one with "..".
Result<std::string> tar_archive(const std::vector<ExportFile>& files);

}  // namespace socsim::interop
