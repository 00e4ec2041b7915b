// The MCAP writer, the CDR serializer and the card export, read back record by record: magic,
// header, data-section, chunk and summary CRCs, message indexes pointing at their messages,
// summary offsets, statistics; CDR alignment and a People message decoded field by field.
// (tests/e2e/mcap.test.mjs reads the same files with @mcap/core and @foxglove/rosmsg2-serialization.)
#include <zlib.h>
#include <zstd.h>

#include <cmath>
#include <cstring>
#include <map>

#include <gtest/gtest.h>

#include "core/crowd/scenario_runner.hpp"
#include "core/interop/cdr_writer.hpp"
#include "core/interop/mcap_export.hpp"
#include "core/interop/mcap_writer.hpp"
#include "core/interop/pedsim_program.hpp"
#include "core/interop/people_msgs.hpp"
#include "tests/core/interop/interop_text.hpp"

namespace socsim::interop {
namespace {

// Little-endian reads at a moving offset; throws past the end so a bad length fails the test.
struct Reader {
  std::string_view bytes;
  std::size_t pos = 0;
  template <class T>
  T get() {
    if (pos + sizeof(T) > bytes.size()) throw std::out_of_range("read past the end");
    T v;
    std::memcpy(&v, bytes.data() + pos, sizeof(T));
    pos += sizeof(T);
    return v;
  }
  std::string_view take(std::size_t n) {
    if (pos + n > bytes.size()) throw std::out_of_range("read past the end");
    auto s = bytes.substr(pos, n);
    pos += n;
    return s;
  }
  std::string_view string() { return take(get<std::uint32_t>()); }
  // CDR: aligned to the value's size, counted after the 4-byte encapsulation header.
  template <class T>
  T cdr() {
    pos += (sizeof(T) - (pos - 4) % sizeof(T)) % sizeof(T);
    return get<T>();
  }
  std::string cdr_string() {
    const auto n = cdr<std::uint32_t>();
    auto s = take(n);
    EXPECT_EQ(s.back(), '\0');
    return std::string(s.substr(0, n - 1));
  }
};

std::uint32_t crc(std::string_view s) {
  return static_cast<std::uint32_t>(
      ::crc32(0, reinterpret_cast<const Bytef*>(s.data()), static_cast<uInt>(s.size())));
}

struct Record {
  std::uint8_t op;
  std::size_t offset;
  std::string_view content;
};

std::vector<Record> records(std::string_view bytes, std::size_t from, std::size_t to) {
  std::vector<Record> out;
  Reader r{bytes, from};
  while (r.pos < to) {
    const std::size_t at = r.pos;
    const auto op = r.get<std::uint8_t>();
    const auto len = r.get<std::uint64_t>();
    out.push_back({op, at, r.take(len)});
  }
  EXPECT_EQ(r.pos, to);
  return out;
}

std::string decompress(std::string_view compression, std::string_view data, std::size_t size) {
  if (compression.empty()) return std::string(data);
  EXPECT_EQ(compression, "zstd");
  std::string out(size, '\0');
  const std::size_t n = ZSTD_decompress(out.data(), out.size(), data.data(), data.size());
  EXPECT_FALSE(ZSTD_isError(n));
  EXPECT_EQ(n, size);
  return out;
}

// Checks the structure of a whole file; returns the messages per channel as (log_time, data).
std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::string>>> read_mcap(
    const std::string& file) {
  const std::string_view magic("\x89MCAP0\r\n", 8);
  EXPECT_EQ(std::string_view(file).substr(0, 8), magic);
  EXPECT_EQ(std::string_view(file).substr(file.size() - 8), magic);
  // Footer: the last record before the magic, 1 + 8 + 20 bytes.
  Reader footer{file, file.size() - 8 - 29};
  EXPECT_EQ(footer.get<std::uint8_t>(), 0x02);
  EXPECT_EQ(footer.get<std::uint64_t>(), 20u);
  const auto summary_start = footer.get<std::uint64_t>();
  const auto offsets_start = footer.get<std::uint64_t>();
  const auto summary_crc = footer.get<std::uint32_t>();
  EXPECT_EQ(summary_crc, crc(std::string_view(file).substr(summary_start, file.size() - 12 - summary_start)));

  std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::string>>> messages;
  std::map<std::uint8_t, std::size_t> data_ops;
  const auto data = records(file, 8, summary_start);
  EXPECT_EQ(data.front().op, 0x01);
  EXPECT_EQ(data.back().op, 0x0F);  // Data End, with the CRC of everything before it
  EXPECT_EQ(Reader{data.back().content}.get<std::uint32_t>(),
            crc(std::string_view(file).substr(0, data.back().offset)));
  std::vector<std::size_t> chunk_offsets;
  for (std::size_t i = 0; i < data.size(); ++i) {
    ++data_ops[data[i].op];
    if (data[i].op != 0x06) continue;
    chunk_offsets.push_back(data[i].offset);
    Reader c{data[i].content};
    const auto start = c.get<std::uint64_t>(), end = c.get<std::uint64_t>();
    const auto size = c.get<std::uint64_t>();
    const auto records_crc = c.get<std::uint32_t>();
    const auto compression = c.string();
    const auto inner = decompress(compression, c.take(c.get<std::uint64_t>()), size);
    EXPECT_EQ(crc(inner), records_crc);
    std::map<std::size_t, std::uint64_t> times;  // offset in the chunk → log time
    for (const Record& m : records(inner, 0, inner.size())) {
      EXPECT_EQ(m.op, 0x05);
      Reader mr{m.content};
      const auto channel = mr.get<std::uint16_t>();
      mr.get<std::uint32_t>();
      const auto log_time = mr.get<std::uint64_t>();
      EXPECT_EQ(mr.get<std::uint64_t>(), log_time);
      EXPECT_GE(log_time, start);
      EXPECT_LE(log_time, end);
      times[m.offset] = log_time;
      messages[channel].emplace_back(log_time, std::string(m.content.substr(22)));
    }
    // The Message Index records after the chunk list every message at its offset and time.
    std::size_t indexed = 0;
    for (std::size_t k = i + 1; k < data.size() && data[k].op == 0x07; ++k) {
      Reader mi{data[k].content};
      mi.get<std::uint16_t>();
      const auto n = mi.get<std::uint32_t>() / 16;
      for (std::uint32_t e = 0; e < n; ++e) {
        const auto t = mi.get<std::uint64_t>();
        const auto off = mi.get<std::uint64_t>();
        EXPECT_EQ(times.at(off), t);
        ++indexed;
      }
    }
    EXPECT_EQ(indexed, times.size());
  }

  // Summary: grouped by opcode, each group in a Summary Offset record; one Chunk Index per chunk.
  const auto summary = records(file, summary_start, offsets_start);
  std::map<std::uint8_t, std::pair<std::size_t, std::size_t>> groups;  // op → (start, length)
  std::vector<std::uint64_t> indexed_chunks;
  std::uint64_t stat_messages = 0;
  for (const Record& r : summary) {
    auto& g = groups[r.op];
    if (g.second == 0) g.first = r.offset;
    g.second = r.offset + 9 + r.content.size() - g.first;
    if (r.op == 0x08) {
      Reader ci{r.content};
      ci.get<std::uint64_t>();
      ci.get<std::uint64_t>();
      indexed_chunks.push_back(ci.get<std::uint64_t>());
    }
    if (r.op == 0x0B) stat_messages = Reader{r.content}.get<std::uint64_t>();
  }
  EXPECT_EQ(indexed_chunks, chunk_offsets);
  std::uint64_t total = 0;
  for (const auto& [ch, list] : messages) total += list.size();
  EXPECT_EQ(stat_messages, total);
  const auto offsets = records(file, offsets_start, file.size() - 8 - 29);
  EXPECT_EQ(offsets.size(), groups.size());
  for (const Record& r : offsets) {
    Reader so{r.content};
    const auto op = so.get<std::uint8_t>();
    EXPECT_EQ(so.get<std::uint64_t>(), groups.at(op).first);
    EXPECT_EQ(so.get<std::uint64_t>(), groups.at(op).second);
  }
  return messages;
}

TEST(CdrWriter, AlignsEachValueToItsSizeAfterTheEncapsulationHeader) {
  CdrWriter w;
  w.u8(7);
  w.u32(0x01020304);
  w.u8(1);
  w.f64(1.5);
  w.string("ab");
  const std::string expected = std::string("\x00\x01\x00\x00", 4) + std::string("\x07\x00\x00\x00", 4) +
                               std::string("\x04\x03\x02\x01", 4) +
                               std::string("\x01\x00\x00\x00\x00\x00\x00\x00", 8) +
                               std::string("\x00\x00\x00\x00\x00\x00\xf8\x3f", 8) +
                               std::string(
                                   "\x03\x00\x00\x00"
                                   "ab\x00",
                                   7);
  EXPECT_EQ(w.bytes(), expected);
  w.reset();
  EXPECT_EQ(w.bytes().size(), 4u);
}

TEST(PeopleMsgs, DefinitionIsPeopleThenEveryDependencyOnce) {
  const std::string& def = people_msg_definition();
  EXPECT_EQ(def.rfind("# Every pedestrian", 0), 0u) << def.substr(0, 80);
  for (const char* type :
       {"std_msgs/Header", "builtin_interfaces/Time", "socsim_people_msgs/Person", "geometry_msgs/Pose",
        "geometry_msgs/Point", "geometry_msgs/Quaternion", "geometry_msgs/Twist", "geometry_msgs/Vector3",
        "socsim_people_msgs/Intent", "socsim_people_msgs/Proxemics", "socsim_people_msgs/PersonMetadata",
        "socsim_people_msgs/Group"}) {
    const std::string section = std::string(80, '=') + "\nMSG: " + type + "\n";
    const auto at = def.find(section);
    ASSERT_NE(at, std::string::npos) << type;
    EXPECT_EQ(def.find(section, at + 1), std::string::npos) << type;
    EXPECT_NE(def[at + section.size()], '=') << type << " has an empty definition";
  }
  EXPECT_TRUE(people_msg_file("Nobody").empty());
  EXPECT_NE(people_msg_file("Person").find("Proxemics proxemics"), std::string::npos);
}

TEST(PeopleMsgs, CdrDecodesBackToTheStates) {
  crowd::PedestrianState a;
  a.id = crowd::AgentId(3);
  a.pose = {1.25, -2.5, 0.5};
  a.twist = {0.75, -0.125, 0.25};
  a.activity = crowd::Activity::kQueuing;
  a.role = "staff";
  a.intent = {"counter_1", 2};
  a.group_id = 4;
  a.proxemics = {0.4, 1.0, 3.0, 0.8};
  a.metadata = {123456789012345ULL, "JoinQueue", {"vip", "tall"}};
  crowd::PedestrianState b = a;
  b.id = crowd::AgentId(9);
  b.pose = {3.25, 0.5, -1.0};
  b.metadata.tags.clear();
  crowd::PedestrianState c;  // alone
  c.id = crowd::AgentId(10);
  const std::vector<crowd::PedestrianState> people{a, b, c};

  CdrWriter w;
  encode_people_cdr(w, 12.3, "map", people);
  Reader r{w.bytes(), 4};
  EXPECT_EQ(r.cdr<std::int32_t>(), 12);
  EXPECT_EQ(r.cdr<std::uint32_t>(), 300000000u);
  EXPECT_EQ(r.cdr_string(), "map");
  ASSERT_EQ(r.cdr<std::uint32_t>(), 3u);
  for (const auto& p : people) {
    EXPECT_EQ(r.cdr<std::uint32_t>(), p.id.value());
    EXPECT_EQ(r.cdr<double>(), p.pose.x);
    EXPECT_EQ(r.cdr<double>(), p.pose.y);
    EXPECT_EQ(r.cdr<double>(), 0.0);
    const double qx = r.cdr<double>(), qy = r.cdr<double>(), qz = r.cdr<double>(), qw = r.cdr<double>();
    EXPECT_EQ(qx, 0.0);
    EXPECT_EQ(qy, 0.0);
    // Components on a 2^-12 grid: the heading within 5e-4 rad (0.03 degrees).
    EXPECT_NEAR(2 * std::atan2(qz, qw), p.pose.yaw, 5e-4);
    EXPECT_EQ(qz * 4096, std::round(qz * 4096));
    EXPECT_EQ(qw * 4096, std::round(qw * 4096));
    EXPECT_EQ(r.cdr<double>(), p.twist.vx);
    EXPECT_EQ(r.cdr<double>(), p.twist.vy);
    EXPECT_EQ(r.cdr<double>(), 0.0);
    EXPECT_EQ(r.cdr<double>(), 0.0);
    EXPECT_EQ(r.cdr<double>(), 0.0);
    EXPECT_EQ(r.cdr<double>(), p.twist.omega);
    EXPECT_EQ(r.cdr<std::uint8_t>(), static_cast<std::uint8_t>(p.activity));
    EXPECT_EQ(r.cdr_string(), p.role);
    EXPECT_EQ(r.cdr_string(), p.intent.target);
    EXPECT_EQ(r.cdr<std::int64_t>(), p.intent.goal_id);
    EXPECT_EQ(r.cdr<std::int64_t>(), p.group_id);
    EXPECT_EQ(r.cdr<double>(), p.proxemics.intimate_radius);
    EXPECT_EQ(r.cdr<double>(), p.proxemics.comfort_radius);
    EXPECT_EQ(r.cdr<double>(), p.proxemics.social_radius);
    EXPECT_EQ(r.cdr<double>(), p.proxemics.compliance);
    EXPECT_EQ(r.cdr<std::uint64_t>(), p.metadata.seed);
    EXPECT_EQ(r.cdr_string(), p.metadata.bt_node);
    ASSERT_EQ(r.cdr<std::uint32_t>(), p.metadata.tags.size());
    for (const auto& tag : p.metadata.tags) EXPECT_EQ(r.cdr_string(), tag);
  }
  ASSERT_EQ(r.cdr<std::uint32_t>(), 1u);  // one group: a and b
  EXPECT_EQ(r.cdr<std::int64_t>(), 4);
  ASSERT_EQ(r.cdr<std::uint32_t>(), 2u);
  EXPECT_EQ(r.cdr<std::uint32_t>(), 3u);
  EXPECT_EQ(r.cdr<std::uint32_t>(), 9u);
  EXPECT_EQ(r.cdr<double>(), 2.25);
  EXPECT_EQ(r.cdr<double>(), -1.0);
  EXPECT_EQ(r.cdr<double>(), 0.0);
  EXPECT_EQ(r.pos, w.bytes().size());
}

TEST(McapWriter, EmptyFileHasHeaderDataEndSummaryAndFooter) {
  McapWriter w;
  const std::string file = w.finish();
  EXPECT_TRUE(read_mcap(file).empty());
}

TEST(McapWriter, ChunksIndexesAndSummaryAgreeCompressedOrNot) {
  for (McapCompression compression : {McapCompression::kNone, McapCompression::kZstd}) {
    McapOptions options;
    options.compression = compression;
    options.chunk_size = 256;  // several chunks
    McapWriter w(options);
    const auto schema = w.add_schema("test/Thing", "jsonschema", R"({"type":"object"})");
    const auto a = w.add_channel(schema, "/a", "json");
    const auto b = w.add_channel(schema, "/b", "json", {{"k", "v"}});
    w.add_metadata("meta", {{"x", "1"}});
    for (std::uint64_t i = 0; i < 50; ++i) {
      w.add_message(a, i * 100, i * 100, "{\"i\":" + std::to_string(i) + "}");
      if (i % 5 == 0) w.add_message(b, i * 100 + 1, i * 100 + 1, "{}");
    }
    EXPECT_THROW(w.add_message(7, 0, 0, "x"), std::invalid_argument);
    const std::string file = w.finish();
    const auto messages = read_mcap(file);
    ASSERT_EQ(messages.at(a).size(), 50u);
    ASSERT_EQ(messages.at(b).size(), 10u);
    for (std::uint64_t i = 0; i < 50; ++i) {
      EXPECT_EQ(messages.at(a)[i].first, i * 100);
      EXPECT_EQ(messages.at(a)[i].second, "{\"i\":" + std::to_string(i) + "}");
    }
  }
}

TEST(McapExport, CardLogBecomesPeopleAndSceneMessagesAtTheFrameTimes) {
  const testing::HallRun hall = testing::run_hall(2.0);
  const scenario::TrajectoryLog& log = hall.log;
  const world::World& world = hall.imported.scenario.world;
  ASSERT_GT(log.frame_count(), 10u);

  McapExportOptions options;
  options.card_id = "crd_test";
  const auto file = export_mcap(log, world, options);
  ASSERT_TRUE(file) << file.error().message();
  const auto again = export_mcap(log, world, options);
  ASSERT_TRUE(again);
  EXPECT_EQ(*file, *again) << "the export is deterministic";
  const auto messages = read_mcap(*file);
  const auto& people = messages.at(1);
  ASSERT_EQ(people.size(), log.frame_count());
  ASSERT_EQ(messages.at(2).size(), 1u);  // the world, once
  ASSERT_EQ(messages.at(3).size(), log.frame_count());
  const Json world_scene = Json::parse(messages.at(2)[0].second);
  EXPECT_EQ(world_scene["entities"][0]["cubes"].size(), world.walls().size());
  for (std::size_t f = 0; f < log.frame_count(); ++f) {
    EXPECT_EQ(people[f].first, to_nanoseconds(log.frame_time(f)));
    Reader r{people[f].second, 4};
    r.cdr<std::int32_t>();
    r.cdr<std::uint32_t>();
    EXPECT_EQ(r.cdr_string(), "map");
    ASSERT_EQ(r.cdr<std::uint32_t>(), log.frame(f).size());
    EXPECT_EQ(r.cdr<std::uint32_t>(), log.frame(f)[0].id);
    EXPECT_EQ(r.cdr<double>(), static_cast<double>(log.frame(f)[0].x));
    const Json scene = Json::parse(messages.at(3)[f].second);
    EXPECT_EQ(scene["entities"][0]["cylinders"].size(), log.frame(f).size());
  }

  options.roles = {{"adult", {{"radius", -1}}}};
  EXPECT_FALSE(export_mcap(log, world, options));
}

}  // namespace
}  // namespace socsim::interop
