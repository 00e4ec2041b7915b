#include "core/knowledge/embedding.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace socsim::knowledge {
namespace {

std::uint64_t fnv1a(std::string_view s, std::uint64_t salt) {
  std::uint64_t h = 1469598103934665603ull ^ salt;
  for (char c : s) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return h;
}

void add_feature(Embedding& v, std::string_view feature, std::uint64_t salt, float weight) {
  const std::uint64_t h = fnv1a(feature, salt);
  const std::size_t index = static_cast<std::size_t>(h % v.size());
  v[index] += (h >> 63) != 0 ? -weight : weight;
}

std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> out;
  std::string w;
  for (char ch : text) {
    const auto u = static_cast<unsigned char>(ch);
    if (std::isalnum(u) || u >= 0x80) {
      w.push_back(static_cast<char>(std::tolower(u)));
    } else if (!w.empty()) {
      out.push_back(std::move(w));
      w.clear();
    }
  }
  if (!w.empty()) out.push_back(std::move(w));
  return out;
}

}  // namespace

Embedding hashed_ngram_vector(const std::string& text, std::size_t dim) {
  Embedding v(dim, 0.0f);
  if (dim == 0) return v;
  for (const std::string& w : words(text)) {
    add_feature(v, w, 0x5157u, 1.0f);
    const std::string padded = "#" + w + "#";
    for (std::size_t i = 0; i + 3 <= padded.size(); ++i)
      add_feature(v, std::string_view(padded).substr(i, 3), 0x7431u, 0.5f);
  }
  double norm = 0.0;
  for (float x : v) norm += static_cast<double>(x) * x;
  if (norm > 0.0) {
    const float inv = static_cast<float>(1.0 / std::sqrt(norm));
    for (float& x : v) x *= inv;
  }
  return v;
}

EmbeddingProvider hashed_ngram_embedding(std::size_t dim) {
  EmbeddingProvider p;
  p.model = "socsim-hashed-ngram-v1-" + std::to_string(dim);
  p.embed = [dim](const std::vector<std::string>& texts) -> Result<std::vector<Embedding>> {
    if (dim == 0) return fail(ErrorCode::kInternal, "hashed n-gram embedding needs a dimension > 0");
    std::vector<Embedding> out;
    out.reserve(texts.size());
    for (const auto& t : texts) out.push_back(hashed_ngram_vector(t, dim));
    return out;
  };
  return p;
}

Status check_embeddings(const std::vector<Embedding>& vectors, std::size_t expected_count,
                        const std::string& model) {
  if (vectors.size() != expected_count) {
    return fail(ErrorCode::kUpstream, "embedding model '" + model + "' returned " +
                                          std::to_string(vectors.size()) + " vectors for " +
                                          std::to_string(expected_count) + " texts");
  }
  if (vectors.empty()) return {};
  const std::size_t dim = vectors.front().size();
  if (dim == 0 || dim > 65536) {
    return fail(ErrorCode::kUpstream,
                "embedding model '" + model + "' returned vectors of dimension " + std::to_string(dim));
  }
  for (std::size_t i = 0; i < vectors.size(); ++i) {
    if (vectors[i].size() != dim) {
      return fail(ErrorCode::kUpstream,
                  "embedding model '" + model + "' returned vectors of different dimensions (" +
                      std::to_string(dim) + " and " + std::to_string(vectors[i].size()) + ")");
    }
    for (float x : vectors[i]) {
      if (!std::isfinite(x))
        return fail(ErrorCode::kUpstream, "embedding model '" + model + "' returned a non-finite value");
    }
  }
  return {};
}

std::string embedding_to_blob(const Embedding& v) {
  std::string out(v.size() * 4, '\0');
  for (std::size_t i = 0; i < v.size(); ++i) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v[i], 4);
    for (int b = 0; b < 4; ++b)
      out[i * 4 + static_cast<std::size_t>(b)] = static_cast<char>((bits >> (8 * b)) & 0xffu);
  }
  return out;
}

Result<Embedding> embedding_from_blob(const std::string& blob, std::size_t dim) {
  if (blob.size() != dim * 4) {
    return fail(ErrorCode::kStore, "stored embedding has " + std::to_string(blob.size()) +
                                       " bytes, expected " + std::to_string(dim * 4));
  }
  Embedding v(dim);
  for (std::size_t i = 0; i < dim; ++i) {
    std::uint32_t bits = 0;
    for (int b = 0; b < 4; ++b)
      bits |=
          static_cast<std::uint32_t>(static_cast<unsigned char>(blob[i * 4 + static_cast<std::size_t>(b)]))
          << (8 * b);
    std::memcpy(&v[i], &bits, 4);
  }
  return v;
}

}  // namespace socsim::knowledge
