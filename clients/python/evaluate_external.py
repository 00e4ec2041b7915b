#!/usr/bin/env python3
"""Evaluates your own planner over cards × seeds with socsim's metrics (docs/cosim.md, "External
clients"): POST /api/v1/evaluations with "client": "external", then every episode the evaluation
opens is driven here, in lock-step, by the example goal seeker; prints the results table.

    python3 evaluate_external.py --base http://localhost:8080 --cards CARD_A,CARD_B --seeds 1,2,3 \\
        [--start 2,1.5,0 --goal 18,1.5] [--invisible] [--time-limit 30] [--binary] [--json]

Replace goal_seeker (drive_goal_seeker.py) with your planner: it gets each observation and returns
one {"cmd": {"v", "omega"}} per robot.
"""
import argparse
import json
import sys

from drive_goal_seeker import goal_seeker, pair
from socsim_cosim import CosimError, run_external_evaluation


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--base", default="http://localhost:8080")
    ap.add_argument("--cards", required=True, help="comma-separated card ids")
    ap.add_argument("--seeds", default="1,2,3", help="comma-separated seeds")
    ap.add_argument("--start", type=lambda t: pair(t, 3), help="x,y,yaw (default: each card's robot)")
    ap.add_argument("--goal", type=lambda t: pair(t, 2), help="x,y")
    ap.add_argument("--invisible", action="store_true", help="people do not see the robot")
    ap.add_argument("--time-limit", type=float, default=60.0)
    ap.add_argument("--binary", action="store_true", help="compact binary observations")
    ap.add_argument("--json", action="store_true", help="print the whole evaluation record as JSON")
    args = ap.parse_args(argv)

    body = {"cards": args.cards.split(","), "seeds": [int(s) for s in args.seeds.split(",")],
            "time_limit_s": args.time_limit}
    if args.start:
        robot = {"start": dict(zip(("x", "y", "yaw"), args.start)), "visible": not args.invisible}
        if args.goal:
            robot["goal"] = dict(zip(("x", "y"), args.goal))
        body["robot"] = robot

    def progress(current, report):
        robot = report["metrics"]["robots"][0]
        print(f"episode {current['episode']}/{current['episodes']} card {current['card']} seed {current['seed']}: "
              f"{robot['outcome']} in {report['steps']} steps", file=sys.stderr)

    try:
        evaluation = run_external_evaluation(args.base, body, goal_seeker, binary=args.binary, on_episode=progress)
    except CosimError as e:
        print(f"socsim: {e} {json.dumps(e.problem.get('errors', []))}", file=sys.stderr)
        return 1
    if evaluation["status"] != "succeeded":
        print(f"socsim: evaluation {evaluation['status']}: {evaluation.get('error', {}).get('detail')}",
              file=sys.stderr)
        return 1
    if args.json:
        print(json.dumps(evaluation, sort_keys=True, separators=(",", ":")))
    else:
        for line in evaluation["result"]["table"]["summary"]:
            print(line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
