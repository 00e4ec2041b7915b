#pragma once
// An MCAP (v0) writer, after the format specification (mcap.dev/spec): Header, Schema and Channel
// records, Messages in Chunks (CRC32 of the records, zstd-compressed or not) each followed by its
// Message Index records, Metadata, Data End, then the summary (Schemas, Channels, Chunk Indexes,
// Metadata Indexes, Statistics), Summary Offsets and the Footer. Writes into memory; the bytes
// depend only on what was added (deterministic). Full chunks are compressed (and their CRCs taken)
// on two threads while the caller fills the next one; chunks are written in order.
#include <cstdint>
#include <deque>
#include <future>
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

  // The open chunk with its time range and per channel (log_time, offset) pairs.
  struct OpenChunk {
    std::string records;
    std::uint64_t start = 0, end = 0;
    std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> index;
  };
  struct SealedChunk {
    OpenChunk chunk;
    std::string compressed;  // empty without compression
    std::uint32_t crc = 0;
  };
  SealedChunk seal(OpenChunk chunk, void* zstd) const;
  void write_chunk(const SealedChunk& sealed);
  // Hands the open chunk to a compression thread (writing the oldest first when all are busy).
  void flush_chunk();
  // Writes the oldest chunk being compressed.
  void write_oldest();
  // Writes every chunk being compressed: afterwards out_ holds every record added so far.
  void drain();

  McapOptions options_;
  std::string out_;
  std::vector<SchemaRecord> schemas_;
  std::vector<ChannelRecord> channels_;
  std::vector<ChunkIndexRecord> chunk_indexes_;
  std::vector<MetadataIndexRecord> metadata_indexes_;
  OpenChunk chunk_;
  static constexpr std::size_t kThreads = 2;
  std::deque<std::future<SealedChunk>> sealing_;  // oldest first, at most kThreads
  std::size_t sealed_count_ = 0;                  // chunks handed over so far
  std::vector<std::string> spare_;                // records buffers of written chunks, for reuse
  std::uint64_t message_count_ = 0, start_time_ = 0, end_time_ = 0;
  // ZSTD_CCtx per thread: chunk k uses zstd_[k % kThreads], free again once chunk k - kThreads is written.
  void* zstd_[kThreads] = {};
};

}  // namespace socsim::interop
