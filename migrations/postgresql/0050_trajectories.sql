-- PostgreSQL's form of 0050_trajectories.sql.
CREATE TABLE trajectory_logs (
  sha256         TEXT PRIMARY KEY CHECK (length(sha256) = 64),
  format         TEXT NOT NULL,
  frames         BIGINT NOT NULL CHECK (frames >= 0),
  agents         BIGINT NOT NULL CHECK (agents >= 0),
  frame_interval DOUBLE PRECISION NOT NULL CHECK (frame_interval > 0),
  raw_bytes      BIGINT NOT NULL CHECK (raw_bytes >= 0),
  data           BYTEA NOT NULL,
  created_at     TEXT NOT NULL
);
