#include "core/interop/trajectory_csv.hpp"

#include <charconv>

namespace socsim::interop {

namespace {

template <class T>
void put_number(std::string& out, T v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, ec == std::errc() ? end : buf);
}

}  // namespace

std::string trajectories_csv(const scenario::TrajectoryLog& log) {
  std::string out = "t,id,x,y,vx,vy,state,role,group_id\n";
  const auto& roles = log.roles();
  for (std::size_t i = 0; i < log.frame_count(); ++i) {
    const double t = log.frame_time(i);
    for (const scenario::LoggedAgent& a : log.frame(i)) {
      put_number(out, t);
      out += ',';
      put_number(out, a.id);
      for (float v : {a.x, a.y, a.vx, a.vy}) {
        out += ',';
        put_number(out, v);
      }
      out += ',';
      out += crowd::activity_name(a.activity);
      out += ',';
      out += a.role < roles.size() ? roles[a.role] : std::string("unknown");
      out += ',';
      put_number(out, a.group_id);
      out += '\n';
    }
  }
  return out;
}

}  // namespace socsim::interop
