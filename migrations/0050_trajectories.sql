-- Trajectory logs of scenario cards (frames at a fixed interval, socsim-traj-v1, zlib), stored
-- once per content: the key is the SHA-256 of the uncompressed log, which the card records, so a
-- replay that produces the same bytes proves itself by the key alone.
CREATE TABLE trajectory_logs (
  sha256         TEXT PRIMARY KEY CHECK (length(sha256) = 64),
  format         TEXT NOT NULL,
  frames         INTEGER NOT NULL CHECK (frames >= 0),
  agents         INTEGER NOT NULL CHECK (agents >= 0),
  frame_interval REAL NOT NULL CHECK (frame_interval > 0),
  raw_bytes      INTEGER NOT NULL CHECK (raw_bytes >= 0),
  data           BLOB NOT NULL,
  created_at     TEXT NOT NULL
) STRICT;
