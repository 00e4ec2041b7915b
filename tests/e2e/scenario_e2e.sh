#!/usr/bin/env bash
# Text to scenario as a lab meets it from the shell: the real `socsim serve`, curl, a real
# SQLite file. Usage: scenario_e2e.sh /path/to/socsim
# (No `producer | grep -q` under pipefail: grep's early exit would fail the producer with SIGPIPE.)
# Covers: POST /scenarios → job with progress → card; the log downloads and its hash is the
# card's; replay job identical; CSV/HuNavSim/pedsim/MCAP/Gazebo exports (MCAP: API and CLI agree); a live session of the card streams
# frames over WebSocket (Python standard library client) and takes pause/seek/stop; the CLI's
# `scenario replay` agrees on an exported card; the card survives a restart.
set -euo pipefail
SOCSIM=${1:?usage: scenario_e2e.sh /path/to/socsim}
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
DB="$WORK/socsim.db"
wait_job() {  # prints the finished job document
  local id=$1 doc status
  for _ in $(seq 1 600); do
    doc=$(curl -fsS "$BASE/jobs/$id")
    status=$(echo "$doc" | json 'd["status"]')
    case "$status" in succeeded|failed|cancelled) echo "$doc"; return 0 ;; esac
    sleep 0.2
  done
  fail "job $id did not finish"
}

start
# 1. A prompt becomes a job, then a card.
accepted=$(curl -fsS -D "$WORK/h" -X POST -H 'Content-Type: application/json' \
  -d '{"prompt":"About twenty visitors queue at the reception desk while two nurses chat near the corridor","seed":9,"duration_s":20}' \
  "$BASE/scenarios")
grep -qi '^location: /api/v1/jobs/' "$WORK/h" || fail "202 without Location"
JOB=$(echo "$accepted" | json 'd["id"]')
done_doc=$(wait_job "$JOB")
[ "$(echo "$done_doc" | json 'd["status"]')" = succeeded ] || fail "scenario job: $done_doc"
[ "$(echo "$done_doc" | json 'd["progress"]')" = 1.0 ] || fail "progress did not reach 1"
CARD=$(echo "$done_doc" | json 'd["result"]["card_id"]')
card=$(curl -fsS "$BASE/cards/$CARD")
SHA=$(echo "$card" | json 'd["trajectory_log"]["sha256"]')
echo "$card" | json '"queuing" in d["tags"] or exit(1)' >/dev/null || fail "queuing not among the card's tags"
echo "ok - a prompt became card $CARD (trajectory $SHA)"

# 2. The log downloads; its uncompressed bytes hash to the card's sha256.
curl -fsS -o "$WORK/traj.bin" "http://127.0.0.1:$PORT$(echo "$card" | json 'd["trajectory_log"]["uri"]')"
python3 - "$WORK/traj.bin" "$SHA" <<'PY' || fail "downloaded log does not hash to the card's sha256"
import hashlib, struct, sys, zlib
data = open(sys.argv[1], 'rb').read()
raw = zlib.decompress(data[8:])
assert struct.unpack('<Q', data[:8])[0] == len(raw) and raw[:8] == b'SOCTRAJ1'
assert hashlib.sha256(raw).hexdigest() == sys.argv[2]
PY
echo "ok - the trajectory log matches its hash"

# 3. Replay is bit-identical.
replay=$(curl -fsS -X POST -H 'Content-Type: application/json' -d '{}' "$BASE/cards/$CARD/replay" | json 'd["id"]')
replayed=$(wait_job "$replay")
[ "$(echo "$replayed" | json 'd["result"]["identical"]')" = True ] || fail "replay differs: $replayed"
echo "ok - replay identical"

# 4. Exports.
curl -fsS "$BASE/cards/$CARD/export?format=csv" -o "$WORK/traj.csv"
grep -q '^t,id,x,y,vx,vy,state' <(head -1 "$WORK/traj.csv") || fail "CSV header"
[ "$(wc -l < "$WORK/traj.csv")" -gt 100 ] || fail "CSV too short"
curl -fsS "$BASE/cards/$CARD/export?format=pedsim" -o "$WORK/scenario.xml" || fail "pedsim export"
grep -q '<scenario' "$WORK/scenario.xml" || fail "pedsim export is not a scenario"
curl -fsS "$BASE/cards/$CARD/export?format=hunav" -o "$WORK/hunav.tar" || fail "hunav export"
tar tf "$WORK/hunav.tar" > "$WORK/hunav.list" || fail "hunav export is not a tar"
grep -q '\.yaml$' "$WORK/hunav.list" || fail "hunav export has no agents YAML"
# MCAP from the API and from the CLI on the same database: the same bytes (tests/e2e/mcap.test.mjs reads them).
curl -fsS "$BASE/cards/$CARD/export?format=mcap" -o "$WORK/card.mcap" || fail "mcap export"
"$SOCSIM" card export "$CARD" --format mcap -o "$WORK/cli.mcap" --db "$DB" || fail "socsim card export --format mcap"
cmp -s "$WORK/card.mcap" "$WORK/cli.mcap" || fail "the CLI's MCAP differs from the API's"
[ "$(head -c 8 "$WORK/card.mcap" | od -An -c | tr -d ' ')" = '211MCAP0\r\n' ] || fail "mcap export lacks the magic"
curl -fsS "$BASE/cards/$CARD/export?format=gazebo" -o "$WORK/card.world" || fail "gazebo export"
xmllint --noout "$WORK/card.world" || fail "the Gazebo world is not well-formed XML"
[ "$(grep -c '<actor ' "$WORK/card.world")" -gt 0 ] || fail "the Gazebo world has no actors"
echo "ok - CSV, pedsim, HuNavSim, MCAP and Gazebo actor exports"

# 5. A live session of the card: frames over WebSocket, then stop.
session=$(curl -fsS -X POST -H 'Content-Type: application/json' -d "{\"card_id\":\"$CARD\",\"speed\":4}" "$BASE/simulations")
SID=$(echo "$session" | json 'd["id"]')
python3 - "$WS_PORT" "$SID" <<'PY' || fail "WebSocket stream"
import base64, json, os, socket, struct, sys
port, sid = int(sys.argv[1]), sys.argv[2]
s = socket.create_connection(('127.0.0.1', port), timeout=10)
key = base64.b64encode(os.urandom(16)).decode()
s.sendall((f'GET /ws/simulations/{sid} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nUpgrade: websocket\r\n'
           f'Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n').encode())
buf = b''
while b'\r\n\r\n' not in buf: buf += s.recv(4096)
assert b' 101 ' in buf.split(b'\r\n')[0], buf
buf = buf.split(b'\r\n\r\n', 1)[1]
def read(n):
    global buf
    while len(buf) < n: buf += s.recv(65536)
    out, buf = buf[:n], buf[n:]
    return out
def message():
    b0, b1 = read(2)
    n = b1 & 0x7f
    if n == 126: n = struct.unpack('>H', read(2))[0]
    elif n == 127: n = struct.unpack('>Q', read(8))[0]
    return b0 & 0x0f, read(n)
def send(obj):
    data, mask = json.dumps(obj).encode(), os.urandom(4)
    s.sendall(bytes([0x81, 0x80 | len(data)]) + mask + bytes(c ^ mask[i % 4] for i, c in enumerate(data)))
kinds, times = [], []
while len(times) < 10:
    op, payload = message()
    if op == 1:
        m = json.loads(payload)
        kinds.append(m['type'])
        if m['type'] == 'frame':
            assert m['agents'] and {'id', 'x', 'y', 'state', 'role'} <= set(m['agents'][0]), m
            times.append(m['t'])
assert kinds[0] == 'hello', kinds
assert times == sorted(times) and times[-1] > times[0], times
send({'action': 'stop'})
while True:
    op, payload = message()
    if op == 8: break
    if op == 1 and json.loads(payload)['type'] == 'end': break
PY
echo "ok - the card streams live over WebSocket and stops on request"

# 6. The CLI agrees on an exported card, and the card survives a restart.
curl -fsS "$BASE/cards/$CARD/export" -o "$WORK/card.json"
"$SOCSIM" scenario replay "$WORK/card.json" > "$WORK/replay.txt" || fail "CLI replay: $(cat "$WORK/replay.txt")"
grep -q "^identical $SHA" "$WORK/replay.txt" || fail "CLI replay: $(cat "$WORK/replay.txt")"
kill -TERM "$PID"; wait "$PID" || true; PID=""
start
[ "$(curl -fsS "$BASE/cards/$CARD" | json 'd["trajectory_log"]["sha256"]')" = "$SHA" ] || fail "card after restart"
curl -fsS -o /dev/null "$BASE/trajectories/$SHA" || fail "log after restart"
echo "ok - CLI replay identical; card and log survive a restart"

# 7. Bad input: problem+json naming the field, nothing stored.
before=$(curl -fsS "$BASE/cards?page_size=100" | json 'len(d["items"])')
code=$(curl -s -o "$WORK/p.json" -w '%{http_code}' -X POST -H 'Content-Type: application/json' \
  -d '{"prompt":"a queue","agents":0,"duration_s":-1}' "$BASE/scenarios")
[ "$code" = 422 ] || fail "expected 422, got $code"
grep -q '"/agents"' "$WORK/p.json" && grep -q '"/duration_s"' "$WORK/p.json" || fail "problem does not name the fields"
[ "$(curl -fsS "$BASE/cards?page_size=100" | json 'len(d["items"])')" = "$before" ] || fail "a refused request stored something"
# A prompt in another language, or with nothing to simulate: 422 at /prompt, and the CLI says the same.
code=$(curl -s -o "$WORK/p.json" -w '%{http_code}' -X POST -H 'Content-Type: application/json' \
  -d '{"prompt":"Zwanzig Patienten warten im Wartezimmer auf den Arzt"}' "$BASE/scenarios")
[ "$code" = 422 ] && grep -q 'socsim reads English prompts' "$WORK/p.json" || fail "non-English prompt: $code $(cat "$WORK/p.json")"
if "$SOCSIM" scenario generate --prompt "hello there" --seconds 2 > "$WORK/cli.txt" 2>&1; then fail "CLI generated from 'hello there'"; fi
grep -q "names no person, place or activity" "$WORK/cli.txt" || fail "CLI refusal: $(cat "$WORK/cli.txt")"
[ "$(curl -fsS "$BASE/cards?page_size=100" | json 'len(d["items"])')" = "$before" ] || fail "a refused prompt stored something"
echo "ok - bad requests and prompts are refused with pointers and store nothing"
