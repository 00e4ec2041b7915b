#!/usr/bin/env bash
# A robot in the loop as a lab meets it (issue 19): the real `socsim serve`, the Python
# standard-library client of clients/python driving its example planner. Usage: cosim_e2e.sh /path/to/socsim
# Covers: a card made over REST is driven twice in lock-step → byte-identical reports; on a scripted
# corridor encounter (the robot parked in a walker's way) the minimum distance of people to a
# visible robot is larger than to an invisible one, which the walker runs into; bad input over the
# socket ends in a protocol error.
set -euo pipefail
SOCSIM=${1:?usage: cosim_e2e.sh /path/to/socsim}
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
CLIENT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../clients/python" && pwd)"
DB="$WORK/socsim.db"
start

cat > "$WORK/world.yaml" <<'YAML'
zones:
  - {name: corridor, polygon: [[0, 0], [20, 0], [20, 3], [0, 3]]}
YAML
cat > "$WORK/program.json" <<'JSON'
{"name": "corridor encounter",
 "agents": [{"name": "walker", "position": [14, 1.5], "speed": 1.2, "goals": [[1, 1.5]], "cyclic_goals": false}]}
JSON

# 1. A card with the corridor and the walker, driven twice by the example planner.
card=$(python3 - "$WORK/program.json" <<'PY'
import json, sys
program = json.load(open(sys.argv[1]))
world = {"zones": [{"name": "corridor", "polygon": [[0, 0], [20, 0], [20, 3], [0, 3]]}]}
print(json.dumps({"title": "Corridor encounter", "world": world, "program": program, "seed": 7}))
PY
)
CARD=$(curl -fsS -X POST -H 'Content-Type: application/json' -d "$card" "$BASE/cards" | json 'd["id"]')
drive() { python3 "$CLIENT/drive_goal_seeker.py" --base "http://127.0.0.1:$PORT" "$@"; }
drive --card "$CARD" --start 2,1.4,0 --goal 18,1.5 > "$WORK/a.json" || fail "example on the card"
drive --card "$CARD" --start 2,1.4,0 --goal 18,1.5 > "$WORK/b.json" || fail "example on the card, again"
cmp -s "$WORK/a.json" "$WORK/b.json" || fail "reports differ: $(diff "$WORK/a.json" "$WORK/b.json" | head -5)"
python3 - "$WORK/a.json" <<'PY' || fail "report: $(cat "$WORK/a.json")"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["type"] == "report" and r["end_reason"] == "episode_ended", r
robot = r["metrics"]["robots"][0]
for k in ("outcome", "time_to_reach_goal", "path_length", "minimum_distance_to_people", "intimate_space_intrusions",
          "robot_on_person_collision", "social_work", "avg_speed", "avg_jerk", "path_efficiency"):
    assert k in robot, k
assert robot["outcome"] in ("success", "collision_person", "stuck", "timeout"), robot
print(f"  card {sys.argv[1]}: outcome {robot['outcome']}, {r['steps']} steps, "
      f"min distance {robot['minimum_distance_to_people']:.3f} m, path efficiency {robot['path_efficiency']:.3f}")
PY
echo "ok - the example drove card $CARD twice in lock-step: byte-identical reports"

# 1b. The same card with binary observations (float32): the same episode to within rounding.
drive --card "$CARD" --start 2,1.4,0 --goal 18,1.5 --binary > "$WORK/binary.json" || fail "example, binary"
python3 - "$WORK/a.json" "$WORK/binary.json" <<'PY' || fail "binary observations drive another episode"
import json, sys
a, b = (json.load(open(f))["metrics"]["robots"][0] for f in sys.argv[1:])
assert a["outcome"] == b["outcome"], (a["outcome"], b["outcome"])
assert abs(a["path_length"] - b["path_length"]) < 0.05, (a["path_length"], b["path_length"])
print(f"  binary: outcome {b['outcome']}, path {b['path_length']:.3f} m (JSON {a['path_length']:.3f} m)")
PY
echo "ok - the example drives the card with binary observations to the same outcome"

# 1c. The same planner as an external client of an evaluation: 1 card × 2 seeds, a table back.
python3 "$CLIENT/evaluate_external.py" --base "http://127.0.0.1:$PORT" --cards "$CARD" --seeds 1,2 \
  --start 2,1.4,0 --goal 18,1.5 --time-limit 30 --json > "$WORK/external.json" 2> "$WORK/external.log" ||
  fail "external evaluation: $(cat "$WORK/external.log")"
python3 - "$WORK/external.json" <<'PY' || fail "external evaluation record: $(head -c 600 "$WORK/external.json")"
import json, sys
e = json.load(open(sys.argv[1]))
assert e["status"] == "succeeded" and e["request"]["client"] == "external", e["status"]
rows = e["result"]["episodes"]
assert [r["seed"] for r in rows] == [1, 2] and all(r["planner"] == "external" for r in rows), rows
assert all(r["end_reason"] == "episode_ended" for r in rows), rows
print("  " + e["result"]["table"]["summary"][0])
PY
echo "ok - an evaluation with an external client: the example drove both episodes, the table came back"

# 2. Scripted corridor encounter: the robot stands 10 cm off the walker's line; visible or not.
drive --program "$WORK/program.json" --world "$WORK/world.yaml" --start 7,1.4,0 --goal 18,1.5 \
  --planner stand_still > "$WORK/visible.json" || fail "visible run"
drive --program "$WORK/program.json" --world "$WORK/world.yaml" --start 7,1.4,0 --goal 18,1.5 \
  --planner stand_still --invisible > "$WORK/invisible.json" || fail "invisible run"
python3 - "$WORK/visible.json" "$WORK/invisible.json" <<'PY' || fail "people do not avoid the visible robot"
import json, sys
v = json.load(open(sys.argv[1]))["metrics"]["robots"][0]
i = json.load(open(sys.argv[2]))["metrics"]["robots"][0]
print(f"  visible: min distance {v['minimum_distance_to_people']:.3f} m, outcome {v['outcome']}; "
      f"invisible: {i['minimum_distance_to_people']:.3f} m, outcome {i['outcome']}")
assert v["minimum_distance_to_people"] > i["minimum_distance_to_people"], (v, i)
assert v["outcome"] != "collision_person" and i["outcome"] == "collision_person", (v["outcome"], i["outcome"])
PY
echo "ok - people keep away from a visible robot and walk into an invisible one"

# 3. Bad input over the socket: a protocol error, then the connection closes.
python3 - "http://127.0.0.1:$PORT" "$WORK/program.json" "$CLIENT" <<'PY' || fail "protocol error"
import json, sys
sys.path.insert(0, sys.argv[3])
from socsim_cosim import CosimClient, CosimError, open_session
session = open_session(sys.argv[1], {"program": json.load(open(sys.argv[2])),
                                     "robot": {"start": {"x": 2, "y": 1, "yaw": 0}, "goal": {"x": 9, "y": 1}}})
c = CosimClient.connect(session)
c.step([{"cmd": {"v": 0.5, "omega": 0}}])
c.step_number = 4  # skips steps 2..4
try:
    c.step([{"cmd": {"v": 0.5, "omega": 0}}])
    raise SystemExit("no error for an out-of-order step")
except CosimError as e:
    assert e.problem["code"] == "out_of_order", e.problem
    assert "expected 2, got 5" in e.problem["detail"], e.problem
try:
    c.receive()
    raise SystemExit("still open")
except (EOFError, ConnectionError):
    pass
PY
echo "ok - an out-of-order step is a protocol error and closes the connection"
