#pragma once
// Catalogue events across daemons on one PostgreSQL database (issue 21): what one daemon
// publishes on the catalogue topics ("cards", "worlds") is sent with NOTIFY on the channel
// socsim_events; every daemon LISTENs there and delivers the others' events to its own
// subscribers (its /ws/catalogue clients), so a card created on one worker appears on every
// worker's catalogue WebSocket. A listener thread with its own connection; reconnects after a
// lost connection (events sent meanwhile are lost, as a WebSocket client's would be).
#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "server/event_hub.hpp"

namespace socsim::server {

class PgEventRelay {
 public:
  // url: the store's postgresql:// URL; instance: this daemon's id (its own events come back too).
  PgEventRelay(std::string url, EventHub& events);
  ~PgEventRelay();
  PgEventRelay(const PgEventRelay&) = delete;
  PgEventRelay& operator=(const PgEventRelay&) = delete;

  // Connects the listener (false with the reason in `error` when it cannot) and hooks the hub.
  bool start(std::string& error);
  void stop();

 private:
  struct Connections;
  void listen_loop();
  void send(const std::string& topic, const std::string& payload);

  std::string url_;
  EventHub& events_;
  std::string instance_;
  std::unique_ptr<Connections> pg_;
  std::mutex send_mutex_;
  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

}  // namespace socsim::server
