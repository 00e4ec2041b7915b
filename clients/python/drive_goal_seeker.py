#!/usr/bin/env python3
"""Drives a simple planner through a socsim scenario and prints the metrics report (docs/cosim.md).

    python3 drive_goal_seeker.py --base http://localhost:8080 --card CARD_ID \\
        --start 2,1.5,0 --goal 18,1.5 [--invisible] [--seed 7] [--planner goal_seeker|stand_still] [--binary]
    python3 drive_goal_seeker.py --program program.json --world world.yaml --start ... --goal ...

The planner, a goal seeker, turns towards the goal and slows down when a person is close ahead
(within 1.5 m of its path in the next 2 m). Lock-step: the crowd waits for each command, so the
report is the same for the same scenario, seed and planner. Prints the report as sorted, compact
JSON on one line.
"""
import argparse
import json
import math
import sys

from socsim_cosim import CosimClient, CosimError, open_session


def goal_seeker(observation, k=0, max_speed=1.0):
    robot = observation["robots"][k]
    pose, goal = robot["pose"], robot["goal"]
    if goal is None:
        return {"cmd": {"v": 0.0, "omega": 0.0}}
    dx, dy = goal["x"] - pose["x"], goal["y"] - pose["y"]
    error = math.remainder(math.atan2(dy, dx) - pose["yaw"], 2 * math.pi)
    omega = max(-1.5, min(1.5, 2.0 * error))
    v = min(max_speed, math.hypot(dx, dy)) * max(0.0, math.cos(error))
    c, s = math.cos(pose["yaw"]), math.sin(pose["yaw"])
    for p in observation["people"]:
        ahead = c * (p["pose"]["x"] - pose["x"]) + s * (p["pose"]["y"] - pose["y"])
        side = -s * (p["pose"]["x"] - pose["x"]) + c * (p["pose"]["y"] - pose["y"])
        if 0.0 < ahead < 2.0 and abs(side) < 1.5:
            v = min(v, 0.3 * ahead)
    return {"cmd": {"v": v, "omega": omega}}


def stand_still(observation, k=0, max_speed=1.0):
    return {"cmd": {"v": 0.0, "omega": 0.0}}


PLANNERS = {"goal_seeker": goal_seeker, "stand_still": stand_still}


def pair(text, n):
    values = [float(v) for v in text.split(",")]
    if len(values) != n:
        raise argparse.ArgumentTypeError(f"expected {n} comma-separated numbers")
    return values


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--base", default="http://localhost:8080")
    where = ap.add_mutually_exclusive_group(required=True)
    where.add_argument("--card", help="a card id from the catalogue")
    where.add_argument("--program", help="a scenario program (JSON file)")
    ap.add_argument("--world", help="world.yaml for --program")
    ap.add_argument("--start", type=lambda t: pair(t, 3), help="x,y,yaw (default: the program's robot)")
    ap.add_argument("--goal", type=lambda t: pair(t, 2), help="x,y")
    ap.add_argument("--invisible", action="store_true", help="people do not see the robot")
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--time-limit", type=float, default=60.0)
    ap.add_argument("--planner", choices=sorted(PLANNERS), default="goal_seeker")
    ap.add_argument("--binary", action="store_true", help="compact binary observations (socsim.cosim.v1.binary)")
    args = ap.parse_args(argv)

    body = {"seed": args.seed, "time_limit": args.time_limit, "mode": "lockstep"}
    if args.card:
        body["card_id"] = args.card
    else:
        with open(args.program) as f:
            body["program"] = json.load(f)
        if args.world:
            with open(args.world) as f:
                body["world"] = f.read()
    if args.start:
        robot = {"start": dict(zip(("x", "y", "yaw"), args.start)), "visible": not args.invisible}
        if args.goal:
            robot["goal"] = dict(zip(("x", "y"), args.goal))
        body["robot"] = robot
    try:
        session = open_session(args.base, body)
        planner = PLANNERS[args.planner]
        with CosimClient.connect(session, binary=args.binary) as c:
            speeds = [r["limits"]["max_speed"] for r in c.hello["robots"]]
            while c.running:
                c.step([planner(c.observation, k, speeds[k]) for k in range(len(speeds))])
            print(json.dumps(c.report, sort_keys=True, separators=(",", ":")))
    except CosimError as e:
        print(f"socsim: {e} {json.dumps(e.problem.get('errors', []))}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
