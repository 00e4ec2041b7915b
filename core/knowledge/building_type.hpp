#pragma once
// Building-type classification of a prompt or a scene graph's room names (paper 001 §III-C a):
// a curated, weighted lexicon of indicator words and phrases per type; residential when nothing
// indicates otherwise. The answer names the words that decided it.
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/json_io.hpp"

namespace socsim::knowledge {

struct BuildingTypeEvidence {
  std::string term;  // the lexicon entry that matched, e.g. "waiting room"
  std::string type;  // the building type it points to
  double weight = 0.0;
};

struct BuildingTypeGuess {
  std::string type;                            // one of building_types()
  double confidence = 0.0;                     // in (0, 1); the default guess has 0.3
  std::vector<BuildingTypeEvidence> evidence;  // every match, in text order (negated ones excluded)
  std::map<std::string, double> scores;        // summed weight per type that had evidence
  std::string explanation;                     // one sentence naming the deciding words
};

// Words are matched case-insensitively after simple singularisation (aisles → aisle); phrases
// ("waiting room", "coffee shop") take precedence over their words; a match within two words
// after "no", "not", "non" or "without" is ignored ("an office, not a hospital").
BuildingTypeGuess classify_building_type(std::string_view text);

// Scene graph: room names such as "patient_room_01" or "NurseStation" are split into words and
// classified together.
BuildingTypeGuess classify_building_type(const std::vector<std::string>& room_names);

Json to_json(const BuildingTypeGuess& guess);

}  // namespace socsim::knowledge
