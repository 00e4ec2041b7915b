-- Number and separation of exits as knowledge entries (until now the compliance checker carried
-- these thresholds in code). IBC 2018 Table 1006.3.3(2) gives, for a story with one exit at the
-- first story above grade plane, the largest occupant load and exit access travel distance that
-- exit may serve, by occupancy; §1007.1.1 asks two required exits to stand at least half the
-- overall diagonal of the area apart (one third with sprinklers; our plans are unsprinklered).
-- Three entries: the general one (occupancies A, B, E, F, M, U), hospitals (I-2) and
-- warehouses (S). The checker uses the merged values: the type's own entry wins over "general".

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1006_1007_exits', 'general', 'US',
  'IBC 2018 1006.3 and 1007.1: number and separation of exits',
  'A story may have a single exit only while its occupant load and the exit access travel distance stay within the limits of Table 1006.3.3(2): for assembly, business, educational, factory, mercantile and utility occupancies 49 occupants and 75 feet (22.86 m). Beyond either limit a second exit is required, and two required exits must be placed at least half the overall diagonal of the area apart, measured in a straight line between them (unsprinklered buildings).',
  'exit exits number of exits second exit single exit egress separation diagonal means of egress evacuation',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1006.3.3 Single exits, Table 1006.3.3(2) Stories with one exit"},
   {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1007.1.1 Two exits or exit access doorways"}]',
  '[{"name": "single_exit_occupant_load", "type": "max", "value": 49, "unit": "persons", "confidence": 0.9, "applies_to": "building", "original": "49 occupants (A, B, E, F, M, U)"},
   {"name": "single_exit_travel_distance", "type": "max", "value": 22.86, "unit": "m", "confidence": 0.9, "applies_to": "building", "original": "75 ft"},
   {"name": "exit_separation_diagonal_fraction", "type": "min", "value": 0.5, "unit": "ratio", "confidence": 1.0, "applies_to": "building", "original": "one-half of the overall diagonal"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1006_exits_institutional', 'hospital', 'US',
  'IBC 2018 1006.3.3: single exit limits for institutional occupancies',
  'Institutional (I-2, hospitals and nursing homes) stories may rely on one exit only up to 10 occupants and 75 feet (22.86 m) of exit access travel; any larger ward, clinic or waiting area needs a second exit.',
  'hospital clinic ward exit exits single exit second exit evacuation',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1006.3.3 Single exits, Table 1006.3.3(2) Stories with one exit"}]',
  '[{"name": "single_exit_occupant_load", "type": "max", "value": 10, "unit": "persons", "confidence": 0.9, "applies_to": "building", "original": "10 occupants (H-4, H-5, I, R-1, R-2, R-4)"},
   {"name": "single_exit_travel_distance", "type": "max", "value": 22.86, "unit": "m", "confidence": 0.9, "applies_to": "building", "original": "75 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1006_exits_storage', 'warehouse', 'US',
  'IBC 2018 1006.3.3: single exit limits for storage occupancies',
  'Storage (S) stories may rely on one exit up to 29 occupants and 100 feet (30.48 m) of exit access travel.',
  'warehouse storage exit exits single exit second exit evacuation',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018/chapter-10-means-of-egress", "section": "1006.3.3 Single exits, Table 1006.3.3(2) Stories with one exit"}]',
  '[{"name": "single_exit_occupant_load", "type": "max", "value": 29, "unit": "persons", "confidence": 0.9, "applies_to": "building", "original": "29 occupants (S)"},
   {"name": "single_exit_travel_distance", "type": "max", "value": 30.48, "unit": "m", "confidence": 0.9, "applies_to": "building", "original": "100 ft"}]');
