// MCAP exports of scenario cards (issue 20) read by the real readers, not ours: a card of each of
// the seven Table II categories is made through the API and exported with ?format=mcap; @mcap/core's
// indexed reader opens it (summary and chunk CRCs checked) and its stream reader reads it through
// (record CRCs); message counts and log times equal the card's frames; @foxglove/rosmsg parses our
// .msg files and the schema in the file; @foxglove/rosmsg2-serialization decodes every /people
// message back to the states of the card's log (its CSV export). For the same seven cards the
// simulator exports are read by real readers too (Gazebo SDF by xmllint, the Arena-Rosnav scenario as
// JSON, the Isaac Sim IRA configuration by the `yaml` package) and a live session of each card
// reaches Foxglove's own WebSocket client (@foxglove/ws-protocol), whose /people messages decode.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { McapIndexedReader, McapStreamReader } from '@mcap/core';
import { parse as parseMessageDefinition } from '@foxglove/rosmsg';
import { MessageReader } from '@foxglove/rosmsg2-serialization';
import { decompress } from 'fzstd';
import { spawnSync } from 'node:child_process';
import WebSocket from 'ws';
import wsProtocol from '@foxglove/ws-protocol';
import YAML from 'yaml';
import { startServer, repoRoot } from './server.mjs';

const { FoxgloveClient } = wsProtocol;

const msgDir = join(repoRoot, 'schemas', 'ros2', 'socsim_people_msgs', 'msg');
const STATES = ['walking', 'standing', 'queuing', 'sitting', 'interacting', 'evacuating', 'waiting', 'running', 'exited'];
// One prompt per Table II category (the prompts of socsim-bench scenario).
const PROMPTS = {
  queuing: 'About twenty patients queue at the reception desk of a clinic',
  emergency: 'Fire alarm in the office: everyone evacuates',
  coffee_break: 'Staff take a coffee break around the coffee machine of the office',
  reception: 'Visitors check in at the front desk of the office and then leave',
  bottleneck: 'A crowd squeezes through the narrow door into the canteen',
  social_party: 'A birthday party at home: guests chat in the living room',
  normal_operation: 'Normal daily traffic in a hospital ward: nurses and visitors walk between rooms',
};
const decompressHandlers = { zstd: (buffer, size) => decompress(buffer, new Uint8Array(Number(size))) };

let server;
const cards = {};
before(async () => {
  server = await startServer();
  // All seven jobs queued at once, then awaited.
  const jobs = {};
  for (const [category, prompt] of Object.entries(PROMPTS)) {
    const r = await server.post('/api/v1/scenarios', { prompt, seed: 1, duration_s: 8 });
    assert.equal(r.status, 202, JSON.stringify(r.body));
    jobs[category] = r.body.id;
  }
  for (const [category, id] of Object.entries(jobs)) {
    let job;
    for (let i = 0; i < 900; i++) {
      job = await (await fetch(`${server.base}/api/v1/jobs/${id}`)).json();
      if (['succeeded', 'failed', 'cancelled'].includes(job.status)) break;
      await new Promise((r) => setTimeout(r, 200));
    }
    assert.equal(job.status, 'succeeded', `${category}: ${JSON.stringify(job.error)}\n${server.log()}`);
    cards[category] = job.result.card_id;
  }
});
after(async () => { await server?.stop(); });

async function download(path) {
  const r = await fetch(server.base + path);
  assert.equal(r.status, 200, `${path}: ${r.status} ${await r.clone().text()}`);
  return new Uint8Array(await r.arrayBuffer());
}

// The card's log as rows per frame time, from its CSV export (t,id,x,y,vx,vy,state,role,group_id).
function framesOf(csv) {
  const frames = new Map();
  for (const line of csv.trim().split('\n').slice(1)) {
    const [t, id, x, y, vx, vy, state, role, group] = line.split(',');
    if (!frames.has(t)) frames.set(t, []);
    frames.get(t).push({ id: Number(id), x: Number(x), y: Number(y), vx: Number(vx), vy: Number(vy), state, role, group: Number(group) });
  }
  return frames;
}

test('our .msg files parse with @foxglove/rosmsg as ROS 2 definitions', () => {
  const files = readdirSync(msgDir).filter((f) => f.endsWith('.msg')).sort();
  assert.deepEqual(files, ['Group.msg', 'Intent.msg', 'People.msg', 'Person.msg', 'PersonMetadata.msg', 'Proxemics.msg']);
  for (const f of files) {
    const [def] = parseMessageDefinition(readFileSync(join(msgDir, f), 'utf8'), { ros2: true, skipTypeFixup: true });
    assert.ok(def.definitions.length > 0, f);
  }
  const person = parseMessageDefinition(readFileSync(join(msgDir, 'Person.msg'), 'utf8'), { ros2: true, skipTypeFixup: true })[0];
  const constants = person.definitions.filter((d) => d.isConstant).map((d) => [d.name, d.value]);
  assert.deepEqual(constants, STATES.map((s, i) => [`STATE_${s.toUpperCase()}`, i]));
  assert.deepEqual(person.definitions.filter((d) => !d.isConstant).map((d) => d.name),
    ['id', 'pose', 'twist', 'state', 'role', 'intent', 'group_id', 'proxemics', 'metadata']);
});

for (const category of Object.keys(PROMPTS)) {
  test(`${category}: the card's MCAP reads back with @mcap/core and its CDR decodes to the card's states`, async () => {
    const id = cards[category];
    const card = await (await fetch(`${server.base}/api/v1/cards/${id}`)).json();
    const frameCount = card.trajectory_log.frames;
    assert.ok(frameCount > 10, `${category}: ${frameCount} frames`);
    const frames = framesOf(new TextDecoder().decode(await download(`/api/v1/cards/${id}/export?format=csv`)));
    const bytes = await download(`/api/v1/cards/${id}/export?format=mcap`);
    const again = await download(`/api/v1/cards/${id}/export?format=mcap`);
    assert.deepEqual(again, bytes, 'the same card exports to the same bytes');

    const readable = { size: async () => BigInt(bytes.length), read: async (offset, size) => bytes.subarray(Number(offset), Number(offset + size)) };
    const reader = await McapIndexedReader.Initialize({ readable, decompressHandlers });
    assert.equal(reader.header.profile, 'ros2');
    const topics = new Map([...reader.channelsById.values()].map((c) => [c.topic, c]));
    assert.deepEqual([...topics.keys()].sort(), ['/people', '/scene/people', '/scene/world']);
    const people = topics.get('/people');
    assert.equal(people.messageEncoding, 'cdr');
    const schema = reader.schemasById.get(people.schemaId);
    assert.equal(schema.name, 'socsim_people_msgs/msg/People');
    assert.equal(schema.encoding, 'ros2msg');
    const schemaText = new TextDecoder().decode(schema.data);
    assert.ok(schemaText.startsWith(readFileSync(join(msgDir, 'People.msg'), 'utf8')), 'the schema starts with People.msg');
    assert.ok(schemaText.includes(`${'='.repeat(80)}\nMSG: socsim_people_msgs/Person\n${readFileSync(join(msgDir, 'Person.msg'), 'utf8')}`));
    const scene = topics.get('/scene/people');
    assert.equal(scene.messageEncoding, 'json');
    assert.equal(reader.schemasById.get(scene.schemaId).name, 'foxglove.SceneUpdate');
    assert.equal(reader.schemasById.get(scene.schemaId).encoding, 'jsonschema');
    assert.equal(reader.statistics.channelMessageCounts.get(people.id), BigInt(frameCount));
    assert.equal(reader.statistics.channelMessageCounts.get(scene.id), BigInt(frameCount));
    assert.equal(reader.statistics.channelMessageCounts.get(topics.get('/scene/world').id), 1n);
    assert.ok(reader.chunkIndexes.length >= 1);
    assert.equal(reader.metadataIndexes[0].name, 'socsim_map');

    const cdr = new MessageReader(parseMessageDefinition(schemaText, { ros2: true }));
    const times = [...frames.keys()];
    let n = 0;
    let scenes = 0;
    for await (const m of reader.readMessages({ validateCrcs: true })) {
      if (m.channelId === scene.id) {
        const update = JSON.parse(new TextDecoder().decode(m.data));
        assert.equal(update.entities[0].cylinders.length, frames.get(times[scenes]).length);
        scenes++;
        continue;
      }
      if (m.channelId !== people.id) continue;
      const t = Number(times[n]);
      assert.equal(m.logTime, BigInt(Math.round(t * 1e9)), `frame ${n} log time`);
      const msg = cdr.readMessage(m.data);
      assert.equal(cdr.lastReadHadTrailingBytes(), false);
      assert.equal(msg.header.frame_id, 'map');
      assert.equal(BigInt(msg.header.stamp.sec) * 1000000000n + BigInt(msg.header.stamp.nsec ?? msg.header.stamp.nanosec), m.logTime);
      const expected = frames.get(times[n]);
      assert.equal(msg.people.length, expected.length, `frame ${n}`);
      msg.people.forEach((p, i) => {
        const e = expected[i];
        assert.equal(p.id, e.id);
        // The log holds floats; the CSV writes the shortest text that reads back to the float.
        assert.equal(p.pose.position.x, Math.fround(e.x));
        assert.equal(p.pose.position.y, Math.fround(e.y));
        assert.equal(p.twist.linear.x, Math.fround(e.vx));
        assert.equal(p.twist.linear.y, Math.fround(e.vy));
        // Orientation components on a 2^-12 grid (core/interop/people_msgs.cpp): a unit quaternion within 5e-4.
        assert.ok(Math.abs(p.pose.orientation.z ** 2 + p.pose.orientation.w ** 2 - 1) < 5e-4);
        assert.equal(p.pose.orientation.z * 4096, Math.round(p.pose.orientation.z * 4096));
        assert.equal(STATES[p.state], e.state);
        assert.equal(p.role, e.role);
        assert.equal(p.group_id, BigInt(e.group));
        assert.ok(p.proxemics.intimate_radius <= p.proxemics.comfort_radius && p.proxemics.comfort_radius <= p.proxemics.social_radius);
      });
      const grouped = new Set(expected.filter((e) => e.group >= 0).map((e) => e.group));
      assert.equal(msg.groups.length, grouped.size);
      for (const g of msg.groups) assert.equal(g.member_ids.length, expected.filter((e) => BigInt(e.group) === g.id).length);
      n++;
    }
    assert.equal(n, frameCount);
    assert.equal(scenes, frameCount);

    // Start to end with the stream reader: every record, chunk CRCs checked on the way.
    const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
    stream.append(bytes);
    const kinds = {};
    for (let r; (r = stream.nextRecord());) kinds[r.type] = (kinds[r.type] ?? 0) + 1;
    assert.ok(stream.done());
    assert.equal(kinds.Message, 2 * frameCount + 1);
    assert.equal(kinds.DataEnd, 1);
    assert.equal(kinds.Footer, 1);
  });
}

// The first /people message of a live session of the card, through Foxglove's client.
async function firstLivePeople(cardId) {
  const sim = await server.post('/api/v1/simulations', { card_id: cardId });
  assert.equal(sim.status, 201, JSON.stringify(sim.body));
  const client = new FoxgloveClient({ ws: new WebSocket(`ws://127.0.0.1:${server.wsPort}/foxglove/${sim.body.id}`, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]) });
  client.on('error', () => {});
  try {
    return await new Promise((resolve, reject) => {
      const timer = setTimeout(() => reject(new Error('no /people message within 20 s')), 20000);
      let reader, sub;
      client.on('advertise', (channels) => {
        const people = channels.find((c) => c.topic === '/people');
        if (!people || sub !== undefined) return;
        reader = new MessageReader(parseMessageDefinition(people.schema, { ros2: true }));
        sub = client.subscribe(people.id);
      });
      client.on('message', (m) => {
        if (m.subscriptionId !== sub) return;
        clearTimeout(timer);
        resolve(reader.readMessage(new Uint8Array(m.data.buffer, m.data.byteOffset, m.data.byteLength)));
      });
    });
  } finally {
    client.close();
    await fetch(`${server.base}/api/v1/simulations/${sim.body.id}`, { method: 'DELETE' });  // one of few slots
  }
}

for (const category of Object.keys(PROMPTS)) {
  test(`${category}: Gazebo, Arena and Isaac exports read back, and a live session reaches a Foxglove client`, async () => {
    const id = cards[category];
    const sdf = new TextDecoder().decode(await download(`/api/v1/cards/${id}/export?format=gazebo`));
    const lint = spawnSync('xmllint', ['--noout', '-'], { input: sdf });
    assert.equal(lint.status, 0, `xmllint: ${lint.stderr}`);
    assert.ok((sdf.match(/<actor /g) ?? []).length > 0);

    const arena = JSON.parse(new TextDecoder().decode(await download(`/api/v1/cards/${id}/export?format=arena`)));
    assert.equal(arena.robots.length, 1);
    assert.ok(arena.obstacles.dynamic.length > 0);
    for (const o of arena.obstacles.dynamic) {
      assert.equal(o.pos.length, 3);
      assert.ok(o.waypoints.length > 0 && o.waypoints.every((w) => w.length === 3 && w.every(Number.isFinite)));
    }

    const isaac = JSON.parse(new TextDecoder().decode(await download(`/api/v1/cards/${id}/export?format=isaac&archive=json`)));
    assert.deepEqual(Object.keys(isaac.files).sort(), ['ira_config.yaml', 'people_commands.txt', 'world.usda']);
    assert.ok(isaac.files['world.usda'].startsWith('#usda 1.0\n'));
    const ira = YAML.parse(isaac.files['ira_config.yaml'])['isaacsim.replicator.agent'];
    assert.equal(ira.environment.base_stage_asset_path, 'world.usda');
    const people = Object.values(ira.character.groups).reduce((n, g) => n + g.num, 0);
    const characters = new Set(isaac.files['people_commands.txt'].split('\n').filter((l) => l && !l.startsWith('#')).map((l) => l.split(' ')[0]));
    assert.equal(characters.size, people);
    for (const line of isaac.files['people_commands.txt'].split('\n').filter((l) => l && !l.startsWith('#')))
      assert.match(line, /^Character(_\d+)? (GoTo -?[\d.]+ -?[\d.]+ 0 _|Idle [\d.]+)$/);

    const live = await firstLivePeople(id);
    assert.equal(live.header.frame_id, 'map');
    assert.ok(live.people.length > 0, `${category}: no people in the live frame`);
  });
}

test('format=mcap without a log or with a bad option is a problem, not a file', async () => {
  const r = await fetch(`${server.base}/api/v1/cards/${cards.queuing}/export?format=mcap&scene_people=maybe`);
  assert.equal(r.status, 422);
  const none = await server.post('/api/v1/cards', { title: 'no log', prompt: 'nothing' });
  assert.equal(none.status, 201, JSON.stringify(none.body));
  const missing = await fetch(`${server.base}/api/v1/cards/${none.body.id}/export?format=mcap`);
  assert.ok([404, 422].includes(missing.status), String(missing.status));
});
