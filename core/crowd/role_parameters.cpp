#include "core/crowd/role_parameters.hpp"

#include <cmath>

#include "core/common/json_check.hpp"

namespace socsim::crowd {
namespace {

struct Range {
  const char* pointer;
  double value;
  double lo;
  double hi;
  bool lo_open;
};

void check_ranges(JsonChecker& check, const std::string& base, std::initializer_list<Range> ranges) {
  for (const Range& r : ranges) {
    const bool ok =
        std::isfinite(r.value) && (r.lo_open ? r.value > r.lo : r.value >= r.lo) && r.value <= r.hi;
    if (!ok)
      check.add(base + r.pointer, "must be a finite number in " + std::string(r.lo_open ? "(" : "[") +
                                      std::to_string(r.lo) + ", " + std::to_string(r.hi) + "]");
  }
}

void read(JsonChecker& check, const Json& obj, const std::string& ptr, std::string_view key, double& field) {
  if (auto v = check.number(obj, ptr, key, false)) field = *v;
}

RoleParameters role(std::string name, SpeedDistribution speed, double radius) {
  RoleParameters r;
  r.name = std::move(name);
  r.speed = speed;
  r.radius = radius;
  return r;
}

}  // namespace

Status validate(const RoleParameters& r, const std::string& p) {
  JsonChecker check;
  if (r.name.empty() || r.name.size() > 64) check.add(p + "/name", "must have 1 to 64 characters");
  const ForceParameters& f = r.forces;
  check_ranges(check, p,
               {
                   {"/speed/mean", r.speed.mean, 0.0, kMaxAgentSpeed, false},
                   {"/speed/sd", r.speed.sd, 0.0, 5.0, false},
                   {"/speed/min", r.speed.min, 0.0, kMaxAgentSpeed, false},
                   {"/speed/max", r.speed.max, 0.0, kMaxAgentSpeed, false},
                   {"/radius", r.radius, 0.05, 1.5, false},
                   {"/max_speed_factor", r.max_speed_factor, 0.0, 3.0, true},
                   {"/forces/desired_factor", f.desired_factor, 0.0, 100.0, false},
                   {"/forces/obstacle_factor", f.obstacle_factor, 0.0, 1000.0, false},
                   {"/forces/obstacle_sigma", f.obstacle_sigma, 0.01, 5.0, false},
                   {"/forces/social_factor", f.social_factor, 0.0, 1000.0, false},
                   {"/forces/group_gaze_factor", f.group_gaze_factor, 0.0, 100.0, false},
                   {"/forces/group_coherence_factor", f.group_coherence_factor, 0.0, 100.0, false},
                   {"/forces/group_repulsion_factor", f.group_repulsion_factor, 0.0, 100.0, false},
                   {"/forces/lambda", f.lambda, 0.0, 100.0, false},
                   {"/forces/gamma", f.gamma, 0.0, 100.0, true},
                   {"/forces/n", f.n, 0.0, 100.0, false},
                   {"/forces/n_prime", f.n_prime, 0.0, 100.0, false},
                   {"/forces/relaxation_time", f.relaxation_time, 0.01, 100.0, false},
                   {"/forces/headway_distance", f.headway_distance, 0.0, 10.0, false},
                   {"/forces/headway_time", f.headway_time, 0.0, 100.0, false},
                   {"/forces/headway_band", f.headway_band, 0.0, 10.0, false},
                   {"/forces/headway_anticipation", f.headway_anticipation, 0.0, 100.0, false},
                   {"/forces/zipper_band", f.zipper_band, 0.0, 10.0, false},
                   {"/forces/zipper_reach", f.zipper_reach, 0.0, 10.0, false},
                   {"/forces/side_factor", f.side_factor, 0.0, 100.0, false},
                   {"/forces/side_range", f.side_range, 0.01, 100.0, false},
                   {"/forces/side_bias", f.side_bias, -10.0, 10.0, false},
                   {"/forces/side_band", f.side_band, 0.0, 10.0, false},
                   {"/proxemics/intimate_radius", r.proxemics.intimate_radius, 0.0, 100.0, false},
                   {"/proxemics/comfort_radius", r.proxemics.comfort_radius, 0.0, 100.0, false},
                   {"/proxemics/social_radius", r.proxemics.social_radius, 0.0, 100.0, false},
                   {"/proxemics/compliance", r.proxemics.compliance, 0.0, 1.0, false},
               });
  if (r.speed.min > r.speed.max) check.add(p + "/speed/min", "must not exceed speed.max");
  if (r.speed.max * r.max_speed_factor > kMaxAgentSpeed)
    check.add(p + "/max_speed_factor",
              "speed.max × max_speed_factor must not exceed " + std::to_string(kMaxAgentSpeed) + " m/s");
  if (!(r.proxemics.intimate_radius <= r.proxemics.comfort_radius &&
        r.proxemics.comfort_radius <= r.proxemics.social_radius))
    check.add(p + "/proxemics", "radii must satisfy intimate_radius <= comfort_radius <= social_radius");
  if (!check.ok()) return tl::unexpected(check.error("invalid role parameters for '" + r.name + "'"));
  return {};
}

Json to_json(const RoleParameters& r) {
  const ForceParameters& f = r.forces;
  return Json{
      {"name", r.name},
      {"speed", {{"mean", r.speed.mean}, {"sd", r.speed.sd}, {"min", r.speed.min}, {"max", r.speed.max}}},
      {"radius", r.radius},
      {"max_speed_factor", r.max_speed_factor},
      {"forces",
       {{"desired_factor", f.desired_factor},
        {"obstacle_factor", f.obstacle_factor},
        {"obstacle_sigma", f.obstacle_sigma},
        {"social_factor", f.social_factor},
        {"group_gaze_factor", f.group_gaze_factor},
        {"group_coherence_factor", f.group_coherence_factor},
        {"group_repulsion_factor", f.group_repulsion_factor},
        {"lambda", f.lambda},
        {"gamma", f.gamma},
        {"n", f.n},
        {"n_prime", f.n_prime},
        {"relaxation_time", f.relaxation_time},
        {"headway_distance", f.headway_distance},
        {"headway_time", f.headway_time},
        {"headway_band", f.headway_band},
        {"headway_anticipation", f.headway_anticipation},
        {"zipper_band", f.zipper_band},
        {"zipper_reach", f.zipper_reach},
        {"side_factor", f.side_factor},
        {"side_range", f.side_range},
        {"side_bias", f.side_bias},
        {"side_band", f.side_band}}},
      {"proxemics",
       {{"intimate_radius", r.proxemics.intimate_radius},
        {"comfort_radius", r.proxemics.comfort_radius},
        {"social_radius", r.proxemics.social_radius},
        {"compliance", r.proxemics.compliance}}},
  };
}

Result<RoleParameters> role_parameters_from_json(const Json& j, const RoleParameters& base,
                                                 const std::string& p) {
  JsonChecker check;
  RoleParameters r = base;
  if (!j.is_object()) {
    check.add(p, std::string("must be an object, not ") + j.type_name());
    return tl::unexpected(check.error("invalid role parameters"));
  }
  check.only_keys(j, p, {"name", "speed", "radius", "max_speed_factor", "forces", "proxemics"});
  if (auto name = check.string(j, p, "name", false, 1, 64)) r.name = *name;
  if (const Json* s = check.object(j, p, "speed", false)) {
    const std::string sp = JsonChecker::child(p, "speed");
    check.only_keys(*s, sp, {"mean", "sd", "min", "max"});
    read(check, *s, sp, "mean", r.speed.mean);
    read(check, *s, sp, "sd", r.speed.sd);
    read(check, *s, sp, "min", r.speed.min);
    read(check, *s, sp, "max", r.speed.max);
  }
  read(check, j, p, "radius", r.radius);
  read(check, j, p, "max_speed_factor", r.max_speed_factor);
  if (const Json* f = check.object(j, p, "forces", false)) {
    const std::string fp = JsonChecker::child(p, "forces");
    check.only_keys(*f, fp,
                    {"desired_factor",
                     "obstacle_factor",
                     "obstacle_sigma",
                     "social_factor",
                     "group_gaze_factor",
                     "group_coherence_factor",
                     "group_repulsion_factor",
                     "lambda",
                     "gamma",
                     "n",
                     "n_prime",
                     "relaxation_time",
                     "headway_distance",
                     "headway_time",
                     "headway_band",
                     "headway_anticipation",
                     "zipper_band",
                     "zipper_reach",
                     "side_factor",
                     "side_range",
                     "side_bias",
                     "side_band"});
    ForceParameters& x = r.forces;
    read(check, *f, fp, "desired_factor", x.desired_factor);
    read(check, *f, fp, "obstacle_factor", x.obstacle_factor);
    read(check, *f, fp, "obstacle_sigma", x.obstacle_sigma);
    read(check, *f, fp, "social_factor", x.social_factor);
    read(check, *f, fp, "group_gaze_factor", x.group_gaze_factor);
    read(check, *f, fp, "group_coherence_factor", x.group_coherence_factor);
    read(check, *f, fp, "group_repulsion_factor", x.group_repulsion_factor);
    read(check, *f, fp, "lambda", x.lambda);
    read(check, *f, fp, "gamma", x.gamma);
    read(check, *f, fp, "n", x.n);
    read(check, *f, fp, "n_prime", x.n_prime);
    read(check, *f, fp, "relaxation_time", x.relaxation_time);
    read(check, *f, fp, "headway_distance", x.headway_distance);
    read(check, *f, fp, "headway_time", x.headway_time);
    read(check, *f, fp, "headway_band", x.headway_band);
    read(check, *f, fp, "headway_anticipation", x.headway_anticipation);
    read(check, *f, fp, "zipper_band", x.zipper_band);
    read(check, *f, fp, "zipper_reach", x.zipper_reach);
    read(check, *f, fp, "side_factor", x.side_factor);
    read(check, *f, fp, "side_range", x.side_range);
    read(check, *f, fp, "side_bias", x.side_bias);
    read(check, *f, fp, "side_band", x.side_band);
  }
  if (const Json* x = check.object(j, p, "proxemics", false)) {
    const std::string xp = JsonChecker::child(p, "proxemics");
    check.only_keys(*x, xp, {"intimate_radius", "comfort_radius", "social_radius", "compliance"});
    read(check, *x, xp, "intimate_radius", r.proxemics.intimate_radius);
    read(check, *x, xp, "comfort_radius", r.proxemics.comfort_radius);
    read(check, *x, xp, "social_radius", r.proxemics.social_radius);
    read(check, *x, xp, "compliance", r.proxemics.compliance);
  }
  // Range errors are reported together with type errors, so a client sees every problem at once.
  std::vector<FieldError> errors = check.errors();
  if (auto ok = validate(r, p); !ok)
    errors.insert(errors.end(), ok.error().errors.begin(), ok.error().errors.end());
  if (!errors.empty()) return fail(ErrorCode::kValidation, "invalid role parameters", std::move(errors));
  return r;
}

RoleTable RoleTable::defaults() {
  RoleTable t;
  // Weidmann (1993): free walking speed 1.34 ± 0.26 m/s. Radius 0.23 m: circles of that size,
  // packed hexagonally, reach Weidmann's jam density of 5.4 persons/m² (and 0.46 m is about the
  // shoulder breadth of adults); larger bodies jam a crowd long before real ones do.
  t.roles_.push_back(role("adult", {1.34, 0.26, 0.5, 2.2}, 0.23));
  // Bohannon & Williams Andrews (2011), normal gait speed, ages 80–99: 0.94–0.97 m/s.
  t.roles_.push_back(role("elderly", {0.95, 0.20, 0.4, 1.5}, 0.23));
  // Assumed: staff walk with purpose, in the upper part of Weidmann's distribution.
  t.roles_.push_back(role("staff", {1.45, 0.20, 0.8, 2.2}, 0.23));
  // Assumed: recreational jogging pace of about 10 km/h.
  t.roles_.push_back(role("jogger", {2.7, 0.4, 1.8, 4.0}, 0.23));
  // Assumed: slower than adults, with a larger footprint for the pram.
  t.roles_.push_back(role("stroller_pusher", {1.1, 0.2, 0.5, 1.6}, 0.45));
  return t;
}

Status RoleTable::put(RoleParameters r) {
  if (auto ok = validate(r); !ok) return ok;
  for (RoleParameters& existing : roles_) {
    if (existing.name == r.name) {
      existing = std::move(r);
      return {};
    }
  }
  roles_.push_back(std::move(r));
  return {};
}

Status RoleTable::apply_json(const Json& roles, const std::string& pointer) {
  if (!roles.is_object())
    return fail(ErrorCode::kValidation, "invalid roles",
                {FieldError{pointer, std::string("must be an object, not ") + roles.type_name()}});
  std::vector<FieldError> errors;
  RoleTable next = *this;
  for (const auto& [name, body] : roles.items()) {
    const std::string p = JsonChecker::child(pointer, name);
    const auto idx = index_of(name);
    RoleParameters base = idx ? at(*idx) : at(*index_of("adult"));
    base.name = name;
    auto parsed = role_parameters_from_json(body, base, p);
    if (!parsed) {
      errors.insert(errors.end(), parsed.error().errors.begin(), parsed.error().errors.end());
      continue;
    }
    if (parsed->name != name) {
      errors.push_back(FieldError{p + "/name", "must equal the key '" + name + "'"});
      continue;
    }
    (void)next.put(std::move(*parsed));
  }
  if (!errors.empty()) return fail(ErrorCode::kValidation, "invalid roles", std::move(errors));
  *this = std::move(next);
  return {};
}

std::optional<std::size_t> RoleTable::index_of(std::string_view name) const {
  for (std::size_t i = 0; i < roles_.size(); ++i)
    if (roles_[i].name == name) return i;
  return std::nullopt;
}

std::vector<std::string> RoleTable::names() const {
  std::vector<std::string> out;
  out.reserve(roles_.size());
  for (const RoleParameters& r : roles_) out.push_back(r.name);
  return out;
}

}  // namespace socsim::crowd
