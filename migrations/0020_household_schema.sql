-- Dynamic household scenes (paper 000): curated knowledge the offline generators draw on.
-- Seed rows arrive in the following migrations; core/household loads them once into plain structs.
-- Personas: the paper's 8 fields as a JSON object; built-in rows ship here, posted ones are added at run time.
CREATE TABLE household_personas (
  id         TEXT PRIMARY KEY CHECK (length(id) BETWEEN 1 AND 80),
  builtin    INTEGER NOT NULL CHECK (builtin IN (0, 1)),
  body       TEXT NOT NULL CHECK (json_valid(body) AND json_type(body) = 'object'
                                  AND json_type(body, '$.name') = 'text' AND json_type(body, '$.age') = 'integer'
                                  AND json_type(body, '$.personality') = 'array'),
  created_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%SZ', 'now'))
) STRICT;

-- Activity vocabulary: a primary name, its role in a day, synonyms (which share its effects),
-- typical duration and time-of-day windows, persona keywords that make it likely, and its
-- effects: p(l|a) over room types and, per object type, p(o|a,l) with receptacle weights.
CREATE TABLE household_activities (
  name TEXT PRIMARY KEY CHECK (length(name) BETWEEN 1 AND 80),
  role TEXT NOT NULL,
  body TEXT NOT NULL CHECK (json_valid(body) AND json_type(body, '$.effects') = 'object'
                            AND json_type(body, '$.synonyms') = 'array')
) STRICT;

-- Receptacle types: plausible room types, footprint, surface height, wall or middle placement,
-- and what a tidy house keeps on them (used when a house is furnished procedurally).
CREATE TABLE household_receptacle_types (
  type TEXT PRIMARY KEY,
  body TEXT NOT NULL CHECK (json_valid(body) AND json_type(body, '$.rooms') = 'array')
) STRICT;

-- AI2-THOR object types the scenes know: movable objects (relocated by activities) and fixtures.
CREATE TABLE household_object_types (
  type TEXT PRIMARY KEY,
  kind TEXT NOT NULL CHECK (kind IN ('movable', 'fixture'))
) STRICT;

-- Furniture program and size range per room type for the procedural house generator.
CREATE TABLE household_room_programs (
  room_type TEXT PRIMARY KEY CHECK (room_type IN ('Bedroom', 'Bathroom', 'LivingRoom', 'Kitchen')),
  body      TEXT NOT NULL CHECK (json_valid(body) AND json_type(body, '$.furniture') = 'array')
) STRICT;
