#!/usr/bin/env bash
# socsim behind real nginx, configured by deploy/nginx.conf (issue 14). Usage: nginx_e2e.sh /path/to/socsim
# The shipped site file is used as written except for what a test cannot have: TLS (certificates)
# and the fixed ports. Checks: nginx accepts the file (nginx -t); health through the proxy; per-
# client rate limits behind the proxy (--trusted-proxies: two clients, two buckets); a refused
# request's body is never parsed as a request; slow and idle connections at nginx leave /health
# fast; the WebSocket upgrade passes.
set -euo pipefail
SOCSIM=${1:?usage: nginx_e2e.sh /path/to/socsim}
HERE="$(dirname "${BASH_SOURCE[0]}")"
NGINX=$(command -v nginx || echo /usr/sbin/nginx)
[ -x "$NGINX" ] || { echo "SKIP: nginx is not installed (bash deploy/install-deps.sh --with-browser)"; exit 0; }
source "$HERE/lib.sh"
DB="$WORK/var/socsim.db"
NGX_PORT=$(free_port)
NGX_PID=""
trap 'cleanup; [ -n "$NGX_PID" ] && kill "$NGX_PID" 2>/dev/null || true' EXIT

sed -e "s|listen 443 ssl http2;|listen 127.0.0.1:$NGX_PORT;|" \
    -e "/ssl_certificate/d" \
    -e "s|server_name socsim.example.org;|server_name localhost;|" \
    -e "s|127.0.0.1:8080|127.0.0.1:$PORT|" -e "s|127.0.0.1:8081|127.0.0.1:$WS_PORT|" \
    "$HERE/../../deploy/nginx.conf" > "$WORK/site.conf"
mkdir -p "$WORK/nginx"
{
  [ "$(id -u)" = 0 ] && echo "user root;"
  cat <<CONF
worker_processes 1;
pid $WORK/nginx/nginx.pid;
error_log $WORK/nginx/error.log;
events { worker_connections 4096; }
http {
  access_log off;
  client_body_temp_path $WORK/nginx/body;
  proxy_temp_path $WORK/nginx/proxy;
  fastcgi_temp_path $WORK/nginx/fastcgi;
  uwsgi_temp_path $WORK/nginx/uwsgi;
  scgi_temp_path $WORK/nginx/scgi;
  include $WORK/site.conf;
}
CONF
} > "$WORK/nginx.conf"
"$NGINX" -t -q -c "$WORK/nginx.conf" -p "$WORK/nginx" || fail "nginx refuses deploy/nginx.conf"
echo "ok - nginx -t accepts deploy/nginx.conf"
"$NGINX" -c "$WORK/nginx.conf" -p "$WORK/nginx" -g 'daemon off;' &
NGX_PID=$!

start --trusted-proxies 127.0.0.1 --allowed-hosts localhost --rate-limit 1 --rate-burst 5
PROXY="http://localhost:$NGX_PORT/api/v1"
for _ in $(seq 1 50); do curl -fsS "$PROXY/health" >/dev/null 2>&1 && break; sleep 0.1; done
curl -fsS "$PROXY/health" | grep -q '"status":"ok"' || fail "health through nginx"
echo "ok - health through nginx"

# Client A (127.0.0.2) spends its bucket; client B (127.0.0.3) is still served.
codes_a=""; for _ in $(seq 1 8); do codes_a+="$(curl -sS -o /dev/null -w '%{http_code} ' --interface 127.0.0.2 "$PROXY/health")"; done
code_b=$(curl -sS -o /dev/null -w '%{http_code}' --interface 127.0.0.3 "$PROXY/health")
echo "$codes_a" | grep -q 429 || fail "client A was never limited: $codes_a"
[ "$code_b" = 200 ] || fail "client B shares A's bucket behind the proxy: $code_b"
grep -q '"client":"127.0.0.2"' "$WORK/server.log" || fail "the log does not name the client behind the proxy"
echo "ok - rate limits per client behind nginx (A: $codes_a; B: $code_b)"

reply=$(printf 'POST /api/v1/cards HTTP/1.1\r\nHost: localhost\r\nContent-Type: text/plain\r\nContent-Length: 48\r\nConnection: close\r\n\r\nGET /api/v1/health HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n' |
  timeout 5 python3 -c '
import socket, sys
s = socket.create_connection(("127.0.0.1", int(sys.argv[1])), source_address=("127.0.0.4", 0))
s.sendall(sys.stdin.buffer.read())
data = b""
while True:
    chunk = s.recv(65536)
    if not chunk: break
    data += chunk
print(data.count(b"HTTP/1.1 "), data.split(b" ")[1].decode())' "$NGX_PORT")
[ "$reply" = "1 415" ] || fail "smuggling through nginx: expected one 415, got '$reply'"
echo "ok - a refused request's body is not parsed as a request through nginx"

kill "$PID"; wait "$PID" 2>/dev/null || true; PID=""
start --trusted-proxies 127.0.0.1 --allowed-hosts localhost  # no rate limit for the load below
python3 "$HERE/slow_clients.py" 127.0.0.1 "$NGX_PORT" --idle 500 --slow 200 --requests 100 ||
  fail "slow clients at nginx stalled /health"
echo "ok - /health fast through nginx with 500 idle and 200 slow connections"

code=$(curl -sS -o /dev/null -w '%{http_code}' --max-time 2 -H 'Connection: Upgrade' -H 'Upgrade: websocket' \
  -H 'Sec-WebSocket-Version: 13' -H 'Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==' \
  "http://localhost:$NGX_PORT/ws/catalogue" 2>/dev/null || true)
[ "$code" = 101 ] || fail "WebSocket upgrade through nginx: $code"
echo "ok - WebSocket upgrade through nginx"
