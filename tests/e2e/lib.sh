# Shared by the shell end-to-end tests (source it after setting SOCSIM): a scratch folder removed
# on exit, free ports, JSON field access, and start/stop of a real `socsim serve` on a SQLite file.
# Callers set DB before `start`; extra arguments to `start` go to `socsim serve`.
WORK=$(mktemp -d)
PID=""
cleanup() { [ -n "$PID" ] && kill -9 "$PID" 2>/dev/null || true; rm -rf "$WORK"; }
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; [ -f "$WORK/server.log" ] && tail -n 20 "$WORK/server.log" >&2; exit 1; }
free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
json() { python3 -c "import json,sys; d=json.load(sys.stdin); print($1)"; }

PORT=$(free_port); WS_PORT=$(free_port)
BASE="http://127.0.0.1:$PORT/api/v1"

start() {
  "$SOCSIM" serve --port "$PORT" --ws-port "$WS_PORT" --db "$DB" --web-root "$WORK" --rate-limit 0 "$@" \
    >>"$WORK/server.log" 2>&1 &
  PID=$!
  for _ in $(seq 1 300); do  # 30 s: a loaded CI machine (the sanitizer build) starts slowly
    curl -fsS "$BASE/health" >/dev/null 2>&1 && return 0
    sleep 0.1
  done
  fail "server did not answer /health"
}
