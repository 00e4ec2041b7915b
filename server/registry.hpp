#pragma once
// Route groups and CLI commands register themselves from their own files (routes_*.cpp,
// cli_*.cpp), so adding a capability is adding a file. socsim_server is an object library, so
// every registration is linked in.
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace socsim::server {

class Router;
struct RouteContext;

using RouteRegistrar = std::function<void(Router&, RouteContext&)>;
using CommandFn = std::function<int(const std::vector<std::string>& args)>;

struct CommandInfo {
  std::string usage;  // one or more lines for `socsim --help`
  CommandFn run;
};

std::map<std::string, RouteRegistrar>& route_groups();
std::map<std::string, CommandInfo>& commands();

struct RegisterRoutes {
  RegisterRoutes(const char* name, RouteRegistrar fn) { route_groups()[name] = std::move(fn); }
};
struct RegisterCommand {
  RegisterCommand(const char* name, const char* usage, CommandFn fn) {
    commands()[name] = {usage, std::move(fn)};
  }
};

}  // namespace socsim::server

#define SOCSIM_CAT2_(a, b) a##b
#define SOCSIM_CAT_(a, b) SOCSIM_CAT2_(a, b)
// SOCSIM_ROUTES("cards", [](Router& http, RouteContext& ctx) { http.Get(...); });
#define SOCSIM_ROUTES(name, fn) \
  static const ::socsim::server::RegisterRoutes SOCSIM_CAT_(socsim_routes_, __COUNTER__)(name, fn)
// SOCSIM_COMMAND("card", "  card list …\n", [](const std::vector<std::string>& args) { return 0; });
// A two-word name ("scenario generate") registers one subcommand; args then start after both words.
#define SOCSIM_COMMAND(name, usage, fn) \
  static const ::socsim::server::RegisterCommand SOCSIM_CAT_(socsim_command_, __COUNTER__)(name, usage, fn)
