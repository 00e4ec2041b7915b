// The start page (/) in headless Debian Chromium, as a new user meets it (issue 16): type a prompt
// with a number and an exception, watch "what was understood" fill in as you type (highlighted
// words, the group with its exact count, the venue, "nobody else"), generate, and count the people
// on the canvas: exactly the number asked for. A prompt in another language is refused in the
// panel and by Generate, and no job is queued. Screenshots land in tests/e2e/artifacts/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { artifacts, browserSkip as skip, browserSuite } from './browser.mjs';

const suite = browserSuite();

const PROMPT = 'A library that is empty except for 3 librarians shelving books';

const jobCount = async () => (await (await fetch(`${suite.server.base}/api/v1/jobs?page_size=100`)).json()).items.length;
const marks = (page, kind) => page.$$eval(`#understood-prompt mark[data-kind="${kind}"]`, (ms) => ms.map((m) => m.textContent));

test('what was understood, then exactly the people asked for on the canvas', { skip }, async () => {
  const page = await suite.browser.newPage({ viewport: { width: 1400, height: 1000 } });
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  let interprets = 0;
  page.on('request', (r) => { if (r.url().endsWith('/api/v1/scenarios/interpret')) interprets++; });
  await page.goto(suite.server.base + '/');
  assert.equal(await page.textContent('header nav a[aria-current=page]'), 'Text to scenario');
  assert.equal(await page.locator('#examples button[data-prompt]').count(), 6);
  // Every page of the navigation is served (the catalogue moved to catalogue.html).
  const links = await page.$$eval('header nav a', (as) => as.map((a) => a.href));
  assert.equal(links.length, 5);
  for (const href of links) assert.equal((await fetch(href)).status, 200, href);
  // The prompt already in the box is read on arrival.
  await page.waitForSelector('#understood[data-state=shown] #understood-groups li');

  interprets = 0;
  await page.fill('#prompt', '');
  await page.waitForSelector('#understood[data-state=empty]');  // an empty box is a hint, not an error
  assert.equal(await page.textContent('#understood-problem'), '');
  await page.locator('#prompt').pressSequentially(PROMPT, { delay: 15 });
  await page.waitForFunction((p) => document.getElementById('understood-prompt').textContent === p, PROMPT, { timeout: 10000 });
  assert.ok(interprets >= 1 && interprets <= 6, `typing ${PROMPT.length} characters sent ${interprets} interpret requests (debounced)`);
  assert.match(await page.textContent('#understood-source'), /as you type/);

  // The words it came from, highlighted.
  assert.deepEqual(await marks(page, 'count'), ['3']);
  assert.deepEqual(await marks(page, 'group'), [' librarians']);
  assert.deepEqual(await marks(page, 'venue'), ['library']);
  assert.deepEqual(await marks(page, 'only'), ['empty', 'except for']);
  // One group: three librarians, exactly; a library; nobody else.
  const groups = await page.$$eval('#understood-groups li', (ls) => ls.map((l) => ({ ...l.dataset, text: l.textContent })));
  assert.equal(groups.length, 1, JSON.stringify(groups));
  assert.equal(groups[0].role, 'librarian');
  assert.equal(groups[0].count, '3');
  assert.equal(groups[0].kind, 'exact');
  assert.match(groups[0].text, /shelving/);
  assert.match(await page.textContent('[data-fact="venue"]'), /^library/);
  assert.equal(await page.textContent('[data-fact="people in all"]'), '3');
  assert.equal(await page.textContent('[data-fact="nobody else"]'), "'empty', 'except for'");
  await page.screenshot({ path: join(artifacts, 'intent-typed.png'), fullPage: true });

  // Generate: the card plays, with exactly three people on the canvas, all librarians.
  await page.fill('#seed', '1');
  await page.fill('#duration', '20');
  await page.click('#generate');
  await page.waitForFunction(() => document.getElementById('card-title').textContent !== 'No scenario open', null, { timeout: 120000 });
  assert.equal(await page.textContent('#error'), '');
  await page.waitForFunction(() => Number(document.getElementById('stage').dataset.people) > 0, null, { timeout: 30000 });
  await page.waitForTimeout(1500);  // a few frames later: nobody arrives, nobody is missing
  assert.equal(await page.getAttribute('#stage', 'data-people'), '3');
  assert.deepEqual(JSON.parse(await page.getAttribute('#stage', 'data-roles')), { librarian: 3 });
  assert.match(await page.textContent('#clock'), / 3 people$/);
  // The panel now shows the interpretation stored with the card.
  assert.match(await page.textContent('#understood-source'), /^Stored with card crd_/);
  assert.equal(await page.getAttribute('#understood-groups li', 'data-count'), '3');
  await page.screenshot({ path: join(artifacts, 'intent-generated.png'), fullPage: true });
  assert.deepEqual(errors, []);
  await page.close();
});

test('an example fills the box and is read; a prompt in another language is refused', { skip }, async () => {
  const page = await suite.browser.newPage({ viewport: { width: 1400, height: 1000 } });
  await page.goto(suite.server.base + '/');
  await page.click('#examples button:has-text("ticket-gate bottleneck")');
  assert.match(await page.inputValue('#prompt'), /^Between 20 and 30 commuters/);
  await page.waitForSelector('#understood-groups li[data-role="commuter"]');
  assert.equal(await page.getAttribute('#understood-groups li', 'data-count'), '20–30');
  assert.equal(await page.getAttribute('#understood-groups li', 'data-kind'), 'range');
  assert.match(await page.textContent('[data-fact="venue"]'), /^train station/);

  // Spans are UTF-8 byte offsets: after a two-byte 'é' the highlights still cover the right words.
  await page.fill('#prompt', 'In the café, 20 customers wait');
  await page.waitForFunction(() => document.getElementById('understood-prompt').textContent === 'In the café, 20 customers wait');
  assert.deepEqual(await marks(page, 'venue'), ['café']);
  assert.deepEqual(await marks(page, 'count'), ['20']);
  assert.deepEqual(await marks(page, 'group'), [' customers']);

  // A word no dictionary knows is marked and said in the warnings; the rest is still read.
  await page.fill('#prompt', 'Twenty passengers wait on the platform while the zorgs dance');
  await page.waitForSelector('#understood-warnings li');
  assert.match(await page.textContent('#understood-warnings'), /'zorgs' is not a person, place or object I know: ignored/);
  assert.deepEqual(await marks(page, 'warning'), ['zorgs']);
  assert.equal(await page.getAttribute('#understood-groups li', 'data-count'), '20');
  await page.screenshot({ path: join(artifacts, 'intent-warning.png'), fullPage: true });

  const jobs = await jobCount();
  await page.fill('#prompt', 'Zwanzig Patienten warten im Wartezimmer auf den Arzt');
  await page.waitForSelector('#understood[data-state=problem]');
  assert.match(await page.textContent('#understood-problem'), /not in English[\s\S]*socsim reads English prompts/);
  assert.equal(await page.locator('#understood-groups li').count(), 0);
  await page.click('#generate');
  await page.waitForFunction(() => document.getElementById('error').textContent !== '');
  assert.match(await page.textContent('#error'), /\/prompt: socsim reads English prompts/);
  assert.equal(await jobCount(), jobs, 'a refused prompt queues no job');
  await page.screenshot({ path: join(artifacts, 'intent-refused.png'), fullPage: true });
  await page.close();
});
