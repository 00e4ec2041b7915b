#pragma once
// Random public identifiers: a prefix and 20 characters of Crockford base32 (100 random bits),
// e.g. "crd_8f3k2m…" for cards and "job_…" for jobs. Not part of any deterministic output.
#include <string>
#include <string_view>

namespace socsim {

std::string random_id(std::string_view prefix);
// True when `s` is prefix + 20 Crockford base32 characters.
bool is_random_id(std::string_view s, std::string_view prefix);
// Current UTC time as 2026-11-21T07:26:08.123Z.
std::string utc_now_rfc3339();

}  // namespace socsim
