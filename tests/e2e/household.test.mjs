// The household viewer in headless Debian Chromium: a household is generated from the page (a job
// through the API), the floor plan and the residents' timeline appear, moving the time slider
// moves an object that the API says changed receptacle, and the statistics are plotted.
// A screenshot lands in tests/e2e/artifacts/household.png.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { artifacts, browserSkip as skip, browserSuite } from './browser.mjs';
const suite = browserSuite();

test('generate a household, see its timeline, move the slider and see an object move', { skip }, async () => {
  const page = await suite.browser.newPage({ viewport: { width: 1400, height: 1100 } });
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`${suite.server.base}/household.html`);
  await page.fill('#rooms', '6');
  await page.fill('#residents-n', '2');
  await page.fill('#days', '2');
  await page.fill('#seed', '3');
  await page.click('#create button[type=submit]');
  await page.waitForSelector('#plan[data-ready="1"]', { timeout: 60000 });

  const id = await page.evaluate(() => window.household.id);
  assert.match(id, /^hh_[0-9a-f]{20}$/);
  const h = await (await fetch(`${suite.server.base}/api/v1/households/${id}`)).json();
  assert.equal(await page.locator('#households li').count(), 1);
  assert.equal(await page.locator('#residents li').count(), h.residents.length);
  assert.equal(await page.getAttribute('#timeline', 'data-rows'), String(h.residents.length));

  // An object the API places on another receptacle later on.
  const t1 = Number(await page.inputValue('#time'));
  const before = await (await fetch(`${suite.server.base}/api/v1/households/${id}/objects?t=${t1}`)).json();
  let t2 = null, moved = null;
  for (let t = t1 + 3600; t <= h.end && !moved; t += 3600) {
    const later = await (await fetch(`${suite.server.base}/api/v1/households/${id}/objects?t=${t}`)).json();
    const o = later.objects.find((x, i) => x.receptacle !== before.objects[i].receptacle);
    if (o) { t2 = t; moved = o.id; }
  }
  assert.ok(moved, 'some object changes receptacle within the scene');
  const drawnBefore = await page.evaluate((o) => window.household.drawn[o], moved);
  assert.ok(drawnBefore, 'the object is drawn');

  await page.locator('#time').fill(String(t2));
  await page.waitForSelector(`#plan[data-t="${t2}"]`, { timeout: 20000 });
  const drawnAfter = await page.evaluate((o) => window.household.drawn[o], moved);
  assert.notDeepEqual(drawnAfter, drawnBefore, `${moved} is drawn elsewhere at t=${t2}`);
  // Its new place carries ink (the dot), not the bare floor.
  const ink = await page.evaluate(([x, y]) => {
    const d = document.querySelector('#plan').getContext('2d').getImageData(Math.round(x), Math.round(y), 1, 1).data;
    return [d[0], d[1], d[2]];
  }, drawnAfter);
  assert.ok(ink.some((c) => c < 200), `a dot is drawn at ${drawnAfter}: ${ink}`);
  assert.match(await page.textContent('#clock'), /^(Mon|Tue|Wed|Thu|Fri|Sat|Sun) \d\d:\d\d$/);

  // Statistics plots.
  await page.waitForSelector('#per-event[data-bars]');
  assert.ok(Number(await page.getAttribute('#per-event', 'data-bars')) > 1);
  assert.ok(Number(await page.getAttribute('#receptacle-types', 'data-bars')) > 1);

  await page.screenshot({ path: join(artifacts, 'household.png'), fullPage: true });
  assert.deepEqual(errors, []);

  // Opening by URL shows the same household.
  const again = await suite.browser.newPage({ viewport: { width: 1200, height: 900 } });
  await again.goto(`${suite.server.base}/household.html?id=${id}`);
  await again.waitForSelector('#plan[data-ready="1"]', { timeout: 30000 });
  assert.equal(await again.evaluate(() => window.household.household.residents.length), h.residents.length);
});
