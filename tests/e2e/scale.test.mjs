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

// The shared queue: a batch of 200 scenarios over both daemons; one is killed with SIGKILL in the
// middle; the survivor takes over the dead one's leases once they run out, and every item is done
// exactly once (200 items succeeded, 200 cards, each card's id the job's).
test('a batch of 200 over two workers survives kill -9 of one, each item exactly once', { skip, timeout: 600_000 }, async () => {
  // Exactly two workers on the database: the first test's daemons leave.
  await a.stop();
  await b.stop();
  const c = await startServer(['--db', url, '--job-lease', '2', '--worker-id', 'doomed']);
  const d = await startServer(['--db', url, '--job-lease', '2', '--worker-id', 'survivor']);
  try {
    const prompts = ['a small cafe with 6 customers and 2 baristas', 'an office corridor with 10 workers walking to a meeting'];
    const made = await c.post('/api/v1/batches', { kind: 'scenarios', prompts, seeds: { first: 1, count: 100 }, parameters: { duration_s: 5 } });
    assert.equal(made.status, 202, JSON.stringify(made.body));
    assert.equal(made.body.total, 200);
    const id = made.body.id;
    const status = async (srv) => (await fetch(`${srv.base}/api/v1/batches/${id}`)).json();
    let held = [];
    for (let i = 0; i < 600; i++) {
      const s = await status(d);
      if (s.counts.succeeded >= 40) {
        // Frozen while its items are read, so none it holds can finish before the kill (under
        // load it once did, between the read and the kill).
        c.freeze();
        const items = await (await fetch(`${d.base}/api/v1/batches/${id}/items?page_size=100&cursor=${Math.max(0, s.counts.succeeded - 20)}`)).json();
        held = items.items.filter((it) => it.status === 'running' && it.worker === 'doomed').map((it) => it.job_id);
        if (held.length > 0) break;
        c.thaw();
      }
      await new Promise((r) => setTimeout(r, 100));
    }
    assert.ok(held.length > 0, 'the doomed worker was running items');
    await c.kill9();
    console.log(`  killed the worker holding ${held.length} item(s) ${held.join(', ')}`);
    let last;
    for (let i = 0; i < 3000; i++) {
      last = await status(d);
      if (last.status !== 'running') break;
      await new Promise((r) => setTimeout(r, 100));
    }
    assert.equal(last.status, 'succeeded', JSON.stringify(last.counts));
    assert.equal(last.counts.succeeded, 200);
    console.log(`  done: ${JSON.stringify(last.succeeded_by_worker)}`);
    // Every item once: 200 distinct jobs, each with its own card named after it.
    const items = [];
    for (let cursor = null; ;) {
      const page = await (await fetch(`${d.base}/api/v1/batches/${id}/items?page_size=100${cursor ? `&cursor=${cursor}` : ''}`)).json();
      items.push(...page.items);
      if (!page.next_cursor) break;
      cursor = page.next_cursor;
    }
    assert.equal(items.length, 200);
    assert.deepEqual(items.map((it) => it.index), [...Array(200).keys()]);
    const cards = new Set(items.map((it) => it.result.card_id));
    assert.equal(cards.size, 200);
    for (const it of items) assert.equal(it.result.card_id, `crd_${it.job_id.slice(4)}`);
    // The survivor finished what the dead worker held, on a second attempt.
    for (const job of held) {
      const it = items.find((x) => x.job_id === job);
      assert.equal(it.worker, 'survivor', `${job} finished by the survivor`);
      assert.equal(it.attempts, 2, `${job} claimed twice`);
    }
    // The catalogue holds those 200 cards and no second copy of any.
    let inCatalogue = 0;
    for (let cursor = null; ;) {
      const page = await (await fetch(`${d.base}/api/v1/cards?page_size=100${cursor ? `&cursor=${cursor}` : ''}`)).json();
      inCatalogue += page.items.filter((card) => prompts.includes(card.prompt ?? card.content?.prompt)).length;
      for (const card of page.items) if (prompts.includes(card.prompt ?? card.content?.prompt)) assert.ok(cards.has(card.id), `${card.id} belongs to an item`);
      if (!page.next_cursor) break;
      cursor = page.next_cursor;
    }
    assert.equal(inCatalogue, 200);
    // The export gives the same bytes each time.
    const a1 = Buffer.from(await (await fetch(`${d.base}/api/v1/batches/${id}/export`)).arrayBuffer());
    const a2 = Buffer.from(await (await fetch(`${d.base}/api/v1/batches/${id}/export`)).arrayBuffer());
    assert.ok(a1.length > 200 * 1000);
    assert.ok(a1.equals(a2), 'same export bytes twice');
  } finally {
    await c.stop();
    await d.stop();
  }
});
