#include "core/floorplan/compliance.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>

#include "core/common/text.hpp"
#include "core/floorplan/rooms.hpp"
#include "core/geometry/geos.hpp"
#include "core/geometry/hull.hpp"
#include "core/geometry/planar.hpp"
#include "core/knowledge/building_type.hpp"
#include "core/world/export_format.hpp"
#include "core/world/geodesic.hpp"

namespace socsim::floorplan {
namespace {

using knowledge::ConstraintType;
using knowledge::MergedConstraint;

constexpr double kEps = 1e-6;
// IBC 1020.4 / ADA 403.5.3: a corridor narrower than the passing-space width needs passing
// spaces at most this far apart; a corridor no longer than this is its own passing interval.
constexpr double kPassingInterval = 60.96;

// Ring without repeated closing point and without collinear vertices.
std::vector<Point> simplified_ring(const std::vector<Point>& ring) {
  std::vector<Point> r = ring;
  if (r.size() > 1 && r.front() == r.back()) r.pop_back();
  bool changed = true;
  while (changed && r.size() > 3) {
    changed = false;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Point& a = r[(i + r.size() - 1) % r.size()];
      const Point& b = r[i];
      const Point& c = r[(i + 1) % r.size()];
      const double cross = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
      const double scale = geometry::distance(a, b) * geometry::distance(b, c);
      if (std::abs(cross) <= 1e-9 * std::max(scale, 1e-12) || geometry::distance(a, b) < 1e-9) {
        r.erase(r.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
        break;
      }
    }
  }
  return r;
}

// Side lengths when the polygon is a rectangle (any orientation) without holes.
std::optional<std::pair<double, double>> rectangle_sides(const Polygon& p) {
  if (!p.holes.empty()) return std::nullopt;
  const auto r = simplified_ring(p.outer);
  if (r.size() != 4) return std::nullopt;
  for (std::size_t i = 0; i < 4; ++i) {
    const Point& a = r[(i + 3) % 4];
    const Point& b = r[i];
    const Point& c = r[(i + 1) % 4];
    const double dot = (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y);
    if (std::abs(dot) > 1e-6 * geometry::distance(a, b) * geometry::distance(b, c)) return std::nullopt;
  }
  return std::pair{geometry::distance(r[0], r[1]), geometry::distance(r[1], r[2])};
}

// Area an opening with a disc of radius r removes at the polygon's convex corners alone.
double corner_loss(const Polygon& p, double r) {
  const auto ring = simplified_ring(p.outer);
  const double orientation = geometry::signed_area(ring) >= 0 ? 1.0 : -1.0;
  double loss = 0.0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = ring[(i + n - 1) % n];
    const Point& b = ring[i];
    const Point& c = ring[(i + 1) % n];
    const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - b.x, vy = c.y - b.y;
    const double cross = (ux * vy - uy * vx) * orientation;
    if (cross <= 0) continue;  // reflex or straight
    const double turn = std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy);
    const double interior = std::numbers::pi - turn;
    loss += r * r * (1.0 / std::tan(interior / 2) - (std::numbers::pi - interior) / 2);
  }
  return loss;
}

std::string num2(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

const MergedConstraint* find(std::span<const MergedConstraint> cs, std::string_view name) {
  for (const auto& c : cs)
    if (c.constraint.name == name) return &c;
  return nullptr;
}
double value_of(std::span<const MergedConstraint> cs, std::string_view name, double fallback = 0.0) {
  const auto* c = find(cs, name);
  return c ? c->constraint.value : fallback;
}

constexpr double kUnmeasured = std::numeric_limits<double>::quiet_NaN();

struct ZoneInfo {
  std::string type;  // canonical
  double area = 0.0;
  std::optional<double> width;     // clear width, computed on demand
  std::optional<double> diameter;  // inscribed circle, computed on demand
  std::size_t desks = 0;
};

class Checker {
 public:
  Checker(const World& world, std::string_view building_type, std::span<const MergedConstraint> constraints,
          std::optional<double> occupants, ComplianceCache* cache)
      : world_(world),
        building_type_(building_type),
        constraints_(constraints),
        scenario_occupants_(occupants),
        cache_(cache) {
    for (const auto& z : world.zones())
      zones_.push_back({canonical_room_type(z.type), geometry::area(z.polygon), {}, {}, 0});
    for (const auto& e : world.entities())
      if (e.type == "desk" || e.type == "workstation") ++zones_[e.zone.index()].desks;
    residential_ = building_type_ == "residential";
    compute_occupant_load();
    area_load_ = occupant_load_;
    if (scenario_occupants_ && *scenario_occupants_ > occupant_load_) occupant_load_ = *scenario_occupants_;
  }

  // How the occupant load was found, for check details.
  [[nodiscard]] std::string load_words() const {
    if (scenario_occupants_ && *scenario_occupants_ >= area_load_ && *scenario_occupants_ > 0)
      return compact_number(occupant_load_) + " occupants (the scenario's people; the floor areas give " +
             compact_number(area_load_) + ")";
    return compact_number(occupant_load_) + " occupants";
  }

  ComplianceReport run() {
    ComplianceReport report;
    report.building_type = building_type_;
    report.occupant_load = occupant_load_;
    report.occupant_load_from_area = area_load_;
    report.scenario_occupants = scenario_occupants_;
    for (const auto& m : constraints_) {
      if (is_exit_rule(m.constraint.name)) continue;  // thresholds of exit_checks() below
      ComplianceCheck c;
      c.name = m.constraint.name;
      c.applies_to = m.constraint.applies_to;
      c.type = std::string(knowledge::to_string(m.constraint.type));
      c.required = m.constraint.value;
      c.unit = m.constraint.unit;
      c.ref_id = m.ref_id;
      c.title = m.title;
      c.jurisdiction = m.jurisdiction;
      c.confidence = m.constraint.confidence;
      for (const auto& s : m.sources) {
        if (s.section.empty()) continue;
        if (!c.section.empty()) c.section += "; ";
        c.section += s.section;
      }
      evaluate(c);
      if (c.status == CheckStatus::kFail) report.passed = false;
      report.checks.push_back(std::move(c));
    }
    // Number and separation of exits (IBC 2018 §1006.3.3, §1007.1.1), from the store's
    // single-exit limits; dwellings (IRC) need one egress door, and their entries set no limits.
    for (ComplianceCheck c : exit_checks()) {
      if (c.status == CheckStatus::kFail) report.passed = false;
      report.checks.push_back(std::move(c));
    }
    return report;
  }

 private:
  // --- measurements -------------------------------------------------------------------
  // Widths of outlines other than rectangles come from GEOS morphological openings, whose cost
  // grows faster than the vertex count (a 2,000-vertex sawtooth ran for minutes). A report measures
  // outlines of at most kMaxMeasuredVertices, kMeasuredVertexBudget in all; the rest are NaN,
  // which measure() reports as not checked.
  bool afford(const Polygon& p) {
    if (rectangle_sides(p)) return true;
    std::size_t n = p.outer.size();
    for (const auto& h : p.holes) n += h.size();
    if (n > kMaxMeasuredVertices || n > measure_budget_) return false;
    measure_budget_ -= n;
    return true;
  }
  double width_of(std::size_t z) {
    const Polygon& p = world_.zones()[z].polygon;
    if (!zones_[z].width) zones_[z].width = afford(p) ? clear_width(p) : kUnmeasured;
    return *zones_[z].width;
  }
  double diameter_of(std::size_t z) {
    const Polygon& p = world_.zones()[z].polygon;
    if (!zones_[z].diameter) zones_[z].diameter = afford(p) ? inscribed_diameter(p) : kUnmeasured;
    return *zones_[z].diameter;
  }
  std::vector<std::size_t> zones_where(const std::function<bool(const ZoneInfo&)>& pred) const {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < zones_.size(); ++i)
      if (pred(zones_[i])) out.push_back(i);
    return out;
  }
  std::vector<std::size_t> bedrooms() const {
    return zones_where([](const ZoneInfo& z) { return is_bedroom_type(z.type); });
  }
  std::optional<std::size_t> largest(const std::vector<std::size_t>& zs) const {
    std::optional<std::size_t> best;
    for (auto z : zs)
      if (!best || zones_[z].area > zones_[*best].area) best = z;
    return best;
  }
  double min_wall_height() const {
    double h = std::numeric_limits<double>::infinity();
    for (const auto& w : world_.walls()) h = std::min(h, w.height);
    return h;
  }
  bool onto_public_space(const Door& d) const {
    if (!d.other) return true;
    for (ZoneId z : {d.zone, *d.other}) {
      const std::string& t = zones_[z.index()].type;
      if (is_circulation_type(t) || t == "lobby" || t == "reception" || t == "waiting_room" ||
          t == "ticket_hall")
        return true;
    }
    return false;
  }
  std::optional<std::size_t> zone_of_roi(const Roi& roi) const {
    const auto z = world_.zone_at(geometry::centroid(roi.polygon.outer));
    if (!z) return std::nullopt;
    return z->index();
  }

  void compute_occupant_load() {
    // Per zone: the load factor of its use (residential: the dwelling's gross factor for all).
    for (const auto& m : constraints_) {
      const std::string& n = m.constraint.name;
      const std::string prefix = "occupant_load_factor_";
      if (n.rfind(prefix, 0) != 0 || !(m.constraint.value > 0)) continue;
      const std::string use = n.substr(prefix.size());
      double area = 0.0;
      double persons = 0.0;
      for (const auto& z : zones_) {
        const RoomType* rt = find_room_type(z.type);
        const bool counts =
            use == "residential" ? residential_ : (!residential_ && rt && rt->load_use == use);
        if (!counts) continue;
        area += z.area;
        persons += std::ceil(z.area / m.constraint.value - 1e-9);
      }
      if (use == "residential") persons = area > 0 ? std::ceil(area / m.constraint.value - 1e-9) : 0.0;
      load_by_use_[use] = {area, persons};
      occupant_load_ += persons;
    }
  }

  // --- verdicts ----------------------------------------------------------------------
  static bool meets(const ComplianceCheck& c, double v) {
    if (c.type == "max") return v <= c.required + kEps;
    return v >= c.required - kEps;  // min and recommended (at least the recommended figure)
  }
  // Measures `elements` with `measure`, keeps the worst value and the failures.
  void measure(ComplianceCheck& c, const std::vector<std::pair<std::string, double>>& values) {
    c.checked = values.size();
    std::size_t unmeasured = 0;
    for (const auto& [element, v] : values) {
      if (std::isnan(v)) {
        ++unmeasured;
        continue;
      }
      const bool worse = !c.value || (c.type == "max" ? v > *c.value : v < *c.value);
      if (worse) {
        c.value = v;
        c.element = element;
      }
      if (!meets(c, v)) c.failures.push_back({element, v});
    }
    if (values.empty()) {
      c.status = CheckStatus::kNotApplicable;
      return;
    }
    const bool ok = c.failures.empty();
    c.status =
        ok ? CheckStatus::kPass : (c.type == "recommended" ? CheckStatus::kAdvisory : CheckStatus::kFail);
    if (unmeasured > 0) {
      c.checked -= unmeasured;
      if (ok) c.status = CheckStatus::kNotChecked;
      c.unmeasured = unmeasured;
    }
  }
  void zone_values(ComplianceCheck& c, const std::vector<std::size_t>& zs,
                   const std::function<double(std::size_t)>& f, const std::string& what,
                   const std::string& none) {
    std::vector<std::pair<std::string, double>> values;
    for (auto z : zs) values.emplace_back(world_.zones()[z].name, f(z));
    measure(c, values);
    c.detail = values.empty() ? none : what;
    note_unmeasured(c);
  }
  static void note_unmeasured(ComplianceCheck& c) {
    if (c.unmeasured == 0) return;
    c.detail += "; " + std::to_string(c.unmeasured) + " outline(s) not measured (more than " +
                std::to_string(kMaxMeasuredVertices) + " vertices, or past the report's budget of " +
                std::to_string(kMeasuredVertexBudget) + ")";
  }
  static void not_checked(ComplianceCheck& c, std::string why) {
    c.status = CheckStatus::kNotChecked;
    c.detail = std::move(why);
  }
  static void not_applicable(ComplianceCheck& c, std::string why) {
    c.status = CheckStatus::kNotApplicable;
    c.detail = std::move(why);
  }

  void evaluate(ComplianceCheck& c) {
    const std::string& n = c.name;
    auto area = [this](std::size_t z) { return zones_[z].area; };
    auto width = [this](std::size_t z) { return width_of(z); };
    const auto corridors = zones_where([](const ZoneInfo& z) { return is_corridor_type(z.type); });
    const auto beds = bedrooms();

    if (n == "habitable_room_area") {
      return zone_values(c, zones_where([](const ZoneInfo& z) { return is_habitable_type(z.type); }), area,
                         "net area of every habitable room (living, sleeping, dining, study)",
                         "no habitable room");
    }
    if (n == "habitable_room_min_dimension") {
      return zone_values(c, zones_where([](const ZoneInfo& z) { return is_habitable_type(z.type); }), width,
                         "narrowest clear width of every habitable room", "no habitable room");
    }
    if (n == "largest_habitable_room_area") {
      const auto l = largest(zones_where([](const ZoneInfo& z) { return is_habitable_type(z.type); }));
      return zone_values(c, l ? std::vector{*l} : std::vector<std::size_t>{}, area,
                         "net area of the largest habitable room", "no habitable room");
    }
    if (n == "bedroom_single_area")
      return zone_values(c, beds, area, "net area of every bedroom", "no bedroom");
    if (n == "bedroom_single_min_width")
      return zone_values(c, beds, width, "narrowest clear width of every bedroom", "no bedroom");
    if (n == "bedroom_double_area" || n == "bedroom_double_min_width") {
      const auto l = largest(beds);
      return zone_values(c, l ? std::vector{*l} : std::vector<std::size_t>{},
                         n == "bedroom_double_area" ? std::function<double(std::size_t)>(area)
                                                    : std::function<double(std::size_t)>(width),
                         "the main (largest) bedroom, a double bedroom", "no bedroom");
    }
    if (n == "bedroom_double_other_min_width") {
      const double dbl = value_of(constraints_, "bedroom_double_area", 11.5);
      const auto l = largest(beds);
      std::vector<std::size_t> others;
      for (auto z : beds)
        if (z != *l && zones_[z].area >= dbl - kEps) others.push_back(z);
      return zone_values(
          c, others, width,
          "bedrooms other than the main one that are double-sized (≥ " + compact_number(dbl) + " m²)",
          "no other double-sized bedroom");
    }
    if (n == "patient_bedroom_area")
      return zone_values(c, zones_where([](const ZoneInfo& z) { return z.type == "patient_room"; }), area,
                         "net area of every patient room", "no patient room");
    if (n == "icu_room_area")
      return zone_values(c, zones_where([](const ZoneInfo& z) { return z.type == "icu_room"; }), area,
                         "net area of every ICU room", "no ICU room");
    if (n.rfind("built_in_storage_", 0) == 0) return storage(c);
    if (n.rfind("dwelling_gia_", 0) == 0) return gross_area(c);
    if (n == "corridor_clear_width" || n == "corridor_clear_width_small_occupancy" ||
        n == "accessible_route_clear_width")
      return zone_values(c, corridors, width, "narrowest clear width of every corridor", "no corridor");
    if (n == "exit_route_clear_width") {
      std::vector<std::pair<std::string, double>> values;
      for (auto z : corridors) values.emplace_back(world_.zones()[z].name, width_of(z));
      for (const auto& d : world_.doors()) values.emplace_back(d.name, d.width);
      measure(c, values);
      c.detail = "clear width of every corridor and door on the way out";
      return;
    }
    if (n == "passing_space_width") {
      std::vector<std::pair<std::string, double>> values;
      for (auto z : corridors) {
        const auto b = geometry::bounds(world_.zones()[z].polygon.outer);
        const double len = std::max(b.width(), b.height());
        // A corridor shorter than the passing interval needs no passing space of its own.
        values.emplace_back(world_.zones()[z].name, len <= kPassingInterval ? c.required : width_of(z));
      }
      measure(c, values);
      c.detail = values.empty()
                     ? "no corridor"
                     : "corridors longer than " + compact_number(kPassingInterval) +
                           " m (ADA 403.5.3 interval) must be this wide throughout; shorter ones pass";
      return;
    }
    if (n == "door_clear_width") {
      std::vector<std::pair<std::string, double>> values;
      for (const auto& d : world_.doors()) values.emplace_back(d.name, d.width);
      measure(c, values);
      c.detail = values.empty() ? "no door" : "clear width of every door";
      return;
    }
    if (n == "door_clear_width_public") {
      if (residential_) return not_applicable(c, "a dwelling has no public doors");
      std::vector<std::pair<std::string, double>> values;
      for (const auto& d : world_.doors())
        if (onto_public_space(d)) values.emplace_back(d.name, d.width);
      measure(c, values);
      c.detail = values.empty() ? "no public door"
                                : "entrances and doors onto corridors, halls, lobbies and waiting rooms";
      return;
    }
    if (n == "ceiling_height" || n == "ceiling_height_service_rooms" || n == "exit_route_headroom") {
      const double h = min_wall_height();
      if (!std::isfinite(h)) return not_applicable(c, "the world has no walls");
      measure(c, {{"walls", h}});
      c.detail = "lowest wall height (walls run floor to ceiling)";
      return;
    }
    if (n == "turning_circle_diameter") {
      std::vector<std::size_t> all(zones_.size());
      for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
      return zone_values(
          c, all, [this](std::size_t z) { return diameter_of(z); }, "largest circle that fits in every zone",
          "no zone");
    }
    if (n.rfind("occupant_load_factor_", 0) == 0) {
      const auto it = load_by_use_.find(n.substr(std::string("occupant_load_factor_").size()));
      if (it == load_by_use_.end() || it->second.first <= 0) return not_applicable(c, "no zone of this use");
      c.status = CheckStatus::kUsed;
      c.value = it->second.first;
      c.checked = 1;
      c.detail = compact_number(it->second.second) + " persons over " + num2(it->second.first) +
                 " m² (area ÷ factor, per zone); used by the egress-width check";
      return;
    }
    if (n == "egress_width_per_occupant") return egress(c);
    if (n == "exit_access_travel_distance" || n == "exit_access_travel_distance_unsprinklered")
      return travel(c);
    if (n == "workspace_area_per_person" || n == "workroom_volume_per_person") {
      const bool volume = n == "workroom_volume_per_person";
      const double h = min_wall_height();
      std::vector<std::pair<std::string, double>> values;
      for (std::size_t z = 0; z < zones_.size(); ++z) {
        const RoomType* rt = find_room_type(zones_[z].type);
        if (!rt || rt->load_use != "business" || zones_[z].desks == 0) continue;
        const double per = zones_[z].area / static_cast<double>(zones_[z].desks);
        values.emplace_back(world_.zones()[z].name, volume ? per * (std::isfinite(h) ? h : 0.0) : per);
      }
      measure(c, values);
      c.detail = values.empty() ? "no work room with desks"
                 : volume       ? "area × ceiling (lowest wall) height per desk in every work room"
                                : "area per desk in every work room";
      return;
    }
    if (n == "aisle_clear_width" || n == "storage_aisle_width" || n == "checkout_aisle_width") {
      std::vector<std::pair<std::string, double>> values;
      for (const auto& roi : world_.rois()) {
        const auto z = zone_of_roi(roi);
        const std::string zt = z ? zones_[*z].type : "";
        bool applies = false;
        if (n == "aisle_clear_width") applies = roi.kind == "walkway";
        if (n == "storage_aisle_width")
          applies =
              roi.kind == "walkway" && (zt == "warehouse_floor" || zt == "stock_room" || zt == "loading_bay");
        if (n == "checkout_aisle_width") applies = roi.kind == "queue_lane" && zt == "sales_floor";
        if (applies)
          values.emplace_back(roi.name, afford(roi.polygon) ? clear_width(roi.polygon) : kUnmeasured);
      }
      measure(c, values);
      c.detail = values.empty() ? "no aisle in the plan (walkway / check-out queue_lane ROIs)"
                                : "clear width of every aisle ROI it applies to";
      note_unmeasured(c);
      return;
    }
    if (n.rfind("stair_", 0) == 0 || n.rfind("ramp_", 0) == 0)
      return not_applicable(c, "a single-storey plan has no stairs or ramps");
    if (n.rfind("escape_opening_", 0) == 0) return not_checked(c, "windows are not part of the world model");
    if (n.rfind("kitchen_", 0) == 0 || n.rfind("wc_", 0) == 0 || n.rfind("lavatory_", 0) == 0 ||
        n.rfind("shower_", 0) == 0 || n.rfind("service_counter_", 0) == 0 || n == "dining_surface_height")
      return not_checked(c, "fixture and furniture sizes are not modelled (entities are points)");
    if (n == "door_clear_height" || n == "door_threshold_height")
      return not_checked(c, "door openings carry no height or threshold");
    if (n == "door_leaf_width")
      return not_checked(c, "door leaves are not modelled; an opening wider than one leaf is a double door");
    if (n.rfind("dead_end_corridor_length", 0) == 0)
      return not_checked(c,
                         "needs the sprinkler status and a second exit; single-exit plans are bounded by the "
                         "exit access travel distance instead");
    not_checked(c, "no check is defined for this constraint");
  }

  void storage(ComplianceCheck& c) {
    if (!residential_) return not_applicable(c, "dwellings only");
    const std::size_t b = bedrooms().size();
    const std::string suffix = c.name.substr(std::string("built_in_storage_").size());  // "2b"
    const std::size_t want = static_cast<std::size_t>(std::atoi(suffix.c_str()));
    const bool applies = b == want || (want == 3 && b > 3);
    if (!applies) return not_applicable(c, "the dwelling has " + std::to_string(b) + " bedroom(s)");
    double total = 0.0;
    for (const auto& z : zones_)
      if (z.type == "storage") total += z.area;
    measure(c, {{"storage", total}});
    c.detail = "total area of storage rooms for " + std::to_string(b) + " bedroom(s)";
  }

  void gross_area(ComplianceCheck& c) {
    if (!residential_) return not_applicable(c, "dwellings only");
    const auto beds = bedrooms();
    std::vector<double> areas;
    for (auto z : beds) areas.push_back(zones_[z].area);
    const std::string want = c.name.substr(std::string("dwelling_gia_").size());  // "2b3p"
    const std::string chosen = dwelling_entry(areas);
    if (chosen != want)
      return not_applicable(
          c, chosen.empty() ? "no entry for a dwelling with " + std::to_string(beds.size()) + " bedroom(s)"
                            : "the dwelling is " + chosen);
    double total = 0.0;
    for (const auto& z : zones_) total += z.area;
    measure(c, {{"dwelling", total}});
    c.detail = "sum of the zone areas for a " + want + " dwelling (bedrooms ≥ double area sleep two)";
  }

  // The table row for these bedrooms: same bedroom count, the smallest person count ≥ ours.
  std::string dwelling_entry(const std::vector<double>& bedroom_areas) const {
    return dwelling_entry_for(constraints_, bedroom_areas);
  }

 public:
  static std::string dwelling_entry_for(std::span<const MergedConstraint> cs,
                                        std::span<const double> bedroom_areas) {
    if (bedroom_areas.empty()) return "";
    const double dbl = value_of(cs, "bedroom_double_area", 11.5);
    int persons = 0;
    for (double a : bedroom_areas) persons += a >= dbl - kEps ? 2 : 1;
    const int b = static_cast<int>(bedroom_areas.size());
    std::string best;
    int best_p = 0;
    for (const auto& m : cs) {
      const std::string& n = m.constraint.name;
      if (n.rfind("dwelling_gia_", 0) != 0) continue;
      int eb = 0, ep = 0;
      if (std::sscanf(n.c_str() + 13, "%db%dp", &eb, &ep) != 2 || eb != b || ep < persons) continue;
      if (best.empty() || ep < best_p) {
        best = n.substr(13);
        best_p = ep;
      }
    }
    return best;
  }

 private:
  std::vector<std::size_t> exits() const {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < world_.doors().size(); ++i)
      if (!world_.doors()[i].other) out.push_back(i);
    return out;
  }

  void egress(ComplianceCheck& c) {
    if (occupant_load_ <= 0) return not_applicable(c, "no occupant load (no occupant-load factor applies)");
    double width = 0.0;
    std::string names;
    for (auto i : exits()) {
      width += world_.doors()[i].width;
      names += (names.empty() ? "" : ", ") + world_.doors()[i].name;
    }
    c.required = c.required * occupant_load_;
    c.unit = "m";
    measure(c, {{names.empty() ? "exits" : names, width}});
    c.detail = "total width of the exits against " + load_words() + " × the per-occupant width";
  }

  static bool is_exit_rule(std::string_view name) {
    return name == "single_exit_occupant_load" || name == "single_exit_travel_distance" ||
           name == "exit_separation_diagonal_fraction" || name == "three_exits_occupant_load" ||
           name == "four_exits_occupant_load";
  }

  // The exit count against the single-exit limits (occupants, travel distance) and, where two
  // exits are required, their separation; none when the store gives no single-exit limits.
  std::vector<ComplianceCheck> exit_checks() {
    const MergedConstraint* occupants = find(constraints_, "single_exit_occupant_load");
    const MergedConstraint* travel = find(constraints_, "single_exit_travel_distance");
    const MergedConstraint* spread = find(constraints_, "exit_separation_diagonal_fraction");
    if (occupants == nullptr || travel == nullptr) return {};
    auto base = [](std::string name, std::string unit, std::string title, const MergedConstraint& from) {
      ComplianceCheck c;
      c.name = std::move(name);
      c.applies_to = "building";
      c.type = "min";
      c.unit = std::move(unit);
      c.ref_id = from.ref_id;
      c.title = std::move(title);
      for (const auto& src : from.sources) {
        if (src.section.empty()) continue;
        if (!c.section.empty()) c.section += "; ";
        c.section += src.section;
      }
      c.jurisdiction = from.jurisdiction;
      c.confidence = from.constraint.confidence;
      return c;
    };
    const double max_occupants = occupants->constraint.value;
    const double max_travel = travel->constraint.value;
    const auto ex = exits();
    std::string names;
    for (auto i : ex) names += (names.empty() ? "" : ", ") + world_.doors()[i].name;
    const bool crowded = occupant_load_ > max_occupants + kEps;
    // The travel distance one exit alone would give: the best of the exits, each on its own (a
    // geodesic field per exit). Not needed when the occupant load alone asks for two exits.
    std::optional<double> far;
    if (!crowded)
      for (auto i : ex) {
        const double d = travel_distance({i}).first;
        far = far ? std::min(*far, d) : d;
      }
    const bool distant = far && *far > max_travel + kEps;

    // More exits for larger loads (IBC 2018 Table 1006.3.2: 3 from 501, 4 from 1001 occupants).
    const MergedConstraint* three = find(constraints_, "three_exits_occupant_load");
    const MergedConstraint* four = find(constraints_, "four_exits_occupant_load");
    const MergedConstraint* decided = occupants;
    double needed = crowded || distant ? 2.0 : 1.0;
    if (three && occupant_load_ >= three->constraint.value - kEps) needed = 3.0, decided = three;
    if (four && occupant_load_ >= four->constraint.value - kEps) needed = 4.0, decided = four;
    ComplianceCheck count = base("exit_count", "exits", "number of exits from a story", *decided);
    count.required = needed;
    measure(count, {{names.empty() ? "exits" : names, static_cast<double>(ex.size())}});
    count.detail =
        "doors to the outside against the single-exit limit (" + compact_number(max_occupants) +
        " occupants, " + num2(max_travel) + " m travel, " + occupants->ref_id + ")" +
        (three ? std::string(" and the exits per occupant load (3 from ") +
                     compact_number(three->constraint.value) +
                     (four ? ", 4 from " + compact_number(four->constraint.value) : std::string()) + ", " +
                     three->ref_id + ")"
               : std::string()) +
        ": " + load_words() +
        (far       ? ", " + num2(*far) + " m of travel to the best single exit"
         : crowded ? std::string(", more than one exit for the occupant load alone")
                   : std::string(", no exit")) +
        "; decided by " + decided->ref_id;

    const double fraction = spread != nullptr ? spread->constraint.value : 0.0;
    ComplianceCheck apart =
        base("exit_separation", "m", "separation of two exits", spread != nullptr ? *spread : *occupants);
    std::vector<Point> corners;
    for (const auto& z : world_.zones())
      corners.insert(corners.end(), z.polygon.outer.begin(), z.polygon.outer.end());
    const double diagonal = geometry::diameter(corners);
    apart.required = diagonal * fraction;
    if (spread == nullptr) {
      not_checked(apart, "the knowledge store gives no separation rule");
    } else if (count.required < 2.0 || ex.size() < 2) {
      not_applicable(apart, count.required < 2.0 ? "one exit suffices" : "fewer than two exits to separate");
    } else {
      double best = -1.0;
      std::string pair;
      for (std::size_t a = 0; a < ex.size(); ++a)
        for (std::size_t b = a + 1; b < ex.size(); ++b) {
          const Door& da = world_.doors()[ex[a]];
          const Door& db = world_.doors()[ex[b]];
          const double d = geometry::distance(Point{da.pose.x, da.pose.y}, Point{db.pose.x, db.pose.y});
          if (d > best) {
            best = d;
            pair = da.name + " and " + db.name;
          }
        }
      measure(apart, {{pair, best}});
      apart.detail = "straight line between the centres of the two exits farthest apart against " +
                     num2(fraction) + " of the building's overall diagonal (" + num2(diagonal) +
                     " m; unsprinklered)";
    }
    return {std::move(count), std::move(apart)};
  }

  // Longest walking distance to the nearest of `through` (every exit when empty) and the zone
  // where it is measured.
  std::pair<double, std::string> travel_distance(const std::vector<std::size_t>& through = {}) {
    auto& cached = travel_[through];
    if (!cached) {
      std::vector<Point> sources;
      for (auto i : through.empty() ? exits() : through) {
        const Door& d = world_.doors()[i];
        const Point a = d.opening.a, b = d.opening.b;
        const Point mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
        const double len = std::max(geometry::distance(a, b), 1e-9);
        const Point normal{-(b.y - a.y) / len, (b.x - a.x) / len};
        // Step into the zone the door belongs to (the outline itself is blocked in the grid).
        for (double s : {0.3, -0.3}) {
          const Point p{mid.x + normal.x * s, mid.y + normal.y * s};
          if (geometry::contains(world_.zone(d.zone).polygon, p)) sources.push_back(p);
        }
      }
      std::vector<double> key;
      for (const Point& p : sources) key.insert(key.end(), {p.x, p.y});
      const OccupancyGrid& grid = travel_grid();
      std::optional<std::pair<double, std::optional<std::uint32_t>>> measured;
      if (cache_) {
        auto hit = cache_->travel.find(key);
        if (hit != cache_->travel.end()) measured = hit->second;
      }
      if (!measured) {
        const auto field = GeodesicField::from_points(grid, sources);
        double worst = 0.0;
        std::optional<ZoneId> where;
        for (int y = 0; y < grid.height(); ++y)
          for (int x = 0; x < grid.width(); ++x) {
            const Cell cell{x, y};
            if (grid.blocked(cell)) continue;
            const float v = field.at(cell);
            if (std::isfinite(v) && v > worst) {
              worst = v;
              where = grid.zone_of(cell);
            }
          }
        measured = {worst, where ? std::optional<std::uint32_t>(static_cast<std::uint32_t>(where->index()))
                                 : std::nullopt};
        if (cache_) cache_->travel[key] = *measured;
      }
      cached = std::pair{measured->first,
                         measured->second ? world_.zones()[*measured->second].name : std::string("plan")};
    }
    return *cached;
  }

  // The 0.2 m grid of the travel distances: the cache's when it was rasterised from the same
  // zones, walls and outline (its measured distances are dropped when it is not).
  const OccupancyGrid& travel_grid() {
    if (grid_) return *grid_;
    if (!cache_) return grid_.emplace(OccupancyGrid::rasterise(world_, {0.2, 0.0, 1'000'000}));
    std::vector<double> of;
    for (const auto& z : world_.zones()) {
      of.push_back(static_cast<double>(z.polygon.outer.size()));
      for (const Point& p : z.polygon.outer) of.insert(of.end(), {p.x, p.y});
      for (const auto& hole : z.polygon.holes) {
        of.push_back(static_cast<double>(hole.size()));
        for (const Point& p : hole) of.insert(of.end(), {p.x, p.y});
      }
    }
    of.push_back(-1.0);
    for (const auto& w : world_.walls())
      of.insert(of.end(), {w.segment.a.x, w.segment.a.y, w.segment.b.x, w.segment.b.y});
    of.push_back(-1.0);
    for (const auto& s : world_.outline()) of.insert(of.end(), {s.a.x, s.a.y, s.b.x, s.b.y});
    if (!cache_->grid || cache_->grid_of != of) {
      cache_->grid = OccupancyGrid::rasterise(world_, {0.2, 0.0, 1'000'000});
      cache_->grid_of = std::move(of);
      cache_->travel.clear();
    }
    return *cache_->grid;
  }

  void travel(ComplianceCheck& c) {
    if (exits().empty()) {
      measure(c, {{"exits", std::numeric_limits<double>::infinity()}});
      c.value.reset();
      c.detail = "the plan has no door to the outside";
      return;
    }
    const auto [worst, where] = travel_distance();
    measure(c, {{where, worst}});
    c.detail = "longest walking distance (geodesic, 0.2 m grid) from any point to the nearest exit";
  }

  const World& world_;
  std::string building_type_;
  std::span<const MergedConstraint> constraints_;
  std::vector<ZoneInfo> zones_;
  std::size_t measure_budget_ = kMeasuredVertexBudget;
  bool residential_ = false;
  std::optional<double> scenario_occupants_;
  double occupant_load_ = 0.0;
  double area_load_ = 0.0;
  std::map<std::string, std::pair<double, double>> load_by_use_;  // use → (area, persons)
  ComplianceCache* cache_ = nullptr;
  std::optional<OccupancyGrid> grid_;  // when there is no cache
  std::map<std::vector<std::size_t>, std::optional<std::pair<double, std::string>>> travel_;
};

double round_micro(double v) {
  return std::isfinite(v) ? std::round(v * 1e6) / 1e6 : v;
}

}  // namespace

std::string_view to_string(CheckStatus status) {
  switch (status) {
    case CheckStatus::kPass:
      return "pass";
    case CheckStatus::kFail:
      return "fail";
    case CheckStatus::kAdvisory:
      return "advisory";
    case CheckStatus::kUsed:
      return "used";
    case CheckStatus::kNotApplicable:
      return "not_applicable";
    case CheckStatus::kNotChecked:
      return "not_checked";
  }
  return "not_checked";
}

std::vector<const ComplianceCheck*> ComplianceReport::failures() const {
  std::vector<const ComplianceCheck*> out;
  for (const auto& c : checks)
    if (c.status == CheckStatus::kFail) out.push_back(&c);
  return out;
}

std::string building_type_of(const World& world) {
  std::vector<std::string> names;
  names.reserve(world.zones().size());
  for (const auto& z : world.zones()) names.push_back(z.name + " " + z.type);
  return knowledge::classify_building_type(names).type;
}

ComplianceReport check_compliance(const World& world, std::string_view building_type,
                                  std::span<const MergedConstraint> constraints,
                                  std::optional<double> occupants) {
  return Checker(world, building_type, constraints, occupants, nullptr).run();
}

ComplianceReport check_compliance(const World& world, std::string_view building_type,
                                  std::span<const MergedConstraint> constraints,
                                  std::optional<double> occupants, ComplianceCache& cache) {
  return Checker(world, building_type, constraints, occupants, &cache).run();
}

Json to_json(const ComplianceCheck& c) {
  Json failures = Json::array();
  for (const auto& f : c.failures)
    failures.push_back({{"element", f.element}, {"value", round_micro(f.value)}});
  Json j{{"name", c.name},
         {"applies_to", c.applies_to},
         {"type", c.type},
         {"required", round_micro(c.required)},
         {"unit", c.unit},
         {"value", c.value ? Json(round_micro(*c.value)) : Json(nullptr)},
         {"element", c.element},
         {"checked", c.checked},
         {"status", to_string(c.status)},
         {"failures", std::move(failures)},
         {"detail", c.detail},
         {"ref_id", c.ref_id},
         {"title", c.title},
         {"section", c.section},
         {"jurisdiction", c.jurisdiction},
         {"confidence", c.confidence}};
  if (c.unmeasured > 0) j["unmeasured"] = c.unmeasured;
  return j;
}

Json to_json(const ComplianceReport& r) {
  Json summary = Json::object();
  for (auto s : {CheckStatus::kPass, CheckStatus::kFail, CheckStatus::kAdvisory, CheckStatus::kUsed,
                 CheckStatus::kNotApplicable, CheckStatus::kNotChecked})
    summary[std::string(to_string(s))] = 0;
  Json checks = Json::array();
  for (const auto& c : r.checks) {
    summary[std::string(to_string(c.status))] = summary[std::string(to_string(c.status))].get<int>() + 1;
    checks.push_back(to_json(c));
  }
  Json out{{"building_type", r.building_type},
           {"passed", r.passed},
           {"occupant_load", round_micro(r.occupant_load)},
           {"summary", std::move(summary)},
           {"checks", std::move(checks)}};
  if (r.scenario_occupants) {
    out["scenario_occupants"] = round_micro(*r.scenario_occupants);
    out["occupant_load_from_area"] = round_micro(r.occupant_load_from_area);
  }
  return out;
}

RoomRequirement room_requirement(std::span<const MergedConstraint> cs, std::string_view room_type,
                                 bool main_bedroom) {
  const std::string t = canonical_room_type(room_type);
  RoomRequirement r;
  auto raise_area = [&](std::string_view name) { r.min_area = std::max(r.min_area, value_of(cs, name)); };
  auto raise_dim = [&](std::string_view name) {
    r.min_dimension = std::max(r.min_dimension, value_of(cs, name));
  };
  if (is_habitable_type(t)) {
    raise_area("habitable_room_area");
    raise_dim("habitable_room_min_dimension");
  }
  if (t == "living_room") raise_area("largest_habitable_room_area");
  if (is_bedroom_type(t)) {
    raise_area("bedroom_single_area");
    raise_dim("bedroom_single_min_width");
    raise_dim("bedroom_double_other_min_width");
    if (main_bedroom) {
      raise_area("bedroom_double_area");
      raise_dim("bedroom_double_min_width");
    }
  }
  if (t == "patient_room") raise_area("patient_bedroom_area");
  if (t == "icu_room") raise_area("icu_room_area");
  raise_dim("turning_circle_diameter");
  if (is_corridor_type(t)) {
    for (auto n : {"corridor_clear_width", "corridor_clear_width_small_occupancy",
                   "accessible_route_clear_width", "exit_route_clear_width"})
      raise_dim(n);
  }
  return r;
}

PlanRequirement plan_requirement(std::span<const MergedConstraint> cs, std::string_view building_type) {
  PlanRequirement p;
  for (auto n : {"corridor_clear_width", "corridor_clear_width_small_occupancy",
                 "accessible_route_clear_width", "exit_route_clear_width"})
    p.corridor_width = std::max(p.corridor_width, value_of(cs, n));
  p.door_width = std::max({value_of(cs, "door_clear_width"), value_of(cs, "exit_route_clear_width"), 0.6});
  p.public_door_width = p.door_width;
  if (building_type != "residential")
    p.public_door_width = std::max(p.door_width, value_of(cs, "door_clear_width_public"));
  p.walkway_width = std::max(value_of(cs, "aisle_clear_width"), value_of(cs, "storage_aisle_width"));
  p.queue_lane_width = value_of(cs, "checkout_aisle_width");
  p.turning_diameter = value_of(cs, "turning_circle_diameter");
  for (auto n : {"ceiling_height", "ceiling_height_service_rooms", "exit_route_headroom"})
    p.ceiling_height = std::max(p.ceiling_height, value_of(cs, n));
  for (const auto& m : cs) {
    if (m.constraint.name.rfind("exit_access_travel_distance", 0) != 0) continue;
    p.travel_distance =
        p.travel_distance > 0 ? std::min(p.travel_distance, m.constraint.value) : m.constraint.value;
  }
  return p;
}

DwellingRequirement dwelling_requirement(std::span<const MergedConstraint> cs,
                                         std::span<const double> bedroom_areas) {
  DwellingRequirement d;
  const std::string entry = Checker::dwelling_entry_for(cs, bedroom_areas);
  if (!entry.empty()) d.gross_internal_area = value_of(cs, "dwelling_gia_" + entry);
  const std::size_t b = bedroom_areas.size();
  if (b > 0)
    d.storage_area = value_of(cs, "built_in_storage_" + std::to_string(std::min<std::size_t>(b, 3)) + "b");
  return d;
}

double clear_width(const Polygon& polygon) {
  if (auto sides = rectangle_sides(polygon)) return std::min(sides->first, sides->second);
  geometry::Geos geos;
  const geometry::MultiPolygon shape{polygon};
  const double total = geometry::area(polygon);
  if (!(total > 0)) return 0.0;
  const auto box = geometry::bounds(polygon.outer);
  double lo = 0.0, hi = std::min(box.width(), box.height());
  auto opening_keeps = [&](double w) {
    const double r = w / 2;
    const auto opened = geos.buffer(geos.buffer(shape, -r), r);
    const double lost = total - geos.area(opened);
    return lost <= corner_loss(polygon, r) * 1.05 + 0.002 * total + 1e-4;
  };
  for (int i = 0; i < 24 && hi - lo > 5e-4; ++i) {
    const double mid = (lo + hi) / 2;
    (opening_keeps(mid) ? lo : hi) = mid;
  }
  return std::floor(lo * 1000) / 1000;
}

double inscribed_diameter(const Polygon& polygon) {
  if (auto sides = rectangle_sides(polygon)) return std::min(sides->first, sides->second);
  geometry::Geos geos;
  const geometry::MultiPolygon shape{polygon};
  const auto box = geometry::bounds(polygon.outer);
  double lo = 0.0, hi = std::min(box.width(), box.height());
  for (int i = 0; i < 24 && hi - lo > 5e-4; ++i) {
    const double mid = (lo + hi) / 2;
    (geos.area(geos.buffer(shape, -mid / 2)) > 1e-9 ? lo : hi) = mid;
  }
  return std::floor(lo * 1000) / 1000;
}

}  // namespace socsim::floorplan
