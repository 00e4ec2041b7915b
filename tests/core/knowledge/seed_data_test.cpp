// The seed data of migrations/0011 and 0012: complete provenance and SI units for every
// building-code entry, the five references of paper 001, the node library the crowd engine
// implements, conformance to schemas/*.schema.json, and HuNavSim's own trees and node models.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/common/json_schema.hpp"
#include "core/knowledge/knowledge_base.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::knowledge {
namespace {

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class KnowledgeSeedDataTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto s = store::Store::open(dir_.file("seed.db"));
    ASSERT_TRUE(s) << s.error().message();
    store_ = std::move(*s);
    kb_ = std::make_unique<KnowledgeBase>(*store_);
    auto codes = kb_->building_codes();
    ASSERT_TRUE(codes) << codes.error().message();
    codes_ = *codes;
    auto nodes = kb_->behavior_nodes();
    ASSERT_TRUE(nodes) << nodes.error().message();
    nodes_ = *nodes;
  }

  const BehaviorNode* node_or_alias(const std::string& tag) const {
    for (const auto& n : nodes_) {
      if (n.name == tag) return &n;
      for (const auto& a : n.aliases)
        if (a == tag) return &n;
    }
    return nullptr;
  }

  testing::TempDir dir_;
  std::unique_ptr<store::Store> store_;
  std::unique_ptr<KnowledgeBase> kb_;
  std::vector<BuildingCode> codes_;
  std::vector<BehaviorNode> nodes_;
};

TEST_F(KnowledgeSeedDataTest, EveryBuildingCodeHasSourceUrlSectionAndSiUnits) {
  ASSERT_GE(codes_.size(), 40u);
  const auto units = si_units();
  std::map<std::string, std::string> unit_of;
  for (const auto& c : codes_) {
    ASSERT_FALSE(c.sources.empty()) << c.ref_id;
    for (const auto& s : c.sources) {
      EXPECT_FALSE(s.title.empty()) << c.ref_id;
      EXPECT_EQ(s.url.rfind("https://", 0), 0u) << c.ref_id;
      EXPECT_FALSE(s.section.empty()) << c.ref_id;
    }
    EXPECT_GE(c.description.size(), 40u) << c.ref_id;
    for (const auto& k : c.constraints) {
      EXPECT_NE(std::find(units.begin(), units.end(), k.unit), units.end()) << c.ref_id << " " << k.unit;
      EXPECT_GT(k.value, 0.0) << c.ref_id;
      EXPECT_GT(k.confidence, 0.0) << c.ref_id;
      EXPECT_LE(k.confidence, 1.0) << c.ref_id;
      EXPECT_FALSE(k.original.empty()) << c.ref_id << " " << k.name;
      // A merge key means one quantity: the same name always carries the same unit.
      auto [it, inserted] = unit_of.emplace(k.name, k.unit);
      EXPECT_EQ(it->second, k.unit) << k.name << " in " << c.ref_id;
    }
  }
}

TEST_F(KnowledgeSeedDataTest, EveryDomainOfTheIssueIsCovered) {
  std::map<std::string, int> per_type;
  for (const auto& c : codes_) ++per_type[c.building_type];
  for (const char* t : {"residential", "office", "hospital", "canteen", "retail", "warehouse", "general"})
    EXPECT_GE(per_type[t], 3) << t;
  EXPECT_GE(per_type["school"], 1);
  EXPECT_GE(per_type["airport"], 1);
  // The venues of the worlds issue: occupant load factors and travel distance at least, each.
  for (const char* t : {"train_station", "hotel", "library", "museum", "theatre", "arena", "factory", "mall",
                        "supermarket", "restaurant", "university", "gym", "care_home", "community_hall"})
    EXPECT_GE(per_type[t], 2) << t;
}

TEST_F(KnowledgeSeedDataTest, ThePaperFiveReferencesCarryTheirValuesInSi) {
  struct Expect {
    const char* ref;
    const char* name;
    double value;
  };
  for (const Expect& e : {Expect{"irc2021_r304_room_area", "habitable_room_area", 6.5},
                          Expect{"ndss2015_bedrooms", "bedroom_single_area", 7.5},
                          Expect{"ndss2015_bedrooms", "bedroom_double_area", 11.5},
                          Expect{"bco2019_workplace_density", "workspace_area_per_person", 10.0},
                          Expect{"hbn0301_patient_bedroom", "patient_bedroom_area", 15.0},
                          Expect{"aushfg_icu_room", "icu_room_area", 25.0}}) {
    auto code = kb_->building_code(e.ref);
    ASSERT_TRUE(code) << e.ref;
    bool found = false;
    for (const auto& k : code->constraints) {
      if (k.name != e.name) continue;
      found = true;
      EXPECT_NEAR(k.value, e.value, 0.01) << e.ref;
    }
    EXPECT_TRUE(found) << e.ref << " " << e.name;
  }
}

TEST_F(KnowledgeSeedDataTest, EntriesConformToTheirJsonSchemas) {
  for (const auto& [file, is_code] :
       {std::pair{"building_code.schema.json", true}, std::pair{"behavior_node.schema.json", false}}) {
    const auto path = std::filesystem::path(SOCSIM_SOURCE_DIR) / "schemas" / file;
    auto doc = parse_json_untrusted(read_file(path));
    ASSERT_TRUE(doc) << path;
    auto schema = JsonSchema::compile(*doc);
    ASSERT_TRUE(schema) << schema.error().message();
    if (is_code) {
      for (const auto& c : codes_) EXPECT_TRUE(schema->check(to_json(c), c.ref_id)) << c.ref_id;
    } else {
      for (const auto& n : nodes_) {
        auto s = schema->check(to_json(n), n.name);
        EXPECT_TRUE(s) << n.name << ": " << (s ? "" : s.error().message());
      }
    }
  }
}

TEST_F(KnowledgeSeedDataTest, TheNodeLibraryHasEveryNodeTheCrowdEngineImplements) {
  const std::map<std::string, NodeKind> required = {{"GoTo", NodeKind::kAction},
                                                    {"RegularNav", NodeKind::kAction},
                                                    {"SetGoal", NodeKind::kAction},
                                                    {"UpdateGoal", NodeKind::kAction},
                                                    {"IsGoalReached", NodeKind::kCondition},
                                                    {"StopAndWait", NodeKind::kAction},
                                                    {"TimeExpired", NodeKind::kCondition},
                                                    {"LookAtAgent", NodeKind::kAction},
                                                    {"ApproachAgent", NodeKind::kAction},
                                                    {"FollowAgent", NodeKind::kAction},
                                                    {"AvoidAgent", NodeKind::kAction},
                                                    {"ConversationFormation", NodeKind::kAction},
                                                    {"SetGroupWalk", NodeKind::kAction},
                                                    {"IsAgentClose", NodeKind::kCondition},
                                                    {"IsRobotVisible", NodeKind::kCondition},
                                                    {"IsRobotClose", NodeKind::kCondition},
                                                    {"RandomChance", NodeKind::kCondition},
                                                    {"IsAtPosition", NodeKind::kCondition},
                                                    {"JoinQueue", NodeKind::kAction},
                                                    {"AdvanceQueue", NodeKind::kAction},
                                                    {"ServeAtCounter", NodeKind::kAction},
                                                    {"SitAt", NodeKind::kAction},
                                                    {"Wander", NodeKind::kAction},
                                                    {"Gather", NodeKind::kAction},
                                                    {"Evacuate", NodeKind::kAction},
                                                    {"WaitAt", NodeKind::kAction},
                                                    {"FollowVelocityField", NodeKind::kAction},
                                                    {"Sequence", NodeKind::kControl},
                                                    {"Fallback", NodeKind::kControl},
                                                    {"ReactiveSequence", NodeKind::kControl},
                                                    {"ReactiveFallback", NodeKind::kControl},
                                                    {"Parallel", NodeKind::kControl},
                                                    {"SubTree", NodeKind::kControl},
                                                    {"Inverter", NodeKind::kDecorator},
                                                    {"Repeat", NodeKind::kDecorator},
                                                    {"RetryUntilSuccessful", NodeKind::kDecorator},
                                                    {"Timeout", NodeKind::kDecorator},
                                                    {"Delay", NodeKind::kDecorator},
                                                    {"ForceSuccess", NodeKind::kDecorator},
                                                    {"ForceFailure", NodeKind::kDecorator}};
  for (const auto& [name, kind] : required) {
    const BehaviorNode* n = node_or_alias(name);
    ASSERT_NE(n, nullptr) << name;
    EXPECT_EQ(n->kind, kind) << name;
  }
  for (const auto& n : nodes_) {
    // The example uses the node itself (by name or alias), and leaves have the agent they act for.
    bool shown = n.example.find("<" + n.name) != std::string::npos;
    for (const auto& a : n.aliases) shown = shown || n.example.find("<" + a) != std::string::npos;
    EXPECT_TRUE(shown) << n.name;
    EXPECT_FALSE(n.when_to_use.empty()) << n.name;
  }
}

// A few string scans stand in for an XML parser (std::regex recurses per character).
std::string strip_comments(std::string xml) {
  for (auto at = xml.find("<!--"); at != std::string::npos; at = xml.find("<!--", at)) {
    const auto close = xml.find("-->", at);
    xml.erase(at, close == std::string::npos ? std::string::npos : close + 3 - at);
  }
  return xml;
}

std::string attribute(std::string_view element, std::string_view name) {
  const std::string key = " " + std::string(name) + "=\"";
  const auto at = element.find(key);
  if (at == std::string::npos) return {};
  const auto begin = at + key.size();
  return std::string(element.substr(begin, element.find('"', begin) - begin));
}

std::vector<std::string> tag_names(const std::string& xml) {
  std::vector<std::string> out;
  for (std::size_t i = xml.find('<'); i != std::string::npos; i = xml.find('<', i + 1)) {
    std::size_t j = i + 1;
    while (j < xml.size() && (std::isalnum(static_cast<unsigned char>(xml[j])) || xml[j] == '_')) ++j;
    if (j > i + 1) out.push_back(xml.substr(i + 1, j - i - 1));
  }
  return out;
}

struct ModelPort {
  std::string direction, name, type;
};

// <Action|Condition|Decorator|Control ID="X"> … </…> of a TreeNodesModel, with their ports.
std::map<std::string, std::vector<ModelPort>> node_models(const std::string& xml) {
  std::map<std::string, std::vector<ModelPort>> out;
  for (std::string kind : {"Action", "Condition", "Decorator", "Control"}) {
    const std::string open = "<" + kind + " ID=\"";
    for (auto at = xml.find(open); at != std::string::npos; at = xml.find(open, at + 1)) {
      const auto head_end = xml.find('>', at);
      const std::string id = attribute(std::string_view(xml).substr(at, head_end - at), "ID");
      if (xml[head_end - 1] == '/') {
        out[id];
        continue;
      }
      const auto close = xml.find("</" + kind + ">", head_end);
      const std::string body = xml.substr(head_end, close - head_end);
      auto& ports = out[id];
      for (std::string port_tag : {"input_port", "output_port", "inout_port"}) {
        for (auto p = body.find("<" + port_tag); p != std::string::npos;
             p = body.find("<" + port_tag, p + 1)) {
          const std::string element = body.substr(p, body.find('>', p) - p);
          std::string type = attribute(element, "type");
          if (type == "std::string") type = "string";
          ports.push_back({port_tag == "input_port"    ? "in"
                           : port_tag == "output_port" ? "out"
                                                       : "inout",
                           attribute(element, "name"), type});
        }
      }
    }
  }
  return out;
}

// Every tag HuNavSim's trees use and every node its TreeNodesModel declares is in our library,
// and every port HuNavSim declares exists with the same direction and type.
TEST_F(KnowledgeSeedDataTest, HuNavSimTreesAndNodeModelsResolveAgainstTheLibrary) {
  const auto dir = std::filesystem::path(SOCSIM_SHARED_DIR) / "peers" / "hunav";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "HuNavSim peer files not found at " << dir;
  const std::set<std::string> structural = {"root",       "TreeNodesModel", "BehaviorTree", "include",
                                            "input_port", "output_port",    "inout_port",   "Action",
                                            "Condition",  "Decorator",      "Control"};
  int files = 0;
  std::set<std::string> checked;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".xml") continue;
    ++files;
    const std::string xml = strip_comments(read_file(entry.path()));
    for (const auto& tag : tag_names(xml)) {
      if (structural.count(tag)) continue;
      checked.insert(tag);
      EXPECT_NE(node_or_alias(tag), nullptr) << tag << " used in " << entry.path().filename();
    }
    for (const auto& [id, ports] : node_models(xml)) {
      const BehaviorNode* node = node_or_alias(id);
      ASSERT_NE(node, nullptr) << id << " declared in " << entry.path().filename();
      checked.insert(id);
      for (const auto& mp : ports) {
        const auto port = std::find_if(node->ports.begin(), node->ports.end(),
                                       [&](const Port& x) { return x.name == mp.name; });
        ASSERT_NE(port, node->ports.end()) << id << "." << mp.name;
        EXPECT_EQ(std::string(to_string(port->direction)), mp.direction) << id << "." << mp.name;
        if (!mp.type.empty()) {
          EXPECT_EQ(port->type, mp.type) << id << "." << mp.name;
        }
      }
    }
  }
  if (files == 0) GTEST_SKIP() << "no HuNavSim XML files in " << dir;
  EXPECT_GE(checked.size(), 20u);
}

}  // namespace
}  // namespace socsim::knowledge
