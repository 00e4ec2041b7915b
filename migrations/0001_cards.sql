-- Scenario-card catalogue. A card is immutable: its canonical JSON lives in `body`; the other
-- columns are copies of its fields for filtering and listing. `seq` orders the catalogue and
-- backs cursor pagination.
CREATE TABLE cards (
  seq          INTEGER PRIMARY KEY,
  id           TEXT NOT NULL UNIQUE,
  title        TEXT NOT NULL,
  description  TEXT NOT NULL,
  prompt       TEXT NOT NULL,
  domain       TEXT,
  author       TEXT NOT NULL,
  version      INTEGER NOT NULL CHECK (version >= 1),
  parent_id    TEXT,
  content_hash TEXT NOT NULL CHECK (length(content_hash) = 64),
  created_at   TEXT NOT NULL,
  tags         TEXT NOT NULL CHECK (json_valid(tags) AND json_type(tags) = 'array'),
  body         TEXT NOT NULL CHECK (json_valid(body))
) STRICT;

CREATE INDEX cards_author ON cards(author, seq);
CREATE INDEX cards_domain ON cards(domain, seq);
CREATE INDEX cards_parent ON cards(parent_id);

CREATE TABLE card_tags (
  tag      TEXT NOT NULL,
  card_seq INTEGER NOT NULL REFERENCES cards(seq) ON DELETE CASCADE,
  PRIMARY KEY (tag, card_seq)
) STRICT, WITHOUT ROWID;

-- Full-text search over title, description, prompt and tags (BM25 via FTS5), kept in step with
-- `cards` by triggers so a card and its index entry commit together.
CREATE VIRTUAL TABLE cards_fts USING fts5(
  title, description, prompt, tags,
  content = 'cards', content_rowid = 'seq', tokenize = 'porter unicode61');

CREATE TRIGGER cards_fts_insert AFTER INSERT ON cards BEGIN
  INSERT INTO cards_fts(rowid, title, description, prompt, tags)
  VALUES (new.seq, new.title, new.description, new.prompt,
          (SELECT group_concat(value, ' ') FROM json_each(new.tags)));
END;

CREATE TRIGGER cards_fts_delete AFTER DELETE ON cards BEGIN
  INSERT INTO cards_fts(cards_fts, rowid, title, description, prompt, tags)
  VALUES ('delete', old.seq, old.title, old.description, old.prompt,
          (SELECT group_concat(value, ' ') FROM json_each(old.tags)));
END;
