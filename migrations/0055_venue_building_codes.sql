-- The venues of the worlds issue as building types of the knowledge store: train and metro
-- stations, hotels, libraries, museums and galleries, cinemas and theatres, arenas and concert
-- halls, factories, shopping malls, supermarkets, cafés and restaurants, universities, sports
-- halls and gyms, care homes and community halls (polling stations). Each gets the IBC 2018
-- occupancy group it belongs to (Chapter 3) with the occupant load factors of Table 1004.5 that
-- its rooms use, its exit access travel distance (Table 1017.2) and, where its group differs
-- from the general limits, single-exit limits (Table 1006.3.3(2)), corridors (Table 1020.2) and
-- assembly aisles (1029.9.1). A general entry adds the exits per story of Table 1006.3.2 (three
-- from 501 occupants, four above 1,000). Egress width per occupant (1005.3.2) and exit
-- separation (1007.1.1) hold through the general entries of 0011 and 0051.
--
-- building_types gains the new types: SQLite cannot change a CHECK, so the table is rebuilt with
-- the same rows, rowids (the full-text index is keyed by them) and triggers.

CREATE TABLE building_codes_v2 (
  seq           INTEGER PRIMARY KEY,
  ref_id        TEXT NOT NULL UNIQUE
                CHECK (length(ref_id) BETWEEN 3 AND 80 AND ref_id NOT GLOB '*[^a-z0-9_]*'),
  building_type TEXT NOT NULL
                CHECK (building_type IN ('general', 'residential', 'office', 'hospital', 'canteen',
                                         'retail', 'warehouse', 'school', 'airport', 'train_station',
                                         'hotel', 'library', 'museum', 'theatre', 'arena', 'factory',
                                         'mall', 'supermarket', 'restaurant', 'university', 'gym',
                                         'care_home', 'community_hall')),
  jurisdiction  TEXT NOT NULL CHECK (length(jurisdiction) > 0),
  title         TEXT NOT NULL CHECK (length(title) > 0),
  description   TEXT NOT NULL CHECK (length(description) > 0),
  keywords      TEXT NOT NULL DEFAULT '',
  sources       TEXT NOT NULL CHECK (json_valid(sources) AND json_type(sources) = 'array'
                                     AND json_array_length(sources) >= 1),
  constraints   TEXT NOT NULL CHECK (json_valid(constraints) AND json_type(constraints) = 'array'
                                     AND json_array_length(constraints) >= 1)
) STRICT;

INSERT INTO building_codes_v2 (seq, ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints)
  SELECT seq, ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints
  FROM building_codes;
DROP TABLE building_codes;
ALTER TABLE building_codes_v2 RENAME TO building_codes;
CREATE INDEX building_codes_type ON building_codes(building_type, ref_id);

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


INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1006_3_2_exits_per_story', 'general', 'US',
  'IBC 2018 Table 1006.3.2: minimum number of exits per story',
  'Every story needs at least two exits, or access to two exits, once a single exit is not permitted (Table 1006.3.3(1)/(2)); from 501 to 1,000 occupants it needs three and above 1,000 four (Table 1006.3.2). Exits are counted per story from the occupant load of Section 1004.',
  'exits number of exits per story occupant load three exits four exits large assembly',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1006.3.2 Egress based on occupant load, Table 1006.3.2 Minimum number of exits or access to exits per story"}]',
  '[{"name": "three_exits_occupant_load", "type": "min", "value": 501, "unit": "persons", "confidence": 1.0, "applies_to": "building", "original": "501-1,000 occupants: 3 exits"},
   {"name": "four_exits_occupant_load", "type": "min", "value": 1001, "unit": "persons", "confidence": 1.0, "applies_to": "building", "original": "more than 1,000 occupants: 4 exits"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_transit', 'train_station', 'US',
  'IBC 2018 Table 1004.5: transportation terminal occupant load factors (Group A-3)',
  'Waiting areas in transportation terminals are Group A-3 (IBC 303.4). Table 1004.5 counts one occupant per 15 square feet gross (1.39 m2) in waiting areas, which we apply to ticket halls, waiting rooms and platforms, and one per 100 square feet gross (9.29 m2) in concourses.',
  'train station metro railway platform ticket hall concourse waiting occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-3-occupancy-classification-and-use", "section": "303.4 Assembly Group A-3"}]',
  '[{"name": "occupant_load_factor_waiting", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "ticket hall, waiting room, platform", "original": "15 ft² gross"},
   {"name": "occupant_load_factor_concourse", "type": "max", "value": 9.29, "unit": "m²/person", "confidence": 1.0, "applies_to": "concourse", "original": "100 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_transit', 'train_station', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, Group A-3',
  'In stations (Group A-3) the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet (60.96 m) without.',
  'stations exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_hotel', 'hotel', 'US',
  'IBC 2018 Table 1004.5: hotel occupant load factors (Group R-1)',
  'Hotels and motels are Group R-1 (IBC 310.3). Guest rooms count as residential areas, one occupant per 200 square feet gross (18.58 m2); a hotel restaurant counts as unconcentrated assembly, one per 15 square feet net (1.39 m2), and its kitchen as a commercial kitchen, one per 200 square feet gross.',
  'hotel motel guest room restaurant kitchen occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-3-occupancy-classification-and-use", "section": "310.3 Residential Group R-1"}]',
  '[{"name": "occupant_load_factor_hotel", "type": "max", "value": 18.581, "unit": "m²/person", "confidence": 1.0, "applies_to": "hotel room", "original": "200 ft² gross"},
   {"name": "occupant_load_factor_dining", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "restaurant", "original": "15 ft² net"},
   {"name": "occupant_load_factor_commercial_kitchen", "type": "max", "value": 18.581, "unit": "m²/person", "confidence": 1.0, "applies_to": "kitchen", "original": "200 ft² gross"},
   {"name": "occupant_load_factor_waiting", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "lobby", "original": "15 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1006_exits_hotel', 'hotel', 'US',
  'IBC 2018 Table 1006.3.3(2): single exit limits for Group R-1',
  'Hotel (Group R-1) stories may rely on one exit only up to 10 occupants and 75 feet (22.86 m) of exit access travel; beyond either a second exit is required.',
  'Hotel exit exits single exit second exit evacuation',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1006.3.3 Single exits, Table 1006.3.3(2) Stories with one exit or access to one exit for other occupancies"}]',
  '[{"name": "single_exit_occupant_load", "type": "max", "value": 10, "unit": "persons", "confidence": 1.0, "applies_to": "building", "original": "10 occupants (R-1)"},
   {"name": "single_exit_travel_distance", "type": "max", "value": 22.86, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "75 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_hotel', 'hotel', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, Group R-1',
  'In hotels (Group R-1) the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet (60.96 m) without.',
  'hotels exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_library', 'library', 'US',
  'IBC 2018 Table 1004.5: library occupant load factors (Group A-3)',
  'Libraries are Group A-3 (IBC 303.4). Reading rooms count one occupant per 50 square feet net (4.65 m2) and stack areas one per 100 square feet gross (9.29 m2); staff offices count as business areas (150 gross).',
  'library reading room stacks books study occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-3-occupancy-classification-and-use", "section": "303.4 Assembly Group A-3"}]',
  '[{"name": "occupant_load_factor_reading", "type": "max", "value": 4.645, "unit": "m²/person", "confidence": 1.0, "applies_to": "reading room, study room", "original": "50 ft² net"},
   {"name": "occupant_load_factor_stacks", "type": "max", "value": 9.29, "unit": "m²/person", "confidence": 1.0, "applies_to": "stacks", "original": "100 ft² gross"},
   {"name": "occupant_load_factor_business", "type": "max", "value": 13.935, "unit": "m²/person", "confidence": 1.0, "applies_to": "office", "original": "150 ft² gross"},
   {"name": "occupant_load_factor_waiting", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "lobby", "original": "15 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_library', 'library', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, Group A-3',
  'In libraries (Group A-3) the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet (60.96 m) without.',
  'libraries exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1018_aisles_library', 'library', 'US',
  'IBC 2018 1018.3/1018.4: aisles between shelving',
  'Aisles between bookshelves and furniture serving the public are at least 36 inches (0.91 m) clear (1018.3 for business and mercantile areas; 1018.4 for non-public aisles serving stacks at 28 inches).',
  'library aisle shelves stacks width',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1018.3 Groups B and M"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1018.4 Non-public aisles"}]',
  '[{"name": "aisle_clear_width", "type": "min", "value": 0.914, "unit": "m", "confidence": 1.0, "applies_to": "aisle", "original": "36 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_museum', 'museum', 'US',
  'IBC 2018 Table 1004.5: exhibit gallery and museum occupant load factor (Group A-3)',
  'Museums and exhibition halls are Group A-3 (IBC 303.4); Table 1004.5 counts exhibit galleries and museums at one occupant per 30 square feet net (2.79 m2).',
  'museum gallery exhibition exhibit art occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-3-occupancy-classification-and-use", "section": "303.4 Assembly Group A-3"}]',
  '[{"name": "occupant_load_factor_exhibit", "type": "max", "value": 2.787, "unit": "m²/person", "confidence": 1.0, "applies_to": "gallery", "original": "30 ft² net"},
   {"name": "occupant_load_factor_waiting", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "foyer", "original": "15 ft² gross"},
   {"name": "occupant_load_factor_dining", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "cafe", "original": "15 ft² net"},
   {"name": "occupant_load_factor_mercantile", "type": "max", "value": 5.574, "unit": "m²/person", "confidence": 1.0, "applies_to": "museum shop", "original": "60 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_museum', 'museum', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, Group A-3',
  'In museums (Group A-3) the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet (60.96 m) without.',
  'museums exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_theatre', 'theatre', 'US',
  'IBC 2018 Table 1004.5 and 1004.6: theatre and cinema occupant loads (Group A-1)',
  'Theatres and cinemas are Group A-1 (IBC 303.2). With fixed seats the occupant load is the number of seats (1004.6); auditoriums without fixed seats count one occupant per 7 square feet net (0.65 m2) of loose chairs, stages one per 15 square feet net (1.39 m2), and waiting spaces in foyers one per 15 square feet gross.',
  'theatre cinema auditorium seats stage foyer occupant load density audience',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1004.6 Fixed seating"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-3-occupancy-classification-and-use", "section": "303.2 Assembly Group A-1"}]',
  '[{"name": "occupant_load_factor_concentrated_seating", "type": "max", "value": 0.65, "unit": "m²/person", "confidence": 1.0, "applies_to": "auditorium", "original": "7 ft² net"},
   {"name": "occupant_load_factor_stage", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "stage, backstage", "original": "15 ft² net"},
   {"name": "occupant_load_factor_waiting", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "foyer", "original": "15 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1029_aisles_theatre', 'theatre', 'US',
  'IBC 2018 1029.9.1: aisles in assembly seating',
  'Level aisles between rows of seats in theatres and cinemas are at least 42 inches (1.07 m) clear where seats are on both sides and 36 inches (0.91 m) where they are on one side; the clear width between rows is at least 12 inches (305 mm) (1029.13.1).',
  'theatres and cinemas aisle seat rows seating assembly width audience',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1029.9.1 Minimum aisle width"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1029.13.1 Clear width of aisle accessways serving seating"}]',
  '[{"name": "aisle_clear_width", "type": "min", "value": 1.067, "unit": "m", "confidence": 1.0, "applies_to": "aisle", "original": "42 in (seating on both sides)"},
   {"name": "seat_row_clear_width", "type": "min", "value": 0.305, "unit": "m", "confidence": 1.0, "applies_to": "seat row", "original": "12 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_theatre', 'theatre', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, Group A-1',
  'In theatres (Group A-1) the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet (60.96 m) without.',
  'theatres exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_arena', 'arena', 'US',
  'IBC 2018 Table 1004.5: arena and concert hall occupant loads (Groups A-4, A-5)',
  'Indoor sports arenas with spectator seating are Group A-4 and outdoor stadiums Group A-5 (IBC 303.5, 303.6); concert halls are A-1. Standing space counts one occupant per 5 square feet net (0.46 m2), loose seating one per 7 square feet net (0.65 m2), concession stands as mercantile (60 gross) and locker rooms one per 50 square feet gross (4.65 m2).',
  'arena stadium concert hall spectators standing seats concession locker occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-3-occupancy-classification-and-use", "section": "303.5 Assembly Group A-4"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-3-occupancy-classification-and-use", "section": "303.6 Assembly Group A-5"}]',
  '[{"name": "occupant_load_factor_standing", "type": "max", "value": 0.465, "unit": "m²/person", "confidence": 1.0, "applies_to": "arena floor", "original": "5 ft² net"},
   {"name": "occupant_load_factor_concentrated_seating", "type": "max", "value": 0.65, "unit": "m²/person", "confidence": 1.0, "applies_to": "seating", "original": "7 ft² net"},
   {"name": "occupant_load_factor_mercantile", "type": "max", "value": 5.574, "unit": "m²/person", "confidence": 1.0, "applies_to": "concession", "original": "60 ft² gross"},
   {"name": "occupant_load_factor_locker_room", "type": "max", "value": 4.645, "unit": "m²/person", "confidence": 1.0, "applies_to": "locker room", "original": "50 ft² gross"},
   {"name": "occupant_load_factor_outpatient", "type": "max", "value": 9.29, "unit": "m²/person", "confidence": 1.0, "applies_to": "first aid", "original": "100 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1029_aisles_arena', 'arena', 'US',
  'IBC 2018 1029.9.1: aisles in assembly seating',
  'Level aisles between rows of seats in arenas and concert halls are at least 42 inches (1.07 m) clear where seats are on both sides and 36 inches (0.91 m) where they are on one side; the clear width between rows is at least 12 inches (305 mm) (1029.13.1).',
  'arenas and concert halls aisle seat rows seating assembly width audience',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1029.9.1 Minimum aisle width"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1029.13.1 Clear width of aisle accessways serving seating"}]',
  '[{"name": "aisle_clear_width", "type": "min", "value": 1.067, "unit": "m", "confidence": 1.0, "applies_to": "aisle", "original": "42 in (seating on both sides)"},
   {"name": "seat_row_clear_width", "type": "min", "value": 0.305, "unit": "m", "confidence": 1.0, "applies_to": "seat row", "original": "12 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_arena', 'arena', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, Group A-4',
  'In arenas (Group A-4) the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet (60.96 m) without.',
  'arenas exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_factory', 'factory', 'US',
  'IBC 2018 Table 1004.5: industrial occupant load factors (Group F-1)',
  'Factories with moderate-hazard manufacturing are Group F-1 (IBC 306.2). Industrial areas count one occupant per 100 square feet gross (9.29 m2), storage and shipping one per 300 square feet gross (27.87 m2), locker rooms one per 50 gross and offices one per 150 gross.',
  'factory manufacturing production workshop industrial occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-3-occupancy-classification-and-use", "section": "306.2 Moderate-hazard factory industrial, Group F-1"}]',
  '[{"name": "occupant_load_factor_industrial", "type": "max", "value": 9.29, "unit": "m²/person", "confidence": 1.0, "applies_to": "production floor", "original": "100 ft² gross"},
   {"name": "occupant_load_factor_stock_storage", "type": "max", "value": 27.871, "unit": "m²/person", "confidence": 1.0, "applies_to": "storage", "original": "300 ft² gross"},
   {"name": "occupant_load_factor_locker_room", "type": "max", "value": 4.645, "unit": "m²/person", "confidence": 1.0, "applies_to": "locker room", "original": "50 ft² gross"},
   {"name": "occupant_load_factor_business", "type": "max", "value": 13.935, "unit": "m²/person", "confidence": 1.0, "applies_to": "office", "original": "150 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_factory', 'factory', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, Group F-1',
  'In factories (Group F-1) the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet (60.96 m) without.',
  'factories exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'osha1910_36_exit_routes_factory', 'factory', 'US',
  'OSHA 29 CFR 1910.36: exit routes in workplaces',
  'US workplace rules keep every exit access at least 28 inches (0.71 m) wide and exit routes at least 7 ft 6 in (2.29 m) high, also between machines on a production floor.',
  'factory workplace exit route width headroom machines',
  '[{"title": "OSHA 29 CFR 1910.36 Design and construction requirements for exit routes", "url": "https://www.osha.gov/laws-regs/regulations/standardnumber/1910/1910.36", "section": "1910.36(g)(1) and (g)(2)"}]',
  '[{"name": "exit_route_clear_width", "type": "min", "value": 0.711, "unit": "m", "confidence": 1.0, "applies_to": "exit route", "original": "28 in"},
   {"name": "exit_route_headroom", "type": "min", "value": 2.286, "unit": "m", "confidence": 1.0, "applies_to": "exit route", "original": "7 ft 6 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_mall', 'mall', 'US',
  'IBC 2018 402.8.2 and Table 1004.5: covered mall occupant loads (Group M)',
  'Covered mall buildings (IBC 402) count their occupant load from the gross leasable area with a factor between 30 and 50 square feet (402.8.2.1); tenant shops are Group M at one occupant per 60 square feet gross (5.57 m2) and food courts count as assembly with tables, one per 15 square feet net (1.39 m2). The mall concourse itself is not counted again.',
  'mall shopping centre shops tenant food court concourse occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-4-special-detailed-requirements-based-on-occupancy-and-use", "section": "402.8.2 Occupant formula"}]',
  '[{"name": "occupant_load_factor_mercantile", "type": "max", "value": 5.574, "unit": "m²/person", "confidence": 1.0, "applies_to": "shop", "original": "60 ft² gross"},
   {"name": "occupant_load_factor_dining", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "food court", "original": "15 ft² net"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_402_8_mall_egress', 'mall', 'US',
  'IBC 2018 402.8: means of egress in covered malls',
  'The mall concourse is at least 20 feet (6.1 m) wide (402.8.1) and the travel distance within a tenant space to an exit or the mall is at most 200 feet (61 m) (402.8.5).',
  'mall concourse width travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-4-special-detailed-requirements-based-on-occupancy-and-use", "section": "402.8.1 Minimum width"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-4-special-detailed-requirements-based-on-occupancy-and-use", "section": "402.8.5 Travel distance"}]',
  '[{"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_mall', 'mall', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, Group M',
  'In malls (Group M) the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet (60.96 m) without.',
  'malls exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_supermarket', 'supermarket', 'US',
  'IBC 2018 Table 1004.5: supermarket occupant load factors (Group M)',
  'Supermarkets are Group M (IBC 309.1): sales floors count one occupant per 60 square feet gross (5.57 m2), stock rooms and loading bays one per 300 square feet gross (27.87 m2) and offices one per 150 gross.',
  'supermarket grocery sales floor aisles checkout stock room occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-3-occupancy-classification-and-use", "section": "309.1 Mercantile Group M"}]',
  '[{"name": "occupant_load_factor_mercantile", "type": "max", "value": 5.574, "unit": "m²/person", "confidence": 1.0, "applies_to": "sales floor", "original": "60 ft² gross"},
   {"name": "occupant_load_factor_stock_storage", "type": "max", "value": 27.871, "unit": "m²/person", "confidence": 1.0, "applies_to": "stock room", "original": "300 ft² gross"},
   {"name": "occupant_load_factor_business", "type": "max", "value": 13.935, "unit": "m²/person", "confidence": 1.0, "applies_to": "office", "original": "150 ft² gross"},
   {"name": "occupant_load_factor_warehouse", "type": "max", "value": 46.452, "unit": "m²/person", "confidence": 1.0, "applies_to": "loading bay", "original": "500 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1018_aisles_supermarket', 'supermarket', 'US',
  'IBC 2018 1018.3 and ADA 904.3: aisles and check-out aisles',
  'Aisles between shelving in mercantile spaces are at least 36 inches (0.91 m) clear (1018.3); accessible check-out aisles are at least 36 inches wide (ADA 904.3.1).',
  'supermarket aisle checkout shelves width',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1018.3 Groups B and M"}, {"title": "2010 ADA Standards for Accessible Design", "url": "https://www.access-board.gov/ada/", "section": "904.3 Check-out aisles"}]',
  '[{"name": "aisle_clear_width", "type": "min", "value": 0.914, "unit": "m", "confidence": 1.0, "applies_to": "aisle", "original": "36 in"},
   {"name": "checkout_aisle_width", "type": "min", "value": 0.914, "unit": "m", "confidence": 1.0, "applies_to": "check-out aisle", "original": "36 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_supermarket', 'supermarket', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, Group M',
  'In supermarkets (Group M) the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet (60.96 m) without.',
  'supermarkets exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_restaurant', 'restaurant', 'US',
  'IBC 2018 Table 1004.5: restaurant occupant load factors (Group A-2)',
  'Restaurants, cafés and bars are Group A-2 (IBC 303.3). Dining with tables and chairs counts one occupant per 15 square feet net (1.39 m2), standing at a bar one per 5 square feet net, commercial kitchens one per 200 square feet gross (18.58 m2).',
  'restaurant cafe bar dining tables kitchen occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-3-occupancy-classification-and-use", "section": "303.3 Assembly Group A-2"}]',
  '[{"name": "occupant_load_factor_dining", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "dining room", "original": "15 ft² net"},
   {"name": "occupant_load_factor_commercial_kitchen", "type": "max", "value": 18.581, "unit": "m²/person", "confidence": 1.0, "applies_to": "kitchen", "original": "200 ft² gross"},
   {"name": "occupant_load_factor_stock_storage", "type": "max", "value": 27.871, "unit": "m²/person", "confidence": 1.0, "applies_to": "storage", "original": "300 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_restaurant', 'restaurant', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, Group A-2',
  'In restaurants (Group A-2) the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet (60.96 m) without.',
  'restaurants exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_university', 'university', 'US',
  'IBC 2018 Table 1004.5: university occupant load factors (Groups B, A-3)',
  'Education above the 12th grade is Group B (IBC 304.1) and lecture halls with 50 or more seats are Group A-3. Classroom areas count one occupant per 20 square feet net (1.86 m2), lecture halls with loose seating one per 7 square feet net (0.65 m2), offices one per 150 gross, reading rooms one per 50 net.',
  'university college lecture hall seminar classroom students occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-3-occupancy-classification-and-use", "section": "304.1 Business Group B"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-3-occupancy-classification-and-use", "section": "303.4 Assembly Group A-3"}]',
  '[{"name": "occupant_load_factor_classroom", "type": "max", "value": 1.858, "unit": "m²/person", "confidence": 1.0, "applies_to": "seminar room", "original": "20 ft² net"},
   {"name": "occupant_load_factor_concentrated_seating", "type": "max", "value": 0.65, "unit": "m²/person", "confidence": 1.0, "applies_to": "lecture hall", "original": "7 ft² net"},
   {"name": "occupant_load_factor_business", "type": "max", "value": 13.935, "unit": "m²/person", "confidence": 1.0, "applies_to": "office", "original": "150 ft² gross"},
   {"name": "occupant_load_factor_reading", "type": "max", "value": 4.645, "unit": "m²/person", "confidence": 1.0, "applies_to": "reading room", "original": "50 ft² net"},
   {"name": "occupant_load_factor_waiting", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "lobby", "original": "15 ft² gross"},
   {"name": "occupant_load_factor_dining", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "cafe", "original": "15 ft² net"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1029_aisles_university', 'university', 'US',
  'IBC 2018 1029.9.1: aisles in assembly seating',
  'Level aisles between rows of seats in lecture halls are at least 42 inches (1.07 m) clear where seats are on both sides and 36 inches (0.91 m) where they are on one side; the clear width between rows is at least 12 inches (305 mm) (1029.13.1).',
  'lecture halls aisle seat rows seating assembly width audience',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1029.9.1 Minimum aisle width"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1029.13.1 Clear width of aisle accessways serving seating"}]',
  '[{"name": "aisle_clear_width", "type": "min", "value": 1.067, "unit": "m", "confidence": 1.0, "applies_to": "aisle", "original": "42 in (seating on both sides)"},
   {"name": "seat_row_clear_width", "type": "min", "value": 0.305, "unit": "m", "confidence": 1.0, "applies_to": "seat row", "original": "12 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_university', 'university', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, Group B',
  'In universities (Group B) the walking distance to an exit may reach 300 feet (91.44 m) with sprinklers and 200 feet (60.96 m) without.',
  'universities exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 91.44, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "300 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_gym', 'gym', 'US',
  'IBC 2018 Table 1004.5: gymnasium and exercise occupant load factors (Group A-3)',
  'Gymnasiums without spectator seating are Group A-3 (IBC 303.4). Exercise rooms count one occupant per 50 square feet gross (4.65 m2), and so do locker rooms.',
  'gym gymnasium sports hall fitness exercise locker changing room occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-3-occupancy-classification-and-use", "section": "303.4 Assembly Group A-3"}]',
  '[{"name": "occupant_load_factor_exercise", "type": "max", "value": 4.645, "unit": "m²/person", "confidence": 1.0, "applies_to": "sports hall, fitness room", "original": "50 ft² gross"},
   {"name": "occupant_load_factor_locker_room", "type": "max", "value": 4.645, "unit": "m²/person", "confidence": 1.0, "applies_to": "changing room", "original": "50 ft² gross"},
   {"name": "occupant_load_factor_waiting", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "lobby", "original": "15 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_gym', 'gym', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, Group A-3',
  'In sports halls (Group A-3) the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet (60.96 m) without.',
  'sports halls exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_care_home', 'care_home', 'US',
  'IBC 2018 Table 1004.5: nursing home occupant load factors (Group I-2)',
  'Nursing homes are Group I-2 (IBC 308.3). Sleeping areas count one occupant per 120 square feet gross (11.15 m2); day rooms and dining with tables one per 15 square feet net; outpatient and nursing areas one per 100 gross.',
  'care home nursing home residents sleeping day room dining occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-3-occupancy-classification-and-use", "section": "308.3 Institutional Group I-2"}]',
  '[{"name": "occupant_load_factor_sleeping", "type": "max", "value": 11.148, "unit": "m²/person", "confidence": 1.0, "applies_to": "resident''s room", "original": "120 ft² gross"},
   {"name": "occupant_load_factor_dining", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "day room", "original": "15 ft² net"},
   {"name": "occupant_load_factor_outpatient", "type": "max", "value": 9.29, "unit": "m²/person", "confidence": 1.0, "applies_to": "nurse station", "original": "100 ft² gross"},
   {"name": "occupant_load_factor_commercial_kitchen", "type": "max", "value": 18.581, "unit": "m²/person", "confidence": 1.0, "applies_to": "kitchen", "original": "200 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1020_corridor_care_home', 'care_home', 'US',
  'IBC 2018 Table 1020.2: corridors in Group I-2',
  'In nursing homes (Group I-2) corridors used for moving residents in beds are at least 96 inches (2.44 m) wide, and doors in those paths give 41.5 inches (1.05 m) of clear width (1010.1.1).',
  'care home nursing home corridor door width beds',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1020.2 Width and capacity, Table 1020.2 Minimum corridor width"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1010.1.1 Size of doors"}]',
  '[{"name": "corridor_clear_width", "type": "min", "value": 2.438, "unit": "m", "confidence": 1.0, "applies_to": "corridor", "original": "96 in"},
   {"name": "door_clear_width", "type": "min", "value": 1.054, "unit": "m", "confidence": 1.0, "applies_to": "door", "original": "41.5 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1006_exits_care_home', 'care_home', 'US',
  'IBC 2018 Table 1006.3.3(2): single exit limits for Group I-2',
  'Nursing home (Group I-2) stories may rely on one exit only up to 10 occupants and 75 feet (22.86 m) of exit access travel; beyond either a second exit is required.',
  'Nursing home exit exits single exit second exit evacuation',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1006.3.3 Single exits, Table 1006.3.3(2) Stories with one exit or access to one exit for other occupancies"}]',
  '[{"name": "single_exit_occupant_load", "type": "max", "value": 10, "unit": "persons", "confidence": 1.0, "applies_to": "building", "original": "10 occupants (I-2)"},
   {"name": "single_exit_travel_distance", "type": "max", "value": 22.86, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "75 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_care_home', 'care_home', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, Group I-2',
  'In nursing homes (Group I-2) the walking distance to an exit may reach 200 feet (60.96 m) with sprinklers and 0 feet (0.0 m) without.',
  'nursing homes exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft (sprinklered)"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_community_hall', 'community_hall', 'US',
  'IBC 2018 Table 1004.5: community hall occupant load factors (Group A-3)',
  'Community halls, including those used as polling stations, are Group A-3 (IBC 303.4). With tables and chairs they count one occupant per 15 square feet net (1.39 m2), with rows of loose chairs one per 7 square feet net; kitchens count as commercial kitchens.',
  'community hall village hall polling station voting assembly tables chairs occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}, {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-3-occupancy-classification-and-use", "section": "303.4 Assembly Group A-3"}]',
  '[{"name": "occupant_load_factor_unconcentrated", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "main hall", "original": "15 ft² net"},
   {"name": "occupant_load_factor_commercial_kitchen", "type": "max", "value": 18.581, "unit": "m²/person", "confidence": 1.0, "applies_to": "kitchen", "original": "200 ft² gross"},
   {"name": "occupant_load_factor_business", "type": "max", "value": 13.935, "unit": "m²/person", "confidence": 1.0, "applies_to": "meeting room, office", "original": "150 ft² gross"},
   {"name": "occupant_load_factor_stock_storage", "type": "max", "value": 27.871, "unit": "m²/person", "confidence": 1.0, "applies_to": "storage", "original": "300 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_community_hall', 'community_hall', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, Group A-3',
  'In community halls (Group A-3) the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet (60.96 m) without.',
  'community halls exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');
