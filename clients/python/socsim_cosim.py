"""A co-simulation client for socsim (docs/cosim.md) in Python's standard library only.

    session = open_session("http://localhost:8080", {"card_id": "...", "seed": 7, "robot": {...}})
    with CosimClient.connect(session) as c:       # hello and the first observation are read
        while c.running:
            c.step([{"cmd": {"v": 0.5, "omega": 0.0}}])
        print(c.report["metrics"])

The WebSocket is spoken by hand (RFC 6455: handshake, masked client frames), as in the README's
example, so that nothing beyond the standard library is needed. CosimClient.connect(session,
binary=True) asks for the compact observations of socsim.cosim.v1.binary (float32, 32 bytes per
person; docs/cosim.md "Binary observations"); they are decoded into the same dictionaries as the
JSON ones (without intent, proxemics and metadata), so a planner works with either.
"""
import base64
import json
import os
import socket
import struct
import time
import urllib.error
import urllib.request
from urllib.parse import urlparse

PROTOCOL = "socsim.cosim.v1"
BINARY_PROTOCOL = "socsim.cosim.v1.binary"
OUTCOMES = ("running", "success", "collision_person", "collision_wall", "timeout", "stuck")
STATES = ("walking", "standing", "queuing", "sitting", "interacting", "evacuating", "waiting", "running")


class CosimError(Exception):
    """The server answered with a problem (HTTP) or an "error" message (WebSocket)."""

    def __init__(self, problem):
        super().__init__(problem.get("detail", str(problem)))
        self.problem = problem


def request_json(base_url, method, path, body=None):
    """One REST call; returns the JSON answer, raises CosimError with the problem document."""
    data = None if body is None else json.dumps(body).encode()
    req = urllib.request.Request(base_url.rstrip("/") + path, data, {"Content-Type": "application/json"},
                                 method=method)
    try:
        with urllib.request.urlopen(req, timeout=30) as r:
            return json.load(r)
    except urllib.error.HTTPError as e:
        raise CosimError(json.loads(e.read() or b"{}")) from None


def open_session(base_url, body):
    """POST /api/v1/cosim; returns the session status (id, ws_url, ws_port, websocket_url, ...)."""
    return request_json(base_url, "POST", "/api/v1/cosim", body)

def decode_binary_observation(data, hello):
    """One binary observation (docs/cosim.md table) as the JSON observation's dictionary."""
    if data[:4] != b"SCB1":
        raise CosimError({"detail": "not a socsim.cosim.v1.binary observation"})
    status, n_robots = data[4], data[5]
    step, t, n_people = struct.unpack_from("<QdI", data, 8)
    robots, offset = [], 32
    for k in range(n_robots):
        x, y, yaw, vx, vy, omega, outcome = struct.unpack_from("<6fB", data, offset)
        spec = hello["robots"][k]
        robots.append({"name": spec["name"], "pose": {"x": x, "y": y, "yaw": yaw},
                       "twist": {"vx": vx, "vy": vy, "omega": omega}, "goal": spec.get("goal"),
                       "outcome": OUTCOMES[outcome] if outcome < len(OUTCOMES) else "unknown"})
        offset += 28
    roles, people = hello.get("roles", []), []
    for _ in range(n_people):
        pid, x, y, yaw, vx, vy, group, state, role = struct.unpack_from("<I5fiBB", data, offset)
        people.append({"id": pid, "pose": {"x": x, "y": y, "yaw": yaw}, "twist": {"vx": vx, "vy": vy},
                       "group_id": group, "state": STATES[state] if state < len(STATES) else "unknown",
                       "role": roles[role] if role < len(roles) else None})
        offset += 32
    return {"type": "observation", "step": step, "t": t, "status": "ended" if status == 1 else "running",
            "robots": robots, "people": people}


class CosimClient:
    def __init__(self, host, port, path, timeout=30.0, binary=False):
        self.sock = socket.create_connection((host, port), timeout=timeout)
        key = base64.b64encode(os.urandom(16)).decode()
        self.sock.sendall((f"GET {path} HTTP/1.1\r\nHost: {host}:{port}\r\nUpgrade: websocket\r\n"
                           f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n"
                           f"Sec-WebSocket-Protocol: {BINARY_PROTOCOL if binary else PROTOCOL}\r\n\r\n").encode())
        self.f = self.sock.makefile("rb")
        self.hello = None
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
    def connect(cls, session, timeout=30.0, binary=False):
        url = urlparse(session["websocket_url"])
        return cls(url.hostname, url.port, url.path, timeout, binary)

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
        """The next message (binary observations decoded); raises CosimError for an "error"
        message, EOFError on close."""
        payload, binary = b"", False
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
            if opcode in (0, 1, 2):
                binary = binary or opcode == 2
                payload += data
                if b0 & 0x80:
                    break
        if binary:
            return decode_binary_observation(payload, self.hello)
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


def run_external_evaluation(base_url, body, planner, binary=False, poll=0.05, on_episode=None):
    """POST /api/v1/evaluations with "client": "external" and drive every episode it opens with
    planner(observation, k, max_speed) until the job ends; returns the evaluation record (its
    result.table once it succeeded). on_episode(current, report) is called after each episode."""
    body = dict(body, client="external")
    evaluation = request_json(base_url, "POST", "/api/v1/evaluations", body)
    path, driven = "/api/v1/evaluations/" + evaluation["id"], None
    ws_base = None
    while True:
        evaluation = request_json(base_url, "GET", path)
        current = evaluation.get("current")
        if evaluation["status"] in ("succeeded", "failed", "cancelled"):
            return evaluation
        if not current or current["cosim"] == driven:
            time.sleep(poll)
            continue
        if ws_base is None:
            ws_base = request_json(base_url, "GET", "/api/v1/cosim/" + current["cosim"])["websocket_url"]
        session = {"websocket_url": ws_base.rsplit("/ws/cosim/", 1)[0] + current["ws_url"]}
        with CosimClient.connect(session, binary=binary) as c:
            speeds = [r["limits"]["max_speed"] for r in c.hello["robots"]]
            while c.running:
                c.step([planner(c.observation, k, speeds[k]) for k in range(len(speeds))])
        driven = current["cosim"]
        if on_episode:
            on_episode(current, c.report)
