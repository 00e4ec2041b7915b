#pragma once
// An MCAP (v0) writer, after the format specification (mcap.dev/spec): Header, Schema and Channel
// records, Messages in Chunks (CRC32 of the records, zstd-compressed or not) each followed by its
// Message Index records, Metadata, Data End, then the summary (Schemas, Channels, Chunk Indexes,
// Metadata Indexes, Statistics), Summary Offsets and the Footer. Writes into memory; the bytes
// depend only on what was added (deterministic).
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace socsim::interop {

enum class McapCompression { kNone, kZstd };

struct McapOptions {
  std::string profile;  // "ros2" for files ros2 bag reads
  std::string library = "socsim";
  McapCompression compression = McapCompression::kZstd;
  int zstd_level = 3;
  std::size_t chunk_size = 1u << 20;  // uncompressed bytes at which a chunk is closed
};

class McapWriter {
 public:
  explicit McapWriter(McapOptions options = {});
  McapWriter(const McapWriter&) = delete;
  McapWriter& operator=(const McapWriter&) = delete;
  ~McapWriter();

  // Ids are handed out from 1 in call order.
  std::uint16_t add_schema(std::string_view name, std::string_view encoding, std::string_view data);
  std::uint16_t add_channel(std::uint16_t schema_id, std::string_view topic,
                            std::string_view message_encoding,
                            const std::map<std::string, std::string>& metadata = {});
  // Times in nanoseconds; the sequence number counts per channel from 0.
  void add_message(std::uint16_t channel_id, std::uint64_t log_time, std::uint64_t publish_time,
                   std::string_view data);
  void add_metadata(std::string_view name, const std::map<std::string, std::string>& metadata);

  // Closes the file and returns its bytes. Call once; nothing may be added afterwards.
  std::string finish();

 private:
  struct SchemaRecord {
    std::uint16_t id;
    std::string name, encoding, data;
  };
  struct ChannelRecord {
    std::uint16_t id, schema_id;
    std::string topic, encoding;
    std::map<std::string, std::string> metadata;
    std::uint32_t sequence = 0;
    std::uint64_t count = 0;
  };
  struct ChunkIndexRecord {
    std::uint64_t start_time, end_time, offset, length;
    std::map<std::uint16_t, std::uint64_t> index_offsets;
    std::uint64_t index_length, compressed_size, uncompressed_size;
  };
  struct MetadataIndexRecord {
    std::uint64_t offset, length;
    std::string name;
  };

  void flush_chunk();

  McapOptions options_;
  std::string out_;
  std::vector<SchemaRecord> schemas_;
  std::vector<ChannelRecord> channels_;
  std::vector<ChunkIndexRecord> chunk_indexes_;
  std::vector<MetadataIndexRecord> metadata_indexes_;
  // The open chunk: its records, time range and per channel (log_time, offset) pairs.
  std::string chunk_;
  std::uint64_t chunk_start_ = 0, chunk_end_ = 0;
  std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunk_index_;
  std::uint64_t message_count_ = 0, start_time_ = 0, end_time_ = 0;
  void* zstd_ = nullptr;  // ZSTD_CCtx, reused across chunks
};

}  // namespace socsim::interop
