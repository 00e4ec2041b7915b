// Two daemons on one PostgreSQL database (issue 21): a card created through one is in the other's
// catalogue at once and reaches the other's /ws/catalogue WebSocket within a second (LISTEN/NOTIFY,
// server/pg_event_relay.cpp). Needs the scratch server of SOCSIM_TEST_POSTGRES (tests/run-all.sh
// starts one); skipped without it.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import WebSocket from 'ws';
import { startServer } from './server.mjs';

const admin = process.env.SOCSIM_TEST_POSTGRES;
const skip = admin ? false : 'SOCSIM_TEST_POSTGRES is not set (tests/run-all.sh starts a scratch PostgreSQL server)';
const dbName = `socsim_e2e_scale_${process.pid}`;
const url = admin ? admin.replace(/\/[^/?]*(\?|$)/, `/${dbName}$1`) : '';
let a, b;

const psql = (sql) => execFileSync('psql', [admin, '-v', 'ON_ERROR_STOP=1', '-qc', sql], { stdio: 'pipe' });

before(async () => {
  if (skip) return;
  psql(`DROP DATABASE IF EXISTS ${dbName} WITH (FORCE)`);
  psql(`CREATE DATABASE ${dbName}`);
  a = await startServer(['--db', url]);
  b = await startServer(['--db', url]);  // waits for a's migrations, applies none
});

after(async () => {
  await a?.stop();
  await b?.stop();
  if (!skip) psql(`DROP DATABASE IF EXISTS ${dbName} WITH (FORCE)`);
});

test('a card created on one daemon reaches the other daemon\'s catalogue WebSocket within a second', { skip }, async () => {
  assert.match(b.log(), /"migrations_applied":\[\]/, 'the second daemon found the schema made');
  assert.doesNotMatch(a.log() + b.log(), /postgresql:\/\/[^"]*:[^*@"]+@/, 'no password in the logs');
  const ws = new WebSocket(`ws://127.0.0.1:${b.wsPort}/ws/catalogue`);
  await new Promise((resolve, reject) => { ws.once('open', resolve); ws.once('error', reject); });
  const seen = new Promise((resolve) => {
    ws.on('message', (data) => {
      const m = JSON.parse(data.toString());
      if (m.type === 'card.created') resolve({ m, at: performance.now() });
    });
  });
  const sent = performance.now();
  const created = await a.post('/api/v1/cards', {
    title: 'Shared across workers', prompt: 'two daemons, one catalogue', tags: ['scale'], seed: 1,
  });
  assert.equal(created.status, 201, JSON.stringify(created.body));
  const { m, at } = await Promise.race([seen, new Promise((_, reject) => setTimeout(() => reject(new Error('no event on the other daemon within 1 s')), 1000))]);
  assert.equal(m.card.id, created.body.id);
  console.log(`  card.created reached the other daemon's WebSocket ${(at - sent).toFixed(0)} ms after the POST`);
  // The other daemon serves the card and finds it by search.
  const got = await (await fetch(`${b.base}/api/v1/cards/${created.body.id}`)).json();
  assert.equal(got.content_hash, created.body.content_hash);
  const found = await (await fetch(`${b.base}/api/v1/cards?q=catalogue+daemons`)).json();
  assert.deepEqual(found.items.map((c) => c.id), [created.body.id]);
  // Its own events do not come back twice to its own clients.
  const own = new WebSocket(`ws://127.0.0.1:${a.wsPort}/ws/catalogue`);
  await new Promise((resolve, reject) => { own.once('open', resolve); own.once('error', reject); });
  const events = [];
  own.on('message', (data) => events.push(JSON.parse(data.toString())));
  const second = await a.post('/api/v1/cards', { title: 'Once only', prompt: 'one event per card', seed: 2 });
  await new Promise((r) => setTimeout(r, 500));
  assert.equal(events.filter((e) => e.type === 'card.created' && e.card.id === second.body.id).length, 1);
  ws.close();
  own.close();
});
