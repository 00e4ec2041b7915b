#include "core/scenario/wordnet.hpp"

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>

extern "C" {
#include <wn.h>
}

namespace socsim::scenario {

namespace {

// The C library keeps global state (open files, static buffers): every call goes through this.
std::mutex& library_lock() {
  static std::mutex m;
  return m;
}

std::string underscored(std::string_view w) {
  std::string out(w);
  for (char& c : out)
    if (c == ' ' || c == '-') c = '_';
  return out;
}

std::string spaced(const char* w) {
  std::string out(w);
  for (char& c : out) {
    if (c == '_') c = ' ';
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

// Caller holds the lock. Base form for a part of speech: the word itself when WordNet has it,
// else its morphological base ("children" → "child"), else "".
// The morphological base wins over a surface form that is a word of its own ("gates" → "gate",
// not the proper noun Gates).
std::string base_form(const std::string& word, int pos) {
  std::vector<char> buf(word.begin(), word.end());
  buf.push_back('\0');
  if (const char* base = morphstr(buf.data(), pos); base != nullptr) {
    std::string b(base);
    std::vector<char> bb(b.begin(), b.end());
    bb.push_back('\0');
    if (is_defined(bb.data(), pos) != 0) return b;
  }
  std::vector<char> again(word.begin(), word.end());
  again.push_back('\0');
  return is_defined(again.data(), pos) != 0 ? word : std::string();
}

void collect_hypernyms(SynsetPtr s, std::vector<std::string>& out, std::set<std::string>& seen, int depth) {
  for (; s != nullptr && depth < MAXDEPTH; s = s->nextss) {
    if (s->wcount > 0 && s->words != nullptr && s->words[0] != nullptr) {
      std::string w = spaced(s->words[0]);
      if (seen.insert(w).second) out.push_back(std::move(w));
    }
    collect_hypernyms(s->ptrlist, out, seen, depth + 1);
  }
}

}  // namespace

struct WordNet::Cache {
  std::mutex mutex;
  std::map<std::string, NounEntry, std::less<>> nouns;
  std::map<std::pair<std::string, int>, bool, std::less<>> pos;
};

std::string wordnet_directory() {
  const char* env = std::getenv("WNSEARCHDIR");
  if (env != nullptr && *env != '\0') return env;
  return "/usr/share/wordnet";
}

WordNet::WordNet(std::string directory)
    : directory_(std::move(directory)), cache_(std::make_unique<Cache>()) {}
WordNet::~WordNet() = default;

Result<const WordNet*> WordNet::open() {
  static std::mutex once;
  static std::unique_ptr<WordNet> instance;
  static std::optional<Error> failure;
  std::lock_guard<std::mutex> guard(once);
  if (instance) return instance.get();
  if (failure) return tl::unexpected(*failure);
  const std::string dir = wordnet_directory();
  std::error_code ec;
  for (const char* f : {"index.noun", "data.noun", "index.verb", "index.adj", "index.adv"}) {
    if (!std::filesystem::is_regular_file(std::filesystem::path(dir) / f, ec)) {
      failure = Error{ErrorCode::kInternal,
                      "WordNet data not found: " + dir + "/" + f +
                          " is missing (install the Debian package wordnet-base, or point WNSEARCHDIR at "
                          "a WordNet 3.0 dict directory)"};
      return tl::unexpected(*failure);
    }
  }
  {
    std::lock_guard<std::mutex> lib(library_lock());
    if (wninit() != 0) {
      failure = Error{ErrorCode::kInternal, "WordNet could not open its data files in " + dir};
      return tl::unexpected(*failure);
    }
  }
  instance.reset(new WordNet(dir));
  return instance.get();
}

const NounEntry& WordNet::noun(std::string_view word) const {
  const std::string key = underscored(word);
  {
    std::lock_guard<std::mutex> g(cache_->mutex);
    if (auto it = cache_->nouns.find(key); it != cache_->nouns.end()) return it->second;
  }
  NounEntry e;
  {
    std::lock_guard<std::mutex> lib(library_lock());
    const std::string base = key.empty() ? std::string() : base_form(key, NOUN);
    if (!base.empty()) {
      e.known = true;
      e.lemma = spaced(base.c_str());
      std::vector<char> buf(base.begin(), base.end());
      buf.push_back('\0');
      SynsetPtr s = findtheinfo_ds(buf.data(), NOUN, -HYPERPTR, ALLSENSES);
      std::size_t k = 0;
      for (SynsetPtr p = s; p != nullptr && k < NounEntry::kMaxSenses; p = p->nextss) {
        // Proper nouns (Walker, Ussher, Gates) are never the sense a prompt means.
        if (p->wcount > 0 && p->words != nullptr && p->words[0] != nullptr &&
            std::isupper(static_cast<unsigned char>(p->words[0][0])) != 0)
          continue;
        ++k;
        NounSense sense;
        sense.lexfile = (p->fnum >= 0 && p->fnum < MAXFNUM && lexfiles[p->fnum] != nullptr)
                            ? lexfiles[p->fnum]
                            : std::string();
        std::set<std::string> seen;
        collect_hypernyms(p->ptrlist, sense.hypernyms, seen, 0);
        e.senses.push_back(std::move(sense));
      }
      if (s != nullptr) free_syns(s);
    }
    for (const std::string& w : {key, base}) {
      if (w.empty()) continue;
      e.verb = e.verb || !base_form(w, VERB).empty();
      e.adjective = e.adjective || !base_form(w, ADJ).empty();
      e.adverb = e.adverb || !base_form(w, ADV).empty();
    }
  }
  std::lock_guard<std::mutex> g(cache_->mutex);
  return cache_->nouns.emplace(key, std::move(e)).first->second;
}

namespace {
bool cached_pos(std::mutex& m, std::map<std::pair<std::string, int>, bool, std::less<>>& cache,
                std::string_view word, int pos) {
  const auto key = std::make_pair(underscored(word), pos);
  {
    std::lock_guard<std::mutex> g(m);
    if (auto it = cache.find(key); it != cache.end()) return it->second;
  }
  bool yes = false;
  {
    std::lock_guard<std::mutex> lib(library_lock());
    yes = !key.first.empty() && !base_form(key.first, pos).empty();
  }
  std::lock_guard<std::mutex> g(m);
  cache[key] = yes;
  return yes;
}
}  // namespace

bool WordNet::is_verb(std::string_view word) const {
  return cached_pos(cache_->mutex, cache_->pos, word, VERB);
}
bool WordNet::is_adjective(std::string_view word) const {
  return cached_pos(cache_->mutex, cache_->pos, word, ADJ);
}
bool WordNet::is_adverb(std::string_view word) const {
  return cached_pos(cache_->mutex, cache_->pos, word, ADV);
}

}  // namespace socsim::scenario
