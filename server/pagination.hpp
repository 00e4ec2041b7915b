#pragma once
// The page parameters of every list (?page_size=, ?cursor=), read one way everywhere:
// page_size an integer in [1, max_page_size] (the default when absent), else 422 naming it;
// a cursor this server did not issue is 400 naming it. Transport-free: handlers pass the raw
// query values, so the same rules hold whatever reads the request.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/common/error.hpp"

namespace socsim::server {

struct PageParams {
  std::size_t page_size = 20;
  std::optional<std::string> cursor;  // syntactically plausible; each list checks it is one it issued
};

Result<PageParams> parse_page(const std::optional<std::string>& page_size,
                              const std::optional<std::string>& cursor, std::size_t default_page_size,
                              std::size_t max_page_size);

// 400 at ?cursor: the answer for any cursor a list cannot place.
Error bad_cursor();

// Cursors of the form <prefix><n> (n a decimal sequence number, as worlds "w1." and jobs "j1." issue).
Result<std::int64_t> parse_sequence_cursor(const std::string& cursor, std::string_view prefix);

}  // namespace socsim::server
