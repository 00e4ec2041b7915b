// socsim: the daemon (`socsim serve`) and the offline commands that call the same core.
#include <csignal>
#include <iostream>
#include <string>
#include <vector>

#include "server/cli/cli.hpp"

int main(int argc, char** argv) {
  std::signal(SIGPIPE, SIG_IGN);
  std::vector<std::string> args(argv + 1, argv + argc);
  return socsim::server::run_cli(args);
}
