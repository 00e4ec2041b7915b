// The offline hashed n-gram embedding and the vector helpers behind dense retrieval.
#include "core/knowledge/embedding.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace socsim::knowledge {
namespace {

double cosine(const Embedding& a, const Embedding& b) {
  double dot = 0, na = 0, nb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    dot += static_cast<double>(a[i]) * b[i];
    na += static_cast<double>(a[i]) * a[i];
    nb += static_cast<double>(b[i]) * b[i];
  }
  return dot / std::sqrt(na * nb);
}

TEST(KnowledgeHashedEmbedding, IsDeterministicUnitLengthAndCaseInsensitive) {
  const Embedding a = hashed_ngram_vector("Queue at the Counter", 256);
  const Embedding b = hashed_ngram_vector("queue at the counter", 256);
  ASSERT_EQ(a.size(), 256u);
  EXPECT_EQ(a, b);
  double norm = 0;
  for (float x : a) norm += static_cast<double>(x) * x;
  EXPECT_NEAR(norm, 1.0, 1e-5);
}

TEST(KnowledgeHashedEmbedding, MisspellingsStayCloserThanUnrelatedWords) {
  const auto corridor = hashed_ngram_vector("corridor", 512);
  const auto typo = hashed_ngram_vector("corrdior", 512);
  const auto other = hashed_ngram_vector("bedroom", 512);
  EXPECT_GT(cosine(corridor, typo), 0.3);
  EXPECT_GT(cosine(corridor, typo), cosine(corridor, other) + 0.2);
}

TEST(KnowledgeHashedEmbedding, ProviderNamesItsModelAndEmbedsEveryText) {
  const auto p = hashed_ngram_embedding(64);
  EXPECT_EQ(p.model, "socsim-hashed-ngram-v1-64");
  auto v = p.embed({"a", "b c", ""});
  ASSERT_TRUE(v);
  ASSERT_EQ(v->size(), 3u);
  EXPECT_TRUE(check_embeddings(*v, 3, p.model));
}

TEST(KnowledgeEmbeddingBlob, RoundTripsBitExactly) {
  const Embedding v = {1.0f, -0.5f, 3.25e-7f, 12345.678f};
  const std::string blob = embedding_to_blob(v);
  ASSERT_EQ(blob.size(), 16u);
  EXPECT_EQ(static_cast<unsigned char>(blob[3]), 0x3fu);  // 1.0f = 0x3f800000, little-endian
  auto back = embedding_from_blob(blob, 4);
  ASSERT_TRUE(back);
  EXPECT_EQ(*back, v);
  EXPECT_FALSE(embedding_from_blob(blob, 5));
}

TEST(KnowledgeCheckEmbeddings, RejectsWrongCountMixedDimensionsAndNonFiniteValues) {
  EXPECT_EQ(check_embeddings({{1.0f}}, 2, "m").error().code, ErrorCode::kUpstream);
  EXPECT_FALSE(check_embeddings({{1.0f, 2.0f}, {1.0f}}, 2, "m"));
  EXPECT_FALSE(check_embeddings({{}}, 1, "m"));
  EXPECT_FALSE(check_embeddings({{std::nanf("")}}, 1, "m"));
}

}  // namespace
}  // namespace socsim::knowledge
