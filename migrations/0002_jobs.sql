-- Long-running work (LLM generation, batch household generation, benchmark runs) runs as a job:
-- the request returns 202 + Location: /api/v1/jobs/{id}; progress and the result are kept here.
CREATE TABLE jobs (
  seq         INTEGER PRIMARY KEY,
  id          TEXT NOT NULL UNIQUE,
  kind        TEXT NOT NULL,
  status      TEXT NOT NULL CHECK (status IN ('queued', 'running', 'succeeded', 'failed', 'cancelled')),
  progress    REAL NOT NULL DEFAULT 0 CHECK (progress >= 0 AND progress <= 1),
  message     TEXT NOT NULL DEFAULT '',
  author      TEXT NOT NULL,
  request     TEXT NOT NULL CHECK (json_valid(request)),
  result      TEXT CHECK (result IS NULL OR json_valid(result)),
  error       TEXT CHECK (error IS NULL OR json_valid(error)),
  created_at  TEXT NOT NULL,
  started_at  TEXT,
  finished_at TEXT
) STRICT;

CREATE INDEX jobs_status ON jobs(status, seq);
CREATE INDEX jobs_kind ON jobs(kind, seq);
