// Behaviour-tree interpreter: each control and decorator is ticked on small trees and the status
// of every child is checked after each tick (the style of BehaviorTree.CPP's own gtests), plus
// blackboard typing, SubTree remapping, <include> and the load-time errors with XML lines.
#include <filesystem>
#include <fstream>
#include <map>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/crowd/bt_document.hpp"

namespace socsim::crowd {
namespace {

using ::testing::HasSubstr;
constexpr BtStatus kIdle = BtStatus::kIdle;
constexpr BtStatus kRunning = BtStatus::kRunning;
constexpr BtStatus kSuccess = BtStatus::kSuccess;
constexpr BtStatus kFailure = BtStatus::kFailure;
constexpr BtStatus kSkipped = BtStatus::kSkipped;

struct Probe {
  int ticks = 0;
  int halts = 0;
};
std::map<std::string, Probe>* g_probes = nullptr;

// RUNNING for `ticks` ticks after it starts, then SUCCESS (or `result`).
class AsyncAction final : public BtNode {
 public:
  using BtNode::BtNode;

 protected:
  BtStatus on_tick() override {
    ++(*g_probes)[name()].ticks;
    if (status() != kRunning) count_ = 0;
    auto n = input<std::int64_t>("ticks");
    auto result = input<std::string>("result");
    if (!n || !result) return kFailure;
    if (count_++ < *n) return kRunning;
    return *result == "FAILURE" ? kFailure : kSuccess;
  }
  void on_halt() override { ++(*g_probes)[name()].halts; }

 private:
  std::int64_t count_ = 0;
};

// Returns what its `result` port says (usually a blackboard key the test changes).
class ResultCondition final : public BtNode {
 public:
  using BtNode::BtNode;

 protected:
  BtStatus on_tick() override {
    ++(*g_probes)[name()].ticks;
    auto result = input<std::string>("result");
    if (!result) return kFailure;
    return *result == "SUCCESS" ? kSuccess : kFailure;
  }
};

// Writes port `value` (a double) to the output port `out`.
class WriteAction final : public BtNode {
 public:
  using BtNode::BtNode;

 protected:
  BtStatus on_tick() override {
    auto v = input<double>("value");
    if (!v) return kFailure;
    (void)output("out", BtValue{*v * 2.0});
    return kSuccess;
  }
};

class BtTreeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    g_probes = &probes;
    registry = BtRegistry::builtins();
    auto in = [](std::string n, BtPortType t, std::optional<std::string> d = std::nullopt) {
      return BtPortSpec{std::move(n), BtPortDirection::kIn, t, std::move(d)};
    };
    ASSERT_TRUE(registry.add(
        {"Async",
         BtNodeKind::kAction,
         {in("ticks", BtPortType::kInt, "1"), in("result", BtPortType::kString, "SUCCESS")},
         [](const BtNodeInit& i) { return std::make_unique<AsyncAction>(i.spec, i.tree, i.blackboard); },
         {}}));
    ASSERT_TRUE(registry.add(
        {"Check",
         BtNodeKind::kCondition,
         {in("result", BtPortType::kString)},
         [](const BtNodeInit& i) { return std::make_unique<ResultCondition>(i.spec, i.tree, i.blackboard); },
         {"CheckCondition"}}));
    ASSERT_TRUE(registry.add(
        {"Write",
         BtNodeKind::kAction,
         {in("value", BtPortType::kDouble),
          BtPortSpec{"out", BtPortDirection::kOut, BtPortType::kDouble, {}}},
         [](const BtNodeInit& i) { return std::make_unique<WriteAction>(i.spec, i.tree, i.blackboard); },
         {}}));
  }
  void TearDown() override { g_probes = nullptr; }

  BtTree make(const std::string& xml) {
    BtLoadOptions options;
    options.seeded_keys.emplace_back("a", BtPortType::kString);
    options.seeded_keys.emplace_back("b", BtPortType::kString);
    auto doc = BtDocument::parse(xml, registry, options);
    EXPECT_TRUE(doc) << doc.error().message();
    if (!doc) return {};
    documents.push_back(*doc);
    BtTree t = doc->instantiate();
    t.blackboard().set("a", BtValue{std::string("SUCCESS")});
    t.blackboard().set("b", BtValue{std::string("SUCCESS")});
    return t;
  }
  Error error_of(const std::string& xml, const BtLoadOptions& options = {}) {
    auto doc = BtDocument::parse(xml, registry, options);
    EXPECT_FALSE(doc);
    return doc ? Error() : doc.error();
  }
  static BtStatus st(const BtTree& t, const char* name) { return t.find(name)->status(); }

  BtRegistry registry;
  std::vector<BtDocument> documents;
  std::map<std::string, Probe> probes;
};

std::string tree(const std::string& body) {
  return R"(<root BTCPP_format="4" main_tree_to_execute="T"><BehaviorTree ID="T">)" + body +
         "</BehaviorTree></root>";
}

TEST_F(BtTreeTest, SequenceResumesAtTheRunningChild) {
  BtTree t = make(
      tree(R"(<Sequence name="seq"><Check name="c" result="{a}"/><Async name="act" ticks="2"/></Sequence>)"));
  EXPECT_EQ(t.tick(0.0), kRunning);
  EXPECT_EQ(st(t, "c"), kSuccess);
  EXPECT_EQ(st(t, "act"), kRunning);
  t.blackboard().set("a", BtValue{std::string("FAILURE")});  // not re-checked: Sequence has memory
  EXPECT_EQ(t.tick(0.1), kRunning);
  EXPECT_EQ(t.tick(0.2), kSuccess);
  EXPECT_EQ(probes["c"].ticks, 1);
  EXPECT_EQ(probes["act"].ticks, 3);
  EXPECT_EQ(st(t, "c"), kIdle);  // children are reset once the sequence completes
  EXPECT_EQ(st(t, "act"), kIdle);
  EXPECT_EQ(t.tick(0.3), kFailure);  // restarted: the condition now fails
  EXPECT_EQ(probes["act"].ticks, 3);
}

TEST_F(BtTreeTest, ReactiveSequenceHaltsTheRunningActionWhenAConditionFails) {
  BtTree t = make(tree(
      R"(<ReactiveSequence name="rs"><Check name="c" result="{a}"/><Async name="act" ticks="5"/></ReactiveSequence>)"));
  EXPECT_EQ(t.tick(0.0), kRunning);
  EXPECT_EQ(t.tick(0.1), kRunning);
  EXPECT_EQ(probes["c"].ticks, 2);  // re-checked every tick
  EXPECT_EQ(st(t, "act"), kRunning);
  t.blackboard().set("a", BtValue{std::string("FAILURE")});
  EXPECT_EQ(t.tick(0.2), kFailure);
  EXPECT_EQ(probes["act"].halts, 1);
  EXPECT_EQ(st(t, "act"), kIdle);
  EXPECT_EQ(probes["act"].ticks, 2);
}

TEST_F(BtTreeTest, FallbackStopsAtTheFirstSuccess) {
  BtTree t = make(
      tree(R"(<Fallback name="fb"><Check name="c1" result="{a}"/><Async name="act" ticks="1"/></Fallback>)"));
  t.blackboard().set("a", BtValue{std::string("FAILURE")});
  EXPECT_EQ(t.tick(0.0), kRunning);
  EXPECT_EQ(st(t, "c1"), kFailure);
  EXPECT_EQ(st(t, "act"), kRunning);
  EXPECT_EQ(t.tick(0.1), kSuccess);
  EXPECT_EQ(probes["c1"].ticks, 1);
  t.blackboard().set("a", BtValue{std::string("SUCCESS")});
  EXPECT_EQ(t.tick(0.2), kSuccess);
  EXPECT_EQ(probes["act"].ticks, 2);  // not ticked: the first child succeeded
}

TEST_F(BtTreeTest, ReactiveFallbackLetsAHigherPriorityChildInterrupt) {
  BtTree t = make(tree(
      R"(<ReactiveFallback><Check name="urgent" result="{a}"/><Async name="idle" ticks="9"/></ReactiveFallback>)"));
  t.blackboard().set("a", BtValue{std::string("FAILURE")});
  EXPECT_EQ(t.tick(0.0), kRunning);
  EXPECT_EQ(t.tick(0.1), kRunning);
  EXPECT_EQ(st(t, "idle"), kRunning);
  t.blackboard().set("a", BtValue{std::string("SUCCESS")});
  EXPECT_EQ(t.tick(0.2), kSuccess);
  EXPECT_EQ(probes["idle"].halts, 1);
  EXPECT_EQ(st(t, "idle"), kIdle);
}

TEST_F(BtTreeTest, ParallelUsesSuccessAndFailureThresholds) {
  BtTree t = make(tree(R"(<Parallel success_count="1" failure_count="2">
      <Async name="fast" ticks="1"/><Async name="slow" ticks="4"/></Parallel>)"));
  EXPECT_EQ(t.tick(0.0), kRunning);
  EXPECT_EQ(st(t, "fast"), kRunning);
  EXPECT_EQ(st(t, "slow"), kRunning);
  EXPECT_EQ(t.tick(0.1), kSuccess);  // one success is enough; the slow child is halted
  EXPECT_EQ(probes["slow"].halts, 1);
  EXPECT_EQ(st(t, "slow"), kIdle);

  BtTree all = make(tree(R"(<Parallel><Async name="p1" ticks="1"/><Async name="p2" ticks="2"/></Parallel>)"));
  EXPECT_EQ(all.tick(0.0), kRunning);
  EXPECT_EQ(all.tick(0.1), kRunning);  // p1 done, p2 still running: -1 means all must succeed
  EXPECT_EQ(st(all, "p2"), kRunning);
  EXPECT_EQ(all.tick(0.2), kSuccess);
  EXPECT_EQ(probes["p1"].ticks, 2);  // a completed child is not ticked again

  BtTree fails = make(tree(R"(<Parallel success_count="2" failure_count="1">
      <Async name="good" ticks="3"/><Async name="bad" ticks="0" result="FAILURE"/></Parallel>)"));
  EXPECT_EQ(fails.tick(0.0), kFailure);
  EXPECT_EQ(probes["good"].halts, 1);
}

TEST_F(BtTreeTest, DecoratorsInvertAndForce) {
  BtTree inv = make(tree(R"(<Inverter><Check name="c" result="{a}"/></Inverter>)"));
  EXPECT_EQ(inv.tick(0.0), kFailure);
  inv.blackboard().set("a", BtValue{std::string("FAILURE")});
  EXPECT_EQ(inv.tick(0.1), kSuccess);
  BtTree running = make(tree(R"(<Inverter><Async name="r" ticks="1"/></Inverter>)"));
  EXPECT_EQ(running.tick(0.0), kRunning);  // RUNNING passes through
  EXPECT_EQ(running.tick(0.1), kFailure);

  BtTree fs = make(tree(R"(<ForceSuccess><Check result="FAILURE"/></ForceSuccess>)"));
  EXPECT_EQ(fs.tick(0.0), kSuccess);
  BtTree ff = make(tree(R"(<ForceFailure><Async name="f" ticks="1"/></ForceFailure>)"));
  EXPECT_EQ(ff.tick(0.0), kRunning);
  EXPECT_EQ(ff.tick(0.1), kFailure);
}

TEST_F(BtTreeTest, RepeatAndRetryCountCompletions) {
  BtTree rep = make(tree(R"(<Repeat num_cycles="3"><Check name="c" result="SUCCESS"/></Repeat>)"));
  EXPECT_EQ(rep.tick(0.0), kSuccess);
  EXPECT_EQ(probes["c"].ticks, 3);

  BtTree rep_async = make(tree(R"(<Repeat num_cycles="2"><Async name="a" ticks="1"/></Repeat>)"));
  EXPECT_EQ(rep_async.tick(0.0), kRunning);
  EXPECT_EQ(rep_async.tick(0.1), kRunning);  // first cycle done, the second starts in the same tick
  EXPECT_EQ(probes["a"].ticks, 3);
  EXPECT_EQ(rep_async.tick(0.2), kSuccess);

  BtTree rep_fail = make(tree(R"(<Repeat num_cycles="5"><Check name="f" result="FAILURE"/></Repeat>)"));
  EXPECT_EQ(rep_fail.tick(0.0), kFailure);
  EXPECT_EQ(probes["f"].ticks, 1);

  // Forever over a child that always succeeds at once: bounded work per tick, never done.
  BtTree forever = make(tree(R"(<Repeat num_cycles="-1"><Check name="e" result="SUCCESS"/></Repeat>)"));
  EXPECT_EQ(forever.tick(0.0), kRunning);
  EXPECT_EQ(probes["e"].ticks, kBtMaxLoopsPerTick);

  BtTree retry = make(tree(
      R"(<RetryUntilSuccessful num_attempts="3"><Check name="r" result="{a}"/></RetryUntilSuccessful>)"));
  retry.blackboard().set("a", BtValue{std::string("FAILURE")});
  EXPECT_EQ(retry.tick(0.0), kFailure);
  EXPECT_EQ(probes["r"].ticks, 3);
  retry.blackboard().set("a", BtValue{std::string("SUCCESS")});
  EXPECT_EQ(retry.tick(0.1), kSuccess);
  EXPECT_EQ(probes["r"].ticks, 4);
}

TEST_F(BtTreeTest, TimeoutAndDelayUseSimulatedTime) {
  BtTree to = make(tree(R"(<Timeout msec="250"><Async name="long" ticks="100"/></Timeout>)"));
  EXPECT_EQ(to.tick(1.0), kRunning);
  EXPECT_EQ(to.tick(1.2), kRunning);
  EXPECT_EQ(to.tick(1.25), kFailure);
  EXPECT_EQ(probes["long"].halts, 1);
  EXPECT_EQ(to.tick(2.0), kRunning);  // restarted with a fresh timer

  BtTree de = make(tree(R"(<Delay delay_msec="500"><Check name="c" result="SUCCESS"/></Delay>)"));
  EXPECT_EQ(de.tick(0.0), kRunning);
  EXPECT_EQ(de.tick(0.4), kRunning);
  EXPECT_EQ(probes["c"].ticks, 0);
  EXPECT_EQ(de.tick(0.5), kSuccess);
  EXPECT_EQ(probes["c"].ticks, 1);
}

TEST_F(BtTreeTest, RunOnceSkipsAfterTheFirstRunAsInBtCppV4) {
  // The HuNavSim warehouse pattern: set goals once, then fall through to navigation.
  BtTree t = make(tree(R"(<Fallback>
      <Sequence name="once"><RunOnce><Check name="set" result="SUCCESS"/></RunOnce>
        <Inverter><RunOnce><Check name="last" result="SUCCESS"/></RunOnce></Inverter></Sequence>
      <Async name="nav" ticks="0"/></Fallback>)"));
  EXPECT_EQ(t.tick(0.0), kSuccess);
  EXPECT_EQ(st(t, "once"), kIdle);
  EXPECT_EQ(probes["nav"].ticks, 1);
  EXPECT_EQ(t.tick(0.1), kSuccess);
  EXPECT_EQ(probes["set"].ticks, 1);  // never again
  EXPECT_EQ(probes["last"].ticks, 1);
  EXPECT_EQ(probes["nav"].ticks, 2);

  BtTree all_skipped = make(tree(R"(<Sequence><RunOnce><Check result="SUCCESS"/></RunOnce></Sequence>)"));
  EXPECT_EQ(all_skipped.tick(0.0), kSuccess);
  EXPECT_EQ(all_skipped.tick(0.1), kSkipped);
}

TEST_F(BtTreeTest, BlackboardPortsConvertTypesLikeBtCpp) {
  BtTree t = make(tree(
      R"(<Sequence><SetBlackboard output_key="x" value="2.5"/><Write value="{x}" out="{y}"/></Sequence>)"));
  EXPECT_EQ(t.tick(0.0), kSuccess);
  EXPECT_EQ(std::get<double>(*t.blackboard().get("y")), 5.0);

  EXPECT_EQ(std::get<bool>(*bt_convert(BtValue{std::string("True")}, BtPortType::kBool)), true);
  EXPECT_EQ(std::get<bool>(*bt_convert(BtValue{std::string("FALSE")}, BtPortType::kBool)), false);
  EXPECT_EQ(std::get<std::int64_t>(*bt_convert(BtValue{3.0}, BtPortType::kInt)), 3);
  EXPECT_FALSE(bt_convert(BtValue{3.5}, BtPortType::kInt));
  EXPECT_FALSE(bt_convert(BtValue{std::string("-1")}, BtPortType::kUnsigned));
  EXPECT_FALSE(bt_convert(BtValue{std::string("1.5x")}, BtPortType::kDouble));
  EXPECT_EQ(std::get<std::string>(*bt_convert(BtValue{std::int64_t{7}}, BtPortType::kString)), "7");

  // A blackboard value of the wrong type at run time: the node fails and the tree reports it.
  BtTree bad = make(tree(
      R"(<Sequence><SetBlackboard output_key="x" value="abc"/><Write name="w" value="{x}" out="{y}"/></Sequence>)"));
  EXPECT_EQ(bad.tick(0.0), kFailure);
  ASSERT_EQ(bad.context().errors.size(), 1u);
  EXPECT_THAT(bad.context().errors[0],
              HasSubstr("line 1: Write: port 'value' ({x}): 'abc' is not a valid double"));
}

TEST_F(BtTreeTest, SubTreeRemapsPortsInBothDialects) {
  const std::string sub = R"(<BehaviorTree ID="Sub"><Write value="{in}" out="{out}"/></BehaviorTree>)";
  BtTree v4 = make(R"(<root BTCPP_format="4" main_tree_to_execute="Main"><BehaviorTree ID="Main"><Sequence>
      <SetBlackboard output_key="p" value="1.5"/>
      <SubTree ID="Sub" in="{p}" out="{q}"/>
      <SubTree ID="Sub" in="4" out="{r}"/></Sequence></BehaviorTree>)" +
                   sub + "</root>");
  EXPECT_EQ(v4.tick(0.0), kSuccess);
  EXPECT_EQ(std::get<double>(*v4.blackboard().get("q")), 3.0);
  EXPECT_EQ(std::get<double>(*v4.blackboard().get("r")), 8.0);  // literal port of the subtree
  EXPECT_EQ(v4.blackboard().get("out"), nullptr);               // the subtree's own key stays private

  BtTree autoremap =
      make(R"(<root BTCPP_format="4" main_tree_to_execute="Main"><BehaviorTree ID="Main"><Sequence>
      <SetBlackboard output_key="in" value="0.5"/><SubTree ID="Sub" _autoremap="true"/></Sequence></BehaviorTree>)" +
           sub + "</root>");
  EXPECT_EQ(autoremap.tick(0.0), kSuccess);
  EXPECT_EQ(std::get<double>(*autoremap.blackboard().get("out")), 1.0);

  // v3 (no BTCPP_format): attribute values name parent keys, as HuNavSim's trees use them.
  BtTree v3 = make(R"(<root main_tree_to_execute="Main"><BehaviorTree ID="Main"><Sequence>
      <SetBlackboard output_key="p" value="{id}"/><SubTree ID="Sub" in="p" out="q"/></Sequence></BehaviorTree>)" +
                   sub + "</root>");
  v3.blackboard().set("id", BtValue{std::int64_t{21}});
  EXPECT_EQ(v3.tick(0.0), kSuccess);
  EXPECT_EQ(std::get<double>(*v3.blackboard().get("q")), 42.0);
}

TEST_F(BtTreeTest, IncludesResolveRelativeToTheFile) {
  const auto dir = std::filesystem::temp_directory_path() / ("bt_include_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir / "lib");
  std::ofstream(dir / "lib" / "walk.xml")
      << R"(<root><BehaviorTree ID="Walk"><Async name="walk" ticks="1"/></BehaviorTree></root>)";
  std::ofstream(dir / "main.xml") << R"(<root BTCPP_format="4" main_tree_to_execute="Main">
  <include path="lib/walk.xml"/>
  <BehaviorTree ID="Main"><SubTree ID="Walk"/></BehaviorTree>
</root>)";
  std::ofstream(dir / "loop.xml")
      << R"(<root main_tree_to_execute="A"><include path="loop.xml"/><BehaviorTree ID="A"><AlwaysSuccess/></BehaviorTree></root>)";
  std::ofstream(dir / "escape.xml")
      << R"(<root main_tree_to_execute="A"><include path="../x.xml"/><BehaviorTree ID="A"><AlwaysSuccess/></BehaviorTree></root>)";

  auto doc = BtDocument::load(dir / "main.xml", registry);
  ASSERT_TRUE(doc) << doc.error().message();
  BtTree t = doc->instantiate();
  EXPECT_EQ(t.tick(0.0), kRunning);
  EXPECT_EQ(t.running_leaf(), "Async");
  EXPECT_EQ(t.tick(0.1), kSuccess);

  auto loop = BtDocument::load(dir / "loop.xml", registry);
  ASSERT_FALSE(loop);
  EXPECT_THAT(loop.error().detail, HasSubstr("loop.xml:1: <include path=\"loop.xml\"> includes itself"));
  auto escape = BtDocument::load(dir / "escape.xml", registry);
  ASSERT_FALSE(escape);
  EXPECT_THAT(escape.error().detail, HasSubstr("leaves the scenario directory"));
  auto inline_include = BtDocument::parse(
      R"(<root><include path="x.xml"/><BehaviorTree ID="A"><AlwaysSuccess/></BehaviorTree></root>)",
      registry);
  ASSERT_FALSE(inline_include);
  EXPECT_THAT(inline_include.error().detail, HasSubstr("no base directory"));
  std::filesystem::remove_all(dir);
}

// Found while writing tests/fuzz (bt_xml): 2.4 KB of trees that each use the next twice made
// 2^25 nodes per instance (the target and every agent of a run hung), and a long chain of SubTrees
// recursed as deep as the chain in the checks and in instantiate().
TEST_F(BtTreeTest, InstancesThatExpandTooFarAreRefusedBeforeInstantiation) {
  auto chain = [](int trees, int uses) {
    std::string xml = "<root BTCPP_format=\"4\" main_tree_to_execute=\"T0\">";
    for (int i = 0; i < trees; ++i) {
      xml += "<BehaviorTree ID=\"T" + std::to_string(i) + "\"><Sequence>";
      for (int u = 0; u < uses; ++u) xml += "<SubTree ID=\"T" + std::to_string(i + 1) + "\"/>";
      xml += "</Sequence></BehaviorTree>";
    }
    return xml + "<BehaviorTree ID=\"T" + std::to_string(trees) + "\"><AlwaysSuccess/></BehaviorTree></root>";
  };
  const Error doubling = error_of(chain(24, 2));
  EXPECT_EQ(doubling.code, ErrorCode::kValidation);
  EXPECT_THAT(doubling.detail, HasSubstr("BehaviorTree 'T0' expands to more than 10000 nodes"));
  EXPECT_THAT(error_of(chain(20'000, 1)).detail, HasSubstr("nests SubTrees deeper than 256 levels"));
  // Within the limits: 2^10 copies of the leaf, 11 trees nested.
  auto fits = BtDocument::parse(chain(10, 2), registry);
  ASSERT_TRUE(fits) << fits.error().message();
  EXPECT_EQ(fits->instantiate().tick(0.0), kSuccess);
  BtLoadOptions small;
  small.max_instance_nodes = 100;
  EXPECT_THAT(error_of(chain(10, 2), small).detail, HasSubstr("expands to more than 100 nodes"));
}

TEST_F(BtTreeTest, LoadErrorsNameTheLineAndTheProblem) {
  struct Case {
    std::string body;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"<Sequence>\n<Asynk/></Sequence>", "line 2: unknown node 'Asynk' (did you mean 'Async'?)"},
      {"<Sequence>\n<Check/></Sequence>", "line 2: Check is missing the required port 'result' (string)"},
      {"<Sequence>\n\n<Async ticks=\"two\"/></Sequence>", "line 3: port 'ticks': 'two' is not a valid int"},
      {"<Async speed=\"1\"/>", "line 1: Async has no port 'speed' (ports: ticks, result)"},
      {"<Write value=\"1\" out=\"3\"/>", "output port 'out' must name a blackboard entry like {out}"},
      {"<Write value=\"{nowhere}\" out=\"{y}\"/>", "reads blackboard key '{nowhere}', which nothing writes"},
      {"<Async ticks=\"{dt}\"/>", "Async port 'ticks' is int but {dt} holds double"},
      {"<Inverter><Async/><Async/></Inverter>", "decorator Inverter needs exactly one child, it has 2"},
      {"<SubTree ID=\"Nope\"/>", "SubTree ID 'Nope' is not a BehaviorTree of this document"},
      {"<Async _skipIf=\"x\"/>", "attribute '_skipIf' (BT.CPP scripting/pre-conditions) is not supported"},
      {"<Repeat><Async/></Repeat>", "Repeat is missing the required port 'num_cycles' (int)"},
  };
  for (const Case& c : cases) {
    const Error e = error_of(tree(c.body));
    EXPECT_EQ(e.code, ErrorCode::kValidation) << c.body;
    EXPECT_THAT(e.detail, HasSubstr(c.message)) << c.body;
    ASSERT_FALSE(e.errors.empty());
    EXPECT_GT(e.errors[0].line, 0);
  }
  const Error syntax = error_of("<root>\n<BehaviorTree ID=\"A\"><Async></BehaviorTree></root>");
  EXPECT_EQ(syntax.code, ErrorCode::kBadRequest);
  EXPECT_EQ(syntax.errors.at(0).line, 2);
  EXPECT_THAT(error_of("<root><BehaviorTree ID=\"A\"><AlwaysSuccess/></BehaviorTree><BehaviorTree "
                       "ID=\"B\"><AlwaysSuccess/></BehaviorTree></root>")
                  .detail,
              HasSubstr("several trees and no main_tree_to_execute"));
  EXPECT_THAT(
      error_of(
          "<root main_tree_to_execute=\"A\"><BehaviorTree ID=\"A\"><SubTree ID=\"A\"/></BehaviorTree></root>")
          .detail,
      HasSubstr("includes itself"));
  // Aliases and the generic <Action ID> form are accepted.
  EXPECT_TRUE(BtDocument::parse(
      tree(R"(<Sequence><Condition ID="CheckCondition" result="SUCCESS"/><Action ID="Async"/></Sequence>)"),
      registry));
}

TEST_F(BtTreeTest, DocumentsBuiltAsElementsAreCheckedLikeParsedOnes) {
  auto element = [](std::string name, std::vector<std::pair<std::string, std::string>> attributes,
                    std::vector<world::XmlElement> children = {}) {
    world::XmlElement e;
    e.name = std::move(name);
    e.attributes = std::move(attributes);
    e.children = std::move(children);
    return e;
  };
  auto document = [&](world::XmlElement body) {
    return element("root", {{"BTCPP_format", "4"}, {"main_tree_to_execute", "T"}},
                   {element("BehaviorTree", {{"ID", "T"}}, {std::move(body)})});
  };
  auto doc =
      BtDocument::from_element(document(element("Sequence", {{"name", "seq"}},
                                                {element("Check", {{"name", "c"}, {"result", "SUCCESS"}}),
                                                 element("Async", {{"name", "act"}, {"ticks", "1"}})})),
                               registry);
  ASSERT_TRUE(doc) << doc.error().message();
  EXPECT_EQ(doc->main_tree(), "T");
  BtTree t = doc->instantiate();
  EXPECT_EQ(t.tick(0.0), kRunning);
  EXPECT_EQ(t.tick(0.1), kSuccess);
  EXPECT_EQ(probes["act"].ticks, 2);

  auto bad = BtDocument::from_element(document(element("Async", {{"ticks", "two"}})), registry);
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().code, ErrorCode::kValidation);
  EXPECT_THAT(bad.error().detail, HasSubstr("port 'ticks': 'two' is not a valid int"));
  EXPECT_THAT(BtDocument::from_element(document(element("Asynk", {})), registry).error().detail,
              HasSubstr("unknown node 'Asynk' (did you mean 'Async'?)"));
}

}  // namespace
}  // namespace socsim::crowd
