-- Evacuate walks at the desired speed unless told to hurry (issue 22): with speed_factor 1.3 by
-- default, 80 people left through 1.0 and 1.2 m doors at 2.2-2.5 and 2.9-3.1 /s, above the flows
-- Seyfried et al. 2009 and Kretz et al. 2006 measured (about 1.9 /s per metre of width); at 1.0
-- they are within those ranges (docs/crowd.md, "Bottleneck as a scene author would write it").
-- The node now also walks straight out of the door and counts as out 2 m past its wall line.
UPDATE behavior_nodes SET
  description = 'Walks (speed_factor times the desired speed) along the shortest path to the named exit or, when exit is empty, to the nearest exit of the world; SUCCESS when outside.',
  example = '<Evacuate agent_id="{id}" exit="" speed_factor="1.0" time_step="{dt}"/>',
  ports = '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "exit", "direction": "in", "type": "string", "default": "", "description": "Exit ROI/door; empty: nearest exit."},
   {"name": "speed_factor", "direction": "in", "type": "double", "default": "1.0", "description": "Multiplier of the desired walking speed (above 1 to hurry)."}]'
WHERE name = 'Evacuate';
