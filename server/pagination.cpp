#include "server/pagination.hpp"

#include <algorithm>
#include <charconv>

namespace socsim::server {

Error bad_cursor() {
  return Error(ErrorCode::kBadRequest, "the cursor is not one this server issued",
               {{"", "use next_cursor from a previous page", "cursor", 0, 0}});
}

Result<PageParams> parse_page(const std::optional<std::string>& page_size,
                              const std::optional<std::string>& cursor, std::size_t default_page_size,
                              std::size_t max_page_size) {
  PageParams p;
  p.page_size = std::min(default_page_size, max_page_size);
  if (page_size) {
    std::size_t n = 0;
    const char* end = page_size->data() + page_size->size();
    auto [ptr, ec] = std::from_chars(page_size->data(), end, n);
    if (page_size->empty() || ec != std::errc() || ptr != end || n < 1 || n > max_page_size)
      return fail(
          ErrorCode::kValidation, "query parameter 'page_size' is out of range",
          {{"", "must be an integer between 1 and " + std::to_string(max_page_size), "page_size", 0, 0}});
    p.page_size = n;
  }
  if (cursor) {
    // Every cursor this server issues is short printable ASCII; anything else cannot be one.
    const bool plausible =
        !cursor->empty() && cursor->size() <= 256 &&
        std::all_of(cursor->begin(), cursor->end(), [](char c) { return c > 0x20 && c < 0x7f; });
    if (!plausible) return tl::unexpected(bad_cursor());
    p.cursor = *cursor;
  }
  return p;
}

Result<std::int64_t> parse_sequence_cursor(const std::string& cursor, std::string_view prefix) {
  if (cursor.size() <= prefix.size() || cursor.compare(0, prefix.size(), prefix) != 0)
    return tl::unexpected(bad_cursor());
  const std::string_view digits = std::string_view(cursor).substr(prefix.size());
  if (digits.size() > 18 || digits.find_first_not_of("0123456789") != std::string_view::npos)
    return tl::unexpected(bad_cursor());
  std::int64_t n = 0;
  std::from_chars(digits.data(), digits.data() + digits.size(), n);
  return n;
}

}  // namespace socsim::server
