#include "core/interop/mcap_writer.hpp"

#include <zlib.h>
#include <zstd.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace socsim::interop {
namespace {

static_assert(std::endian::native == std::endian::little, "the record encoders copy host bytes");

constexpr std::string_view kMagic{"\x89MCAP0\r\n", 8};

enum Op : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kStatistics = 0x0B,
  kMetadata = 0x0C,
  kMetadataIndex = 0x0D,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};

template <class T>
void put(std::string& out, T v) {
  char raw[sizeof(T)];
  std::memcpy(raw, &v, sizeof(T));
  out.append(raw, sizeof(T));
}

void put_string(std::string& out, std::string_view s) {
  put(out, static_cast<std::uint32_t>(s.size()));
  out.append(s);
}

void put_string_map(std::string& out, const std::map<std::string, std::string>& m) {
  std::uint32_t bytes = 0;
  for (const auto& [k, v] : m) bytes += static_cast<std::uint32_t>(8 + k.size() + v.size());
  put(out, bytes);
  for (const auto& [k, v] : m) {
    put_string(out, k);
    put_string(out, v);
  }
}

// A record: opcode, uint64 content length, content.
void put_record(std::string& out, Op op, std::string_view content) {
  put(out, static_cast<std::uint8_t>(op));
  put(out, static_cast<std::uint64_t>(content.size()));
  out.append(content);
}

std::uint32_t crc32_of(std::string_view bytes, std::uint32_t crc = 0) {
  // zlib's crc32 is the IEEE CRC-32 MCAP names; it takes at most uInt bytes per call.
  uLong c = crc;
  while (!bytes.empty()) {
    const std::size_t n = std::min<std::size_t>(bytes.size(), 1u << 30);
    c = ::crc32(c, reinterpret_cast<const Bytef*>(bytes.data()), static_cast<uInt>(n));
    bytes.remove_prefix(n);
  }
  return static_cast<std::uint32_t>(c);
}

std::string schema_content(std::uint16_t id, std::string_view name, std::string_view encoding,
                           std::string_view data) {
  std::string c;
  put(c, id);
  put_string(c, name);
  put_string(c, encoding);
  put_string(c, data);  // uint32 length-prefixed bytes
  return c;
}

std::string channel_content(std::uint16_t id, std::uint16_t schema_id, std::string_view topic,
                            std::string_view encoding, const std::map<std::string, std::string>& metadata) {
  std::string c;
  put(c, id);
  put(c, schema_id);
  put_string(c, topic);
  put_string(c, encoding);
  put_string_map(c, metadata);
  return c;
}

}  // namespace

McapWriter::McapWriter(McapOptions options) : options_(std::move(options)) {
  out_.append(kMagic);
  std::string header;
  put_string(header, options_.profile);
  put_string(header, options_.library);
  put_record(out_, kHeader, header);
  if (options_.compression == McapCompression::kZstd) {
    for (void*& context : zstd_) {
      context = ZSTD_createCCtx();
      if (!context) throw std::bad_alloc();
    }
  }
}

McapWriter::~McapWriter() {
  for (auto& job : sealing_) job.wait();
  for (void* context : zstd_) ZSTD_freeCCtx(static_cast<ZSTD_CCtx*>(context));
}

std::uint16_t McapWriter::add_schema(std::string_view name, std::string_view encoding,
                                     std::string_view data) {
  flush_chunk();  // records reach the data section in call order
  drain();
  const auto id = static_cast<std::uint16_t>(schemas_.size() + 1);
  schemas_.push_back({id, std::string(name), std::string(encoding), std::string(data)});
  put_record(out_, kSchema, schema_content(id, name, encoding, data));
  return id;
}

std::uint16_t McapWriter::add_channel(std::uint16_t schema_id, std::string_view topic,
                                      std::string_view message_encoding,
                                      const std::map<std::string, std::string>& metadata) {
  if (schema_id > schemas_.size()) throw std::invalid_argument("McapWriter: unknown schema id");
  flush_chunk();
  drain();
  const auto id = static_cast<std::uint16_t>(channels_.size() + 1);
  channels_.push_back({id, schema_id, std::string(topic), std::string(message_encoding), metadata});
  put_record(out_, kChannel, channel_content(id, schema_id, topic, message_encoding, metadata));
  return id;
}

void McapWriter::add_message(std::uint16_t channel_id, std::uint64_t log_time, std::uint64_t publish_time,
                             std::string_view data) {
  if (channel_id == 0 || channel_id > channels_.size())
    throw std::invalid_argument("McapWriter: unknown channel id");
  ChannelRecord& channel = channels_[channel_id - 1];
  if (chunk_.records.empty()) {
    chunk_.start = chunk_.end = log_time;
  } else {
    chunk_.start = std::min(chunk_.start, log_time);
    chunk_.end = std::max(chunk_.end, log_time);
  }
  if (message_count_ == 0) {
    start_time_ = end_time_ = log_time;
  } else {
    start_time_ = std::min(start_time_, log_time);
    end_time_ = std::max(end_time_, log_time);
  }
  std::string& records = chunk_.records;
  chunk_.index[channel_id].emplace_back(log_time, records.size());
  put(records, static_cast<std::uint8_t>(kMessage));
  put(records, static_cast<std::uint64_t>(2 + 4 + 8 + 8 + data.size()));
  put(records, channel_id);
  put(records, channel.sequence++);
  put(records, log_time);
  put(records, publish_time);
  records.append(data);
  ++channel.count;
  ++message_count_;
  if (records.size() >= options_.chunk_size) flush_chunk();
}

void McapWriter::add_metadata(std::string_view name, const std::map<std::string, std::string>& metadata) {
  flush_chunk();
  drain();
  std::string c;
  put_string(c, name);
  put_string_map(c, metadata);
  const std::uint64_t offset = out_.size();
  put_record(out_, kMetadata, c);
  metadata_indexes_.push_back({offset, out_.size() - offset, std::string(name)});
}

McapWriter::SealedChunk McapWriter::seal(OpenChunk chunk, void* zstd) const {
  SealedChunk sealed;
  sealed.crc = crc32_of(chunk.records);
  if (options_.compression == McapCompression::kZstd) {
    sealed.compressed.resize(ZSTD_compressBound(chunk.records.size()));
    const std::size_t n =
        ZSTD_compressCCtx(static_cast<ZSTD_CCtx*>(zstd), sealed.compressed.data(), sealed.compressed.size(),
                          chunk.records.data(), chunk.records.size(), options_.zstd_level);
    if (ZSTD_isError(n)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(n));
    sealed.compressed.resize(n);
  }
  sealed.chunk = std::move(chunk);
  return sealed;
}

void McapWriter::write_chunk(const SealedChunk& sealed) {
  const OpenChunk& chunk = sealed.chunk;
  const bool zstd = options_.compression == McapCompression::kZstd;
  const std::string_view compression = zstd ? "zstd" : "";
  const std::string_view records =
      zstd ? std::string_view(sealed.compressed) : std::string_view(chunk.records);
  ChunkIndexRecord index{};
  index.start_time = chunk.start;
  index.end_time = chunk.end;
  index.offset = out_.size();
  index.compressed_size = records.size();
  index.uncompressed_size = chunk.records.size();

  put(out_, static_cast<std::uint8_t>(kChunk));
  put(out_, static_cast<std::uint64_t>(8 + 8 + 8 + 4 + 4 + compression.size() + 8 + records.size()));
  put(out_, chunk.start);
  put(out_, chunk.end);
  put(out_, static_cast<std::uint64_t>(chunk.records.size()));
  put(out_, sealed.crc);
  put_string(out_, compression);
  put(out_, static_cast<std::uint64_t>(records.size()));
  out_.append(records);
  index.length = out_.size() - index.offset;

  const std::uint64_t indexes_start = out_.size();
  for (const auto& [channel, entries] : chunk.index) {  // ascending channel id
    index.index_offsets[channel] = out_.size();
    put(out_, static_cast<std::uint8_t>(kMessageIndex));
    put(out_, static_cast<std::uint64_t>(2 + 4 + entries.size() * 16));
    put(out_, channel);
    put(out_, static_cast<std::uint32_t>(entries.size() * 16));
    for (const auto& [time, offset] : entries) {
      put(out_, time);
      put(out_, offset);
    }
  }
  index.index_length = out_.size() - indexes_start;
  chunk_indexes_.push_back(std::move(index));
}

void McapWriter::flush_chunk() {
  if (chunk_.records.empty()) return;
  if (sealing_.size() == kThreads) write_oldest();
  void* zstd = zstd_[sealed_count_++ % kThreads];
  sealing_.push_back(std::async(std::launch::async, [this, zstd, chunk = std::move(chunk_)]() mutable {
    return seal(std::move(chunk), zstd);
  }));
  chunk_ = OpenChunk{};
  if (!spare_.empty()) {
    chunk_.records = std::move(spare_.back());
    spare_.pop_back();
    chunk_.records.clear();
  }
}

void McapWriter::write_oldest() {
  SealedChunk sealed = sealing_.front().get();
  sealing_.pop_front();
  write_chunk(sealed);
  spare_.push_back(std::move(sealed.chunk.records));
}

void McapWriter::drain() {
  while (!sealing_.empty()) write_oldest();
}

std::string McapWriter::finish() {
  flush_chunk();
  drain();
  std::string data_end;
  put(data_end, crc32_of(out_));
  put_record(out_, kDataEnd, data_end);

  // The summary, grouped by opcode; each group is listed in a Summary Offset record.
  const std::uint64_t summary_start = out_.size();
  std::vector<std::pair<Op, std::pair<std::uint64_t, std::uint64_t>>> groups;
  auto group = [&](Op op, auto&& write_all) {
    const std::uint64_t start = out_.size();
    write_all();
    if (out_.size() > start) groups.push_back({op, {start, out_.size() - start}});
  };
  group(kSchema, [&] {
    for (const auto& s : schemas_)
      put_record(out_, kSchema, schema_content(s.id, s.name, s.encoding, s.data));
  });
  group(kChannel, [&] {
    for (const auto& c : channels_)
      put_record(out_, kChannel, channel_content(c.id, c.schema_id, c.topic, c.encoding, c.metadata));
  });
  group(kChunkIndex, [&] {
    for (const auto& ci : chunk_indexes_) {
      std::string c;
      put(c, ci.start_time);
      put(c, ci.end_time);
      put(c, ci.offset);
      put(c, ci.length);
      put(c, static_cast<std::uint32_t>(ci.index_offsets.size() * 10));
      for (const auto& [channel, offset] : ci.index_offsets) {
        put(c, channel);
        put(c, offset);
      }
      put(c, ci.index_length);
      put_string(c, options_.compression == McapCompression::kZstd ? "zstd" : "");
      put(c, ci.compressed_size);
      put(c, ci.uncompressed_size);
      put_record(out_, kChunkIndex, c);
    }
  });
  group(kMetadataIndex, [&] {
    for (const auto& m : metadata_indexes_) {
      std::string c;
      put(c, m.offset);
      put(c, m.length);
      put_string(c, m.name);
      put_record(out_, kMetadataIndex, c);
    }
  });
  group(kStatistics, [&] {
    std::string c;
    put(c, message_count_);
    put(c, static_cast<std::uint16_t>(schemas_.size()));
    put(c, static_cast<std::uint32_t>(channels_.size()));
    put(c, std::uint32_t{0});  // attachments
    put(c, static_cast<std::uint32_t>(metadata_indexes_.size()));
    put(c, static_cast<std::uint32_t>(chunk_indexes_.size()));
    put(c, start_time_);
    put(c, end_time_);
    put(c, static_cast<std::uint32_t>(channels_.size() * 10));
    for (const auto& ch : channels_) {
      put(c, ch.id);
      put(c, ch.count);
    }
    put_record(out_, kStatistics, c);
  });
  const std::uint64_t offsets_start = out_.size();
  for (const auto& [op, range] : groups) {
    std::string c;
    put(c, static_cast<std::uint8_t>(op));
    put(c, range.first);
    put(c, range.second);
    put_record(out_, kSummaryOffset, c);
  }

  // Footer: its CRC covers the summary through summary_offset_start.
  put(out_, static_cast<std::uint8_t>(kFooter));
  put(out_, std::uint64_t{8 + 8 + 4});
  put(out_, summary_start);
  put(out_, offsets_start);
  put(out_, crc32_of(std::string_view(out_).substr(summary_start)));
  out_.append(kMagic);

  std::string file = std::move(out_);
  out_.clear();
  return file;
}

}  // namespace socsim::interop
