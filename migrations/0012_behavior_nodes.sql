-- Seed behaviour-node library: BehaviorTree.CPP v4 control/decorator nodes, HuNavSim's node
-- names and ports (so HuNavSim trees read familiar), and socsim's queueing, seating, crowd and
-- emergency nodes. The crowd engine implements every node listed here. Texts are ours.
-- Append-only: change a node with UPDATE in a new migration, never by editing this file.

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'Sequence', 'control', 'btcpp', 'flow',
  'Ticks its children left to right. Returns FAILURE as soon as one child fails, RUNNING while the current child runs (resuming at that child on the next tick) and SUCCESS when all children succeeded.',
  'Steps that must happen in order: walk to the counter, then wait, then leave.',
  '<Sequence>
  <GoTo agent_id="{id}" goal="counter" time_step="{dt}"/>
  <StopAndWait agent_id="{id}" wait_duration="5.0"/>
</Sequence>',
  'in order steps then chain one after another',
  '[]',
  '[]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'Fallback', 'control', 'btcpp', 'flow',
  'Ticks its children left to right until one does not fail: returns SUCCESS or RUNNING with the first child that does, FAILURE only if every child failed. Known as Selector elsewhere.',
  'Alternatives and priorities: react to the robot if it is close, otherwise keep navigating.',
  '<Fallback>
  <Sequence>
    <IsRobotClose agent_id="{id}" threshold="1.5"/>
    <StopAndWait agent_id="{id}" wait_duration="2.0"/>
  </Sequence>
  <RegularNav agent_id="{id}" time_step="{dt}"/>
</Fallback>',
  'selector alternative priority otherwise else try',
  '[]',
  '[]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'ReactiveSequence', 'control', 'btcpp', 'flow',
  'Like Sequence, but every tick restarts from the first child, so earlier conditions are re-checked while a later action is RUNNING; a failing condition halts the running action.',
  'Keep doing something only while a condition holds: walk with the group while the robot is not visible.',
  '<ReactiveSequence>
  <Inverter><IsRobotVisible agent_id="{id}" distance="4.0"/></Inverter>
  <RegularNav agent_id="{id}" time_step="{dt}"/>
</ReactiveSequence>',
  'while condition holds guard interrupt re-check',
  '[]',
  '[]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'ReactiveFallback', 'control', 'btcpp', 'flow',
  'Like Fallback, but every tick restarts from the first child, so a higher-priority child that starts succeeding interrupts a lower one that is RUNNING.',
  'Interruptible priorities: stop whatever you do when an evacuation starts.',
  '<ReactiveFallback>
  <Sequence>
    <TimeExpired seconds="120" ts="{dt}" only_once="true"/>
    <Evacuate agent_id="{id}" time_step="{dt}"/>
  </Sequence>
  <Wander agent_id="{id}" region="lobby" time_step="{dt}"/>
</ReactiveFallback>',
  'interrupt priority preempt emergency',
  '[]',
  '[]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'Parallel', 'control', 'btcpp', 'flow',
  'Ticks all children every tick. Succeeds when success_count children succeeded and fails when failure_count children failed (negative counts mean all children).',
  'Do two things at once: walk to a goal while looking at the robot, or run an action under a watchdog condition.',
  '<Parallel success_count="1" failure_count="1">
  <GoTo agent_id="{id}" goal="exit_door" time_step="{dt}"/>
  <LookAtRobot agent_id="{id}"/>
</Parallel>',
  'concurrent simultaneously at the same time both',
  '[]',
  '[{"name": "success_count", "direction": "in", "type": "int", "default": "-1", "description": "Children that must succeed for the node to succeed (-1: all)."},
   {"name": "failure_count", "direction": "in", "type": "int", "default": "1", "description": "Children that must fail for the node to fail (-1: all)."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'SubTree', 'control', 'btcpp', 'structure',
  'Runs another <BehaviorTree> of the same document by its ID. Ports of the subtree are remapped with attributes (name="{parent_key}"), or all at once with _autoremap.',
  'Reuse a named tree (RegularNavTree, a queue routine) inside several agents'' trees.',
  '<SubTree ID="RegularNavTree" _autoremap="true"/>',
  'reuse include nested tree',
  '[]',
  '[{"name": "ID", "direction": "in", "type": "string", "default": null, "description": "ID of the <BehaviorTree> to run."},
   {"name": "_autoremap", "direction": "in", "type": "bool", "default": "false", "description": "Remap every port of the subtree to the blackboard entry of the same name."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'Inverter', 'decorator', 'btcpp', 'logic',
  'Turns SUCCESS of its child into FAILURE and FAILURE into SUCCESS; RUNNING passes through.',
  'Negate a condition: continue while the goal is NOT reached.',
  '<Inverter>
  <IsGoalReached agent_id="{id}"/>
</Inverter>',
  'not negate invert',
  '[]',
  '[]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'Repeat', 'decorator', 'btcpp', 'loop',
  'Ticks its child again each time it succeeds, num_cycles times (-1: forever); stops with FAILURE when the child fails.',
  'Loops: patrol a route several times, serve customers one after another.',
  '<Repeat num_cycles="-1">
  <ServeAtCounter agent_id="{id}" counter="counter_1" queue="queue_lane" service_time="20"/>
</Repeat>',
  'loop again forever cycle patrol',
  '[]',
  '[{"name": "num_cycles", "direction": "in", "type": "int", "default": null, "description": "Number of repetitions; -1 repeats forever."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'RetryUntilSuccessful', 'decorator', 'btcpp', 'loop',
  'Ticks its child again each time it fails, up to num_attempts times (-1: forever); succeeds as soon as the child does.',
  'Try again: look for a free seat until one is found.',
  '<RetryUntilSuccessful num_attempts="5">
  <SitAt agent_id="{id}" seat="seating_area" duration="600"/>
</RetryUntilSuccessful>',
  'retry attempt again until',
  '[]',
  '[{"name": "num_attempts", "direction": "in", "type": "int", "default": null, "description": "Attempts before giving up; -1 retries forever."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'Timeout', 'decorator', 'btcpp', 'timing',
  'Halts its child and returns FAILURE if it is still RUNNING after msec milliseconds of simulated time.',
  'Bound how long something may take: give up queueing after five minutes.',
  '<Timeout msec="300000">
  <JoinQueue agent_id="{id}" queue="queue_lane"/>
</Timeout>',
  'time limit deadline give up',
  '[]',
  '[{"name": "msec", "direction": "in", "type": "unsigned", "default": null, "description": "Time limit in milliseconds of simulated time."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'Delay', 'decorator', 'btcpp', 'timing',
  'Waits delay_msec milliseconds of simulated time (returning RUNNING) before ticking its child, then returns the child''s status.',
  'Stagger agents: start walking a few seconds after the scenario begins.',
  '<Delay delay_msec="3000">
  <GoTo agent_id="{id}" goal="reception" time_step="{dt}"/>
</Delay>',
  'wait before start later stagger',
  '[]',
  '[{"name": "delay_msec", "direction": "in", "type": "unsigned", "default": null, "description": "Delay in milliseconds of simulated time."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'ForceSuccess', 'decorator', 'btcpp', 'logic',
  'Returns SUCCESS whenever its child finishes, whatever the child returned (RUNNING passes through).',
  'Optional steps that must not break a Sequence, e.g. an optional glance at the robot.',
  '<ForceSuccess>
  <LookAtRobot agent_id="{id}"/>
</ForceSuccess>',
  'optional ignore failure always succeed',
  '[]',
  '[]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'ForceFailure', 'decorator', 'btcpp', 'logic',
  'Returns FAILURE whenever its child finishes, whatever the child returned (RUNNING passes through).',
  'Run a side effect and then let a Fallback move on to its next alternative.',
  '<ForceFailure>
  <SaySomething agent_id="{id}" message="Excuse me"/>
</ForceFailure>',
  'always fail side effect',
  '[]',
  '[]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'RunOnce', 'decorator', 'btcpp', 'logic',
  'Ticks its child until it completes once; afterwards it is skipped (then_skip=true) or keeps returning the child''s first result.',
  'Initialisation steps in a looping tree, such as setting the agent''s goals once (HuNavSim''s trees use it this way).',
  '<RunOnce>
  <SetGoal agent_id="{id}" goal_id="3"/>
</RunOnce>',
  'once initialise first time setup',
  '[]',
  '[{"name": "then_skip", "direction": "in", "type": "bool", "default": "true", "description": "After the first completion, skip the child (true) or repeat its result (false)."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'TimeDelay', 'decorator', 'hunavsim', 'timing',
  'HuNavSim''s delay: returns FAILURE until delay seconds of simulated time have passed since it was first ticked, then ticks its child.',
  'HuNavSim-style trees that expect a failing wait (inside a Fallback) instead of BT.CPP''s RUNNING Delay.',
  '<TimeDelay delay="5.0">
  <SaySomething agent_id="{id}" message="Hello"/>
</TimeDelay>',
  'wait delay seconds',
  '[]',
  '[{"name": "delay", "direction": "in", "type": "double", "default": "1.0", "description": "Delay in seconds before the child is ticked."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'SetBlackboard', 'action', 'btcpp', 'blackboard',
  'Writes value into the blackboard entry output_key and succeeds.',
  'Pass ids and parameters into a SubTree, or remember a chosen target.',
  '<SetBlackboard output_key="agentid" value="{id}"/>',
  'variable store remember assign',
  '[]',
  '[{"name": "value", "direction": "in", "type": "string", "default": null, "description": "Value to store (literal or {key})."},
   {"name": "output_key", "direction": "inout", "type": "string", "default": null, "description": "Blackboard entry to write."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'AlwaysSuccess', 'action', 'btcpp', 'logic',
  'Does nothing and returns SUCCESS.',
  'Placeholder branch, or the last alternative of a Fallback that must not fail.',
  '<AlwaysSuccess/>',
  'noop nothing placeholder',
  '[]',
  '[]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'AlwaysFailure', 'action', 'btcpp', 'logic',
  'Does nothing and returns FAILURE.',
  'Placeholder for a branch that must fail, e.g. to skip to the next alternative.',
  '<AlwaysFailure/>',
  'noop fail placeholder',
  '[]',
  '[]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'IsGoalReached', 'condition', 'hunavsim', 'navigation',
  'SUCCESS when the agent is within its goal radius of the current goal, FAILURE otherwise.',
  'Loop navigation: keep walking while the goal is not reached, then pick the next goal.',
  '<Inverter>
  <IsGoalReached agent_id="{id}"/>
</Inverter>',
  'arrived destination goal reached',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'IsRobotVisible', 'condition', 'hunavsim', 'perception',
  'SUCCESS when the robot is within distance metres and in the agent''s line of sight (no wall in between).',
  'React to the robot only when the person can see it: curious, scared or threatening behaviour.',
  '<IsRobotVisible agent_id="{id}" distance="4.0"/>',
  'see robot sight visible perception',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "distance", "direction": "in", "type": "double", "default": "5.0", "description": "Maximum distance in metres at which the robot counts as visible."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'IsRobotClose', 'condition', 'hunavsim', 'perception',
  'SUCCESS when the robot is closer than threshold metres, whether or not it is visible.',
  'Proximity reactions: stop or step aside when the robot comes near.',
  '<IsRobotClose agent_id="{id}" threshold="1.5"/>',
  'near robot proximity close',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "threshold", "direction": "in", "type": "double", "default": "1.0", "description": "Distance threshold in metres."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'IsRobotFacingAgent', 'condition', 'hunavsim', 'perception',
  'SUCCESS when the robot''s heading points towards the agent.',
  'Social cues: greet or make way for a robot that is heading at you.',
  '<IsRobotFacingAgent agent_id="{id}"/>',
  'robot facing looking towards heading',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'IsAgentVisible', 'condition', 'hunavsim', 'perception',
  'SUCCESS when agent_id is within distance metres of observer_id, inside its field of view and not hidden by a wall.',
  'Start an interaction (greeting, following) only when one person sees another.',
  '<IsAgentVisible observer_id="{id}" agent_id="7" distance="5.0" field_of_view="2.0"/>',
  'see person sight visible',
  '[]',
  '[{"name": "observer_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent that looks."},
   {"name": "agent_id", "direction": "in", "type": "int", "default": null, "description": "Agent looked for."},
   {"name": "distance", "direction": "in", "type": "double", "default": "5.0", "description": "Maximum distance in metres."},
   {"name": "field_of_view", "direction": "in", "type": "double", "default": "3.14", "description": "Field-of-view angle in radians."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'IsAgentClose', 'condition', 'hunavsim', 'perception',
  'SUCCESS when target_agent_id is closer than threshold metres to observer_id.',
  'Trigger conversations or following when two people meet.',
  '<IsAgentClose observer_id="{id}" target_agent_id="4" threshold="1.5"/>',
  'near person proximity meet',
  '[]',
  '[{"name": "observer_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent whose surroundings are checked."},
   {"name": "target_agent_id", "direction": "in", "type": "int", "default": null, "description": "Other agent."},
   {"name": "threshold", "direction": "in", "type": "double", "default": "1.0", "description": "Distance threshold in metres."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'IsAtPosition', 'condition', 'hunavsim', 'navigation',
  'SUCCESS when the agent is within tolerance metres of (target_x, target_y).',
  'Check arrival at an explicit point that is not one of the agent''s goals.',
  '<IsAtPosition agent_id="{id}" target_x="3.0" target_y="1.5" tolerance="0.3"/>',
  'position location arrived point',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "target_x", "direction": "in", "type": "double", "default": null, "description": "Target x in world metres."},
   {"name": "target_y", "direction": "in", "type": "double", "default": null, "description": "Target y in world metres."},
   {"name": "tolerance", "direction": "in", "type": "double", "default": "0.1", "description": "Distance tolerance in metres."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'RandomChance', 'condition', 'hunavsim', 'logic',
  'SUCCESS with the given probability on each tick, drawn from the agent''s seeded random stream (so runs are reproducible).',
  'Variety: only some customers buy a drink, some people glance at the robot.',
  '<RandomChance agent_id="{id}" probability="0.3"/>',
  'random probability chance sometimes maybe stochastic',
  '["RandomChanceCondition"]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "probability", "direction": "in", "type": "double", "default": "0.3", "description": "Probability of SUCCESS per tick, in [0, 1]."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'TimeExpired', 'condition', 'hunavsim', 'timing',
  'Accumulates ts every tick and returns SUCCESS once seconds have elapsed (then resets unless only_once is true), FAILURE before.',
  'Time-bounded behaviours: be scared of the robot for at most 40 s; trigger an event after two minutes.',
  '<Inverter>
  <TimeExpired seconds="40.0" ts="{dt}" only_once="false"/>
</Inverter>',
  'timer elapsed after seconds duration',
  '["TimeExpiredCondition"]',
  '[{"name": "seconds", "direction": "in", "type": "double", "default": null, "description": "Duration of the timer in seconds."},
   {"name": "ts", "direction": "in", "type": "double", "default": "{dt}", "description": "Time step added on each tick."},
   {"name": "only_once", "direction": "in", "type": "bool", "default": "false", "description": "Keep returning SUCCESS after expiry instead of restarting the timer."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'IsAnyoneSpeaking', 'condition', 'hunavsim', 'social',
  'SUCCESS while some agent within distance_threshold metres is speaking (see SaySomething); writes that agent''s id to speaker_id.',
  'Turn towards or approach someone who talks.',
  '<IsAnyoneSpeaking agent_id="{id}" time_step="{dt}" distance_threshold="5.0" duration="5.0" speaker_id="{speaker}"/>',
  'speak talk hear voice',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "distance_threshold", "direction": "in", "type": "double", "default": "5.0", "description": "Radius in metres."},
   {"name": "duration", "direction": "in", "type": "double", "default": "5.0", "description": "How long the check keeps listening, in seconds."},
   {"name": "speaker_id", "direction": "out", "type": "int", "default": null, "description": "Id of the agent found speaking."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'IsSpeaking', 'condition', 'hunavsim', 'social',
  'SUCCESS while target_id is speaking within distance_threshold metres of the agent.',
  'Wait for a particular person to finish talking.',
  '<IsSpeaking agent_id="{id}" time_step="{dt}" target_id="3" distance_threshold="5.0" duration="5.0"/>',
  'speak talk',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "target_id", "direction": "in", "type": "int", "default": null, "description": "Agent expected to speak."},
   {"name": "distance_threshold", "direction": "in", "type": "double", "default": "5.0", "description": "Radius in metres."},
   {"name": "duration", "direction": "in", "type": "double", "default": "5.0", "description": "Listening time in seconds."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'IsAnyoneLookingAtMe', 'condition', 'hunavsim', 'social',
  'SUCCESS when an agent within distance_threshold metres has the agent inside angle_threshold radians of its heading; writes its id to observer_id.',
  'Return a glance, start a greeting.',
  '<IsAnyoneLookingAtMe agent_id="{id}" time_step="{dt}" distance_threshold="5.0" angle_threshold="0.2" duration="5.0" observer_id="{watcher}"/>',
  'gaze look watch stare',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "distance_threshold", "direction": "in", "type": "double", "default": "5.0", "description": "Radius in metres."},
   {"name": "angle_threshold", "direction": "in", "type": "double", "default": "0.2", "description": "Half-angle in radians."},
   {"name": "duration", "direction": "in", "type": "double", "default": "5.0", "description": "Check duration in seconds."},
   {"name": "observer_id", "direction": "out", "type": "int", "default": null, "description": "Id of the agent looking."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'IsLookingAtMe', 'condition', 'hunavsim', 'social',
  'SUCCESS when target_id is looking at the agent (within angle_threshold radians and distance_threshold metres).',
  'Mutual gaze before a conversation starts.',
  '<IsLookingAtMe agent_id="{id}" time_step="{dt}" target_id="2" distance_threshold="4.0" angle_threshold="0.3" duration="3.0"/>',
  'gaze look watch',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "target_id", "direction": "in", "type": "int", "default": null, "description": "Agent whose gaze is checked."},
   {"name": "distance_threshold", "direction": "in", "type": "double", "default": "5.0", "description": "Radius in metres."},
   {"name": "angle_threshold", "direction": "in", "type": "double", "default": "0.2", "description": "Half-angle in radians."},
   {"name": "duration", "direction": "in", "type": "double", "default": "5.0", "description": "Check duration in seconds."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'RegularNav', 'action', 'hunavsim', 'navigation',
  'One step of ordinary social-force walking towards the agent''s current goal; returns RUNNING.',
  'Default walking between goals; the body of almost every navigation tree.',
  '<RegularNav agent_id="{id}" time_step="{dt}"/>',
  'walk navigate move normal',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'UpdateGoal', 'action', 'hunavsim', 'navigation',
  'Moves the agent on to the next goal of its goal list (cyclically) and succeeds.',
  'After IsGoalReached, to patrol or cycle through waypoints.',
  '<UpdateGoal agent_id="{id}"/>',
  'next goal waypoint patrol cycle',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'SetGoal', 'action', 'hunavsim', 'navigation',
  'Sets the agent''s current goal, by index into its goal list (goal_id, as in HuNavSim) or by the name of an ROI/POI of the world (goal).',
  'Send an agent to a specific place before RegularNav, or change plans in reaction to an event.',
  '<SetGoal agent_id="{id}" goal="reception_desk"/>',
  'destination target set goal place',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "goal_id", "direction": "in", "type": "int", "default": "-1", "description": "Index into the agent''s goals (HuNavSim style); -1 when goal is used."},
   {"name": "goal", "direction": "in", "type": "string", "default": "", "description": "Name of an ROI or POI of the world."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'GoTo', 'action', 'hunavsim', 'navigation',
  'Walks to a goal (an index into the agent''s goals, or an ROI/POI name) with the social force model; RUNNING until within tolerance, then SUCCESS.',
  'Any purposeful walk to a named place: the door, the counter, the lift.',
  '<GoTo agent_id="{id}" goal="elevator_door" tolerance="0.3" time_step="{dt}"/>',
  'walk go move navigate destination reach',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "goal_id", "direction": "in", "type": "int", "default": "-1", "description": "Index into the agent''s goals (HuNavSim style); -1 when goal is used."},
   {"name": "goal", "direction": "in", "type": "string", "default": "", "description": "Name of an ROI or POI of the world."},
   {"name": "tolerance", "direction": "in", "type": "double", "default": "0.1", "description": "Arrival distance in metres."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'StopAndWait', 'action', 'hunavsim', 'timing',
  'Stands still for wait_duration seconds (RUNNING), then succeeds.',
  'Pauses: reading a sign, waiting for a lift, hesitating before a door.',
  '<StopAndWait agent_id="{id}" wait_duration="3.0"/>',
  'stop wait pause idle stand still',
  '["StopAndWaitTimerAction"]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "wait_duration", "direction": "in", "type": "double", "default": "3.0", "description": "Waiting time in seconds."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'StopMovement', 'action', 'hunavsim', 'navigation',
  'Stops the agent where it is (velocity set to zero) until ResumeMovement; succeeds immediately.',
  'Freeze an agent in response to an event, e.g. while talking on the phone.',
  '<StopMovement agent_id="{id}"/>',
  'stop halt freeze',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'ResumeMovement', 'action', 'hunavsim', 'navigation',
  'Lets an agent stopped by StopMovement walk again; succeeds immediately.',
  'Pair with StopMovement.',
  '<ResumeMovement agent_id="{id}"/>',
  'resume continue restart walking',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'SurprisedNav', 'action', 'hunavsim', 'robot_reaction',
  'HuNavSim''s surprised behaviour: the agent stops and looks at the robot for beh_duration seconds.',
  'People startled by a robot.',
  '<SurprisedNav agent_id="{id}" time_step="{dt}" beh_duration="5.0" only_once="true"/>',
  'surprised startled robot reaction',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "beh_duration", "direction": "in", "type": "double", "default": "5.0", "description": "Duration of the behaviour in seconds."},
   {"name": "only_once", "direction": "in", "type": "bool", "default": "true", "description": "Show the behaviour only the first time."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'CuriousNav', 'action', 'hunavsim', 'robot_reaction',
  'HuNavSim''s curious behaviour: the agent walks towards the robot at agent_vel and stops stop_distance metres from it.',
  'Curious bystanders who come to look at the robot.',
  '<CuriousNav agent_id="{id}" time_step="{dt}" beh_duration="10.0" only_once="true" agent_vel="1.0" stop_distance="1.0"/>',
  'curious approach robot interest',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "beh_duration", "direction": "in", "type": "double", "default": "5.0", "description": "Duration in seconds."},
   {"name": "only_once", "direction": "in", "type": "bool", "default": "true", "description": "Show the behaviour only once."},
   {"name": "agent_vel", "direction": "in", "type": "double", "default": "1.0", "description": "Approach speed in m/s."},
   {"name": "stop_distance", "direction": "in", "type": "double", "default": "0.5", "description": "Distance to keep from the robot in metres."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'ScaredNav', 'action', 'hunavsim', 'robot_reaction',
  'HuNavSim''s scared behaviour: the agent moves away from the robot at up to runaway_vel with an extra repulsive force.',
  'People afraid of robots; keeping distance.',
  '<ScaredNav agent_id="{id}" time_step="{dt}" beh_duration="10.0" only_once="true" runaway_vel="1.5" scary_force_factor="5.0"/>',
  'scared afraid flee robot',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "beh_duration", "direction": "in", "type": "double", "default": "5.0", "description": "Duration in seconds."},
   {"name": "only_once", "direction": "in", "type": "bool", "default": "true", "description": "Show the behaviour only once."},
   {"name": "runaway_vel", "direction": "in", "type": "double", "default": "1.5", "description": "Escape speed in m/s."},
   {"name": "scary_force_factor", "direction": "in", "type": "double", "default": "1.0", "description": "Gain of the robot''s repulsive force."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'ThreateningNav', 'action', 'hunavsim', 'robot_reaction',
  'HuNavSim''s threatening behaviour: the agent walks in front of the robot, goal_dist metres ahead of it, to block its way.',
  'Adversarial pedestrians for robustness tests.',
  '<ThreateningNav agent_id="{id}" time_step="{dt}" beh_duration="10.0" only_once="true" goal_dist="1.0"/>',
  'threatening block robot adversarial',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "beh_duration", "direction": "in", "type": "double", "default": "5.0", "description": "Duration in seconds."},
   {"name": "only_once", "direction": "in", "type": "bool", "default": "true", "description": "Show the behaviour only once."},
   {"name": "goal_dist", "direction": "in", "type": "double", "default": "1.0", "description": "Distance in front of the robot to aim for, in metres."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'FindNearestAgent', 'action', 'hunavsim', 'social',
  'Finds the closest other agent and writes its id to target_agent_id; fails when there is none.',
  'Pick someone to approach, follow or talk to.',
  '<FindNearestAgent agent_id="{id}" target_agent_id="{target}"/>',
  'nearest closest person find',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "target_agent_id", "direction": "out", "type": "int", "default": null, "description": "Id of the nearest agent."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'SaySomething', 'action', 'hunavsim', 'social',
  'Marks the agent as speaking message (visible to IsAnyoneSpeaking and in the pedestrian state) and succeeds.',
  'Greetings, calls for attention, announcements.',
  '<SaySomething agent_id="{id}" message="Excuse me!"/>',
  'say speak talk greet',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "message", "direction": "in", "type": "string", "default": "", "description": "What the agent says."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'SetGroupId', 'action', 'hunavsim', 'group',
  'Puts the agent into group group_id (group forces apply between members) and succeeds.',
  'Form groups dynamically, e.g. friends meeting at the entrance.',
  '<SetGroupId agent_id="{id}" group_id="5"/>',
  'group join friends together',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "group_id", "direction": "in", "type": "int", "default": null, "description": "Group to join; -1 leaves any group."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'SetGroupWalk', 'action', 'hunavsim', 'group',
  'Makes the listed agents walk together with the main agent (coherence and gaze forces) for duration seconds.',
  'Families, friends or colleagues walking side by side.',
  '<SetGroupWalk main_agent_id="{id}" non_main_agent_ids="4;5" time_step="{dt}" duration="30.0"/>',
  'group walk together family friends',
  '[]',
  '[{"name": "main_agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Leader of the group."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "non_main_agent_ids", "direction": "in", "type": "string", "default": null, "description": "Members, separated by '';''."},
   {"name": "duration", "direction": "in", "type": "double", "default": "5.0", "description": "Duration in seconds."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'ConversationFormation', 'action', 'hunavsim', 'social',
  'Gathers the main agent and the listed agents around a goal in a circle (an F-formation) and keeps them talking for conversation_duration seconds.',
  'People chatting in a corridor or lobby: obstacles a robot must go around, not through.',
  '<ConversationFormation main_agent_id="{id}" non_main_agent_ids="2;3" goal="corridor_junction" conversation_duration="60.0" time_step="{dt}"/>',
  'conversation chat talk circle formation group standing',
  '[]',
  '[{"name": "main_agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent that leads the conversation."},
   {"name": "non_main_agent_ids", "direction": "in", "type": "string", "default": null, "description": "Other participants, separated by '';''."},
   {"name": "goal_id", "direction": "in", "type": "int", "default": "-1", "description": "Index of the meeting place in the main agent''s goals."},
   {"name": "goal", "direction": "in", "type": "string", "default": "", "description": "Name of the meeting ROI/POI."},
   {"name": "conversation_duration", "direction": "in", "type": "double", "default": "10.0", "description": "Duration in seconds."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'ApproachAgent', 'action', 'hunavsim', 'social',
  'Walks towards target_agent_id at up to max_vel and stops closest_dist metres from it, for at most duration seconds.',
  'Walking up to a colleague, a nurse approaching a patient.',
  '<ApproachAgent agent_id="{id}" target_agent_id="2" closest_dist="0.8" max_vel="1.0" duration="10.0" time_step="{dt}"/>',
  'approach walk up to person',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "target_agent_id", "direction": "in", "type": "int", "default": null, "description": "Agent to approach."},
   {"name": "closest_dist", "direction": "in", "type": "double", "default": "0.5", "description": "Stopping distance in metres."},
   {"name": "max_vel", "direction": "in", "type": "double", "default": "1.0", "description": "Maximum speed in m/s."},
   {"name": "duration", "direction": "in", "type": "double", "default": "5.0", "description": "Time limit in seconds."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'ApproachRobot', 'action', 'hunavsim', 'robot_reaction',
  'Walks towards the robot at up to max_vel and stops closest_dist metres from it.',
  'People who want to interact with the robot.',
  '<ApproachRobot agent_id="{id}" closest_dist="1.5" max_vel="1.2" duration="10.0" time_step="{dt}"/>',
  'approach robot interact',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "closest_dist", "direction": "in", "type": "double", "default": "1.5", "description": "Stopping distance in metres."},
   {"name": "max_vel", "direction": "in", "type": "double", "default": "1.8", "description": "Maximum speed in m/s."},
   {"name": "duration", "direction": "in", "type": "double", "default": "5.0", "description": "Time limit in seconds."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'BlockRobot', 'action', 'hunavsim', 'robot_reaction',
  'Places the agent front_dist metres in front of the robot, in its path, for duration seconds.',
  'Blocked-path scenarios for robot navigation tests.',
  '<BlockRobot agent_id="{id}" front_dist="1.0" duration="10.0" time_step="{dt}"/>',
  'block robot obstruct path',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "front_dist", "direction": "in", "type": "double", "default": "1.0", "description": "Distance in front of the robot in metres."},
   {"name": "duration", "direction": "in", "type": "double", "default": "5.0", "description": "Duration in seconds."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'BlockAgent', 'action', 'hunavsim', 'social',
  'Places the agent front_dist metres in front of target_agent_id, in its path, for duration seconds.',
  'One person getting in another''s way.',
  '<BlockAgent agent_id="{id}" target_agent_id="3" front_dist="1.0" duration="5.0" time_step="{dt}"/>',
  'block obstruct person path',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "target_agent_id", "direction": "in", "type": "int", "default": null, "description": "Agent to block."},
   {"name": "front_dist", "direction": "in", "type": "double", "default": "1.0", "description": "Distance in front of the target in metres."},
   {"name": "duration", "direction": "in", "type": "double", "default": "5.0", "description": "Duration in seconds."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'AvoidRobot', 'action', 'hunavsim', 'robot_reaction',
  'Keeps at least safe_distance metres from the robot, moving away at up to runaway_vel, for duration seconds (0: indefinitely).',
  'Cautious people who give the robot a wide berth.',
  '<AvoidRobot agent_id="{id}" safe_distance="2.0" runaway_vel="1.2" duration="0" time_step="{dt}"/>',
  'avoid keep distance robot',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "safe_distance", "direction": "in", "type": "double", "default": "1.5", "description": "Distance to keep in metres."},
   {"name": "runaway_vel", "direction": "in", "type": "double", "default": "1.2", "description": "Maximum speed while avoiding, m/s."},
   {"name": "duration", "direction": "in", "type": "double", "default": "0.0", "description": "Duration in seconds; 0 means until halted."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'FollowAgent', 'action', 'hunavsim', 'social',
  'Walks behind target_agent_id, keeping a following distance, for duration seconds.',
  'A visitor following a nurse, a child following a parent.',
  '<FollowAgent agent_id="{id}" target_agent_id="1" duration="60.0" time_step="{dt}"/>',
  'follow behind escort accompany',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "target_agent_id", "direction": "in", "type": "int", "default": null, "description": "Agent to follow."},
   {"name": "duration", "direction": "in", "type": "double", "default": "5.0", "description": "Duration in seconds."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'LookAtAgent', 'action', 'hunavsim', 'gaze',
  'Turns the observer''s head and body orientation towards target_id; succeeds.',
  'Attention cues in conversations and greetings.',
  '<LookAtAgent observer_id="{id}" target_id="2"/>',
  'look gaze turn face person',
  '[]',
  '[{"name": "observer_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent that turns."},
   {"name": "target_id", "direction": "in", "type": "int", "default": null, "description": "Agent looked at."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'LookAtRobot', 'action', 'hunavsim', 'gaze',
  'Turns the agent towards the robot; succeeds.',
  'People noticing the robot.',
  '<LookAtRobot agent_id="{id}"/>',
  'look gaze robot notice',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'LookAtPoint', 'action', 'hunavsim', 'gaze',
  'Turns the agent towards a goal or an ROI/POI (a screen, a departure board); succeeds.',
  'Reading signs, watching a display, facing a counter.',
  '<LookAtPoint agent_id="{id}" goal="departure_board"/>',
  'look gaze point sign display',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "goal_id", "direction": "in", "type": "int", "default": "-1", "description": "Index into the agent''s goals."},
   {"name": "goal", "direction": "in", "type": "string", "default": "", "description": "Name of an ROI or POI."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'AvoidAgent', 'action', 'socsim', 'social',
  'Keeps at least safe_distance metres from target_agent_id, stepping away at up to max_vel, for duration seconds (0: until halted).',
  'Social distancing, avoiding a particular person.',
  '<AvoidAgent agent_id="{id}" target_agent_id="6" safe_distance="2.0" duration="30.0" time_step="{dt}"/>',
  'avoid keep distance person',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "target_agent_id", "direction": "in", "type": "int", "default": null, "description": "Agent to avoid."},
   {"name": "safe_distance", "direction": "in", "type": "double", "default": "1.5", "description": "Distance to keep in metres."},
   {"name": "max_vel", "direction": "in", "type": "double", "default": "1.2", "description": "Maximum speed in m/s."},
   {"name": "duration", "direction": "in", "type": "double", "default": "0.0", "description": "Duration in seconds; 0 means until halted."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'JoinQueue', 'action', 'socsim', 'queueing',
  'Walks to the tail of the queue lane (an ROI), takes the next free place spacing metres behind the last person and succeeds once standing in line; writes the place number (0 = head of the queue).',
  'Anything with waiting in line: a queue at a counter, a reception desk, a lift, a check-in desk, a till.',
  '<Sequence>
  <JoinQueue agent_id="{id}" queue="queue_lane" position="{place}" time_step="{dt}"/>
  <AdvanceQueue agent_id="{id}" queue="queue_lane" time_step="{dt}"/>
  <ServeAtCounter agent_id="{id}" counter="counter" queue="queue_lane" service_time="30"/>
</Sequence>',
  'queue line waiting in line join queueing counter reception desk till checkout',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "queue", "direction": "in", "type": "string", "default": null, "description": "Name of the queue-lane ROI; the lane''s axis gives the queue direction."},
   {"name": "spacing", "direction": "in", "type": "double", "default": "0.7", "description": "Distance between people in line, metres."},
   {"name": "position", "direction": "out", "type": "int", "default": null, "description": "Place in the queue after joining (0 = head)."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'AdvanceQueue', 'action', 'socsim', 'queueing',
  'Waits in line and steps forward whenever the person ahead moves up, RUNNING until the agent is at the head of the queue, then SUCCESS. With advance_interval > 0 the head leaves every advance_interval seconds even without a server, as in timed queues.',
  'Between JoinQueue and ServeAtCounter; or alone for timed queues (lift lobbies, boarding gates).',
  '<AdvanceQueue agent_id="{id}" queue="queue_lane" advance_interval="0" time_step="{dt}"/>',
  'queue line advance step forward move up waiting counter',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "queue", "direction": "in", "type": "string", "default": null, "description": "Name of the queue-lane ROI."},
   {"name": "advance_interval", "direction": "in", "type": "double", "default": "0.0", "description": "Seconds after which the head leaves on its own; 0: only when served."},
   {"name": "position", "direction": "out", "type": "int", "default": null, "description": "Current place in the queue."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'ServeAtCounter', 'action', 'socsim', 'queueing',
  'At the head of the queue, steps up to the counter (a POI), is served for service_time seconds (a random spread of service_spread is drawn from the agent''s seeded stream), leaves the queue and succeeds.',
  'Ordering food at a canteen counter, registering at reception, paying at a till.',
  '<ServeAtCounter agent_id="{id}" counter="counter" queue="queue_lane" service_time="30" service_spread="10"/>',
  'counter serve order pay reception desk till checkout service queue',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "counter", "direction": "in", "type": "string", "default": null, "description": "Name of the counter POI (or ROI) where service happens."},
   {"name": "queue", "direction": "in", "type": "string", "default": null, "description": "Queue lane that feeds the counter."},
   {"name": "service_time", "direction": "in", "type": "double", "default": "20.0", "description": "Mean service time in seconds."},
   {"name": "service_spread", "direction": "in", "type": "double", "default": "0.0", "description": "Half-width of the uniform spread around service_time, seconds."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'IsAtQueueHead', 'condition', 'socsim', 'queueing',
  'SUCCESS when the agent is first in the queue lane.',
  'Branch on queue state, e.g. a Fallback that serves the head and lets the others look around.',
  '<IsAtQueueHead agent_id="{id}" queue="queue_lane"/>',
  'queue head first in line next',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "queue", "direction": "in", "type": "string", "default": null, "description": "Name of the queue-lane ROI."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'SitAt', 'action', 'socsim', 'activity',
  'Walks to a free seat in the seating ROI (or to the named seat POI), sits (speed zero, state ''sitting'') for duration seconds and succeeds; fails when no seat is free.',
  'Eating in a canteen, waiting in a waiting room, working at a desk.',
  '<SitAt agent_id="{id}" seat="seating_area" duration="900" time_step="{dt}"/>',
  'sit seat chair table eat rest waiting room bench',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "seat", "direction": "in", "type": "string", "default": null, "description": "Seating ROI or seat POI."},
   {"name": "duration", "direction": "in", "type": "double", "default": "300.0", "description": "Seconds to stay seated."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'Wander', 'action', 'socsim', 'navigation',
  'Walks between random points of a region, pausing between pause_min and pause_max seconds at each, for duration seconds (0: until halted). Points come from the agent''s seeded stream.',
  'Browsing in a shop, strolling in a lobby or park, idle background people.',
  '<Wander agent_id="{id}" region="sales_floor" duration="300" pause_min="2" pause_max="10" time_step="{dt}"/>',
  'wander stroll browse roam random walk idle',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "region", "direction": "in", "type": "string", "default": null, "description": "ROI to wander in."},
   {"name": "duration", "direction": "in", "type": "double", "default": "0.0", "description": "Seconds; 0 until halted."},
   {"name": "pause_min", "direction": "in", "type": "double", "default": "1.0", "description": "Shortest pause at a point, seconds."},
   {"name": "pause_max", "direction": "in", "type": "double", "default": "8.0", "description": "Longest pause at a point, seconds."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'Gather', 'action', 'socsim', 'group',
  'Walks to a meeting point and stays within radius metres of it with the other members of the group until all have arrived, then for duration seconds.',
  'Staff gathering for a briefing, a tour group meeting at the entrance.',
  '<Gather agent_id="{id}" point="corridor_junction" radius="1.5" group_id="2" duration="120" time_step="{dt}"/>',
  'gather meet assemble group briefing huddle',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "point", "direction": "in", "type": "string", "default": null, "description": "Meeting ROI/POI."},
   {"name": "radius", "direction": "in", "type": "double", "default": "1.5", "description": "Radius of the cluster, metres."},
   {"name": "group_id", "direction": "in", "type": "int", "default": "-1", "description": "Group whose members are waited for; -1 for the agent''s own group."},
   {"name": "duration", "direction": "in", "type": "double", "default": "60.0", "description": "Seconds to stay once everyone arrived."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'Evacuate', 'action', 'socsim', 'emergency',
  'Walks quickly (speed_factor times the desired speed) along the shortest path to the named exit or, when exit is empty, to the nearest exit of the world; SUCCESS when outside.',
  'Fire alarms, emergencies, closing time.',
  '<Evacuate agent_id="{id}" exit="" speed_factor="1.4" time_step="{dt}"/>',
  'evacuate emergency fire alarm exit escape leave',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "exit", "direction": "in", "type": "string", "default": "", "description": "Exit ROI/door; empty: nearest exit."},
   {"name": "speed_factor", "direction": "in", "type": "double", "default": "1.3", "description": "Multiplier of the desired walking speed."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'WaitAt', 'action', 'socsim', 'activity',
  'Walks to a place and stands there (state ''waiting'') for duration seconds, turning towards face if given.',
  'Waiting by a lift, at a pick-up point, outside a door.',
  '<WaitAt agent_id="{id}" location="elevator_lobby" duration="45" face="elevator_door" time_step="{dt}"/>',
  'wait stand elevator lift pick up idle',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "location", "direction": "in", "type": "string", "default": null, "description": "ROI/POI to wait at."},
   {"name": "duration", "direction": "in", "type": "double", "default": "30.0", "description": "Seconds to wait."},
   {"name": "face", "direction": "in", "type": "string", "default": "", "description": "ROI/POI to face while waiting."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'IsInRegion', 'condition', 'socsim', 'navigation',
  'SUCCESS when the agent''s position lies inside the named ROI.',
  'Zone-dependent behaviour: slow down inside the ward, stop wandering once in the exit hall.',
  '<IsInRegion agent_id="{id}" region="ward_a"/>',
  'inside region zone area room',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "region", "direction": "in", "type": "string", "default": null, "description": "ROI name."}]');

INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports) VALUES (
  'FollowVelocityField', 'action', 'socsim', 'crowd',
  'Ambient-crowd navigation (paper 001, Algorithm 1): samples the group''s velocity field at the agent''s cell, turns the vector into an intermediate goal (at least 2 x tolerance ahead) and applies the social-force desired force towards it; RUNNING until the group''s goal region is reached.',
  'Large ambient crowds that flow between start and goal regions without individual trees.',
  '<FollowVelocityField agent_id="{id}" field="commuters" tolerance="0.5" time_step="{dt}"/>',
  'crowd flow velocity field ambient stream',
  '[]',
  '[{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent this node acts for (the blackboard key {id} holds the ticking agent''s id)."},
   {"name": "time_step", "direction": "in", "type": "double", "default": "{dt}", "description": "Simulation step in seconds (blackboard key {dt})."},
   {"name": "field", "direction": "in", "type": "string", "default": null, "description": "Name of the ambient group whose field is followed."},
   {"name": "tolerance", "direction": "in", "type": "double", "default": "0.5", "description": "Goal tolerance tol of Algorithm 1, metres."}]');
