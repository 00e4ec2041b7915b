#pragma once
// The `socsim` command line. Each command registers itself (SOCSIM_COMMAND, server/registry.hpp);
// these helpers parse options the same way for all of them.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/common/error.hpp"

namespace socsim::server {

int run_cli(const std::vector<std::string>& args);

// "--key value", "--key=value" and "-o value" options, and positional words.
struct CliArgs {
  std::vector<std::string> words;
  std::map<std::string, std::string> options;
  [[nodiscard]] std::optional<std::string> opt(const std::string& key) const;
  [[nodiscard]] bool flag(const std::string& key) const { return options.count(key) > 0; }
};
CliArgs parse_cli(const std::vector<std::string>& args);
// --db, else $SOCSIM_DB, else ./var/socsim.db
std::string cli_db_path(const CliArgs& a);
// Prints the error and returns the exit code (2 for the caller's mistakes, 1 for ours).
int cli_report(const Error& e);
// A file's bytes ("-": standard input); kNotFound "cannot read 'PATH'" when it cannot be read.
Result<std::string> cli_read_file(const std::string& path);
// Writes the bytes, creating missing parent folders; kInternal "cannot write 'PATH'" on failure.
Status cli_write_file(const std::string& path, const std::string& bytes);

}  // namespace socsim::server
