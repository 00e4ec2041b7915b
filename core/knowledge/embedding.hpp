#pragma once
// Dense text embeddings for knowledge retrieval: the provider interface (the server plugs in the
// LLM endpoint's /v1/embeddings), a built-in offline embedding (hashed word and character-trigram
// features, so misspellings and word forms still land near each other), and vector helpers.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "core/common/error.hpp"

namespace socsim::knowledge {

using Embedding = std::vector<float>;

struct EmbeddingProvider {
  // Names the vector space: vectors are stored and compared per model only.
  std::string model;
  // One vector per text, all of the same dimension. Errors are values (kUpstream, …).
  std::function<Result<std::vector<Embedding>>(const std::vector<std::string>& texts)> embed;

  [[nodiscard]] bool available() const { return !model.empty() && static_cast<bool>(embed); }
};

// Feature hashing (FNV-1a 64) of lower-cased words (weight 1) and their padded character
// trigrams (weight 0.5), signed by a hash bit, L2-normalised. Deterministic on every platform.
// Model name: "socsim-hashed-ngram-v1-<dim>".
EmbeddingProvider hashed_ngram_embedding(std::size_t dim = 512);
Embedding hashed_ngram_vector(const std::string& text, std::size_t dim);

// Checks a provider's answer: one vector per text, one common non-zero dimension, finite values.
Status check_embeddings(const std::vector<Embedding>& vectors, std::size_t expected_count,
                        const std::string& model);

// Little-endian float32 bytes, as stored in knowledge_embeddings.vector.
std::string embedding_to_blob(const Embedding& v);
Result<Embedding> embedding_from_blob(const std::string& blob, std::size_t dim);

}  // namespace socsim::knowledge
