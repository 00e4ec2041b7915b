-- Dynamic household scenes made through POST /api/v1/households or `socsim household generate`.
-- The document holds what rebuilds the scene exactly: the request (house rooms and seed, or the
-- imported ProcTHOR JSON), the residents' profiles (persona, schedule, activity database) and the
-- scene seed; the summary is what listings show without parsing the document.
CREATE TABLE households (
  id         TEXT PRIMARY KEY CHECK (id GLOB 'hh_*' AND length(id) BETWEEN 4 AND 40),
  job_id     TEXT,
  author     TEXT NOT NULL,
  generator  TEXT NOT NULL CHECK (generator IN ('offline', 'llm')),
  summary    TEXT NOT NULL CHECK (json_valid(summary) AND json_type(summary) = 'object'),
  document   TEXT NOT NULL CHECK (json_valid(document) AND json_type(document) = 'object'),
  created_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
) STRICT;
CREATE INDEX households_created ON households(created_at, id);
