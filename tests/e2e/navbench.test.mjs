// The navigation benchmark viewer in headless Debian Chromium: a small benchmark job runs through
// the API, the page shows its table and replays episode 0 — the house, the agent's path step by
// step and the receptacles visited. A screenshot lands in tests/e2e/artifacts/navbench.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { startServer } from './server.mjs';
import { artifacts, browserSkip as skip, launchBrowser } from './browser.mjs';
let server, browser, job;

before(async () => {
  if (skip) return;
  server = await startServer();
  const queued = await server.post('/api/v1/navbench', { split: 'normal', scenes: 3, seed: 5, training_houses: 60 });
  assert.equal(queued.status, 202, JSON.stringify(queued.body));
  for (let i = 0; i < 600; i++) {
    job = await (await fetch(`${server.base}/api/v1/jobs/${queued.body.id}`)).json();
    if (job.status !== 'queued' && job.status !== 'running') break;
    await new Promise((r) => setTimeout(r, 250));
  }
  assert.equal(job.status, 'succeeded', JSON.stringify(job.error));
  browser = await launchBrowser();
});

after(async () => {
  await browser?.close();
  await server?.stop();
});

test('the viewer shows the table and replays an episode step by step', { skip }, async () => {
  const episode = await (await fetch(`${server.base}/api/v1/navbench/${job.id}/episodes/0`)).json();
  const page = await browser.newPage({ viewport: { width: 1400, height: 1000 } });
  await page.goto(`${server.base}/navbench.html?job=${job.id}&n=0`);
  await page.waitForSelector('#replay[data-ready="1"]');
  // The table: one row per method, as in the job's result.
  assert.equal(await page.locator('#table tbody tr').count(), Object.keys(job.result.methods).length);
  assert.equal(await page.locator('#episodes li').count(), job.result.tasks);

  // The first method's whole path is drawn, with its visits listed.
  const method = await page.inputValue('#method');
  const m = episode.methods[method];
  const last = m.path.length - 1;
  assert.equal(await page.getAttribute('#step', 'max'), String(last));
  assert.equal(await page.textContent('#step-label'), `step ${last} / ${last}`);
  assert.equal(await page.locator('#visited li').count(), m.visited.length);

  // Stepping back to the start: nothing reached yet.
  await page.locator('#step').fill('0');
  await page.waitForSelector('#replay[data-step="0"]');
  assert.equal(await page.locator('#visited li.reached').count(), 0);
  assert.equal(await page.textContent('#step-label'), `step 0 / ${last}`);

  // Play runs to the end of the path.
  await page.click('#play');
  await page.waitForSelector(`#replay[data-step="${last}"]`, { timeout: 60000 });
  assert.equal(await page.locator('#visited li.reached').count(), m.visited.length);

  // Another method replays its own path.
  const other = Object.keys(episode.methods).find((k) => k !== method && episode.methods[k].path.length !== m.path.length)
    ?? Object.keys(episode.methods).find((k) => k !== method);
  await page.selectOption('#method', other);
  const otherLast = episode.methods[other].path.length - 1;
  await page.waitForFunction((n) => document.querySelector('#step-label').textContent === `step ${n} / ${n}`, otherLast);

  // The canvas carries the drawing (rooms, walls, path), not a blank surface.
  const inked = await page.evaluate(() => {
    const c = document.querySelector('#replay');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let coloured = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] < 240 || d[i + 1] < 240 || d[i + 2] < 240) coloured++;
    return coloured / (c.width * c.height);
  });
  assert.ok(inked > 0.2, `only ${(inked * 100).toFixed(1)} % of the canvas is drawn`);
  await page.screenshot({ path: join(artifacts, 'navbench.png'), fullPage: true });
  await page.close();
});

test('a bad episode number is reported, not drawn', { skip }, async () => {
  const r = await fetch(`${server.base}/api/v1/navbench/${job.id}/episodes/${job.result.tasks}`);
  assert.equal(r.status, 404);
  assert.match(r.headers.get('content-type'), /problem\+json/);
});
