#include "server/pg_event_relay.hpp"

#include <libpq-fe.h>
#include <poll.h>

#include <chrono>

#include "core/common/ids.hpp"
#include "core/common/json_io.hpp"
#include "server/http_util.hpp"

namespace socsim::server {
namespace {

constexpr const char* kChannel = "socsim_events";
constexpr std::size_t kMaxPayload = 7900;  // PostgreSQL's NOTIFY payload limit is 8000 bytes

bool relayed(const std::string& topic) {
  return topic == "cards" || topic == "worlds";
}

void ignore_notice(void*, const char*) {}

PGconn* connect(const std::string& url, std::string& error) {
  PGconn* c = PQconnectdb(url.c_str());
  if (c && PQstatus(c) == CONNECTION_OK) {
    PQsetNoticeProcessor(c, ignore_notice, nullptr);
    return c;
  }
  error = c ? PQerrorMessage(c) : "out of memory";
  while (!error.empty() && (error.back() == '\n' || error.back() == ' ')) error.pop_back();
  if (c) PQfinish(c);
  return nullptr;
}

bool run(PGconn* c, const std::string& sql) {
  PGresult* r = PQexec(c, sql.c_str());
  const bool ok = r && PQresultStatus(r) == PGRES_COMMAND_OK;
  PQclear(r);
  return ok;
}

}  // namespace

struct PgEventRelay::Connections {
  PGconn* listen = nullptr;
  PGconn* notify = nullptr;
  ~Connections() {
    if (listen) PQfinish(listen);
    if (notify) PQfinish(notify);
  }
};

PgEventRelay::PgEventRelay(std::string url, EventHub& events)
    : url_(std::move(url)),
      events_(events),
      instance_(random_id("ins_")),
      pg_(std::make_unique<Connections>()) {}

PgEventRelay::~PgEventRelay() {
  stop();
}

bool PgEventRelay::start(std::string& error) {
  pg_->listen = connect(url_, error);
  if (!pg_->listen) return false;
  pg_->notify = connect(url_, error);
  if (!pg_->notify) return false;
  if (!run(pg_->listen, std::string("LISTEN ") + kChannel)) {
    error = PQerrorMessage(pg_->listen);
    return false;
  }
  events_.set_relay([this](const std::string& topic, const std::string& payload) {
    if (relayed(topic)) send(topic, payload);
  });
  thread_ = std::thread([this] { listen_loop(); });
  return true;
}

void PgEventRelay::stop() {
  events_.set_relay(nullptr);
  stopping_ = true;
  if (thread_.joinable()) thread_.join();
}

void PgEventRelay::send(const std::string& topic, const std::string& payload) {
  const std::string message = Json{{"i", instance_}, {"t", topic}, {"p", payload}}.dump();
  if (message.size() > kMaxPayload) {
    log_line({{"level", "warn"}, {"event", "relay.too_large"}, {"topic", topic}, {"bytes", message.size()}});
    return;
  }
  std::lock_guard<std::mutex> lock(send_mutex_);
  if (!pg_->notify || PQstatus(pg_->notify) != CONNECTION_OK) {
    if (pg_->notify) PQreset(pg_->notify);
    if (!pg_->notify || PQstatus(pg_->notify) != CONNECTION_OK) return;
  }
  const char* values[2] = {kChannel, message.c_str()};
  PGresult* r =
      PQexecParams(pg_->notify, "SELECT pg_notify($1, $2)", 2, nullptr, values, nullptr, nullptr, 0);
  if (!r || PQresultStatus(r) != PGRES_TUPLES_OK)
    log_line({{"level", "warn"}, {"event", "relay.notify_failed"}, {"detail", PQerrorMessage(pg_->notify)}});
  PQclear(r);
}

void PgEventRelay::listen_loop() {
  while (!stopping_) {
    PGconn* c = pg_->listen;
    if (PQstatus(c) != CONNECTION_OK) {  // lost: reconnect and listen again, once a second
      PQreset(c);
      if (PQstatus(c) != CONNECTION_OK || !run(c, std::string("LISTEN ") + kChannel)) {
        std::this_thread::sleep_for(std::chrono::seconds(1));
        continue;
      }
    }
    pollfd fd{PQsocket(c), POLLIN, 0};
    if (::poll(&fd, 1, 200) <= 0) continue;  // wakes every 200 ms to see whether to stop
    if (!PQconsumeInput(c)) continue;
    while (PGnotify* n = PQnotifies(c)) {
      auto message = parse_json_untrusted(n->extra);
      PQfreemem(n);
      if (!message || !message->is_object() || message->value("i", "") == instance_) continue;
      const std::string topic = message->value("t", "");
      if (relayed(topic) && (*message)["p"].is_string())
        events_.deliver(topic, (*message)["p"].get<std::string>());
    }
  }
}

}  // namespace socsim::server
