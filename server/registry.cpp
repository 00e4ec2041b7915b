#include "server/registry.hpp"

namespace socsim::server {

std::map<std::string, RouteRegistrar>& route_groups() {
  static std::map<std::string, RouteRegistrar> groups;
  return groups;
}

std::map<std::string, CommandInfo>& commands() {
  static std::map<std::string, CommandInfo> all;
  return all;
}

}  // namespace socsim::server
