#pragma once
// In-process publish/subscribe for live events (card created, card deleted …). Publishers
// never block on subscribers: each subscriber's callback must only enqueue.
#include <functional>
#include <map>
#include <mutex>
#include <string>

#include <nlohmann/json.hpp>

namespace socsim::server {

class EventHub {
 public:
  using Callback = std::function<void(const std::string& topic, const std::string& payload)>;
  int subscribe(Callback cb) {
    std::lock_guard<std::mutex> lock(mutex_);
    subscribers_[next_id_] = std::move(cb);
    return next_id_++;
  }
  void unsubscribe(int id) {
    std::lock_guard<std::mutex> lock(mutex_);
    subscribers_.erase(id);
  }
  // An event of this process: to the subscribers and, when set, to the relay that passes it to the
  // other daemons on the same database (server/pg_event_relay.hpp).
  void publish(const std::string& topic, const nlohmann::json& event) {
    const std::string payload = event.dump();
    deliver(topic, payload);
    Callback relay;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      relay = relay_;
    }
    if (relay) relay(topic, payload);
  }
  // An event another daemon published: to the subscribers only.
  void deliver(const std::string& topic, const std::string& payload) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto& [id, cb] : subscribers_) cb(topic, payload);
  }
  void set_relay(Callback relay) {
    std::lock_guard<std::mutex> lock(mutex_);
    relay_ = std::move(relay);
  }

 private:
  std::mutex mutex_;
  std::map<int, Callback> subscribers_;
  Callback relay_;
  int next_id_ = 1;
};

}  // namespace socsim::server
