#include "core/scenario/intent_world.hpp"

#include <algorithm>
#include <cmath>

namespace socsim::scenario {
namespace {

// "the exit", "a counter": the article makes it one thing talked about, not a count of them.
bool article_count(const Count& c) {
  static constexpr std::string_view kArticles[] = {"a",   "an",  "the", "their", "his",  "her",
                                                   "its", "our", "my",  "your",  "this", "that"};
  return std::find(std::begin(kArticles), std::end(kArticles), c.phrase) != std::end(kArticles);
}

int clamped(double v, int lo, int hi) {
  return std::clamp(static_cast<int>(std::llround(v)), lo, hi);
}

}  // namespace

std::size_t people_named(const ScenarioIntent& intent) {
  std::size_t n = 0;
  for (const PeopleGroup& g : intent.groups) n += g.count.people();
  return n;
}

world::WorldRequirements world_requirements(const ScenarioIntent& intent) {
  world::WorldRequirements out;
  for (const Feature& f : intent.world.features) {
    auto kind = world::feature_from_word(f.name);
    if (!kind) kind = world::feature_from_word(f.head);
    if (!kind) continue;  // a counted room ("three galleries") is a named room below
    world::FeatureCount fc;
    fc.feature = *kind;
    fc.words = f.name;
    switch (f.count.kind) {
      case CountKind::kExact:
        fc.count = static_cast<int>(std::llround(f.count.value));
        fc.at_least = article_count(f.count);
        break;
      case CountKind::kUnspecified:
        fc.count = 1;
        fc.at_least = true;
        break;
      default:  // approximate, range, bound: at least its lower end
        fc.count = static_cast<int>(std::floor(std::max(0.0, f.count.min)));
        fc.at_least = true;
        break;
    }
    fc.count = std::clamp(fc.count, 0, world::info(*kind).max_count);
    auto same = std::find_if(out.features.begin(), out.features.end(),
                             [&](const world::FeatureCount& o) { return o.feature == fc.feature; });
    if (same == out.features.end())
      out.features.push_back(std::move(fc));
    else if (fc.count > same->count || (same->at_least && !fc.at_least && fc.count >= same->count))
      *same = std::move(fc);
  }
  auto add_room = [&](const std::string& name, int count) {
    auto same = std::find_if(out.rooms.begin(), out.rooms.end(),
                             [&](const world::NamedRoom& r) { return r.name == name; });
    if (same != out.rooms.end())
      same->count = std::max(same->count, count);
    else if (out.rooms.size() < world::kMaxNamedRooms)
      out.rooms.push_back(world::NamedRoom{name, world::snake_case(name), count});
  };
  auto add_object = [&](const std::string& name, int count) {
    auto same = std::find_if(out.objects.begin(), out.objects.end(),
                             [&](const world::NamedObject& o) { return o.name == name; });
    if (same != out.objects.end())
      same->count = std::max(same->count, count);
    else if (out.objects.size() < world::kMaxNamedObjects)
      out.objects.push_back(world::NamedObject{name, world::snake_case(name), count, ""});
  };
  auto is_room = [&](const std::string& name) {
    return std::any_of(intent.world.rooms.begin(), intent.world.rooms.end(),
                       [&](const NamedThing& r) { return r.name == name; });
  };
  for (const NamedThing& r : intent.world.rooms) add_room(r.name, 1);
  // Features the world generator does not count are rooms ("three galleries") or objects ("the
  // coffee machine"), with their count when one was said.
  for (const Feature& f : intent.world.features) {
    if (world::feature_from_word(f.name) || world::feature_from_word(f.head)) continue;
    const int n = f.count.specified() ? clamped(f.count.value, 1, world::kMaxNamedCount) : 1;
    if (is_room(f.name))
      add_room(f.name, n);
    else
      add_object(f.name, n);
  }
  for (const NamedThing& o : intent.world.objects)
    if (!world::feature_from_word(o.name) && !is_room(o.name)) add_object(o.name, 1);
  if (const std::size_t n = people_named(intent); n > 0)
    out.occupants = static_cast<int>(std::min<std::size_t>(n, world::kMaxOccupants));
  return out;
}

}  // namespace socsim::scenario
