#include "core/interop/tar_archive.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace socsim::interop {

namespace {

void put(char* field, std::size_t size, const std::string& text) {
  std::memcpy(field, text.data(), std::min(size, text.size()));
}

// Octal number, zero-padded to size-1 digits and NUL-terminated.
void octal(char* field, std::size_t size, unsigned long long value) {
  std::string digits(size - 1, '0');
  for (std::size_t i = size - 1; i-- > 0 && value > 0; value >>= 3)
    digits[i] = static_cast<char>('0' + (value & 7));
  std::memcpy(field, digits.data(), size - 1);
  field[size - 1] = '\0';
}

}  // namespace

Result<std::string> tar_archive(const std::vector<ExportFile>& files) {
  std::string out;
  for (const ExportFile& f : files) {
    const std::string& path = f.path;
    if (path.empty() || path.front() == '/' || path.find("..") != std::string::npos)
      return fail(ErrorCode::kValidation, "cannot archive path '" + path + "'");
    std::string prefix;
    std::string name = path;
    if (name.size() > 100) {
      const auto slash = path.rfind('/', 155);
      if (slash == std::string::npos || path.size() - slash - 1 > 100)
        return fail(ErrorCode::kValidation, "path too long for a tar archive: '" + path + "'");
      prefix = path.substr(0, slash);
      name = path.substr(slash + 1);
    }
    char h[512] = {};
    put(h, 100, name);
    octal(h + 100, 8, 0644);
    octal(h + 108, 8, 0);
    octal(h + 116, 8, 0);
    octal(h + 124, 12, f.content.size());
    octal(h + 136, 12, 0);
    h[156] = '0';
    put(h + 257, 6, std::string("ustar\0", 6));
    put(h + 263, 2, "00");
    put(h + 265, 32, "socsim");
    put(h + 297, 32, "socsim");
    put(h + 345, 155, prefix);
    std::memset(h + 148, ' ', 8);
    unsigned sum = 0;
    for (unsigned char c : h) sum += c;
    octal(h + 148, 7, sum);
    h[155] = ' ';
    out.append(h, sizeof h);
    out += f.content;
    out.append((512 - f.content.size() % 512) % 512, '\0');
  }
  out.append(1024, '\0');
  return out;
}

}  // namespace socsim::interop
