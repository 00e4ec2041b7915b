-- PostgreSQL's form of 0055_venue_building_codes.sql: PostgreSQL changes a CHECK in place, so
-- the table is not rebuilt (shared-data-skip: building_codes_v2 — the copy of the old rows into
-- the rebuilt table is SQLite's alone); the new entries follow from the shared file.
ALTER TABLE building_codes DROP CONSTRAINT building_codes_type_check;
ALTER TABLE building_codes ADD CONSTRAINT building_codes_type_check
  CHECK (building_type IN ('general', 'residential', 'office', 'hospital', 'canteen',
                           'retail', 'warehouse', 'school', 'airport', 'train_station',
                           'hotel', 'library', 'museum', 'theatre', 'arena', 'factory',
                           'mall', 'supermarket', 'restaurant', 'university', 'gym',
                           'care_home', 'community_hall'));
