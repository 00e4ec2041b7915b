"""A co-simulation client for socsim (docs/cosim.md) in Python's standard library only.

    session = open_session("http://localhost:8080", {"card_id": "...", "seed": 7, "robot": {...}})
    with CosimClient.connect(session) as c:       # hello and the first observation are read
        while c.running:
            c.step([{"cmd": {"v": 0.5, "omega": 0.0}}])
        print(c.report["metrics"])

The WebSocket is spoken by hand (RFC 6455: handshake, masked client frames), as in the README's
example, so that nothing beyond the standard library is needed.
"""
import base64
import json
import os
import socket
import struct
import urllib.error
import urllib.request
from urllib.parse import urlparse

PROTOCOL = "socsim.cosim.v1"


class CosimError(Exception):
    """The server answered with a problem (HTTP) or an "error" message (WebSocket)."""

    def __init__(self, problem):
        super().__init__(problem.get("detail", str(problem)))
        self.problem = problem


def open_session(base_url, body):
    """POST /api/v1/cosim; returns the session status (id, ws_url, ws_port, websocket_url, ...)."""
    req = urllib.request.Request(base_url.rstrip("/") + "/api/v1/cosim", json.dumps(body).encode(),
                                 {"Content-Type": "application/json"})
    try:
        with urllib.request.urlopen(req, timeout=30) as r:
            return json.load(r)
    except urllib.error.HTTPError as e:
        raise CosimError(json.loads(e.read() or b"{}")) from None


class CosimClient:
    def __init__(self, host, port, path, timeout=30.0):
        self.sock = socket.create_connection((host, port), timeout=timeout)
        key = base64.b64encode(os.urandom(16)).decode()
        self.sock.sendall((f"GET {path} HTTP/1.1\r\nHost: {host}:{port}\r\nUpgrade: websocket\r\n"
                           f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n"
                           f"Sec-WebSocket-Protocol: {PROTOCOL}\r\n\r\n").encode())
        self.f = self.sock.makefile("rb")
        status = self.f.readline()
        headers = []
        while True:
            line = self.f.readline()
            if line in (b"\r\n", b""):
                break
            headers.append(line.decode("latin-1").strip())
        if b" 101 " not in status:
            raise CosimError({"detail": status.decode("latin-1").strip(), "headers": headers})
        self.hello = self.receive()
        self.observation = self.receive()
        self.report = None
        self.step_number = 0

    @classmethod
    def connect(cls, session, timeout=30.0):
        url = urlparse(session["websocket_url"])
        return cls(url.hostname, url.port, url.path, timeout)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    @property
    def running(self):
        return self.report is None

    def send(self, message):
        data = json.dumps(message).encode()
        mask = os.urandom(4)
        n = len(data)
        if n < 126:
            head = struct.pack("!BB", 0x81, 0x80 | n)
        elif n < 65536:
            head = struct.pack("!BBH", 0x81, 0x80 | 126, n)
        else:
            head = struct.pack("!BBQ", 0x81, 0x80 | 127, n)
        self.sock.sendall(head + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(data)))

    def receive(self):
        """The next JSON message; raises CosimError for an "error" message, EOFError on close."""
        payload = b""
        while True:
            b0, b1 = self.f.read(2) or (0x88, 0)
            n = b1 & 127
            if n >= 126:
                n = int.from_bytes(self.f.read(2 if n == 126 else 8), "big")
            data = self.f.read(n)
            opcode = b0 & 15
            if opcode == 8:
                raise EOFError("the server closed the connection")
            if opcode == 9:  # ping: answer with a pong carrying the same data
                mask = os.urandom(4)
                self.sock.sendall(struct.pack("!BB", 0x8A, 0x80 | len(data)) + mask +
                                  bytes(b ^ mask[i % 4] for i, b in enumerate(data)))
                continue
            if opcode in (0, 1):
                payload += data
                if b0 & 0x80:
                    break
        message = json.loads(payload)
        if message.get("type") == "error":
            raise CosimError(message)
        return message

    def step(self, robots):
        """One lock-step step: robots = one {"cmd": {v, omega}} or {"pose": ..., "twist": ...} per robot.
        Returns the observation; after the last one, self.report holds the report."""
        self.step_number += 1
        self.send({"type": "step", "step": self.step_number, "robots": robots})
        self.observation = self.receive()
        if self.observation.get("status") == "ended":
            self.report = self.receive()
        return self.observation

    def stop(self):
        self.send({"type": "stop"})
        self.report = self.receive()
        return self.report

    def close(self):
        try:
            self.sock.close()
        except OSError:
            pass
