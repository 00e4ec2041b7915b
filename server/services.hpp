#pragma once
// What one daemon process shares between its routes: configuration, the store, the event hub,
// the knowledge base, the LLM client (when an endpoint is configured), the job runner and the live
// simulation sessions.
#include <chrono>
#include <memory>

#include "core/knowledge/knowledge_base.hpp"
#include "core/llm/llm_client.hpp"
#include "core/store/store.hpp"
#include "server/config.hpp"
#include "server/cosim_sessions.hpp"
#include "server/event_hub.hpp"
#include "server/jobs.hpp"
#include "server/simulation_sessions.hpp"

namespace socsim::server {

struct Services {
  ServerConfig config;
  store::Store& store;
  EventHub events;
  std::unique_ptr<knowledge::KnowledgeBase> knowledge;
  std::unique_ptr<llm::LlmClient> llm;  // null: no endpoint configured, offline generator only
  std::unique_ptr<JobRunner> jobs;
  std::unique_ptr<SimulationSessions> simulations;  // live sessions streamed on the WebSocket port
  std::unique_ptr<CosimSessions> cosim;             // robot co-simulations driven over the WebSocket port
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();

  Services(ServerConfig c, store::Store& s) : config(std::move(c)), store(s) {}
  // Wires everything; the knowledge base uses the LLM endpoint's embeddings when one is
  // configured with an embedding model, else the built-in offline embedding.
  static Result<std::unique_ptr<Services>> create(ServerConfig config, store::Store& store);
  // Stops the job workers (cancelling running jobs) and the live simulations.
  void shutdown() {
    if (simulations) simulations->shutdown();
    if (cosim) cosim->shutdown();
    if (jobs) jobs->shutdown();
  }
};

}  // namespace socsim::server
