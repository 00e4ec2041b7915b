-- Worlds made through /api/v1/worlds (offline generator, or an LLM job): the world.yaml text is
-- the single source every export is produced from; its compliance report and the provenance of
-- the knowledge used are kept beside it.
CREATE TABLE worlds (
  seq          INTEGER PRIMARY KEY,
  id           TEXT NOT NULL UNIQUE,
  name         TEXT NOT NULL,
  domain       TEXT NOT NULL,
  generator    TEXT NOT NULL CHECK (generator IN ('offline', 'llm')),
  seed         INTEGER NOT NULL,
  author       TEXT NOT NULL,
  request      TEXT NOT NULL CHECK (json_valid(request)),
  scene_graph  TEXT NOT NULL CHECK (json_valid(scene_graph)),
  world_yaml   TEXT NOT NULL,
  compliance   TEXT NOT NULL CHECK (json_valid(compliance)),
  provenance   TEXT NOT NULL CHECK (json_valid(provenance)),
  content_hash TEXT NOT NULL,
  created_at   TEXT NOT NULL
) STRICT;

CREATE INDEX worlds_domain ON worlds(domain, seq);
