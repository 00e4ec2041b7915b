-- PostgreSQL's form of 0026_household_persona_parts.sql (the rows follow from the shared file).
CREATE TABLE household_persona_parts (
  kind TEXT NOT NULL,
  position INTEGER NOT NULL,
  name TEXT NOT NULL,
  body TEXT NOT NULL,
  PRIMARY KEY (kind, name)
);
