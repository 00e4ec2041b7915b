-- LLM response cache. One row per distinct request: the model, the SHA-256 of the canonical JSON
-- of its messages and answer schema, the seed and the temperature. Only answers of generations that
-- succeeded are stored, so a failed attempt never pins a bad answer; replaying a request whose
-- answers are all cached regenerates the artifact exactly and costs no tokens.
CREATE TABLE llm_cache (
  model             TEXT NOT NULL,
  request_hash      TEXT NOT NULL CHECK (length(request_hash) = 64),
  seed              INTEGER NOT NULL,
  temperature       REAL NOT NULL,
  response          TEXT NOT NULL,
  finish_reason     TEXT NOT NULL,
  prompt_tokens     INTEGER NOT NULL CHECK (prompt_tokens >= 0),
  completion_tokens INTEGER NOT NULL CHECK (completion_tokens >= 0),
  created_at        TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
  PRIMARY KEY (model, request_hash, seed, temperature)
) STRICT, WITHOUT ROWID;

-- Every LLM call, cache hits included: what was asked, what came back, what it cost and whether
-- the answer was accepted ('ok'), failed its schema or semantic checks ('invalid') or never came
-- ('error'). job_id is the job that caused the call, when there was one.
CREATE TABLE llm_calls (
  id                INTEGER PRIMARY KEY,
  job_id            TEXT,
  artifact          TEXT NOT NULL,
  model             TEXT NOT NULL,
  round             INTEGER NOT NULL CHECK (round >= 0),
  prompt_hash       TEXT NOT NULL,
  seed              INTEGER NOT NULL,
  temperature       REAL NOT NULL,
  prompt            TEXT NOT NULL CHECK (json_valid(prompt)),
  response          TEXT,
  prompt_tokens     INTEGER NOT NULL CHECK (prompt_tokens >= 0),
  completion_tokens INTEGER NOT NULL CHECK (completion_tokens >= 0),
  latency_ms        INTEGER NOT NULL CHECK (latency_ms >= 0),
  cache_hit         INTEGER NOT NULL CHECK (cache_hit IN (0, 1)),
  status            TEXT NOT NULL CHECK (status IN ('ok', 'invalid', 'error')),
  error             TEXT,
  created_at        TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
) STRICT;

CREATE INDEX llm_calls_job ON llm_calls(job_id, id) WHERE job_id IS NOT NULL;
