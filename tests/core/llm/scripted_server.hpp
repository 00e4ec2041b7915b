#pragma once
// An OpenAI-compatible server on 127.0.0.1 that answers from a script, so tests drive core/llm over
// real HTTP: each request to a path takes the next scripted step (status, body, headers, delay).
#include <httplib.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/llm/llm_client.hpp"

namespace socsim::testing {

class ScriptedServer {
 public:
  struct Step {
    int status = 200;
    std::string body;
    std::multimap<std::string, std::string> headers;
    int delay_ms = 0;          // before answering (interrupted when the server stops)
    bool drop_midway = false;  // announce the full length, send half, close the connection
  };
  struct Seen {
    std::string path;
    nlohmann::json body;
    std::string authorization;
  };

  ScriptedServer() {
    for (const char* path : {"/v1/chat/completions", "/v1/embeddings", "/moved/v1/chat/completions"})
      server_.Post(path, [this](const httplib::Request& req, httplib::Response& res) { handle(req, res); });
    port_ = server_.bind_to_any_port("127.0.0.1");
    thread_ = std::thread([this] { server_.listen_after_bind(); });
    for (int i = 0; i < 200 && !server_.is_running(); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ~ScriptedServer() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    cv_.notify_all();
    server_.stop();
    thread_.join();
  }
  ScriptedServer(const ScriptedServer&) = delete;
  ScriptedServer& operator=(const ScriptedServer&) = delete;

  [[nodiscard]] int port() const { return port_; }
  [[nodiscard]] std::string base_url() const { return "http://127.0.0.1:" + std::to_string(port_); }

  void push(const std::string& path, Step step) {
    std::lock_guard<std::mutex> lock(mutex_);
    script_[path].push_back(std::move(step));
  }
  void push_chat(Step step) { push("/v1/chat/completions", std::move(step)); }

  [[nodiscard]] std::vector<Seen> seen() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return seen_;
  }
  [[nodiscard]] int count() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return static_cast<int>(seen_.size());
  }
  [[nodiscard]] int max_in_flight() const { return max_in_flight_.load(); }

  // A chat.completion whose message content is `content`.
  static Step chat(const std::string& content, const std::string& finish_reason = "stop",
                   int prompt_tokens = 120, int completion_tokens = 40) {
    nlohmann::json body = {{"id", "chatcmpl-test"},
                           {"object", "chat.completion"},
                           {"model", "scripted"},
                           {"choices",
                            {{{"index", 0},
                              {"message", {{"role", "assistant"}, {"content", content}}},
                              {"finish_reason", finish_reason}}}},
                           {"usage",
                            {{"prompt_tokens", prompt_tokens},
                             {"completion_tokens", completion_tokens},
                             {"total_tokens", prompt_tokens + completion_tokens}}}};
    return Step{200, body.dump(), {}, 0, false};
  }
  // An OpenAI-style error body.
  static Step error(int status, const std::string& message,
                    std::multimap<std::string, std::string> headers = {}) {
    nlohmann::json body = {{"error", {{"message", message}, {"type", "scripted_error"}}}};
    return Step{status, body.dump(), std::move(headers), 0, false};
  }
  static Step delayed(Step step, int delay_ms) {
    step.delay_ms = delay_ms;
    return step;
  }

 private:
  void handle(const httplib::Request& req, httplib::Response& res) {
    const int now = ++in_flight_;
    int seen_max = max_in_flight_.load();
    while (now > seen_max && !max_in_flight_.compare_exchange_weak(seen_max, now)) {
    }
    Step step;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      Seen s;
      s.path = req.path;
      s.body = nlohmann::json::parse(req.body, nullptr, false);
      s.authorization = req.get_header_value("Authorization");
      seen_.push_back(std::move(s));
      auto& queue = script_[req.path];
      if (queue.empty()) {
        step = error(500, "script exhausted for " + req.path);
      } else {
        step = std::move(queue.front());
        queue.pop_front();
      }
      if (step.delay_ms > 0)
        cv_.wait_for(lock, std::chrono::milliseconds(step.delay_ms), [this] { return stopping_; });
    }
    res.status = step.status;
    for (const auto& [k, v] : step.headers) res.set_header(k, v);
    if (step.drop_midway) {
      auto body = std::make_shared<std::string>(step.body);
      res.set_content_provider(body->size(), "application/json",
                               [body](std::size_t offset, std::size_t, httplib::DataSink& sink) {
                                 if (offset > 0) return false;  // closes the connection mid-body
                                 sink.write(body->data(), body->size() / 2);
                                 return true;
                               });
    } else {
      res.set_content(step.body, "application/json");
    }
    --in_flight_;
  }

  httplib::Server server_;
  std::thread thread_;
  int port_ = 0;
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  bool stopping_ = false;
  std::map<std::string, std::deque<Step>> script_;
  std::vector<Seen> seen_;
  std::atomic<int> in_flight_{0};
  std::atomic<int> max_in_flight_{0};
};

// A client for generator tests against a ScriptedServer: short timeouts, no retries, two repair
// rounds, model "test-model".
inline std::unique_ptr<llm::LlmClient> scripted_client(const std::string& url) {
  llm::LlmConfig config;
  config.base_url = url;
  config.model = "test-model";
  config.connect_timeout_ms = 500;
  config.attempt_timeout_ms = 2000;
  config.deadline_ms = 4000;
  config.max_retries = 0;
  config.repair_rounds = 2;
  return llm::LlmClient::create(config).value();
}

}  // namespace socsim::testing
