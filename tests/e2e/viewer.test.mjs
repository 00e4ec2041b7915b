// The catalogue viewer (catalogue.html) in headless Debian Chromium, served by the daemon itself:
// cards listed, searched, opened; a card POSTed while the page is open appears live over the
// WebSocket. Share links from before the catalogue moved off `/` (/#card=…) still open the card.
// The co-simulation view (cosim.html) follows a robot driven over /ws/cosim/{id} live: the robot,
// its path and its contact with a person. A screenshot per test lands in tests/e2e/artifacts/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { startServer } from './server.mjs';
import { artifacts, browserSkip as skip, inkedFraction, launchBrowser } from './browser.mjs';
import WebSocket from 'ws';

let server, browser;

const card = (title, prompt, tags, domain) => ({
  title, prompt, tags, domain, description: `${title}: ${prompt}.`, seed: 1, generator: { name: 'offline' },
});

before(async () => {
  if (skip) return;
  server = await startServer();
  await server.post('/api/v1/cards', card('Morning check-in', 'patients queue at the reception desk', ['queue'], 'hospital'));
  await server.post('/api/v1/cards', card('Fire drill', 'everyone evacuates through the two exits', ['emergency'], 'office'));
  browser = await launchBrowser();
});

after(async () => {
  await browser?.close();
  await server?.stop();
});

test('catalogue lists, searches and opens cards', { skip }, async () => {
  const page = await browser.newPage();
  await page.goto(server.base + '/catalogue.html');
  await page.waitForSelector('#cards li');
  assert.equal(await page.locator('#cards li').count(), 2);
  await page.fill('#q', 'evacuate');
  await page.click('#search button');
  await page.waitForFunction(() => document.querySelectorAll('#cards li').length === 1);
  await page.click('#cards li');
  await page.waitForSelector('#detail h2');
  assert.equal(await page.textContent('#detail h2'), 'Fire drill');
  assert.match(page.url(), /#card=crd_/);
  await page.screenshot({ path: join(artifacts, 'catalogue.png'), fullPage: true });
  await page.close();
});

// A search submitted while the first page is still on its way: the late first page must not be
// added to the search's results (seen on a loaded machine: the list then held every card plus the
// hit).
test('a search sent before the first page arrives shows only its own results', { skip }, async () => {
  const page = await browser.newPage();
  const isFirstPage = (url) => url.includes('/api/v1/cards?') && !url.includes('q=');
  await page.route('**/api/v1/cards?*', async (route) => {  // hold back the unfiltered first page
    if (isFirstPage(route.request().url())) await new Promise((r) => setTimeout(r, 1500));
    await route.continue();
  });
  const firstPage = page.waitForRequest((r) => isFirstPage(r.url()));
  await page.goto(server.base + '/catalogue.html');
  await firstPage;
  await page.fill('#q', 'evacuate');
  await page.click('#search button');
  await page.waitForFunction(() => document.querySelectorAll('#cards li').length >= 1);
  await page.waitForTimeout(2500);  // the first page has arrived by now
  assert.equal(await page.locator('#cards li').count(), 1);
  assert.equal(await page.textContent('#cards li .title'), 'Fire drill');
  await page.close();
});

test('a card with a world shows its floor plan', { skip }, async () => {
  const world = {
    name: 'two_rooms', units: { length: 'm', angle: 'rad' }, origin: [0, 0],
    zones: [{ name: 'lobby', type: 'lobby', polygon: [[0, 0], [8, 0], [8, 6], [0, 6]] },
      { name: 'office', type: 'office', polygon: [[8, 0], [14, 0], [14, 6], [8, 6]] }],
    walls: [{ start: [0, 0], end: [14, 0] }, { start: [14, 0], end: [14, 6] }, { start: [14, 6], end: [0, 6] },
      { start: [0, 6], end: [0, 0] }, { start: [8, 0], end: [8, 2.5] }, { start: [8, 3.5], end: [8, 6] }],
    doors: [{ name: 'd1', pose: [8, 3, 0], width: 1, connects: ['lobby', 'office'] }],
    segmentation: [{ name: 'queue', kind: 'queue_lane', polygon: [[2, 1], [3, 1], [3, 4], [2, 4]] }],
    entities: [{ type: 'counter', name: 'reception_counter', pose: [2.5, 4.5, 0] }],
  };
  const created = await server.post('/api/v1/cards', { ...card('Two rooms', 'a lobby and an office', ['world'], 'office'), world });
  assert.equal(created.status, 201, JSON.stringify(created.body));
  const page = await browser.newPage();
  await page.goto(`${server.base}/#card=${created.body.id}`);
  await page.waitForSelector('#detail canvas.world');
  const inked = await inkedFraction(page, '#detail canvas.world');
  assert.ok(inked > 0.3, `the floor plan covers only ${(inked * 100).toFixed(1)} % of the canvas`);
  await page.screenshot({ path: join(artifacts, 'card-world.png'), fullPage: true });
  await page.close();
});

test('a card created elsewhere appears live, and share links open it', { skip }, async () => {
  const page = await browser.newPage();
  await page.goto(server.base + '/catalogue.html');
  await page.waitForSelector('#live.on');
  const created = await server.post('/api/v1/cards', card('Coffee break', 'staff gather at the coffee machine', ['social'], 'office'));
  assert.equal(created.status, 201);
  await page.waitForSelector(`#cards li[data-id="${created.body.id}"]`);
  await page.screenshot({ path: join(artifacts, 'live.png'), fullPage: true });
  const shared = await browser.newPage();
  await shared.goto(`${server.base}/catalogue.html#card=${created.body.id}`);
  await shared.waitForSelector('#detail h2');
  assert.equal(await shared.textContent('#detail h2'), 'Coffee break');
  await shared.close();
  await page.close();
});

// A lab's client of a lock-step co-simulation: messages queued as they come, steps of 0.8 m/s
// straight ahead; drive(n) takes n steps (or runs to the end) and returns the last message.
function cosimClient(url) {
  const ws = new WebSocket(url, ['socsim.cosim.v1']);
  const queue = [], waiting = [];
  ws.on('message', (data) => {
    const m = JSON.parse(data.toString());
    if (waiting.length) waiting.shift()(m); else queue.push(m);
  });
  const next = () => (queue.length ? Promise.resolve(queue.shift()) : new Promise((r) => waiting.push(r)));
  let step = 0;
  return {
    ws,
    async start() { assert.equal((await next()).type, 'hello'); return next(); },
    async drive(n) {
      for (let k = 0; k < n; k++) {
        step += 1;
        ws.send(JSON.stringify({ type: 'step', step, robots: [{ cmd: { v: 0.8, omega: 0 } }] }));
        const m = await next();
        if (m.type === 'error') throw new Error(m.detail);
        if (m.status === 'ended') return next();  // the report
      }
      return null;
    },
  };
}

test('a co-simulation shows the robot, its path and its contact with a person, live; an evaluation its table', { skip }, async () => {
  const world = { zones: [{ name: 'corridor', type: 'corridor', polygon: [[0, 0], [20, 0], [20, 3], [0, 3]] }] };
  const program = { name: 'encounter', agents: [{ name: 'walker', position: [14, 1.5], speed: 1.2, goals: [[1, 1.5]], cyclic_goals: false }] };
  const created = await server.post('/api/v1/cosim', {
    program, world, seed: 3, time_limit: 30,
    robot: { start: { x: 2, y: 1.45, yaw: 0 }, goal: { x: 18, y: 1.5 }, visible: false },
  });
  assert.equal(created.status, 201, JSON.stringify(created.body));
  const client = cosimClient(`ws://127.0.0.1:${server.wsPort}${created.body.ws_url}`);
  assert.equal((await client.start()).type, 'observation');
  assert.equal(await client.drive(40), null);

  const page = await browser.newPage({ viewport: { width: 1400, height: 900 } });
  await page.goto(`${server.base}/cosim.html#${created.body.id}`);
  await page.waitForSelector('#view[data-ready="1"]');
  await page.waitForSelector(`#sessions li[data-id="${created.body.id}"]`);
  assert.match(await page.textContent('#session-info'), /running/);
  assert.ok(await inkedFraction(page, '#view') > 0.2, 'the corridor is drawn');

  const report = await client.drive(2000);  // on to the end: the invisible robot is walked into
  assert.equal(report?.type, 'report');
  const outcome = report.metrics.robots[0].outcome;
  assert.equal(outcome, 'collision_person', JSON.stringify(report.metrics.robots[0]));
  await page.waitForSelector(`#robots dd[data-outcome="${outcome}"]`, { timeout: 10000 });
  await page.waitForFunction(() => Number(document.querySelector('#view').dataset.contacts) >= 1);
  assert.match(await page.textContent('#contacts'), /robot_0 and person 0 at t = /);
  assert.match(await page.textContent('#report'), /collision_person/);
  // The path drawn is the whole episode's: every frame once, though it was fetched in pieces.
  const view = await (await fetch(`${server.base}/api/v1/cosim/${created.body.id}/view`)).json();
  const drawn = await page.evaluate(() => window.__cosimPathLength?.());
  assert.equal(drawn, view.robots[0].path.length);
  await page.screenshot({ path: join(artifacts, 'cosim.png') });
  client.ws.close();

  // An evaluation of two built-in planners on a card of this corridor: its table on the page.
  const card = await server.post('/api/v1/cards', {
    title: 'Corridor encounter', prompt: 'a robot meets a walker in a corridor', seed: 1, world,
    program: { ...program, robot: { position: [2, 1.45], speed: 1.0, goals: [[18, 1.5]] } },
  });
  assert.equal(card.status, 201, JSON.stringify(card.body));
  const queued = await server.post('/api/v1/evaluations', {
    cards: [card.body.id], seeds: [1], planners: ['builtin:straight', 'builtin:orca'], time_limit_s: 20,
  });
  assert.equal(queued.status, 202, JSON.stringify(queued.body));
  let job;
  for (let i = 0; i < 200; i++) {
    job = await (await fetch(`${server.base}/api/v1/evaluations/${queued.body.id}`)).json();
    if (job.status === 'succeeded' || job.status === 'failed') break;
    await new Promise((r) => setTimeout(r, 100));
  }
  assert.equal(job.status, 'succeeded', JSON.stringify(job.error));
  await page.reload();
  await page.locator(`#evaluations li[data-id="${queued.body.id}"]`).click();
  await page.waitForSelector('#evaluation[data-ready="1"]');
  assert.deepEqual(await page.$$eval('#evaluation-table tbody tr', (rows) => rows.map((r) => r.dataset.planner)),
    ['builtin:straight', 'builtin:orca']);
  const success = job.result.table.planners[1].metrics.success.mean.toFixed(2);
  assert.equal(await page.textContent('#evaluation-table tbody tr[data-planner="builtin:orca"] td:nth-child(3)'), success);
  await page.locator('#evaluation').screenshot({ path: join(artifacts, 'cosim-evaluation.png') });
  await page.close();
});
