#pragma once
// The `socsim` command line: serve, card, migrate, version.
#include <string>
#include <vector>

namespace socsim::server {

int run_cli(const std::vector<std::string>& args);
int run_serve(const std::vector<std::string>& args);
int run_card_command(const std::vector<std::string>& args);

}  // namespace socsim::server
