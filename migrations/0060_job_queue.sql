-- Jobs as a queue shared by every worker on the database (issue 21). A worker claims a queued job
-- (or a running one whose lease has run out: its worker died) by writing its id, a lease expiry
-- and the next attempt number; it renews the lease while the job runs, and only the holder of the
-- current attempt may finish the job. `spec` is what any worker needs to run the job again (NULL for
-- a job that only the worker which took it can run, named by `pinned`); `client` carries the per-
-- client quota across workers; `cancel_requested` reaches the worker running the job.
ALTER TABLE jobs ADD COLUMN spec TEXT CHECK (spec IS NULL OR json_valid(spec));
ALTER TABLE jobs ADD COLUMN client TEXT NOT NULL DEFAULT '';
ALTER TABLE jobs ADD COLUMN pinned TEXT;
ALTER TABLE jobs ADD COLUMN worker TEXT;
ALTER TABLE jobs ADD COLUMN lease_expires INTEGER;
ALTER TABLE jobs ADD COLUMN attempts INTEGER NOT NULL DEFAULT 0;
ALTER TABLE jobs ADD COLUMN cancel_requested INTEGER NOT NULL DEFAULT 0;
ALTER TABLE jobs ADD COLUMN batch_id TEXT;
ALTER TABLE jobs ADD COLUMN batch_index INTEGER;
CREATE INDEX jobs_batch ON jobs(batch_id, batch_index);
CREATE INDEX jobs_worker ON jobs(worker, status);

-- Each serving process, with the address clients reach it at; the heartbeat says it is alive.
CREATE TABLE workers (
  id           TEXT PRIMARY KEY,
  public_url   TEXT NOT NULL,
  heartbeat_ms INTEGER NOT NULL,
  started_at   TEXT NOT NULL
) STRICT;

-- A batch: one request split into jobs (items) that every worker takes from the queue.
CREATE TABLE batches (
  seq        INTEGER PRIMARY KEY,
  id         TEXT NOT NULL UNIQUE,
  kind       TEXT NOT NULL,
  author     TEXT NOT NULL,
  request    TEXT NOT NULL CHECK (json_valid(request)),
  total      INTEGER NOT NULL CHECK (total > 0),
  created_at TEXT NOT NULL
) STRICT;
