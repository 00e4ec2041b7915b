// The Foxglove WebSocket protocol on live simulations (issue 20), read by Foxglove's own client
// (@foxglove/ws-protocol over the `ws` package), not ours: serverInfo and advertise on connecting,
// subscribe/unsubscribe, binary Message Data decoded with @foxglove/rosmsg2-serialization from the
// advertised ros2msg schema; a card's world on /scene/world; bad requests answered with a status;
// and the rate a client receives from a 2,000-agent session over 10 s (issue 20: ≥ 19 messages/s).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import WebSocket from 'ws';
import wsProtocol from '@foxglove/ws-protocol';
import { parse as parseMessageDefinition } from '@foxglove/rosmsg';
import { MessageReader } from '@foxglove/rosmsg2-serialization';
import { startServer } from './server.mjs';

const { FoxgloveClient } = wsProtocol;

let server;
before(async () => { server = await startServer(); });
after(async () => { await server?.stop(); });

// Lanes 1 m apart, alternate lanes walking in opposite directions (as socsim-bench stream).
function lanesProgram(agents) {
  const list = [];
  for (let i = 0; i < agents; i++) {
    const lane = Math.floor(i / 40), y = lane;
    const x = (i % 40) * 1.5 + (lane % 2 ? 0.7 : 0);
    const to = lane % 2 ? 0 : 60;
    list.push({ position: [x, y], goals: [[to, y], [60 - to, y]] });
  }
  return { name: 'foxglove lanes', dt: 0.05, decision_period: 0.1, agents: list };
}

// Connects a Foxglove client and collects what it is told until `until()` holds.
function connect(path) {
  const ws = new WebSocket(`ws://127.0.0.1:${server.wsPort}${path}`, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]);
  const client = new FoxgloveClient({ ws });
  const seen = { serverInfo: null, channels: [], statuses: [], messages: [], times: 0, closed: false };
  client.on('serverInfo', (i) => { seen.serverInfo = i; });
  client.on('advertise', (c) => { seen.channels.push(...c); });
  client.on('status', (s) => { seen.statuses.push(s); });
  client.on('time', () => { seen.times++; });
  client.on('message', (m) => { seen.messages.push({ sub: m.subscriptionId, ts: m.timestamp, data: m.data, at: performance.now() }); });
  client.on('close', () => { seen.closed = true; });
  client.on('error', () => {});
  return { client, seen };
}

async function until(predicate, ms = 20000) {
  const start = Date.now();
  while (!predicate()) {
    if (Date.now() - start > ms) throw new Error('timed out');
    await new Promise((r) => setTimeout(r, 20));
  }
}

const decoder = new TextDecoder();
const bytesOf = (view) => new Uint8Array(view.buffer, view.byteOffset, view.byteLength);

test('a client without the subprotocol is refused; an unknown simulation is 404', async () => {
  const sim = await server.post('/api/v1/simulations', { program: lanesProgram(10), seed: 1 });
  assert.equal(sim.status, 201, JSON.stringify(sim.body));
  const refused = await new Promise((resolve) => {
    const ws = new WebSocket(`ws://127.0.0.1:${server.wsPort}/foxglove/${sim.body.id}`);
    ws.on('unexpected-response', (_req, res) => resolve(res.statusCode));
    ws.on('open', () => resolve('open'));
    ws.on('error', () => {});
  });
  assert.equal(refused, 400);
  const unknown = await new Promise((resolve) => {
    const ws = new WebSocket(`ws://127.0.0.1:${server.wsPort}/foxglove/sim_nope`, ['foxglove.websocket.v1']);
    ws.on('unexpected-response', (_req, res) => resolve(res.statusCode));
    ws.on('open', () => resolve('open'));
    ws.on('error', () => {});
  });
  assert.equal(unknown, 404);
});

test('a card session: channels advertised, the world once, people decoded from CDR and JSON', async () => {
  const job = await server.post('/api/v1/scenarios', { prompt: 'About twenty patients queue at the reception desk of a clinic', seed: 2, duration_s: 6 });
  assert.equal(job.status, 202, JSON.stringify(job.body));
  let done;
  for (let i = 0; i < 900; i++) {
    done = await (await fetch(`${server.base}/api/v1/jobs/${job.body.id}`)).json();
    if (['succeeded', 'failed', 'cancelled'].includes(done.status)) break;
    await new Promise((r) => setTimeout(r, 200));
  }
  assert.equal(done.status, 'succeeded', JSON.stringify(done.error));
  const sim = await server.post('/api/v1/simulations', { card_id: done.result.card_id, speed: 1 });
  assert.equal(sim.status, 201, JSON.stringify(sim.body));

  const { client, seen } = connect(`/foxglove/${sim.body.id}`);
  await until(() => seen.serverInfo && seen.channels.length > 0);
  assert.equal(seen.serverInfo.name, 'socsim');
  assert.deepEqual(seen.serverInfo.capabilities, ['time']);
  const byTopic = Object.fromEntries(seen.channels.map((c) => [c.topic, c]));
  assert.deepEqual(Object.keys(byTopic).sort(), ['/people', '/people/json', '/scene/people', '/scene/world']);
  assert.equal(byTopic['/people'].encoding, 'cdr');
  assert.equal(byTopic['/people'].schemaEncoding, 'ros2msg');
  assert.equal(byTopic['/people'].schemaName, 'socsim_people_msgs/msg/People');
  const reader = new MessageReader(parseMessageDefinition(byTopic['/people'].schema, { ros2: true }));

  const subs = {};
  for (const topic of Object.keys(byTopic)) subs[topic] = client.subscribe(byTopic[topic].id);
  await until(() => ['/people', '/people/json', '/scene/people'].every((t) => seen.messages.some((m) => m.sub === subs[t])));

  const world = seen.messages.filter((m) => m.sub === subs['/scene/world']);
  assert.equal(world.length, 1, 'the world is sent once, on subscribing');
  const scene = JSON.parse(decoder.decode(bytesOf(world[0].data)));
  assert.deepEqual(scene.entities.map((e) => e.id), ['walls', 'zones', 'doors']);
  assert.ok(scene.entities[0].cubes.length > 0);

  const cdr = seen.messages.find((m) => m.sub === subs['/people']);
  const people = reader.readMessage(bytesOf(cdr.data));
  const json = JSON.parse(decoder.decode(bytesOf(seen.messages.find((m) => m.sub === subs['/people/json']).data)));
  assert.equal(people.header.frame_id, 'map');
  assert.ok(people.people.length >= 10, `people: ${people.people.length}`);
  assert.ok(json.people.length >= 10);
  assert.ok(seen.times > 0, 'time messages come with the data');
  // The CDR and the JSON of a frame are the same people (the first frame of each, compared by ids).
  const cdrIds = people.people.map((p) => Number(p.id)).sort((a, b) => a - b);
  const firstJson = JSON.parse(decoder.decode(bytesOf(seen.messages.find((m) => m.sub === subs['/people/json'] && m.ts === cdr.ts).data)));
  assert.deepEqual(firstJson.people.map((p) => Number(p.id)).sort((a, b) => a - b), cdrIds);

  // Unsubscribing stops that channel; a bad request is answered with an error status.
  client.unsubscribe(subs['/scene/people']);
  client.unsubscribe(subs['/people/json']);
  await new Promise((r) => setTimeout(r, 300));
  const before = seen.messages.filter((m) => m.sub === subs['/scene/people']).length;
  await new Promise((r) => setTimeout(r, 600));
  assert.equal(seen.messages.filter((m) => m.sub === subs['/scene/people']).length, before);
  client.subscribe(99);
  await until(() => seen.statuses.some((s) => s.level === 2 && /no channel 99/.test(s.message)));
  client.close();
});

test('a 2,000-agent live session reaches a Foxglove client at ≥ 19 messages/s for 10 s', async () => {
  const sim = await server.post('/api/v1/simulations', { program: lanesProgram(2000), seed: 1 });
  assert.equal(sim.status, 201, JSON.stringify(sim.body));
  const { client, seen } = connect(`/foxglove/${sim.body.id}`);
  await until(() => seen.channels.length > 0);
  const people = seen.channels.find((c) => c.topic === '/people');
  assert.ok(!seen.channels.some((c) => c.topic === '/scene/world'), 'a session without a world advertises no world');
  const reader = new MessageReader(parseMessageDefinition(people.schema, { ros2: true }));
  const sub = client.subscribe(people.id);
  await until(() => seen.messages.some((m) => m.sub === sub));
  const start = performance.now();
  const first = seen.messages.length;
  await new Promise((r) => setTimeout(r, 10000));
  const received = seen.messages.slice(first).filter((m) => m.sub === sub);
  const seconds = (performance.now() - start) / 1000;
  const rate = received.length / seconds;
  const last = reader.readMessage(bytesOf(received[received.length - 1].data));
  console.log(`foxglove: ${received.length} /people messages in ${seconds.toFixed(2)} s = ${rate.toFixed(1)}/s, ` +
    `${last.people.length} people, ${received[received.length - 1].data.byteLength} bytes each`);
  assert.equal(last.people.length, 2000);
  assert.ok(rate >= 19, `${rate.toFixed(1)} messages/s`);
  client.close();
});
