-- Seed building-code references (paper 001 schema). Values are SI; each constraint keeps the
-- source's own figure in `original`. Descriptions are ours. Confidence < 1 marks values or
-- section numbers we could not confirm against the text of the source; the description says why.
-- Append-only: correct an entry with UPDATE/INSERT in a new migration, never by editing this file.

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'irc2021_r304_room_area', 'residential', 'US',
  'IRC 2021 R304: minimum habitable room area and dimension',
  'Every habitable room of a one- or two-family dwelling needs at least 70 square feet of floor and no plan dimension under 7 feet; kitchens are exempt. Converted to 6.5 m2 and 2.13 m.',
  'bedroom living room dwelling house home minimum room size',
  '[{"title": "International Residential Code (IRC) 2021", "url": "https://codes.iccsafe.org/content/IRC2021P1/chapter-3-building-planning", "section": "R304.1 Minimum area"},
   {"title": "International Residential Code (IRC) 2021", "url": "https://codes.iccsafe.org/content/IRC2021P1/chapter-3-building-planning", "section": "R304.2 Other rooms"}]',
  '[{"name": "habitable_room_area", "type": "min", "value": 6.503, "unit": "m²", "confidence": 1.0, "applies_to": "habitable room", "original": "70 ft²"},
   {"name": "habitable_room_min_dimension", "type": "min", "value": 2.134, "unit": "m", "confidence": 1.0, "applies_to": "habitable room", "original": "7 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'irc2021_r305_ceiling_height', 'residential', 'US',
  'IRC 2021 R305: minimum ceiling height in dwellings',
  'Habitable spaces, hallways, bathrooms, toilet rooms and laundry rooms of a dwelling need a ceiling at least 7 feet (2.13 m) high; the code lists exceptions for beams and sloped ceilings.',
  'ceiling height headroom dwelling house',
  '[{"title": "International Residential Code (IRC) 2021", "url": "https://codes.iccsafe.org/content/IRC2021P1/chapter-3-building-planning", "section": "R305.1 Minimum height"}]',
  '[{"name": "ceiling_height", "type": "min", "value": 2.134, "unit": "m", "confidence": 1.0, "applies_to": "habitable room, hallway, bathroom", "original": "7 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'irc2021_r311_hallway', 'residential', 'US',
  'IRC 2021 R311.6: hallway width in dwellings',
  'A hallway inside a dwelling must be at least 3 feet (0.91 m) wide; this is the residential counterpart of the commercial corridor rule.',
  'hallway corridor passage width dwelling',
  '[{"title": "International Residential Code (IRC) 2021", "url": "https://codes.iccsafe.org/content/IRC2021P1/chapter-3-building-planning", "section": "R311.6 Hallways"}]',
  '[{"name": "corridor_clear_width", "type": "min", "value": 0.914, "unit": "m", "confidence": 1.0, "applies_to": "hallway", "original": "3 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'irc2021_r311_egress_door', 'residential', 'US',
  'IRC 2021 R311.2: egress door of a dwelling',
  'Each dwelling needs a side-hinged egress door giving at least 32 inches (0.81 m) of clear width with the door open at 90 degrees and 78 inches (1.98 m) of clear height.',
  'front door entrance exit door width dwelling',
  '[{"title": "International Residential Code (IRC) 2021", "url": "https://codes.iccsafe.org/content/IRC2021P1/chapter-3-building-planning", "section": "R311.2 Egress door"}]',
  '[{"name": "door_clear_width", "type": "min", "value": 0.813, "unit": "m", "confidence": 1.0, "applies_to": "egress door", "original": "32 in"},
   {"name": "door_clear_height", "type": "min", "value": 1.981, "unit": "m", "confidence": 1.0, "applies_to": "egress door", "original": "78 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'irc2021_r311_stairways', 'residential', 'US',
  'IRC 2021 R311.7: stairways in dwellings',
  'Dwelling stairs need 36 inches (0.91 m) of clear width, 6 ft 8 in (2.03 m) of headroom, risers of at most 7.75 inches (0.197 m) and treads of at least 10 inches (0.254 m).',
  'stairs staircase steps riser tread headroom dwelling',
  '[{"title": "International Residential Code (IRC) 2021", "url": "https://codes.iccsafe.org/content/IRC2021P1/chapter-3-building-planning", "section": "R311.7.1 Width"},
   {"title": "International Residential Code (IRC) 2021", "url": "https://codes.iccsafe.org/content/IRC2021P1/chapter-3-building-planning", "section": "R311.7.2 Headroom"},
   {"title": "International Residential Code (IRC) 2021", "url": "https://codes.iccsafe.org/content/IRC2021P1/chapter-3-building-planning", "section": "R311.7.5.1 Risers"},
   {"title": "International Residential Code (IRC) 2021", "url": "https://codes.iccsafe.org/content/IRC2021P1/chapter-3-building-planning", "section": "R311.7.5.2 Treads"}]',
  '[{"name": "stair_clear_width", "type": "min", "value": 0.914, "unit": "m", "confidence": 1.0, "applies_to": "stair", "original": "36 in"},
   {"name": "stair_headroom", "type": "min", "value": 2.032, "unit": "m", "confidence": 1.0, "applies_to": "stair", "original": "6 ft 8 in"},
   {"name": "stair_riser_height", "type": "max", "value": 0.197, "unit": "m", "confidence": 1.0, "applies_to": "stair", "original": "7 3/4 in"},
   {"name": "stair_tread_depth", "type": "min", "value": 0.254, "unit": "m", "confidence": 1.0, "applies_to": "stair", "original": "10 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'irc2021_r310_escape_opening', 'residential', 'US',
  'IRC 2021 R310: emergency escape and rescue openings',
  'Sleeping rooms need an emergency escape opening (usually a window) with at least 5.7 square feet (0.53 m2) net clear area, 24 inches clear height, 20 inches clear width and a sill no higher than 44 inches. Section numbers follow the 2021 layout of R310.2 as we understand it; check the exact subsection.',
  'bedroom window escape rescue opening egress sleeping room',
  '[{"title": "International Residential Code (IRC) 2021", "url": "https://codes.iccsafe.org/content/IRC2021P1/chapter-3-building-planning", "section": "R310.2.1 Minimum opening area"},
   {"title": "International Residential Code (IRC) 2021", "url": "https://codes.iccsafe.org/content/IRC2021P1/chapter-3-building-planning", "section": "R310.2.2 Window sill height"}]',
  '[{"name": "escape_opening_area", "type": "min", "value": 0.53, "unit": "m²", "confidence": 0.9, "applies_to": "sleeping room window", "original": "5.7 ft²"},
   {"name": "escape_opening_height", "type": "min", "value": 0.61, "unit": "m", "confidence": 0.9, "applies_to": "sleeping room window", "original": "24 in"},
   {"name": "escape_opening_width", "type": "min", "value": 0.508, "unit": "m", "confidence": 0.9, "applies_to": "sleeping room window", "original": "20 in"},
   {"name": "escape_opening_sill_height", "type": "max", "value": 1.118, "unit": "m", "confidence": 0.9, "applies_to": "sleeping room window", "original": "44 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'irc2021_r307_bathroom_clearances', 'residential', 'US',
  'IRC 2021 R307: toilet and washbasin clearances',
  'Figure R307.1 spaces bathroom fixtures: a toilet''s centreline sits at least 15 inches (0.38 m) from a side wall, with 21 inches (0.53 m) clear in front of the toilet and of the washbasin. These figures decide the smallest workable bathroom.',
  'bathroom toilet water closet washbasin lavatory wc restroom clearance',
  '[{"title": "International Residential Code (IRC) 2021", "url": "https://codes.iccsafe.org/content/IRC2021P1/chapter-3-building-planning", "section": "R307.1 Space required (Figure R307.1)"}]',
  '[{"name": "wc_centerline_to_wall", "type": "min", "value": 0.381, "unit": "m", "confidence": 1.0, "applies_to": "bathroom", "original": "15 in"},
   {"name": "wc_front_clearance", "type": "min", "value": 0.533, "unit": "m", "confidence": 1.0, "applies_to": "bathroom", "original": "21 in"},
   {"name": "lavatory_front_clearance", "type": "min", "value": 0.533, "unit": "m", "confidence": 1.0, "applies_to": "bathroom", "original": "21 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'irc2021_p2708_shower_size', 'residential', 'US',
  'IRC 2021 P2708: minimum shower size',
  'A shower compartment needs at least 900 square inches (0.58 m2) of interior floor and must fit a 30-inch (0.76 m) circle.',
  'bathroom shower cubicle size',
  '[{"title": "International Residential Code (IRC) 2021", "url": "https://codes.iccsafe.org/content/IRC2021P1", "section": "P2708.1 Shower compartments (General)"}]',
  '[{"name": "shower_floor_area", "type": "min", "value": 0.581, "unit": "m²", "confidence": 1.0, "applies_to": "bathroom shower", "original": "900 in²"},
   {"name": "shower_min_dimension", "type": "min", "value": 0.762, "unit": "m", "confidence": 1.0, "applies_to": "bathroom shower", "original": "30 in circle"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1208_dwelling_rooms', 'residential', 'US',
  'IBC 2018 1208: dwelling room sizes and kitchen passage',
  'In apartment buildings under the IBC every dwelling has one room of at least 120 square feet (11.15 m2), other habitable rooms at least 70 square feet (6.5 m2), no habitable room narrower than 7 feet, and kitchens keep a 3-foot (0.91 m) clear passage between counter fronts and appliances or walls.',
  'apartment flat dwelling kitchen living room bedroom minimum size passage',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1208.1 Minimum room widths"},
   {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1208.3 Room area"}]',
  '[{"name": "largest_habitable_room_area", "type": "min", "value": 11.148, "unit": "m²", "confidence": 1.0, "applies_to": "living room", "original": "120 ft² net"},
   {"name": "habitable_room_area", "type": "min", "value": 6.503, "unit": "m²", "confidence": 1.0, "applies_to": "habitable room", "original": "70 ft² net"},
   {"name": "habitable_room_min_dimension", "type": "min", "value": 2.134, "unit": "m", "confidence": 1.0, "applies_to": "habitable room", "original": "7 ft"},
   {"name": "kitchen_clear_passage", "type": "min", "value": 0.914, "unit": "m", "confidence": 1.0, "applies_to": "kitchen", "original": "3 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_residential', 'residential', 'US',
  'IBC 2018 Table 1004.5: residential occupant load factor',
  'For egress design the IBC counts one occupant per 200 square feet gross (18.58 m2) of residential floor area.',
  'occupant load density persons dwelling apartment',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}]',
  '[{"name": "occupant_load_factor_residential", "type": "max", "value": 18.581, "unit": "m²/person", "confidence": 1.0, "applies_to": "dwelling", "original": "200 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ndss2015_bedrooms', 'residential', 'England',
  'UK NDSS 2015: bedroom minimum areas and widths',
  'The nationally described space standard asks for single bedrooms of at least 7.5 m2 and 2.15 m wide, and double or twin bedrooms of at least 11.5 m2; the main double bedroom is at least 2.75 m wide and every other double at least 2.55 m.',
  'bedroom single double twin flat dwelling space standard',
  '[{"title": "Technical housing standards - nationally described space standard (2015)", "url": "https://www.gov.uk/government/publications/technical-housing-standards-nationally-described-space-standard", "section": "para. 10(c) single bedroom"},
   {"title": "Technical housing standards - nationally described space standard (2015)", "url": "https://www.gov.uk/government/publications/technical-housing-standards-nationally-described-space-standard", "section": "para. 10(d) double or twin bedroom"},
   {"title": "Technical housing standards - nationally described space standard (2015)", "url": "https://www.gov.uk/government/publications/technical-housing-standards-nationally-described-space-standard", "section": "para. 10(e) bedroom widths"}]',
  '[{"name": "bedroom_single_area", "type": "min", "value": 7.5, "unit": "m²", "confidence": 1.0, "applies_to": "bedroom", "original": "7.5 m²"},
   {"name": "bedroom_single_min_width", "type": "min", "value": 2.15, "unit": "m", "confidence": 1.0, "applies_to": "bedroom", "original": "2.15 m"},
   {"name": "bedroom_double_area", "type": "min", "value": 11.5, "unit": "m²", "confidence": 1.0, "applies_to": "bedroom", "original": "11.5 m²"},
   {"name": "bedroom_double_min_width", "type": "min", "value": 2.75, "unit": "m", "confidence": 1.0, "applies_to": "main bedroom", "original": "2.75 m"},
   {"name": "bedroom_double_other_min_width", "type": "min", "value": 2.55, "unit": "m", "confidence": 1.0, "applies_to": "bedroom", "original": "2.55 m"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ndss2015_gross_internal_area', 'residential', 'England',
  'UK NDSS 2015 Table 1: minimum gross internal floor area of dwellings',
  'Table 1 of the space standard sets the smallest gross internal area of a new dwelling by bedrooms and bed spaces; we keep the common single-storey sizes (a one-person studio may drop to 37 m2 with a shower room instead of a bathroom).',
  'flat apartment dwelling size gross internal area studio',
  '[{"title": "Technical housing standards - nationally described space standard (2015)", "url": "https://www.gov.uk/government/publications/technical-housing-standards-nationally-described-space-standard", "section": "Table 1 Minimum gross internal floor areas and storage (m2)"}]',
  '[{"name": "dwelling_gia_1b1p", "type": "min", "value": 39, "unit": "m²", "confidence": 0.95, "applies_to": "dwelling", "original": "39 m²"},
   {"name": "dwelling_gia_1b2p", "type": "min", "value": 50, "unit": "m²", "confidence": 0.95, "applies_to": "dwelling", "original": "50 m²"},
   {"name": "dwelling_gia_2b3p", "type": "min", "value": 61, "unit": "m²", "confidence": 0.95, "applies_to": "dwelling", "original": "61 m²"},
   {"name": "dwelling_gia_2b4p", "type": "min", "value": 70, "unit": "m²", "confidence": 0.95, "applies_to": "dwelling", "original": "70 m²"},
   {"name": "dwelling_gia_3b5p", "type": "min", "value": 86, "unit": "m²", "confidence": 0.95, "applies_to": "dwelling", "original": "86 m²"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ndss2015_storage', 'residential', 'England',
  'UK NDSS 2015 Table 1: built-in storage',
  'Alongside floor area the space standard asks for built-in storage that grows with the number of bedrooms: about 1.5 m2 for one bedroom, 2.0 m2 for two and 2.5 m2 for three (values as we read Table 1).',
  'storage cupboard closet dwelling',
  '[{"title": "Technical housing standards - nationally described space standard (2015)", "url": "https://www.gov.uk/government/publications/technical-housing-standards-nationally-described-space-standard", "section": "Table 1 Minimum gross internal floor areas and storage (m2)"}]',
  '[{"name": "built_in_storage_1b", "type": "min", "value": 1.5, "unit": "m²", "confidence": 0.9, "applies_to": "storage", "original": "1.5 m²"},
   {"name": "built_in_storage_2b", "type": "min", "value": 2.0, "unit": "m²", "confidence": 0.9, "applies_to": "storage", "original": "2.0 m²"},
   {"name": "built_in_storage_3b", "type": "min", "value": 2.5, "unit": "m²", "confidence": 0.9, "applies_to": "storage", "original": "2.5 m²"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ndss2015_ceiling_height', 'residential', 'England',
  'UK NDSS 2015: floor-to-ceiling height',
  'The space standard requires a floor-to-ceiling height of at least 2.3 m over at least 75 percent of the gross internal area.',
  'ceiling height headroom flat dwelling',
  '[{"title": "Technical housing standards - nationally described space standard (2015)", "url": "https://www.gov.uk/government/publications/technical-housing-standards-nationally-described-space-standard", "section": "para. 10 (floor-to-ceiling height criterion)"}]',
  '[{"name": "ceiling_height", "type": "min", "value": 2.3, "unit": "m", "confidence": 1.0, "applies_to": "dwelling", "original": "2.3 m"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'nkba_kitchen_aisles', 'residential', 'US',
  'NKBA Kitchen Planning Guidelines: work aisles and walkways',
  'The kitchen planning guidelines of the National Kitchen & Bath Association recommend 42-inch (1.07 m) work aisles for one cook, 48 inches (1.22 m) for several cooks and 36-inch (0.91 m) walkways. They are industry guidance, not law; guideline numbering varies by edition.',
  'kitchen work aisle walkway cooking counter',
  '[{"title": "NKBA Kitchen & Bathroom Planning Guidelines", "url": "https://nkba.org/", "section": "Kitchen planning guidelines: work aisle and walkway widths"}]',
  '[{"name": "kitchen_work_aisle_width", "type": "recommended", "value": 1.067, "unit": "m", "confidence": 0.8, "applies_to": "kitchen", "original": "42 in"},
   {"name": "kitchen_work_aisle_width_multi_cook", "type": "recommended", "value": 1.219, "unit": "m", "confidence": 0.8, "applies_to": "kitchen", "original": "48 in"},
   {"name": "kitchen_walkway_width", "type": "recommended", "value": 0.914, "unit": "m", "confidence": 0.8, "applies_to": "kitchen", "original": "36 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'bco2019_workplace_density', 'office', 'UK',
  'BCO Guide to Specification: workplace density',
  'The British Council for Offices frames office capacity as net internal area per workplace. Paper 001 takes 10 m2 per person from the guide as the design density; the guide itself discusses a band of densities, so confidence is below one.',
  'office workspace desk density workstation open plan occupancy',
  '[{"title": "British Council for Offices: BCO Guide to Specification (2019)", "url": "https://www.bco.org.uk/", "section": "Occupational density guidance"}]',
  '[{"name": "workspace_area_per_person", "type": "recommended", "value": 10.0, "unit": "m²/person", "confidence": 0.8, "applies_to": "open-plan office", "original": "10 m² per person"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'bco2019_ceiling_height', 'office', 'UK',
  'BCO Guide to Specification: office floor-to-ceiling height',
  'For new offices the BCO guide favours a finished floor-to-ceiling height of roughly 2.6 to 3.0 m; we store 2.7 m as the recommended value. This figure is from memory of the guide, hence the low confidence.',
  'office ceiling height floor to ceiling',
  '[{"title": "British Council for Offices: BCO Guide to Specification (2019)", "url": "https://www.bco.org.uk/", "section": "Floor-to-ceiling height guidance"}]',
  '[{"name": "ceiling_height", "type": "recommended", "value": 2.7, "unit": "m", "confidence": 0.6, "applies_to": "office floor", "original": "2.6-3.0 m"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_business', 'office', 'US',
  'IBC 2018 Table 1004.5: business occupant load factor',
  'Offices (business areas) are counted at one occupant per 150 square feet gross (13.94 m2) when sizing exits.',
  'office business occupant load density persons',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}]',
  '[{"name": "occupant_load_factor_business", "type": "max", "value": 13.935, "unit": "m²/person", "confidence": 1.0, "applies_to": "office", "original": "150 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'adb2019_floor_space_office', 'office', 'England',
  'Approved Document B Table D1: office floor space factor',
  'For fire escape design the English guidance counts one person per 6 m2 of office floor. We cite the 2019 edition''s floor space factor table as we recall it.',
  'office occupant load density floor space factor persons fire escape',
  '[{"title": "Approved Document B: Fire safety, Volume 2 - Buildings other than dwellings (2019 edition)", "url": "https://www.gov.uk/government/publications/fire-safety-approved-document-b", "section": "Appendix D, Table D1 Floor space factors"}]',
  '[{"name": "occupant_load_factor_business", "type": "max", "value": 6.0, "unit": "m²/person", "confidence": 0.8, "applies_to": "office", "original": "6.0 m²/person"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'hse_l24_room_space', 'office', 'Great Britain',
  'Workplace Regulations 1992, regulation 10: space per person',
  'The Approved Code of Practice for the Workplace (Health, Safety and Welfare) Regulations asks for at least 11 cubic metres per person in a workroom, ignoring any height above 3.0 m.',
  'office workroom space per person volume workplace',
  '[{"title": "Workplace (Health, Safety and Welfare) Regulations 1992, Approved Code of Practice and guidance (L24)", "url": "https://www.hse.gov.uk/pubns/books/l24.htm", "section": "Regulation 10 Room dimensions and space"}]',
  '[{"name": "workroom_volume_per_person", "type": "min", "value": 11.0, "unit": "m³/person", "confidence": 1.0, "applies_to": "workroom", "original": "11 m³ per person"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_business', 'office', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, business',
  'In business occupancies the walking distance to an exit may reach 300 feet (91.4 m) with sprinklers and 200 feet (61 m) without.',
  'office exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 91.44, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "300 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'hbn0301_patient_bedroom', 'hospital', 'England',
  'HBN 03-01: adult acute patient bedroom',
  'Health Building Note 03-01 covers adult acute mental health in-patient units; paper 001 takes a minimum single patient bedroom of 15 m2 from it. The exact figure depends on the HBN''s room layouts, so confidence is below one.',
  'patient bedroom ward single room inpatient en-suite',
  '[{"title": "Health Building Note 03-01: Adult acute mental health units", "url": "https://www.england.nhs.uk/estates/health-building-notes/", "section": "Bedroom accommodation (room layouts)"}]',
  '[{"name": "patient_bedroom_area", "type": "min", "value": 15.0, "unit": "m²", "confidence": 0.7, "applies_to": "patient bedroom", "original": "15 m²"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'aushfg_icu_room', 'hospital', 'Australia and New Zealand',
  'AusHFG: intensive care room',
  'The Australasian Health Facility Guidelines plan an intensive care bed room of about 25 m2 so that staff and equipment can work on all sides of the bed. Planning-unit number cited from memory.',
  'icu intensive care critical care room bed space',
  '[{"title": "Australasian Health Facility Guidelines (AusHFG), Part B - Intensive Care Unit", "url": "https://healthfacilityguidelines.com.au/", "section": "Part B, HPU 360 Intensive Care Unit (room data)"}]',
  '[{"name": "icu_room_area", "type": "min", "value": 25.0, "unit": "m²", "confidence": 0.8, "applies_to": "icu room", "original": "25 m²"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'fgi2018_patient_room', 'hospital', 'US',
  'FGI Guidelines 2018: medical/surgical patient room',
  'The US Facility Guidelines Institute asks for at least 120 square feet (11.15 m2) of clear floor in a single-patient room, excluding toilet room, closets and vestibule. Section number cited from memory of the 2018 hospital volume.',
  'patient room ward single inpatient medical surgical',
  '[{"title": "FGI Guidelines for Design and Construction of Hospitals (2018)", "url": "https://fgiguidelines.org/", "section": "2.2-2.2.2.2 Space requirements"}]',
  '[{"name": "patient_bedroom_area", "type": "min", "value": 11.148, "unit": "m²", "confidence": 0.8, "applies_to": "patient bedroom", "original": "120 ft² clear"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'fgi2018_icu_room', 'hospital', 'US',
  'FGI Guidelines 2018: critical care patient room',
  'A single-patient intensive care room needs at least 200 square feet (18.58 m2) of clear floor under the FGI hospital guidelines. Section number cited from memory.',
  'icu intensive care critical care room',
  '[{"title": "FGI Guidelines for Design and Construction of Hospitals (2018)", "url": "https://fgiguidelines.org/", "section": "2.2-2.6.2.2 Space requirements (critical care)"}]',
  '[{"name": "icu_room_area", "type": "min", "value": 18.581, "unit": "m²", "confidence": 0.8, "applies_to": "icu room", "original": "200 ft² clear"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1020_corridor_i2', 'hospital', 'US',
  'IBC 2018 Table 1020.2: hospital corridors for bed movement',
  'Where beds are moved in Group I-2 (hospitals, nursing homes) corridors must be at least 96 inches (2.44 m) wide.',
  'hospital corridor bed movement width stretcher',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1020.2 Width and capacity, Table 1020.2 Minimum corridor width"}]',
  '[{"name": "corridor_clear_width", "type": "min", "value": 2.438, "unit": "m", "confidence": 1.0, "applies_to": "corridor", "original": "96 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'nfpa101_health_care_corridor', 'hospital', 'US',
  'NFPA 101: corridor width in new health care occupancies',
  'The Life Safety Code asks for 8-foot (2.44 m) clear corridors and ramps where inpatients are moved in new health care occupancies. Clause numbers shift between editions.',
  'hospital corridor width life safety inpatient',
  '[{"title": "NFPA 101 Life Safety Code", "url": "https://www.nfpa.org/codes-and-standards/nfpa-101-standard-development/101", "section": "18.2.3.4 Corridor width (new health care occupancies)"}]',
  '[{"name": "corridor_clear_width", "type": "min", "value": 2.438, "unit": "m", "confidence": 0.9, "applies_to": "corridor", "original": "8 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1010_door_i2', 'hospital', 'US',
  'IBC 2018 1010.1.1: doors for bed movement',
  'In Group I-2, egress doors used to move beds must give at least 41.5 inches (1.05 m) of clear width.',
  'hospital door bed movement width',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1010.1.1 Size of doors"}]',
  '[{"name": "door_clear_width", "type": "min", "value": 1.054, "unit": "m", "confidence": 1.0, "applies_to": "door", "original": "41.5 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_health_care', 'hospital', 'US',
  'IBC 2018 Table 1004.5: health care occupant load factors',
  'Hospitals are counted at one occupant per 240 square feet gross in inpatient treatment areas, per 100 square feet in outpatient areas and per 120 square feet in sleeping areas.',
  'hospital occupant load inpatient outpatient clinic sleeping density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}]',
  '[{"name": "occupant_load_factor_inpatient_treatment", "type": "max", "value": 22.297, "unit": "m²/person", "confidence": 1.0, "applies_to": "treatment area", "original": "240 ft² gross"},
   {"name": "occupant_load_factor_outpatient", "type": "max", "value": 9.29, "unit": "m²/person", "confidence": 1.0, "applies_to": "outpatient area", "original": "100 ft² gross"},
   {"name": "occupant_load_factor_sleeping", "type": "max", "value": 11.148, "unit": "m²/person", "confidence": 1.0, "applies_to": "ward", "original": "120 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'adb2019_floor_space_waiting', 'hospital', 'England',
  'Approved Document B Table D1: waiting room floor space factor',
  'Waiting rooms, like meeting rooms and staff rooms, are counted at about one person per square metre for fire escape design (value as we recall the 2019 table).',
  'waiting room area reception occupant load density',
  '[{"title": "Approved Document B: Fire safety, Volume 2 - Buildings other than dwellings (2019 edition)", "url": "https://www.gov.uk/government/publications/fire-safety-approved-document-b", "section": "Appendix D, Table D1 Floor space factors"}]',
  '[{"name": "occupant_load_factor_waiting", "type": "max", "value": 1.0, "unit": "m²/person", "confidence": 0.8, "applies_to": "waiting room", "original": "1.0 m²/person"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_i2', 'hospital', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, Group I-2',
  'In hospitals (Group I-2, always sprinklered) the walking distance to an exit may not exceed 200 feet (61 m).',
  'hospital exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft (sprinklered)"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_assembly', 'canteen', 'US',
  'IBC 2018 Table 1004.5: assembly without fixed seats',
  'Dining rooms and canteens with tables and chairs count one occupant per 15 square feet net (1.39 m2); rows of loose chairs count one per 7 square feet and standing or queueing space one per 5 square feet.',
  'canteen cafeteria restaurant dining tables chairs queue standing occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}]',
  '[{"name": "occupant_load_factor_dining", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "dining area", "original": "15 ft² net"},
   {"name": "occupant_load_factor_concentrated_seating", "type": "max", "value": 0.65, "unit": "m²/person", "confidence": 1.0, "applies_to": "seating area", "original": "7 ft² net"},
   {"name": "occupant_load_factor_standing", "type": "max", "value": 0.465, "unit": "m²/person", "confidence": 1.0, "applies_to": "queue area", "original": "5 ft² net"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_commercial_kitchen', 'canteen', 'US',
  'IBC 2018 Table 1004.5: commercial kitchen occupant load factor',
  'Commercial kitchens are counted at one occupant per 200 square feet gross (18.58 m2).',
  'kitchen canteen restaurant commercial occupant load',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}]',
  '[{"name": "occupant_load_factor_commercial_kitchen", "type": "max", "value": 18.581, "unit": "m²/person", "confidence": 1.0, "applies_to": "kitchen", "original": "200 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'adb2019_floor_space_dining', 'canteen', 'England',
  'Approved Document B Table D1: dining floor space factor',
  'Restaurants, dining rooms and canteens are counted at about one person per square metre for fire escape design (value as we recall the 2019 table).',
  'canteen cafeteria restaurant dining occupant load density',
  '[{"title": "Approved Document B: Fire safety, Volume 2 - Buildings other than dwellings (2019 edition)", "url": "https://www.gov.uk/government/publications/fire-safety-approved-document-b", "section": "Appendix D, Table D1 Floor space factors"}]',
  '[{"name": "occupant_load_factor_dining", "type": "max", "value": 1.0, "unit": "m²/person", "confidence": 0.8, "applies_to": "dining area", "original": "1.0 m²/person"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ada2010_902_dining_surfaces', 'canteen', 'US',
  'ADA 2010 902: accessible dining surfaces',
  'Accessible dining and work surfaces have their top between 28 and 34 inches (0.71 to 0.86 m) above the floor, with knee and toe clearance below.',
  'table dining surface height canteen restaurant accessible',
  '[{"title": "2010 ADA Standards for Accessible Design", "url": "https://www.access-board.gov/ada/", "section": "902.3 Height"}]',
  '[{"name": "dining_surface_height", "type": "min", "value": 0.711, "unit": "m", "confidence": 1.0, "applies_to": "dining table", "original": "28 in"},
   {"name": "dining_surface_height", "type": "max", "value": 0.864, "unit": "m", "confidence": 1.0, "applies_to": "dining table", "original": "34 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_assembly', 'canteen', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, assembly',
  'In assembly occupancies such as canteens the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet (61 m) without.',
  'canteen restaurant exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_mercantile', 'retail', 'US',
  'IBC 2018 Table 1004.5: mercantile occupant load factors',
  'Shops count one occupant per 60 square feet gross (5.57 m2) of sales floor and one per 300 square feet (27.9 m2) of storage, stock and shipping areas.',
  'shop store supermarket sales floor stock room occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}]',
  '[{"name": "occupant_load_factor_mercantile", "type": "max", "value": 5.574, "unit": "m²/person", "confidence": 1.0, "applies_to": "sales floor", "original": "60 ft² gross"},
   {"name": "occupant_load_factor_stock_storage", "type": "max", "value": 27.871, "unit": "m²/person", "confidence": 1.0, "applies_to": "stock room", "original": "300 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'adb2019_floor_space_shop', 'retail', 'England',
  'Approved Document B Table D1: shop floor space factor',
  'Shop sales areas are counted at about one person per 2 m2 for fire escape design (value as we recall the 2019 table).',
  'shop store sales area occupant load density',
  '[{"title": "Approved Document B: Fire safety, Volume 2 - Buildings other than dwellings (2019 edition)", "url": "https://www.gov.uk/government/publications/fire-safety-approved-document-b", "section": "Appendix D, Table D1 Floor space factors"}]',
  '[{"name": "occupant_load_factor_mercantile", "type": "max", "value": 2.0, "unit": "m²/person", "confidence": 0.8, "applies_to": "sales floor", "original": "2.0 m²/person"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1018_aisles_mercantile', 'retail', 'US',
  'IBC 2018 1018.3: aisles in business and mercantile spaces',
  'Aisles between shelving, displays and counters in shops and offices must be at least 36 inches (0.91 m) clear, more when the occupant load demands it.',
  'shop aisle shelves display width supermarket',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1018.3 Groups B and M"}]',
  '[{"name": "aisle_clear_width", "type": "min", "value": 0.914, "unit": "m", "confidence": 1.0, "applies_to": "aisle", "original": "36 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_mercantile', 'retail', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, mercantile',
  'In shops the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet (61 m) without.',
  'shop exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_warehouse', 'warehouse', 'US',
  'IBC 2018 Table 1004.5: warehouse occupant load factor',
  'Warehouses are counted at one occupant per 500 square feet gross (46.45 m2).',
  'warehouse storage occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}]',
  '[{"name": "occupant_load_factor_warehouse", "type": "max", "value": 46.452, "unit": "m²/person", "confidence": 1.0, "applies_to": "warehouse floor", "original": "500 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'adb2019_floor_space_storage', 'warehouse', 'England',
  'Approved Document B Table D1: storage floor space factor',
  'Storage and warehousing space is counted at about one person per 30 m2 for fire escape design (value as we recall the 2019 table).',
  'warehouse storage occupant load density',
  '[{"title": "Approved Document B: Fire safety, Volume 2 - Buildings other than dwellings (2019 edition)", "url": "https://www.gov.uk/government/publications/fire-safety-approved-document-b", "section": "Appendix D, Table D1 Floor space factors"}]',
  '[{"name": "occupant_load_factor_warehouse", "type": "max", "value": 30.0, "unit": "m²/person", "confidence": 0.8, "applies_to": "warehouse floor", "original": "30 m²/person"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'osha1910_36_exit_routes', 'warehouse', 'US',
  'OSHA 29 CFR 1910.36: exit routes in workplaces',
  'US workplace rules keep every exit access at least 28 inches (0.71 m) wide and exit routes at least 7 ft 6 in (2.29 m) high.',
  'warehouse factory workplace exit route width headroom',
  '[{"title": "OSHA 29 CFR 1910.36 Design and construction requirements for exit routes", "url": "https://www.osha.gov/laws-regs/regulations/standardnumber/1910/1910.36", "section": "1910.36(g)(1) and (g)(2)"}]',
  '[{"name": "exit_route_clear_width", "type": "min", "value": 0.711, "unit": "m", "confidence": 1.0, "applies_to": "exit route", "original": "28 in"},
   {"name": "exit_route_headroom", "type": "min", "value": 2.286, "unit": "m", "confidence": 1.0, "applies_to": "exit route", "original": "7 ft 6 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ifc2018_high_piled_storage_aisles', 'warehouse', 'US',
  'IFC 2018 Chapter 32: aisles in high-piled storage',
  'The fire code asks for aisles in high-piled storage areas, typically 44 inches (1.12 m) where the public or sprinklers are involved and wider where stock is handled mechanically. Exact subsection and conditions from memory, hence low confidence.',
  'warehouse rack storage aisle picking forklift high-piled',
  '[{"title": "International Fire Code (IFC) 2018", "url": "https://codes.iccsafe.org/content/IFC2018", "section": "Chapter 32 High-piled combustible storage, aisles"}]',
  '[{"name": "storage_aisle_width", "type": "min", "value": 1.118, "unit": "m", "confidence": 0.6, "applies_to": "storage aisle", "original": "44 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_storage', 'warehouse', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, storage',
  'In moderate-hazard storage (S-1) the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet without; low-hazard storage (S-2) allows 400 and 300 feet.',
  'warehouse exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (S-1, sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft (S-1)"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_educational', 'school', 'US',
  'IBC 2018 Table 1004.5: educational occupant load factors',
  'Classrooms count one occupant per 20 square feet net (1.86 m2); shops and vocational rooms one per 50 square feet net (4.65 m2).',
  'school classroom pupils students occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}]',
  '[{"name": "occupant_load_factor_classroom", "type": "max", "value": 1.858, "unit": "m²/person", "confidence": 1.0, "applies_to": "classroom", "original": "20 ft² net"},
   {"name": "occupant_load_factor_vocational", "type": "max", "value": 4.645, "unit": "m²/person", "confidence": 1.0, "applies_to": "workshop", "original": "50 ft² net"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1020_corridor_group_e', 'school', 'US',
  'IBC 2018 Table 1020.2: school corridors',
  'Corridors in educational buildings that serve 100 or more occupants must be at least 72 inches (1.83 m) wide.',
  'school corridor width hallway',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1020.2 Width and capacity, Table 1020.2 Minimum corridor width"}]',
  '[{"name": "corridor_clear_width", "type": "min", "value": 1.829, "unit": "m", "confidence": 1.0, "applies_to": "corridor", "original": "72 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1017_travel_educational', 'school', 'US',
  'IBC 2018 Table 1017.2: exit access travel distance, educational',
  'In schools the walking distance to an exit may reach 250 feet (76.2 m) with sprinklers and 200 feet (61 m) without.',
  'school exit travel distance egress',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1017.2, Table 1017.2 Exit access travel distance"}]',
  '[{"name": "exit_access_travel_distance", "type": "max", "value": 76.2, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "250 ft (sprinklered)"},
   {"name": "exit_access_travel_distance_unsprinklered", "type": "max", "value": 60.96, "unit": "m", "confidence": 1.0, "applies_to": "building", "original": "200 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_t1004_airport', 'airport', 'US',
  'IBC 2018 Table 1004.5: airport terminal occupant load factors',
  'Airport terminals count one occupant per 15 square feet gross in waiting areas, 20 in baggage claim, 100 in concourses and 300 in baggage handling areas.',
  'airport terminal gate waiting concourse baggage occupant load density',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1004.5, Table 1004.5 Maximum floor area allowances per occupant"}]',
  '[{"name": "occupant_load_factor_waiting", "type": "max", "value": 1.394, "unit": "m²/person", "confidence": 1.0, "applies_to": "waiting area", "original": "15 ft² gross"},
   {"name": "occupant_load_factor_baggage_claim", "type": "max", "value": 1.858, "unit": "m²/person", "confidence": 1.0, "applies_to": "baggage claim", "original": "20 ft² gross"},
   {"name": "occupant_load_factor_concourse", "type": "max", "value": 9.29, "unit": "m²/person", "confidence": 1.0, "applies_to": "concourse", "original": "100 ft² gross"},
   {"name": "occupant_load_factor_baggage_handling", "type": "max", "value": 27.871, "unit": "m²/person", "confidence": 1.0, "applies_to": "baggage handling", "original": "300 ft² gross"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1020_corridor_width', 'general', 'US',
  'IBC 2018 Table 1020.2: minimum corridor width',
  'Corridors need at least 44 inches (1.12 m) of clear width; 36 inches (0.91 m) is enough where fewer than 50 people use them. Hospitals and schools need more (see their entries).',
  'corridor hallway width passage circulation',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1020.2 Width and capacity, Table 1020.2 Minimum corridor width"}]',
  '[{"name": "corridor_clear_width", "type": "min", "value": 1.118, "unit": "m", "confidence": 1.0, "applies_to": "corridor", "original": "44 in"},
   {"name": "corridor_clear_width_small_occupancy", "type": "min", "value": 0.914, "unit": "m", "confidence": 1.0, "applies_to": "corridor", "original": "36 in (occupant load < 50)"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1010_door_size', 'general', 'US',
  'IBC 2018 1010.1.1: size of egress doors',
  'Egress doors give at least 32 inches (0.81 m) of clear width and 80 inches (2.03 m) of clear height; a single swinging leaf may not exceed 48 inches (1.22 m).',
  'door width height opening egress doorway',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1010.1.1 Size of doors"}]',
  '[{"name": "door_clear_width", "type": "min", "value": 0.813, "unit": "m", "confidence": 1.0, "applies_to": "door", "original": "32 in"},
   {"name": "door_clear_height", "type": "min", "value": 2.032, "unit": "m", "confidence": 1.0, "applies_to": "door", "original": "80 in"},
   {"name": "door_leaf_width", "type": "max", "value": 1.219, "unit": "m", "confidence": 1.0, "applies_to": "door", "original": "48 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1208_ceiling_height', 'general', 'US',
  'IBC 2018 1208.2: minimum ceiling heights',
  'Occupiable spaces, habitable spaces and corridors need a ceiling of at least 7 ft 6 in (2.29 m); bathrooms, toilet rooms, kitchens, storage and laundry rooms at least 7 ft (2.13 m).',
  'ceiling height headroom room corridor',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1208.2 Minimum ceiling heights"}]',
  '[{"name": "ceiling_height", "type": "min", "value": 2.286, "unit": "m", "confidence": 1.0, "applies_to": "occupiable room, corridor", "original": "7 ft 6 in"},
   {"name": "ceiling_height_service_rooms", "type": "min", "value": 2.134, "unit": "m", "confidence": 1.0, "applies_to": "bathroom, kitchen, storage", "original": "7 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1005_egress_width', 'general', 'US',
  'IBC 2018 1005.3: egress width per occupant',
  'Exits are sized from the occupant load: at least 0.2 inch (5.1 mm) of width per occupant for doors, corridors and other level components and 0.3 inch (7.6 mm) per occupant for stairways.',
  'egress exit width capacity per occupant evacuation door stair',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1005.3.1 Stairways"},
   {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1005.3.2 Other egress components"}]',
  '[{"name": "egress_width_per_occupant", "type": "min", "value": 0.00508, "unit": "m/person", "confidence": 1.0, "applies_to": "exit, door, corridor", "original": "0.2 in per occupant"},
   {"name": "stair_width_per_occupant", "type": "min", "value": 0.00762, "unit": "m/person", "confidence": 1.0, "applies_to": "stair", "original": "0.3 in per occupant"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1011_stairways', 'general', 'US',
  'IBC 2018 1011: stairways',
  'Stairs are at least 44 inches (1.12 m) wide (36 inches for fewer than 50 occupants), with risers between 4 and 7 inches, treads at least 11 inches deep and 80 inches (2.03 m) of headroom.',
  'stairs staircase riser tread headroom width',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1011.2 Width and capacity"},
   {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1011.3 Headroom"},
   {"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1011.5.2 Riser height and tread depth"}]',
  '[{"name": "stair_clear_width", "type": "min", "value": 1.118, "unit": "m", "confidence": 1.0, "applies_to": "stair", "original": "44 in"},
   {"name": "stair_headroom", "type": "min", "value": 2.032, "unit": "m", "confidence": 1.0, "applies_to": "stair", "original": "80 in"},
   {"name": "stair_riser_height", "type": "max", "value": 0.178, "unit": "m", "confidence": 1.0, "applies_to": "stair", "original": "7 in"},
   {"name": "stair_riser_height", "type": "min", "value": 0.102, "unit": "m", "confidence": 1.0, "applies_to": "stair", "original": "4 in"},
   {"name": "stair_tread_depth", "type": "min", "value": 0.279, "unit": "m", "confidence": 1.0, "applies_to": "stair", "original": "11 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ibc2018_1020_dead_ends', 'general', 'US',
  'IBC 2018 1020.4: dead-end corridors',
  'A corridor that leads nowhere may be at most 20 feet (6.1 m) long; in sprinklered business, mercantile, storage and several other occupancies up to 50 feet (15.2 m).',
  'dead end corridor length',
  '[{"title": "International Building Code (IBC) 2018", "url": "https://codes.iccsafe.org/content/IBC2018", "section": "1020.4 Dead ends"}]',
  '[{"name": "dead_end_corridor_length", "type": "max", "value": 6.096, "unit": "m", "confidence": 1.0, "applies_to": "corridor", "original": "20 ft"},
   {"name": "dead_end_corridor_length_sprinklered", "type": "max", "value": 15.24, "unit": "m", "confidence": 1.0, "applies_to": "corridor", "original": "50 ft"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ada2010_404_doors', 'general', 'US',
  'ADA 2010 404.2: accessible doors',
  'Accessible doorways give at least 32 inches (0.815 m) of clear width, measured with the door open 90 degrees, and thresholds are no higher than 1/2 inch.',
  'door width doorway wheelchair accessible threshold',
  '[{"title": "2010 ADA Standards for Accessible Design", "url": "https://www.access-board.gov/ada/", "section": "404.2.3 Clear width"},
   {"title": "2010 ADA Standards for Accessible Design", "url": "https://www.access-board.gov/ada/", "section": "404.2.5 Thresholds"}]',
  '[{"name": "door_clear_width", "type": "min", "value": 0.815, "unit": "m", "confidence": 1.0, "applies_to": "door", "original": "32 in (815 mm)"},
   {"name": "door_threshold_height", "type": "max", "value": 0.013, "unit": "m", "confidence": 1.0, "applies_to": "door", "original": "1/2 in"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ada2010_403_walking_surfaces', 'general', 'US',
  'ADA 2010 403.5: accessible routes',
  'Accessible routes are at least 36 inches (0.915 m) clear; routes narrower than 60 inches need 60-inch (1.525 m) passing spaces at most every 200 feet.',
  'accessible route corridor wheelchair passing width walkway',
  '[{"title": "2010 ADA Standards for Accessible Design", "url": "https://www.access-board.gov/ada/", "section": "403.5.1 Clear width"},
   {"title": "2010 ADA Standards for Accessible Design", "url": "https://www.access-board.gov/ada/", "section": "403.5.3 Passing spaces"}]',
  '[{"name": "accessible_route_clear_width", "type": "min", "value": 0.915, "unit": "m", "confidence": 1.0, "applies_to": "accessible route", "original": "36 in (915 mm)"},
   {"name": "passing_space_width", "type": "min", "value": 1.525, "unit": "m", "confidence": 1.0, "applies_to": "accessible route", "original": "60 in (1525 mm)"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ada2010_304_turning_space', 'general', 'US',
  'ADA 2010 304.3: wheelchair turning space',
  'A wheelchair turning space is a circle of at least 60 inches (1.525 m) diameter or an equivalent T-shaped space; toilet rooms and many rooms need one.',
  'wheelchair turning circle space accessible toilet room',
  '[{"title": "2010 ADA Standards for Accessible Design", "url": "https://www.access-board.gov/ada/", "section": "304.3.1 Circular space"}]',
  '[{"name": "turning_circle_diameter", "type": "min", "value": 1.525, "unit": "m", "confidence": 1.0, "applies_to": "room", "original": "60 in (1525 mm)"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ada2010_405_ramps', 'general', 'US',
  'ADA 2010 405: ramps',
  'Ramp runs are at least 36 inches (0.915 m) wide between handrails and rise at most 30 inches (0.76 m) before a landing.',
  'ramp width rise wheelchair accessible',
  '[{"title": "2010 ADA Standards for Accessible Design", "url": "https://www.access-board.gov/ada/", "section": "405.5 Clear width"},
   {"title": "2010 ADA Standards for Accessible Design", "url": "https://www.access-board.gov/ada/", "section": "405.6 Rise"}]',
  '[{"name": "ramp_clear_width", "type": "min", "value": 0.915, "unit": "m", "confidence": 1.0, "applies_to": "ramp", "original": "36 in (915 mm)"},
   {"name": "ramp_run_rise", "type": "max", "value": 0.76, "unit": "m", "confidence": 1.0, "applies_to": "ramp", "original": "30 in (760 mm)"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'ada2010_904_counters', 'general', 'US',
  'ADA 2010 904: sales, service and check-out counters',
  'Service counters (reception, canteen, shop) keep an accessible portion at least 36 inches (0.915 m) long and no higher than 36 inches above the floor; check-out aisles are at least 36 inches wide.',
  'counter reception desk service check-out till cashier queue accessible',
  '[{"title": "2010 ADA Standards for Accessible Design", "url": "https://www.access-board.gov/ada/", "section": "904.4.1 Parallel approach"},
   {"title": "2010 ADA Standards for Accessible Design", "url": "https://www.access-board.gov/ada/", "section": "904.3.1 Aisle"}]',
  '[{"name": "service_counter_accessible_length", "type": "min", "value": 0.915, "unit": "m", "confidence": 1.0, "applies_to": "counter", "original": "36 in (915 mm)"},
   {"name": "service_counter_height", "type": "max", "value": 0.915, "unit": "m", "confidence": 1.0, "applies_to": "counter", "original": "36 in (915 mm)"},
   {"name": "checkout_aisle_width", "type": "min", "value": 0.915, "unit": "m", "confidence": 1.0, "applies_to": "check-out aisle", "original": "36 in (915 mm)"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'adm2015_vol2_doors', 'general', 'England',
  'Approved Document M Vol 2 Table 2: door clear widths',
  'New non-domestic buildings give doors an effective clear width of at least 800 mm, and at least 1000 mm in buildings used by the general public.',
  'door width doorway accessible public building',
  '[{"title": "Approved Document M: Access to and use of buildings, Volume 2 - Buildings other than dwellings (2015 edition)", "url": "https://www.gov.uk/government/publications/access-to-and-use-of-buildings-approved-document-m", "section": "Table 2 Minimum effective clear widths of doors"}]',
  '[{"name": "door_clear_width", "type": "min", "value": 0.8, "unit": "m", "confidence": 0.9, "applies_to": "door", "original": "800 mm"},
   {"name": "door_clear_width_public", "type": "min", "value": 1.0, "unit": "m", "confidence": 0.9, "applies_to": "door", "original": "1000 mm"}]');

INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints) VALUES (
  'adm2015_vol2_corridors', 'general', 'England',
  'Approved Document M Vol 2: corridors and passageways',
  'Corridors in non-domestic buildings are at least 1200 mm clear, with 1800 mm passing places where they are narrower than that. Paragraph numbers not recorded; values as we recall them.',
  'corridor passageway width wheelchair passing',
  '[{"title": "Approved Document M: Access to and use of buildings, Volume 2 - Buildings other than dwellings (2015 edition)", "url": "https://www.gov.uk/government/publications/access-to-and-use-of-buildings-approved-document-m", "section": "Section 3 Horizontal and vertical circulation (corridors and passageways)"}]',
  '[{"name": "corridor_clear_width", "type": "min", "value": 1.2, "unit": "m", "confidence": 0.8, "applies_to": "corridor", "original": "1200 mm"},
   {"name": "passing_space_width", "type": "min", "value": 1.8, "unit": "m", "confidence": 0.8, "applies_to": "corridor", "original": "1800 mm"}]');
