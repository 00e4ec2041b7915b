// Text to scenario in headless Debian Chromium, as a user does it: type a prompt, watch the
// job's progress, see the card's world and its people move (the canvas changes between two
// looks), pause stops them; open a scenario card from the catalogue and watch it there.
// A screenshot per test lands in tests/e2e/artifacts/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { artifacts, browserSkip as skip, browserSuite } from './browser.mjs';
const suite = browserSuite();

// A fingerprint of the stage's pixels.
const stagePixels = (page) => page.evaluate(() => {
  const c = document.getElementById('stage');
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let h = 0;
  for (let i = 0; i < d.length; i += 4) h = (h * 31 + d[i] + 7 * d[i + 1] + 13 * d[i + 2]) >>> 0;
  return h;
});

// True once the canvas differs from its first look (within 10 s: a loaded machine may be slow).
async function pixelsChange(page) {
  const first = await stagePixels(page);
  for (let i = 0; i < 50; i++) {
    await page.waitForTimeout(200);
    if (await stagePixels(page) !== first) return true;
  }
  return false;
}

async function waitForPeople(page) {
  await page.waitForFunction(() => /\d+ people/.test(document.getElementById('clock').textContent) &&
    !/ 0 people/.test(document.getElementById('clock').textContent), null, { timeout: 30000 });
}

test('a prompt becomes a scenario whose people move', { skip }, async () => {
  const page = await suite.browser.newPage({ viewport: { width: 1400, height: 900 } });
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(suite.server.base + '/scenario.html');  // the old address: now the start page
  await page.waitForURL(suite.server.base + '/');
  await page.fill('#prompt', 'About twenty patients queue at the reception desk while two nurses chat near the corridor');
  await page.fill('#seed', '3');
  await page.fill('#duration', '30');
  await page.click('#generate');
  await page.waitForFunction(() => document.getElementById('card-title').textContent !== 'No scenario open', null, { timeout: 120000 });
  assert.equal(await page.textContent('#error'), '');
  assert.match(page.url(), /#card=crd_/);
  await waitForPeople(page);
  assert.ok(await pixelsChange(page), 'the agents move between two looks at the canvas');
  assert.match(await page.textContent('#metrics'), /mean speed/);
  await page.screenshot({ path: join(artifacts, 'scenario-live.png'), fullPage: true });

  await page.click('#play');  // pause; the server confirms with a status message, after which no frame comes
  await page.waitForSelector('#stage[data-paused="1"]', { timeout: 10000 });
  await page.waitForTimeout(200);
  const paused = await stagePixels(page);
  await page.waitForTimeout(600);
  assert.equal(await stagePixels(page), paused, 'paused: the picture stands still');
  assert.deepEqual(errors, []);
  await page.close();
});

test('a scenario card opens from the catalogue and plays', { skip }, async () => {
  // A second scenario made through the API, then found in the catalogue like any card.
  const job = await suite.server.post('/api/v1/scenarios', { prompt: 'Fire alarm: everyone evacuates the office', seed: 2, duration_s: 20 });
  assert.equal(job.status, 202);
  let done;
  for (let i = 0; i < 600; i++) {
    done = await (await fetch(`${suite.server.base}/api/v1/jobs/${job.body.id}`)).json();
    if (done.status === 'succeeded' || done.status === 'failed') break;
    await new Promise((r) => setTimeout(r, 200));
  }
  assert.equal(done.status, 'succeeded', JSON.stringify(done.error));

  const page = await suite.browser.newPage({ viewport: { width: 1400, height: 900 } });
  await page.goto(suite.server.base + '/catalogue.html');
  await page.fill('#q', 'evacuates');
  await page.click('#search button');
  await page.waitForFunction(() => document.querySelectorAll('#cards li').length === 1);
  await page.click('#cards li');
  await page.waitForSelector('a.watch');
  await page.click('a.watch');
  await page.waitForURL(/\/#card=crd_/);
  await waitForPeople(page);
  assert.match(await page.textContent('#card-title'), /evacuates/);
  assert.ok(await pixelsChange(page), 'the card plays');
  await page.screenshot({ path: join(artifacts, 'scenario-from-catalogue.png'), fullPage: true });
  await page.close();
});
