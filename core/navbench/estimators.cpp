#include "core/navbench/estimators.hpp"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <numeric>
#include <thread>
#include <tuple>

#include "core/common/rng.hpp"

namespace socsim::navbench {
namespace {

using household::House;
using household::RoomType;

constexpr double kBackoff = 1.0;  // pseudo-count pulling a sparse cell towards its back-off rate

std::string key(std::string_view a, std::string_view b = {}, std::string_view c = {}) {
  std::string k(a);
  if (!b.empty()) (k += '|') += b;
  if (!c.empty()) (k += '|') += c;
  return k;
}

double lookup(const std::map<std::string, double, std::less<>>& m, const std::string& k) {
  auto it = m.find(k);
  return it == m.end() ? 0.0 : it->second;
}

void normalise(std::vector<double>& p) {
  const double total = std::accumulate(p.begin(), p.end(), 0.0);
  if (total <= 0.0) return;
  for (double& x : p) x /= total;
}

}  // namespace

GenerativeModel generative_model_of(const household::DynamicScene& scene) {
  // The scene's events and relocations are deliberately not copied.
  return {std::shared_ptr<const House>(std::shared_ptr<const House>{}, &scene.house()), scene.residents()};
}

std::vector<double> UniformEstimator::estimate(const EstimateQuery& q) const {
  std::vector<double> p(q.map->receptacles().size(), 1.0);
  normalise(p);
  return p;
}

void add_house(PlacementCounts& c, const House& h, std::uint64_t seed) {
  for (int idx : h.receptacles) {
    const auto& r = h.entities[static_cast<std::size_t>(idx)];
    if (r.room < 0) continue;
    const auto room = household::room_type_name(h.rooms[static_cast<std::size_t>(r.room)].type);
    c.receptacles[key(r.type, room)] += 1.0;
    c.receptacles[key(r.type)] += 1.0;
    c.total_receptacles += 1.0;
  }
  for (int idx : h.objects) {
    const auto& o = h.entities[static_cast<std::size_t>(idx)];
    if (o.parent < 0) continue;
    const auto& r = h.entities[static_cast<std::size_t>(o.parent)];
    if (r.room < 0) continue;
    const auto room = household::room_type_name(h.rooms[static_cast<std::size_t>(r.room)].type);
    c.objects[key(o.type, r.type, room)] += 1.0;
    c.objects[key(o.type, r.type)] += 1.0;
    c.objects[key(o.type)] += 1.0;
  }
  ++c.houses;
  c.seeds.push_back(seed);
}

std::uint64_t training_house_seed(std::uint64_t training_seed, int index) {
  std::uint64_t state =
      training_seed ^ fnv1a64("navbench/train") ^ (static_cast<std::uint64_t>(index) * 0xD1B54A32D192ED03ULL);
  return splitmix64(state) | (std::uint64_t{1} << 63);
}

Result<PlacementCounts> count_training_placements(const household::HouseholdKnowledge& knowledge, int houses,
                                                  std::uint64_t training_seed, int threads) {
  if (houses < 1 || houses > 100000)
    return fail(ErrorCode::kValidation, "training houses out of range",
                {FieldError{"/training_houses", "must be between 1 and 100000"}});
  // Houses are counted per index and merged in index order, so counts do not depend on threads.
  std::vector<std::optional<House>> built(static_cast<std::size_t>(houses));
  std::atomic<int> next{0};
  auto work = [&] {
    for (int i; (i = next.fetch_add(1)) < houses;) {
      const std::uint64_t seed = training_house_seed(training_seed, i);
      Rng pick(seed, fnv1a64("navbench/train-rooms"));
      auto h =
          household::generate_house({static_cast<int>(pick.between(1, 10)), std::nullopt, seed}, knowledge);
      if (h) built[static_cast<std::size_t>(i)] = std::move(*h);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::max(1, threads); ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  PlacementCounts c;
  for (int i = 0; i < houses; ++i)
    if (built[static_cast<std::size_t>(i)])
      add_house(c, *built[static_cast<std::size_t>(i)], training_house_seed(training_seed, i));
  if (c.houses == 0) return fail(ErrorCode::kInternal, "no training house could be generated");
  return c;
}

double ScenePriorEstimator::rate(std::string_view object_type, std::string_view receptacle_type,
                                 RoomType room) const {
  const auto& c = *counts_;
  const double overall = (lookup(c.objects, key(object_type)) + 1.0) / (c.total_receptacles + 1.0) * 0.01;
  const double by_type = (lookup(c.objects, key(object_type, receptacle_type)) + kBackoff * overall) /
                         (lookup(c.receptacles, key(receptacle_type)) + kBackoff);
  const auto room_name = household::room_type_name(room);
  return (lookup(c.objects, key(object_type, receptacle_type, room_name)) + kBackoff * by_type) /
         (lookup(c.receptacles, key(receptacle_type, room_name)) + kBackoff);
}

std::vector<double> ScenePriorEstimator::estimate(const EstimateQuery& q) const {
  std::vector<double> p;
  p.reserve(q.map->receptacles().size());
  for (const auto& r : q.map->receptacles()) p.push_back(rate(q.target_type, r.type, r.room_type));
  normalise(p);
  return p;
}

std::vector<double> HintEstimator::estimate(const EstimateQuery& q) const {
  std::vector<double> p = prior_->estimate(q);
  const std::vector<household::HintReading> readings = household::read_hints(q.hint, *knowledge_);
  std::vector<household::ReceptacleView> views;
  views.reserve(q.map->receptacles().size());
  for (const auto& r : q.map->receptacles()) views.push_back({r.type, r.room_type});
  // The generator's curated activity tables are not read (see the header).
  return household::hint_distribution(readings, q.target_type, views, p, trust_, /*activity_tables=*/false);
}

std::vector<double> PosteriorEstimator::estimate(const EstimateQuery& q) const {
  const auto& recs = q.map->receptacles();
  std::vector<double> zero(recs.size(), 0.0);
  if (!q.model || !q.model->house) return zero;
  const House& h = *q.model->house;
  int instance = -1, instances = 0;
  for (int idx : h.objects)
    if (h.entities[static_cast<std::size_t>(idx)].type == q.target_type) instance = idx, ++instances;
  if (instances != 1) return zero;
  const std::size_t n = recs.size();
  std::vector<int> slot(h.entities.size(), -1);
  for (std::size_t i = 0; i < n; ++i) slot[static_cast<std::size_t>(recs[i].entity)] = static_cast<int>(i);

  // What the house offers, as configure_scene sees it.
  std::array<bool, household::kRoomTypeCount> has_type{};
  for (const auto& room : h.rooms) has_type[household::index_of(room.type)] = true;
  std::vector<std::map<std::string, std::vector<int>, std::less<>>> receptacles_in(h.rooms.size());
  for (int idx : h.receptacles) {
    const auto& e = h.entities[static_cast<std::size_t>(idx)];
    if (e.room >= 0 && !e.synthetic) receptacles_in[static_cast<std::size_t>(e.room)][e.type].push_back(idx);
  }

  // Events that end by t, in the order configure_scene applies their effects.
  struct Ev {
    household::Seconds end, start;
    int resident, entry;
  };
  std::vector<Ev> events;
  for (std::size_t r = 0; r < q.model->residents.size(); ++r) {
    const auto& entries = q.model->residents[r].profile->schedule.entries;
    for (std::size_t e = 0; e < entries.size(); ++e) {
      const household::Seconds end = entries[e].end * household::Seconds{60};
      if (end <= q.time)
        events.push_back(
            {end, entries[e].start * household::Seconds{60}, static_cast<int>(r), static_cast<int>(e)});
    }
  }
  std::sort(events.begin(), events.end(), [](const Ev& a, const Ev& b) {
    return std::tie(a.end, a.start, a.resident, a.entry) < std::tie(b.end, b.start, b.resident, b.entry);
  });

  // A: where the target is if it has not moved inside the recent window yet; B: if it has.
  std::vector<double> a(n, 0.0), b(n, 0.0), next_a(n), next_b(n), work_a(n), work_b(n), m(n);
  const int start = slot[static_cast<std::size_t>(h.entities[static_cast<std::size_t>(instance)].parent)];
  if (start < 0) return zero;
  a[static_cast<std::size_t>(start)] = 1.0;
  const household::Seconds window_start =
      q.recent > 0 ? q.time - q.recent : std::numeric_limits<household::Seconds>::min();

  for (const Ev& ev : events) {
    const auto& res = q.model->residents[static_cast<std::size_t>(ev.resident)];
    const auto& entry = res.profile->schedule.entries[static_cast<std::size_t>(ev.entry)];
    const household::ActivityPrior* prior = res.profile->activity_db.find(entry.primary);
    if (!prior || prior->locations.empty()) continue;
    bool involves = false;
    for (const auto& loc : prior->locations)
      for (const auto& op : loc.objects) involves = involves || op.type == q.target_type;
    if (!involves) continue;
    double total = 0.0;
    for (const auto& loc : prior->locations)
      total += has_type[household::index_of(loc.room)] && loc.p > 0 ? loc.p : 0.0;
    if (total <= 0.0) continue;
    const bool flagged = ev.end > window_start;
    std::fill(next_a.begin(), next_a.end(), 0.0);
    std::fill(next_b.begin(), next_b.end(), 0.0);
    for (const auto& loc : prior->locations) {
      const double pl = has_type[household::index_of(loc.room)] && loc.p > 0 ? loc.p / total : 0.0;
      if (pl <= 0.0) continue;
      std::vector<int> rooms;
      if (loc.room == RoomType::kBedroom && res.bedroom >= 0)
        rooms = {res.bedroom};
      else if (loc.room == RoomType::kBathroom && res.bathroom >= 0)
        rooms = {res.bathroom};
      else
        rooms = h.rooms_of(loc.room);
      for (int room : rooms) {
        const double weight = pl / static_cast<double>(rooms.size());
        work_a = a;
        work_b = b;
        const auto& here = receptacles_in[static_cast<std::size_t>(room)];
        for (const auto& op : loc.objects) {
          if (op.type != q.target_type) continue;
          double wsum = 0.0;
          for (const auto& [rt, p] : op.receptacles) wsum += here.count(rt) ? p : 0.0;
          if (wsum <= 0.0) continue;
          std::fill(m.begin(), m.end(), 0.0);
          for (const auto& [rt, p] : op.receptacles) {
            auto it = here.find(rt);
            if (it == here.end()) continue;
            for (int idx : it->second)
              m[static_cast<std::size_t>(slot[static_cast<std::size_t>(idx)])] +=
                  p / wsum / static_cast<double>(it->second.size());
          }
          const double qo = op.p;
          const double sa = std::accumulate(work_a.begin(), work_a.end(), 0.0),
                       sb = std::accumulate(work_b.begin(), work_b.end(), 0.0);
          if (!flagged) {
            for (std::size_t i = 0; i < n; ++i) work_a[i] = (1 - qo) * work_a[i] + qo * m[i] * sa;
          } else {
            // Moving onto the receptacle it already rests on is no relocation: that mass stays in A.
            std::vector<double> fa(work_a);
            for (std::size_t i = 0; i < n; ++i) {
              work_a[i] = (1 - qo) * fa[i] + qo * m[i] * fa[i];
              work_b[i] = (1 - qo) * work_b[i] + qo * m[i] * (sb + sa - fa[i]);
            }
          }
        }
        for (std::size_t i = 0; i < n; ++i) next_a[i] += weight * work_a[i], next_b[i] += weight * work_b[i];
      }
    }
    a.swap(next_a);
    b.swap(next_b);
  }
  std::vector<double> p = b;
  if (q.recent <= 0 || std::accumulate(b.begin(), b.end(), 0.0) <= 1e-15)
    for (std::size_t i = 0; i < n; ++i) p[i] = a[i] + b[i];
  normalise(p);
  return p;
}

}  // namespace socsim::navbench
