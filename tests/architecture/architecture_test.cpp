// The dependency rules of docs/ARCHITECTURE.md, checked on the tree: every `#include "core/…"` of a
// core module and every socsim_* in its socsim_module(...) PUBLIC/PRIVATE lists must be allowed by
// the rules block; a PUBLIC link needs a header of the module that includes the dependency; nothing
// in core/ includes server/ or a transport header. A second test shows the checker catching each
// kind of forbidden edge in a small tree written for it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/temp_dir.hpp"

namespace socsim::architecture {
namespace {
namespace fs = std::filesystem;
using Rules = std::map<std::string, std::set<std::string>>;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The ```rules block of ARCHITECTURE.md: "module: allowed allowed …" per line.
Rules read_rules(const fs::path& architecture_md) {
  const std::string text = read(architecture_md);
  Rules rules;
  const auto start = text.find("```rules\n");
  if (start == std::string::npos) return rules;
  const auto end = text.find("```", start + 9);
  std::istringstream block(text.substr(start + 9, end - start - 9));
  for (std::string line; std::getline(block, line);) {
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    auto& allowed = rules[line.substr(0, colon)];
    std::istringstream rest(line.substr(colon + 1));
    for (std::string m; rest >> m;) allowed.insert(m);
  }
  return rules;
}

std::vector<std::string> check_tree(const fs::path& root, const Rules& rules) {
  std::vector<std::string> violations;
  static const std::regex core_include(R"re(#include\s+"core/(\w+)/)re");
  static const std::regex server_include(R"re(#include\s+"server/)re");
  static const std::regex transport_include(
      R"re(#include\s+<(httplib\.h|boost/asio|boost/beast|sys/socket\.h|netinet/|arpa/inet\.h|curl/))re");
  std::map<std::string, std::set<std::string>> header_deps;  // module → modules its headers include
  for (const auto& dir : fs::directory_iterator(root / "core")) {
    if (!dir.is_directory()) continue;
    const std::string module = dir.path().filename().string();
    const auto rule = rules.find(module);
    if (rule == rules.end()) {
      violations.push_back("core/" + module + " has no row in the rules of docs/ARCHITECTURE.md");
      continue;
    }
    for (const auto& file : fs::directory_iterator(dir.path())) {
      const std::string ext = file.path().extension().string();
      if (ext != ".cpp" && ext != ".hpp") continue;
      const std::string text = read(file.path());
      const std::string where = "core/" + module + "/" + file.path().filename().string();
      for (std::sregex_iterator it(text.begin(), text.end(), core_include), end; it != end; ++it) {
        const std::string dep = (*it)[1];
        if (dep == module) continue;
        if (!rule->second.count(dep))
          violations.push_back(where + " includes core/" + dep + " (not allowed for " + module + ")");
        if (ext == ".hpp") header_deps[module].insert(dep);
      }
      if (std::regex_search(text, server_include)) violations.push_back(where + " includes server/");
      // libcurl is the LLM client's transport to its endpoint: allowed there only.
      std::smatch m;
      if (std::regex_search(text, m, transport_include) && !(module == "llm" && m[1] == "curl/"))
        violations.push_back(where + " includes the transport header <" + m[1].str() + ">");
    }
  }
  static const std::regex module_call(R"re(socsim_module\(\s*socsim_(\w+)([^)]*)\))re");
  for (const auto& dir : fs::directory_iterator(root / "core")) {
    const fs::path cmake = dir.path() / "CMakeLists.txt";
    if (!fs::exists(cmake)) continue;
    const std::string text = read(cmake);
    for (std::sregex_iterator it(text.begin(), text.end(), module_call), end; it != end; ++it) {
      const std::string module = (*it)[1];
      std::istringstream words((*it)[2].str());
      std::string section;
      for (std::string w; words >> w;) {
        if (w == "SOURCES" || w == "PUBLIC" || w == "PRIVATE") {
          section = w;
          continue;
        }
        if (section == "SOURCES" || w.rfind("socsim_", 0) != 0) continue;
        const std::string dep = w.substr(7);
        const std::string where = "core/" + module + "/CMakeLists.txt";
        if (!rules.count(module) || !rules.at(module).count(dep))
          violations.push_back(where + " links socsim_" + dep + " (not allowed for " + module + ")");
        else if (section == "PUBLIC" && !header_deps[module].count(dep))
          violations.push_back(where + " links socsim_" + dep + " PUBLIC but no header of " + module +
                               " includes it: link it PRIVATE");
      }
    }
  }
  return violations;
}

std::string joined(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += "  " + s + "\n";
  return out;
}

TEST(Architecture, TheTreeKeepsTheRulesOfArchitectureMd) {
  const fs::path root = SOCSIM_SOURCE_DIR;
  const Rules rules = read_rules(root / "docs/ARCHITECTURE.md");
  ASSERT_GE(rules.size(), 13u) << "the rules block of docs/ARCHITECTURE.md was not found";
  const auto violations = check_tree(root, rules);
  EXPECT_TRUE(violations.empty()) << "forbidden edges:\n" << joined(violations);
}

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

TEST(Architecture, EachKindOfForbiddenEdgeIsCaught) {
  const fs::path root = SOCSIM_SOURCE_DIR;
  const Rules rules = read_rules(root / "docs/ARCHITECTURE.md");
  testing::TempDir tree;
  const fs::path t = tree.path();
  // A tree that keeps the rules...
  write(t / "core/crowd/step.hpp", "#include \"core/world/world.hpp\"\n");
  write(
      t / "core/crowd/CMakeLists.txt",
      "socsim_module(socsim_crowd\n  SOURCES step.cpp\n  PUBLIC socsim_world\n  PRIVATE socsim_geometry)\n");
  write(t / "core/world/world.hpp", "#include \"core/geometry/types.hpp\"\n");
  ASSERT_TRUE(check_tree(t, rules).empty()) << joined(check_tree(t, rules));

  // ...then one forbidden edge at a time.
  write(t / "core/crowd/step.cpp", "#include \"core/store/store.hpp\"\n");
  auto v = check_tree(t, rules);
  ASSERT_EQ(v.size(), 1u) << joined(v);
  EXPECT_NE(v[0].find("core/crowd/step.cpp includes core/store"), std::string::npos) << v[0];
  fs::remove(t / "core/crowd/step.cpp");

  write(
      t / "core/crowd/CMakeLists.txt",
      "socsim_module(socsim_crowd\n  SOURCES step.cpp\n  PUBLIC socsim_world\n  PRIVATE socsim_knowledge)\n");
  v = check_tree(t, rules);
  ASSERT_EQ(v.size(), 1u) << joined(v);
  EXPECT_NE(v[0].find("links socsim_knowledge"), std::string::npos) << v[0];

  write(t / "core/crowd/CMakeLists.txt",
        "socsim_module(socsim_crowd\n  SOURCES step.cpp\n  PUBLIC socsim_world socsim_geometry)\n");
  v = check_tree(t, rules);
  ASSERT_EQ(v.size(), 1u) << joined(v);
  EXPECT_NE(v[0].find("PUBLIC but no header"), std::string::npos) << v[0];
  write(t / "core/crowd/CMakeLists.txt",
        "socsim_module(socsim_crowd SOURCES step.cpp PUBLIC socsim_world)\n");

  write(t / "core/world/export.cpp", "#include <boost/beast.hpp>\n#include \"server/routes.hpp\"\n");
  v = check_tree(t, rules);
  ASSERT_EQ(v.size(), 2u) << joined(v);
  fs::remove(t / "core/world/export.cpp");

  write(t / "core/world/world.hpp", "#include \"core/crowd/step.hpp\"\n");
  v = check_tree(t, rules);
  ASSERT_EQ(v.size(), 1u) << joined(v);
  EXPECT_NE(v[0].find("includes core/crowd (not allowed for world)"), std::string::npos) << v[0];

  write(t / "core/robots/arm.cpp", "");
  EXPECT_EQ(check_tree(t, rules).size(), 2u) << "a module without a rule row is itself a violation";
}

}  // namespace
}  // namespace socsim::architecture
