// One world of each layout family (corridor with rooms, hall with rooms, open hall with zones,
// ProcTHOR-style open-plan home, auditorium, multi-wing, galleries en suite), generated offline by POST /api/v1/worlds, shown on the floor-plan
// view of a card in headless Chromium: the plan covers the canvas, and a screenshot per family
// lands in tests/e2e/artifacts/world-<family>.png to be looked at.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { artifacts, browserSkip as skip, browserSuite, inkedFraction } from './browser.mjs';

const suite = browserSuite();

// The family depends on the building type, its size and the seed: try seeds until it comes.
async function worldOfFamily(prompt, family) {
  for (let seed = 1; seed <= 16; seed++) {
    const made = await suite.server.post('/api/v1/worlds', { prompt, seed });
    assert.equal(made.status, 201, JSON.stringify(made.body));
    const stored = await (await fetch(`${suite.server.base}/api/v1/worlds/${made.body.id}`)).json();
    if (stored.provenance?.layout_family === family) return { seed, stored };
  }
  assert.fail(`no seed of "${prompt}" gave a ${family} plan`);
}

const families = [
  ['corridor_with_rooms', 'a hospital ward with six patient rooms'],
  ['hall_with_rooms', 'an airport departure hall'],
  ['open_hall_zones', 'a supermarket'],
  ['home_open_plan', 'a small flat with one bedroom'],
  ['auditorium', 'an evening at the cinema'],
  ['multi_wing', "residents of a care home with eighteen residents' rooms"],
  ['rooms_en_suite', 'a museum'],
];

for (const [family, prompt] of families) {
  test(`a ${family} world is drawn on the floor-plan view`, { skip }, async () => {
    const { seed, stored } = await worldOfFamily(prompt, family);
    assert.ok(stored.compliant, `${family}: not compliant`);
    const card = await suite.server.post('/api/v1/cards', {
      title: `${family} (${prompt}, seed ${seed})`, prompt, tags: ['world', family], domain: stored.domain,
      description: `A ${family} plan from POST /api/v1/worlds.`, seed, generator: { name: 'offline' },
      world: stored.world,
    });
    assert.equal(card.status, 201, JSON.stringify(card.body));
    const page = await suite.browser.newPage({ viewport: { width: 1280, height: 900 } });
    await page.goto(`${suite.server.base}/catalogue.html#card=${card.body.id}`);
    await page.waitForSelector('#detail canvas.world');
    const inked = await inkedFraction(page, '#detail canvas.world');
    assert.ok(inked > 0.2, `${family}: the floor plan covers only ${(inked * 100).toFixed(1)} % of the canvas`);
    await page.screenshot({ path: join(artifacts, `world-${family}.png`), fullPage: true });
    await page.close();
  });
}
