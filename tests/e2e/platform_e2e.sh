#!/usr/bin/env bash
# End-to-end check of the platform as a user meets it: the real `socsim serve` binary, a real
# SQLite file, curl over HTTP. Usage: platform_e2e.sh /path/to/socsim
# Covers: health; card survives SIGKILL with the same hash; 100 concurrent POSTs lose none;
# 400/422/413/401 problem documents; page walk; CLI export → import into another database;
# SIGTERM shuts down cleanly.
set -euo pipefail
SOCSIM=${1:?usage: platform_e2e.sh /path/to/socsim}
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
DB="$WORK/var/socsim.db"

CARD='{"title":"Evening check-in","description":"Visitors queue at the hospital reception.","tags":["queue","reception"],"prompt":"visitors queue at the reception desk","seed":42,"generator":{"name":"offline"},"domain":"hospital","world":{"zones":[]},"metrics":{"agents":30}}'

start
echo "ok - health answers"

# A card survives SIGKILL unchanged.
created=$(curl -fsS -X POST -H 'Content-Type: application/json' -d "$CARD" "$BASE/cards")
ID=$(echo "$created" | json 'd["id"]')
HASH=$(echo "$created" | json 'd["content_hash"]')
kill -9 "$PID"; wait "$PID" 2>/dev/null || true; PID=""
start
after=$(curl -fsS "$BASE/cards/$ID")
[ "$(echo "$after" | json 'd["content_hash"]')" = "$HASH" ] || fail "hash changed across SIGKILL"
[ "$(echo "$after" | python3 -c 'import json,sys; print(json.dumps(json.load(sys.stdin), sort_keys=True))')" = \
  "$(echo "$created" | python3 -c 'import json,sys; print(json.dumps(json.load(sys.stdin), sort_keys=True))')" ] \
  || fail "card differs after SIGKILL"
echo "ok - card identical after SIGKILL and restart"

# 100 concurrent POSTs.
seq 1 100 | xargs -P 25 -I{} curl -fsS -o /dev/null -w '%{http_code}\n' -X POST \
  -H 'Content-Type: application/json' -d "$CARD" "$BASE/cards" > "$WORK/codes.txt"
[ "$(grep -c '^201$' "$WORK/codes.txt")" = 100 ] || fail "not every concurrent POST was created: $(sort "$WORK/codes.txt" | uniq -c)"
[ "$(curl -fsS "$BASE/health" | json 'd["database"]["cards"]')" = 101 ] || fail "cards were lost"
echo "ok - 100 concurrent POSTs, none lost"

# Errors are problem documents.
code=$(curl -sS -o "$WORK/p.json" -w '%{http_code}' -X POST -H 'Content-Type: application/json' -d '{"title": "x",' "$BASE/cards")
[ "$code" = 400 ] && grep -q '"line"' "$WORK/p.json" || fail "malformed JSON: $code $(cat "$WORK/p.json")"
code=$(curl -sS -o "$WORK/p.json" -w '%{http_code}' -X POST -H 'Content-Type: application/json' -d '{"title": 5, "seed": -1}' "$BASE/cards")
[ "$code" = 422 ] && grep -q '"/title"' "$WORK/p.json" && grep -q '"/seed"' "$WORK/p.json" || fail "schema violation: $code $(cat "$WORK/p.json")"
python3 -c 'print("{\"title\":\"big\",\"prompt\":\"" + "a"*(3<<20) + "\"}")' > "$WORK/big.json"
code=$(curl -sS -o "$WORK/p.json" -w '%{http_code}' -X POST -H 'Content-Type: application/json' --data-binary @"$WORK/big.json" "$BASE/cards")
[ "$code" = 413 ] && grep -q 'problems/payload-too-large' "$WORK/p.json" || fail "3 MiB body: $code"
echo "ok - 400 with position, 422 with pointers, 413 for 3 MiB"

# Page walk.
python3 - "$BASE" <<'PY' || fail "page walk"
import json, sys, urllib.request
base = sys.argv[1]
seen, url = [], base + "/cards?page_size=5"
while True:
    page = json.load(urllib.request.urlopen(url))
    seen += [c["id"] for c in page["items"]]
    if page["next_cursor"] is None: break
    url = base + "/cards?page_size=5&cursor=" + page["next_cursor"]
assert len(seen) == len(set(seen)) == 101, (len(seen), len(set(seen)))
PY
echo "ok - page_size=5 walk visits all 101 cards once"

# SIGTERM: clean shutdown.
kill -TERM "$PID"
wait "$PID" && rc=0 || rc=$?
PID=""
[ "$rc" = 0 ] || fail "exit code $rc after SIGTERM"
grep -q '"event":"stopped"' "$WORK/server.log" || fail "no clean-shutdown log line"
echo "ok - SIGTERM shuts down cleanly"

# CLI export → import into another database keeps the hash and the bytes.
"$SOCSIM" card export "$ID" --db "$DB" -o "$WORK/card.json"
"$SOCSIM" card import "$WORK/card.json" --db "$WORK/other.db" > "$WORK/imp.json"
[ "$(json 'd["content_hash"]' < "$WORK/imp.json")" = "$HASH" ] || fail "hash changed by export/import"
"$SOCSIM" card export "$ID" --db "$WORK/other.db" -o "$WORK/card2.json"
cmp -s "$WORK/card.json" "$WORK/card2.json" || fail "export not byte-stable"
echo "ok - CLI export → import on another database: same hash, same bytes"

# Keys: writes need one, reads don't.
start --api-keys "lab:e2e-secret-0123456789"
code=$(curl -sS -o /dev/null -w '%{http_code}' -X POST -H 'Content-Type: application/json' -d "$CARD" "$BASE/cards")
[ "$code" = 401 ] || fail "write without key gave $code"
code=$(curl -sS -o "$WORK/c.json" -w '%{http_code}' -X POST -H 'Authorization: Bearer e2e-secret-0123456789' -H 'Content-Type: application/json' -d "$CARD" "$BASE/cards")
[ "$code" = 201 ] && [ "$(json 'd["author"]' < "$WORK/c.json")" = lab ] || fail "write with key gave $code"
curl -fsS "$BASE/cards/$ID" >/dev/null || fail "read needed a key"
grep -q 'e2e-secret' "$WORK/server.log" && fail "a key was logged"
echo "ok - 401 without key, author from key, reads open, keys never logged"
echo "platform e2e: 8 passed, 0 failed"
