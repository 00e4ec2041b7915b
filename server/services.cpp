#include "server/services.hpp"

namespace socsim::server {

Result<std::unique_ptr<Services>> Services::create(ServerConfig config, store::Store& store) {
  auto s = std::make_unique<Services>(std::move(config), store);
  knowledge::EmbeddingProvider embeddings = knowledge::hashed_ngram_embedding();
  if (s->config.llm.configured()) {
    auto client = llm::LlmClient::create(s->config.llm);
    if (!client) return tl::unexpected(client.error());
    s->llm = std::move(*client);
    if (!s->config.llm.embedding_model.empty()) {
      llm::LlmClient* c = s->llm.get();
      const std::string model = s->config.llm.embedding_model;
      embeddings.model = model;
      embeddings.embed =
          [c, model](const std::vector<std::string>& texts) -> Result<std::vector<knowledge::Embedding>> {
        llm::EmbeddingRequest req;
        req.inputs = texts;
        req.model = model;
        auto r = c->embed(req);
        if (!r) return tl::unexpected(r.error());
        return r->vectors;
      };
    }
  }
  s->knowledge = std::make_unique<knowledge::KnowledgeBase>(store, std::move(embeddings));
  JobRunnerOptions jobs;
  jobs.workers = s->config.job_workers;
  jobs.max_per_client = s->config.max_jobs_per_client;
  jobs.worker_id = s->config.worker_id;
  jobs.lease = std::chrono::milliseconds(static_cast<std::int64_t>(s->config.job_lease_s * 1000));
  jobs.public_url = "http://" + (s->config.public_host.empty() ? s->config.host : s->config.public_host) +
                    ":" + std::to_string(s->config.port);
  s->jobs = std::make_unique<JobRunner>(store, s->events, std::move(jobs));
  SimulationLimits limits;
  limits.max_sessions = s->config.max_simulations;
  limits.max_viewers = s->config.max_viewers;
  limits.max_agents = s->config.max_sim_agents;
  limits.min_speed = s->config.min_sim_speed;
  limits.max_speed = s->config.max_sim_speed;
  limits.stream_hz = s->config.stream_hz;
  limits.idle_s = s->config.sim_idle_s;
  limits.max_duration_s = s->config.max_sim_duration_s;
  s->simulations = std::make_unique<SimulationSessions>(limits);
  CosimLimits cosim;
  cosim.max_sessions = s->config.max_simulations;
  cosim.max_agents = s->config.max_sim_agents;
  cosim.idle_s = s->config.sim_idle_s;
  s->cosim = std::make_unique<CosimSessions>(cosim);
  return s;
}

}  // namespace socsim::server
