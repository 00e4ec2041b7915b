#pragma once
// A real socsim API server on a free 127.0.0.1 port with its own SQLite file, for tests that
// speak HTTP to it — or its own PostgreSQL database when SOCSIM_TEST_BACKEND=postgres (the ctest
// entries pg.* run the API, jobs and catalogue tests so; tests/support/test_database.hpp).
#include <httplib.h>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "core/common/json_io.hpp"
#include "server/api_server.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/test_database.hpp"

namespace socsim::testing {

// POST a JSON body.
inline httplib::Result post(httplib::Client& c, const std::string& path, const Json& body) {
  return c.Post(path.c_str(), body.dump(), "application/json");
}

// GET a path and parse its JSON body, expecting the status `expect`.
inline Json get_json(httplib::Client& c, const std::string& path, int expect = 200) {
  auto r = c.Get(path.c_str());
  EXPECT_TRUE(r) << path;
  if (!r) return Json();
  EXPECT_EQ(r->status, expect) << path << ": " << r->body;
  return Json::parse(r->body);
}

class TestServer {
 public:
  explicit TestServer(server::ServerConfig config = {}) {
    config.host = "127.0.0.1";
    config.port = 0;
    const char* backend = std::getenv("SOCSIM_TEST_BACKEND");
    if (backend && std::string(backend) == "postgres") {
      db_ = std::make_unique<TestDatabase>(Backend::kPostgres);
      if (db_->target().empty())
        throw std::runtime_error("SOCSIM_TEST_BACKEND=postgres: " + db_->skip_reason());
      config.db = db_->target();
    } else {
      config.db = dir_.file("socsim.db");
    }
    target_ = config.db;
    config.web_root = dir_.file("web");
    std::filesystem::create_directories(config.web_root);
    std::ofstream(config.web_root + "/index.html") << "<!doctype html><title>socsim</title>";
    store_ = std::move(store::Store::open(config.db).value());
    services_ = std::move(server::Services::create(config, *store_).value());
    api_ = std::make_unique<server::ApiServer>(*services_);
    port_ = api_->bind().value();
    thread_ = std::thread([this] { api_->run(); });
    // Wait until the listener accepts.
    for (int i = 0; i < 200; ++i) {
      if (client().Get("/api/v1/health")) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  ~TestServer() {
    api_->stop();
    thread_.join();
    services_->shutdown();
  }
  TestServer(const TestServer&) = delete;
  TestServer& operator=(const TestServer&) = delete;

  [[nodiscard]] httplib::Client client() const {
    httplib::Client c("127.0.0.1", port_);
    c.set_read_timeout(10, 0);
    return c;
  }
  [[nodiscard]] int port() const { return port_; }
  server::Services& services() { return *services_; }
  store::Store& store() { return *store_; }
  // The database the server uses (an SQLite file or a postgresql:// URL), for a second worker.
  [[nodiscard]] const std::string& db_target() const { return target_; }

 private:
  TempDir dir_;
  std::unique_ptr<TestDatabase> db_;  // PostgreSQL runs only; outlives the store
  std::unique_ptr<store::Store> store_;
  std::unique_ptr<server::Services> services_;
  std::unique_ptr<server::ApiServer> api_;
  std::thread thread_;
  int port_ = 0;
  std::string target_;
};

}  // namespace socsim::testing
