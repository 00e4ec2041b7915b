-- Knowledge store (DESIGN.md §4, paper 001 §III-C): building-code references that bound the
-- floor-plan generator, the behaviour-node library the scenario generator composes trees from,
-- and optional dense embeddings of both. Seed rows come in later migrations (0011, 0012, …).

-- One building-code reference in paper 001's schema: ref_id, building_type, jurisdiction,
-- sources[{title, url, section}], constraints[{name, type, value, unit, confidence, applies_to,
-- original}]. Values are SI; `original` keeps the figure as the source prints it.
-- building_type 'general' marks references that hold for every non-dwelling building type.
CREATE TABLE building_codes (
  seq           INTEGER PRIMARY KEY,
  ref_id        TEXT NOT NULL UNIQUE
                CHECK (length(ref_id) BETWEEN 3 AND 80 AND ref_id NOT GLOB '*[^a-z0-9_]*'),
  building_type TEXT NOT NULL
                CHECK (building_type IN ('general', 'residential', 'office', 'hospital', 'canteen',
                                         'retail', 'warehouse', 'school', 'airport')),
  jurisdiction  TEXT NOT NULL CHECK (length(jurisdiction) > 0),
  title         TEXT NOT NULL CHECK (length(title) > 0),
  description   TEXT NOT NULL CHECK (length(description) > 0),
  keywords      TEXT NOT NULL DEFAULT '',
  sources       TEXT NOT NULL CHECK (json_valid(sources) AND json_type(sources) = 'array'
                                     AND json_array_length(sources) >= 1),
  constraints   TEXT NOT NULL CHECK (json_valid(constraints) AND json_type(constraints) = 'array'
                                     AND json_array_length(constraints) >= 1)
) STRICT;

CREATE INDEX building_codes_type ON building_codes(building_type, ref_id);

-- A node the crowd engine's behaviour-tree interpreter implements (BehaviorTree.CPP v4 dialect).
-- origin: 'btcpp' (BehaviorTree.CPP built-ins), 'hunavsim' (HuNavSim's names and ports),
-- 'socsim' (our additions: queueing, seating, velocity fields, …). aliases are other XML tag
-- names accepted for the same node (e.g. HuNavSim's StopAndWaitTimerAction for StopAndWait).
CREATE TABLE behavior_nodes (
  seq         INTEGER PRIMARY KEY,
  name        TEXT NOT NULL UNIQUE
              CHECK (length(name) BETWEEN 2 AND 64 AND name NOT GLOB '*[^A-Za-z0-9_]*'),
  kind        TEXT NOT NULL CHECK (kind IN ('action', 'condition', 'control', 'decorator')),
  origin      TEXT NOT NULL CHECK (origin IN ('btcpp', 'hunavsim', 'socsim')),
  category    TEXT NOT NULL CHECK (length(category) > 0),
  description TEXT NOT NULL CHECK (length(description) > 0),
  when_to_use TEXT NOT NULL CHECK (length(when_to_use) > 0),
  example     TEXT NOT NULL CHECK (length(example) > 0),
  keywords    TEXT NOT NULL DEFAULT '',
  aliases     TEXT NOT NULL DEFAULT '[]' CHECK (json_valid(aliases) AND json_type(aliases) = 'array'),
  ports       TEXT NOT NULL CHECK (json_valid(ports) AND json_type(ports) = 'array')
) STRICT;

CREATE INDEX behavior_nodes_kind ON behavior_nodes(kind, name);

-- Full-text indexes (BM25 via FTS5). They hold their own copy of the searchable text (derived
-- from JSON columns, so an external-content table cannot serve it) and are kept in step by
-- triggers, so an entry and its index row commit together.
CREATE VIRTUAL TABLE building_codes_fts USING fts5(
  title, description, keywords, building_type, jurisdiction, sources, constraints,
  tokenize = 'porter unicode61');

CREATE VIRTUAL TABLE behavior_nodes_fts USING fts5(
  name, description, when_to_use, keywords, category, kind, ports,
  tokenize = 'porter unicode61');

CREATE TRIGGER building_codes_fts_insert AFTER INSERT ON building_codes BEGIN
  INSERT INTO building_codes_fts(rowid, title, description, keywords, building_type, jurisdiction,
                                 sources, constraints)
  VALUES (new.seq, new.title, new.description, new.keywords || ' ' || replace(new.ref_id, '_', ' '),
          new.building_type, new.jurisdiction,
          (SELECT group_concat(json_extract(value, '$.title') || ' ' || json_extract(value, '$.section'), ' ')
             FROM json_each(new.sources)),
          (SELECT group_concat(replace(json_extract(value, '$.name'), '_', ' ') || ' ' ||
                               coalesce(json_extract(value, '$.applies_to'), ''), ' ')
             FROM json_each(new.constraints)));
END;

CREATE TRIGGER building_codes_fts_delete AFTER DELETE ON building_codes BEGIN
  DELETE FROM building_codes_fts WHERE rowid = old.seq;
  DELETE FROM knowledge_embeddings WHERE kind = 'building_code' AND item_id = old.ref_id;
END;

CREATE TRIGGER building_codes_fts_update AFTER UPDATE ON building_codes BEGIN
  DELETE FROM building_codes_fts WHERE rowid = old.seq;
  INSERT INTO building_codes_fts(rowid, title, description, keywords, building_type, jurisdiction,
                                 sources, constraints)
  VALUES (new.seq, new.title, new.description, new.keywords || ' ' || replace(new.ref_id, '_', ' '),
          new.building_type, new.jurisdiction,
          (SELECT group_concat(json_extract(value, '$.title') || ' ' || json_extract(value, '$.section'), ' ')
             FROM json_each(new.sources)),
          (SELECT group_concat(replace(json_extract(value, '$.name'), '_', ' ') || ' ' ||
                               coalesce(json_extract(value, '$.applies_to'), ''), ' ')
             FROM json_each(new.constraints)));
END;

CREATE TRIGGER behavior_nodes_fts_insert AFTER INSERT ON behavior_nodes BEGIN
  INSERT INTO behavior_nodes_fts(rowid, name, description, when_to_use, keywords, category, kind, ports)
  VALUES (new.seq, new.name || ' ' || (SELECT coalesce(group_concat(value, ' '), '') FROM json_each(new.aliases)),
          new.description, new.when_to_use, new.keywords, new.category, new.kind,
          (SELECT group_concat(replace(json_extract(value, '$.name'), '_', ' '), ' ') FROM json_each(new.ports)));
END;

CREATE TRIGGER behavior_nodes_fts_delete AFTER DELETE ON behavior_nodes BEGIN
  DELETE FROM behavior_nodes_fts WHERE rowid = old.seq;
  DELETE FROM knowledge_embeddings WHERE kind = 'behavior_node' AND item_id = old.name;
END;

CREATE TRIGGER behavior_nodes_fts_update AFTER UPDATE ON behavior_nodes BEGIN
  DELETE FROM behavior_nodes_fts WHERE rowid = old.seq;
  INSERT INTO behavior_nodes_fts(rowid, name, description, when_to_use, keywords, category, kind, ports)
  VALUES (new.seq, new.name || ' ' || (SELECT coalesce(group_concat(value, ' '), '') FROM json_each(new.aliases)),
          new.description, new.when_to_use, new.keywords, new.category, new.kind,
          (SELECT group_concat(replace(json_extract(value, '$.name'), '_', ' '), ' ') FROM json_each(new.ports)));
END;

-- Dense vectors of entries, one per (entry, embedding model): little-endian float32, `dim` of
-- them. text_hash is the SHA-256 of the text that was embedded, so a changed entry is re-embedded.
CREATE TABLE knowledge_embeddings (
  kind      TEXT NOT NULL CHECK (kind IN ('building_code', 'behavior_node')),
  item_id   TEXT NOT NULL,
  model     TEXT NOT NULL CHECK (length(model) > 0),
  text_hash TEXT NOT NULL CHECK (length(text_hash) = 64),
  dim       INTEGER NOT NULL CHECK (dim BETWEEN 1 AND 65536),
  vector    BLOB NOT NULL CHECK (length(vector) = 4 * dim),
  PRIMARY KEY (kind, model, item_id)
) STRICT, WITHOUT ROWID;
